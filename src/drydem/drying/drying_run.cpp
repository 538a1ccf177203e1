// SPDX-License-Identifier: MIT
#include "drydem/drying/drying_run.hpp"
#include "drydem/analysis/analyze.hpp"
#include "drydem/output/analysis_writer.hpp"
#include "drydem/core/error.hpp"
#include "drydem/core/stop_request.hpp"
#include "drydem/drying/eta.hpp"
#include "drydem/drying/liquid_level.hpp"
#include "drydem/drying/scaling.hpp"
#include "drydem/engine/simulation.hpp"
#include "drydem/output/checkpoint.hpp"
#include "drydem/io/particle_io.hpp"
#include "drydem/io/snapshot_writers.hpp"
#include "drydem/setup/formulation.hpp"
#include "drydem/setup/insertion.hpp"
#include "drydem/git_hash.hpp"
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>
#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <type_traits>
#include <unistd.h>

namespace drydem {
namespace {

using Clock = std::chrono::steady_clock;

std::shared_ptr<spdlog::logger> make_logger(const std::filesystem::path& dir, bool quiet, bool append) {
    auto file = std::make_shared<spdlog::sinks::basic_file_sink_mt>((dir / "log.txt").string(), !append);
    auto console = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
    console->set_level(quiet ? spdlog::level::warn : spdlog::level::info);
    console->set_pattern("%v");
    file->set_pattern("[%Y-%m-%d %H:%M:%S.%e] [%l] %v");
    auto log = std::make_shared<spdlog::logger>("drydem", spdlog::sinks_init_list{console, file});
    log->set_level(spdlog::level::debug);
    log->flush_on(spdlog::level::info);
    return log;
}

/// 99th percentile of the particle tops z + r: a robust thickness that ignores stray particles.
double top_percentile(const ParticleStore& p, double q) {
    std::vector<double> tops(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) tops[i] = p.position[i].z + p.radius[i];
    if (tops.empty()) return 0.0;
    const std::size_t k = std::min(tops.size() - 1, std::size_t(q * double(tops.size())));
    std::nth_element(tops.begin(), tops.begin() + std::ptrdiff_t(k), tops.end());
    return tops[k];
}

std::size_t particles_cutting_level(const ParticleStore& p, double level) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < p.size(); ++i) n += std::abs(level - p.position[i].z) < p.radius[i];
    return n;
}

/// Particles from a file: species by type (type = species + 1), density from the recipe where the
/// file has none.
ParticleStore particles_from_file(const std::filesystem::path& file, const FilmRecipe& recipe,
                                  const Box& box) {
    const ParticleFile in = read_particles(file);
    auto same = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(a, b); };
    if ((in.lx && !same(*in.lx, box.lx)) || (in.ly && !same(*in.ly, box.ly)))
        throw InputError(fmt::format(
            "--particles {}: the file's periodic box is {:.6g} x {:.6g} um but the config's is "
            "{:.6g} x {:.6g} um; set film.box_x and film.box_y to the file's box",
            file.string(), in.lx.value_or(box.lx) * 1e6, in.ly.value_or(box.ly) * 1e6, box.lx * 1e6,
            box.ly * 1e6));
    // Refused before step 1 with the line and the reason: coincident spheres or one below the
    // substrate would otherwise blow up and be blamed on the time step or the forces.
    check_particle_geometry(in, box.lx, box.ly, file);
    ParticleStore p;
    for (const ParticleRecord& r : in.particles) {
        if (r.type < 1 || r.type > int(recipe.species.size()))
            throw InputError(fmt::format("--particles {}: particle {} has type {}; the config "
                                         "defines types 1..{} (NCM classes, then CB)",
                                         file.string(), r.id, r.type, recipe.species.size()));
        const int sp = r.type - 1;
        const double rho = std::isnan(r.density) ? recipe.species[sp].density : r.density;
        Vec3 x = r.position;
        x.x -= in.xlo.value_or(0.0);
        x.y -= in.ylo.value_or(0.0);
        box.wrap(x);
        p.add(r.id, std::uint8_t(sp), r.radius, rho, x);
    }
    return p;
}

/// The drying run's own progress beside the engine state: what a resumed run needs to continue
/// its end criterion, outputs and diagnostics exactly where the checkpoint was taken.
struct RunProgress {
    bool final_found = false, warned_c21 = false, warned_overlap = false;
    double final_thickness = 0.0, process_time_final = 0.0;
    double t_end = INFINITY, next_row = 0.0, next_snapshot = 0.0;
    double dt_min = 0.0, dt_lambda = 0.0, warned_lambda = 0.0;
    std::uint64_t builds_seen = 0;
    std::int32_t frame = 0;           ///< snapshot frames written
    std::int32_t threads = 1;         ///< threads the run used
    double wall_before = 0.0;         ///< wall-clock seconds of the sessions before this one
    std::uint64_t series_bytes = 0;   ///< timeseries.csv length at the checkpoint
    std::uint64_t dump_bytes = 0;     ///< dump.lammpstrj length at the checkpoint
    std::uint64_t seed = 0;
};
static_assert(std::is_trivially_copyable_v<RunProgress>);

struct Checkpoint {
    std::string config_toml;
    RunProgress progress;
    EngineState engine;
};

Checkpoint read_checkpoint(const std::filesystem::path& output_dir) {
    const auto file = checkpoint_file(output_dir);
    const std::vector<unsigned char> bytes = read_checkpoint_file(file);
    BinaryReader r(bytes, file.string());
    Checkpoint ck;
    ck.config_toml = r.str();
    ck.progress = r.pod<RunProgress>();
    ck.engine = read_engine_state(r);
    if (!r.at_end()) throw InputError(fmt::format("{}: unexpected data after the state", file.string()));
    return ck;
}

/// Cuts a file back to `size` bytes: output written after the checkpoint is replayed.
void truncate_file(const std::filesystem::path& file, std::uint64_t size) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) {
        if (size == 0) return;
        throw InputError(fmt::format("--resume: {} is missing", file.string()));
    }
    if (std::filesystem::file_size(file) < size)
        throw InputError(fmt::format("--resume: {} is shorter than at the checkpoint", file.string()));
    std::filesystem::resize_file(file, size, ec);
    if (ec) throw RunError(fmt::format("cannot truncate {}: {}", file.string(), ec.message()));
}

} // namespace

std::filesystem::path checkpoint_file(const std::filesystem::path& output_dir) {
    return output_dir / "checkpoint" / "state.bin";
}

Config resume_config(const std::filesystem::path& output_dir) {
    const Checkpoint ck = read_checkpoint(output_dir);
    Config c = load_config(ck.config_toml, checkpoint_file(output_dir).string());
    c.threads = ck.progress.threads;
    return c;
}

DryingResult run_drying(const Config& c, const RunOptions& opt) {
    namespace fs = std::filesystem;
    const auto wall_start = Clock::now();
    std::optional<Checkpoint> resumed;
    if (opt.resume) resumed = read_checkpoint(opt.output_dir);
    fs::create_directories(opt.output_dir / "snapshots");
    fs::create_directories(opt.output_dir / "checkpoint");
    auto log = make_logger(opt.output_dir, opt.quiet, opt.resume);
    if (!opt.resume) {
        std::ofstream cfg(opt.output_dir / "config.toml");
        cfg << to_toml(c);
    }
    RunProgress pr;
    if (resumed) pr = resumed->progress;

    // --- set-up (M-1) and scaling (M-7) ---
    const FilmRecipe recipe = make_recipe(c);
    const ScaledParameters scaled = scale_parameters(c);
    const Box box{c.box_x, c.box_y};
    ParticleStore particles;
    if (resumed)
        ; // the particles come with the engine state
    else if (opt.particles_file)
        particles = particles_from_file(*opt.particles_file, recipe, box);
    else
        particles = insert_particles(recipe, box, recipe.wet_film_height, c.seed);
    if (opt.particles_file && !resumed) {
        double top = 0.0;
        for (std::size_t i = 0; i < particles.size(); ++i)
            top = std::max(top, particles.position[i].z + particles.radius[i]);
        if (top > recipe.wet_film_height)
            log->warn("--particles: the highest particle top ({:.4g} um) is above the initial liquid "
                      "level H_wet = {:.4g} um of this config (film.areal_loading); the end "
                      "criterion may fire at once", top * 1e6, recipe.wet_film_height * 1e6);
    }
    if (!resumed) write_particles_csv(opt.output_dir / "initial.csv", particles); // the wet film
    const ParticleStore& species_of = resumed ? resumed->engine.particles : particles;
    std::size_t n_ncm = 0, n_cb = 0;
    for (std::uint8_t s : species_of.species) (recipe.species[s].is_cb ? n_cb : n_ncm)++;
    const double final_gap = c.final_gap > 0.0 ? c.final_gap : recipe.largest_diameter();
    LiquidLevelSchedule schedule{recipe.wet_film_height, scaled.level_speeds_scaled,
                                 scaled.zone_duration_scaled};
    log->info("DryDEM {} ({}) run '{}': {} NCM + {} CB particles, box {:.4g} x {:.4g} um, "
              "H_wet = {:.4g} um, seed {}",
              DRYDEM_VERSION, DRYDEM_GIT_HASH, c.name, n_ncm, n_cb, c.box_x * 1e6, c.box_y * 1e6,
              recipe.wet_film_height * 1e6, c.seed);

    EngineSettings es;
    es.integrator = integrator_of(c);
    const double time_step_cap = c.time_step_cap();
    es.dt = time_step_cap;
    es.skin = c.neighbor_skin();
    es.threads = c.threads;
    es.sort_every = c.sort_every;
    es.overlap_limit = c.overlap_limit;
    // The level is known before the first force evaluation: forces (and contact histories) are
    // computed once at t = 0.
    es.initial_liquid_level = schedule.level(0.0);
    Simulation sim = resumed ? Simulation(std::move(resumed->engine), box,
                                          make_drying_force_field(c, recipe, scaled), es)
                             : Simulation(std::move(particles), box,
                                          make_drying_force_field(c, recipe, scaled), es);
    sim.set_liquid_level_schedule([schedule](double t) { return schedule.level(t); });
    if (resumed) {
        if (sim.threads() != pr.threads)
            log->warn("--resume with {} threads where the run used {}: the continuation is valid "
                      "but not bit-identical to an uninterrupted run", sim.threads(), pr.threads);
        log->info("resumed from the checkpoint at step {} (process time {:.4f} s)", sim.step_count(),
                  scaled.process_time(sim.time()));
    }
    pr.threads = sim.threads();
    pr.seed = c.seed;

    // --- stability guard (docs/model.md "Stability guard") ---
    // At every neighbour rebuild the rates of what stays explicit are estimated on the laws' own
    // operators; "adapt" sets Δt to the guarded step (never above the cap run.time_step),
    // "refuse" stops the run where Δt is beyond the stability bound, "warn" only warns.
    if (!resumed) pr.dt_min = sim.settings().dt;
    double guard_wall = 0.0; // this session's wall time in the guard [s]
    auto guard = [&](bool at_start) {
        const auto guard_start = Clock::now();
        const auto e = sim.stability_estimate();
        guard_wall += std::chrono::duration<double>(Clock::now() - guard_start).count();
        const double dt = sim.settings().dt;
        if (c.stability_guard == "adapt") {
            const double target = guarded_time_step(time_step_cap, e);
            if (target != dt)
                log->debug("step {}: dt {:.3g} -> {:.3g} s (damping {:.3g} /s, stiffness {:.3g} "
                           "rad/s, at particle {}; {} power iterations)",
                           sim.step_count(), dt, target, e.damping_rate, e.stiffness_rate,
                           e.particle_id, e.iterations);
            sim.set_time_step(target);
            pr.dt_min = std::min(pr.dt_min, target);
            return stability_indicator(target, e);
        }
        const double indicator = stability_indicator(dt, e);
        if (indicator >= 2.0) {
            const std::string msg = fmt::format(
                "time step {:.3g} s is beyond the explicit stability bound: dt*lambda = {:.3g} >= 2 "
                "at particle {} (damping rate {:.3g} /s, stiffness rate {:.3g} rad/s; docs/model.md "
                "\"Stability guard\"); lower run.time_step or use numerics.stability_guard = "
                "\"adapt\"",
                dt, indicator, e.particle_id, e.damping_rate, e.stiffness_rate);
            if (c.stability_guard == "refuse") {
                if (at_start) throw InputError(msg);
                throw RunError(msg);
            }
            log->warn("{}", msg);
        } else if (indicator > 1.5 && indicator > pr.warned_lambda + 0.05) {
            pr.warned_lambda = indicator; // warn again only when it keeps rising
            log->warn("time step {:.3g} s is close to the stability bound: dt*lambda = {:.3g} at "
                      "particle {}", dt, indicator, e.particle_id);
        }
        return indicator;
    };
    // A resumed run must not re-run the guard here: the uninterrupted run only runs it at rebuilds.
    // "refuse" at the start fails the run like a refusal later on: summary.json says why.
    std::optional<std::string> refused_at_start;
    if (!resumed) {
        try {
            pr.dt_lambda = guard(true);
        } catch (const InputError& e) {
            refused_at_start = e.what();
        }
    }
    log->info("threads {}, integrator {}, dt = {:.3g} s (scaled, cap {:.3g} s), dt*lambda = {:.3g} "
              "(stable < 2), level speeds {} m/s (scaled)", sim.threads(), c.integrator,
              sim.settings().dt, time_step_cap, pr.dt_lambda,
              fmt::join(scaled.level_speeds_scaled, ", "));

    // --- outputs (a resumed run cuts them back to the checkpoint and continues them) ---
    const fs::path series_file = opt.output_dir / "timeseries.csv";
    const fs::path dump_file = opt.output_dir / "snapshots" / "dump.lammpstrj";
    if (resumed) {
        truncate_file(series_file, pr.series_bytes);
        truncate_file(dump_file, pr.dump_bytes);
    }
    CsvSeriesWriter series(series_file,
                           {"process_time_s", "sim_time_s", "step", "liquid_level_um",
                            "film_thickness_um", "film_top_p99_um", "kinetic_energy_J", "contacts",
                            "wall_contacts", "max_overlap_rel", "particles_at_level",
                            "dt_lambda", "time_step_s", "zone"},
                           opt.resume);
    PvdWriter pvd(opt.output_dir / "snapshots" / "particles.pvd");
    PvdWriter level_pvd(opt.output_dir / "snapshots" / "liquid_level.pvd");
    if (resumed) {
        for (PvdWriter* w : {&pvd, &level_pvd}) {
            w->load_existing();
            w->truncate(std::size_t(pr.frame));
        }
    }
    std::ofstream dump(dump_file, resumed ? std::ios::app : std::ios::trunc);
    auto snapshot = [&]() {
        const std::string name = fmt::format("frame_{:05d}.vtp", pr.frame++);
        const double tp = scaled.process_time(sim.time());
        write_vtp(opt.output_dir / "snapshots" / name, sim.particles(), sim.time(), tp,
                  sim.coordination());
        pvd.add(tp, name);
        const std::string level_name = fmt::format("level_{:05d}.vtp", pr.frame - 1);
        write_level_vtp(opt.output_dir / "snapshots" / level_name, box, sim.liquid_level(), tp);
        level_pvd.add(tp, level_name);
        append_lammps_dump(dump, sim.particles(), box, sim.step_count(), sim.stats().layer_top);
        dump.flush();
    };
    auto row = [&]() {
        const auto& st = sim.stats();
        const double values[] = {scaled.process_time(sim.time()),
                                 sim.time(),
                                 double(sim.step_count()),
                                 sim.liquid_level() * 1e6,
                                 st.layer_top * 1e6,
                                 top_percentile(sim.particles(), 0.99) * 1e6,
                                 sim.kinetic_energy(),
                                 double(st.contacts),
                                 double(st.wall_contacts),
                                 st.max_overlap_rel,
                                 double(particles_cutting_level(sim.particles(), sim.liquid_level())),
                                 pr.dt_lambda,
                                 sim.settings().dt,
                                 double(schedule.zone(sim.time()) + 1)};
        series.row(values);
    };
    auto wall_total = [&]() {
        return pr.wall_before + std::chrono::duration<double>(Clock::now() - wall_start).count();
    };
    auto write_checkpoint = [&]() {
        dump.flush();
        pr.series_bytes = fs::file_size(series_file);
        pr.dump_bytes = fs::file_size(dump_file);
        RunProgress saved = pr;
        saved.wall_before = wall_total();
        BinaryWriter w;
        w.str(to_toml(c));
        w.pod(saved);
        write_engine_state(w, sim.state());
        write_checkpoint_file(checkpoint_file(opt.output_dir), w);
        log->debug("checkpoint at step {} (process time {:.4f} s)", sim.step_count(),
                   scaled.process_time(sim.time()));
    };
    // One updating line on a terminal; plain log lines otherwise (and always in log.txt).
    const bool tty = !opt.quiet && isatty(STDERR_FILENO);
    bool progress_shown = false;
    auto clear_progress = [&]() {
        if (progress_shown) std::fputs("\r\033[K", stderr);
        progress_shown = false;
    };

    DryingResult result;
    nlohmann::json summary;
    const double t_max = scaled.sim_time(c.max_process_time);
    std::uint64_t& builds_seen = pr.builds_seen;
    if (!resumed) builds_seen = sim.neighbors().builds();
    auto last_progress = Clock::now(), last_checkpoint = Clock::now();
    RecentPace pace;
    pace.add(0.0, sim.time());
    const std::int64_t step_session = sim.step_count();
    const double areal_mass = recipe.realised_dry_mass() / recipe.base_area;
    try {
        if (refused_at_start) throw RunError(*refused_at_start);
        if (!resumed) {
            row();
            snapshot();
            pr.next_row = scaled.sim_time(c.timeseries_every);
            pr.next_snapshot = c.snapshot_every > 0 ? scaled.sim_time(c.snapshot_every) : INFINITY;
            // A first checkpoint at once: a run killed before the first checkpoint_every (10 min
            // by default) can still be resumed.
            if (c.checkpoint_every > 0) write_checkpoint();
        }
        while (true) {
            sim.step();
            const double t = sim.time(), level = sim.liquid_level(), top = sim.stats().layer_top;
            // M-8.2: the final thickness is reached once the layer no longer follows the level.
            if (!pr.final_found && (top - level > final_gap || level <= 0.0)) {
                pr.final_found = true;
                pr.final_thickness = top;
                pr.process_time_final = scaled.process_time(t);
                pr.t_end = t + scaled.sim_time(c.relaxation);
                clear_progress();
                if (level <= 0.0)
                    log->warn("the liquid level reached the substrate before the layer top rose "
                              "{:.4g} um above it; final thickness taken there", final_gap * 1e6);
                log->info("final thickness {:.4f} um at process time {:.3f} s; relaxing for {} s",
                          top * 1e6, pr.process_time_final, c.relaxation);
            }
            if (!pr.warned_overlap && sim.stats().max_overlap_rel > 0.25) {
                pr.warned_overlap = true;
                clear_progress();
                log->warn("overlaps exceed 25 % of the smaller radius at process time {:.3f} s "
                          "(max {:.3f}): the scaled capillary and van der Waals forces press the "
                          "particles harder than their contact stiffness resists (model.md C-9)",
                          scaled.process_time(t), sim.stats().max_overlap_rel);
            }
            if (sim.neighbors().builds() != builds_seen) {
                builds_seen = sim.neighbors().builds();
                pr.dt_lambda = guard(false);
            }
            if (!pr.warned_c21 && int(t / scaled.zone_duration_scaled) >= int(scaled.level_speeds_scaled.size())) {
                pr.warned_c21 = true;
                clear_progress();
                log->warn("the film is still shrinking after the last dryer zone ({:.4g} s); its "
                          "rate is kept (model.md C-21)", scaled.process_time(t));
            }
            const bool done = t >= pr.t_end;
            const bool timeout = t >= t_max;
            if (t >= pr.next_row || done || timeout) {
                row();
                pr.next_row += scaled.sim_time(c.timeseries_every);
            }
            if (t >= pr.next_snapshot) {
                snapshot();
                pr.next_snapshot += scaled.sim_time(c.snapshot_every);
            }
            if (done) break;
            const auto now = Clock::now();
            if (const int sig = stop_requested()) {
                write_checkpoint(); // a stopped run (Ctrl-C, a scheduler's SIGTERM) can resume
                throw RunError(fmt::format("interrupted by signal {} at process time {:.4g} s; the "
                                           "results so far and a checkpoint are written (continue "
                                           "with drydem run --resume {})",
                                           sig, scaled.process_time(t), opt.output_dir.string()));
            }
            if (timeout)
                throw RunError(fmt::format("no final thickness within run.max_process_time = {} s "
                                           "(layer top {:.4g} um, level {:.4g} um)",
                                           c.max_process_time, top * 1e6, level * 1e6));
            if (c.checkpoint_every > 0 &&
                std::chrono::duration<double>(now - last_checkpoint).count() >= c.checkpoint_every) {
                last_checkpoint = now;
                write_checkpoint();
            }
            if (std::chrono::duration<double>(now - last_progress).count() >= c.progress_every) {
                last_progress = now;
                // ETA: until the level is d_max below the expected final top (the current top,
                // or at most the thickness of an uncalendered film of ~2.4 g/cm3, M-8.3), plus
                // the relaxation window; at the pace of the last two minutes (RecentPace).
                const double expected_top = std::min(top, std::max(areal_mass / 2400.0, 0.5 * top));
                const double remaining =
                    pr.final_found ? pr.t_end - t
                                   : std::max(0.0, schedule.time_at_level(std::max(0.0, expected_top - final_gap)) - t) +
                                         scaled.sim_time(c.relaxation);
                const double elapsed = std::chrono::duration<double>(now - wall_start).count();
                pace.add(elapsed, t);
                const double eta = pace.eta(remaining);
                const std::string line = fmt::format(
                    "step {:>9}  t = {:8.3f} s ({:.4g} us sim)  level {:7.3f} um  top {:7.3f} um  "
                    "contacts {:>7}  {:.3g} particle-steps/s  ETA {:.0f} s",
                    sim.step_count(), scaled.process_time(t), t * 1e6, level * 1e6, top * 1e6,
                    sim.stats().contacts,
                    double(sim.particles().size()) * double(sim.step_count() - step_session) / elapsed, eta);
                if (tty) {
                    log->debug("{}", line); // log.txt only
                    std::fprintf(stderr, "\r\033[K%s", line.c_str());
                    std::fflush(stderr);
                    progress_shown = true;
                } else {
                    log->info("{}", line);
                }
            }
        }
        result.completed = true;
        result.relaxed_thickness = sim.stats().layer_top;
    } catch (const RunError& e) {
        result.completed = false;
        result.error = e.what();
        clear_progress();
        log->error("run failed: {}", e.what());
    }
    clear_progress();

    // --- results (also after a failure: keep what the run reached) ---
    result.steps = sim.step_count();
    result.wall_time = wall_total();
    result.final_thickness = pr.final_thickness;
    result.process_time_final = pr.process_time_final;
    const bool final_found = pr.final_found;
    if (final_found) {
        const CoatingDensity d = coating_density(areal_mass, result.final_thickness, recipe.solids_density);
        result.density = d.density;
        result.porosity = d.porosity;
    }
    try {
        snapshot();
        write_particles_csv(opt.output_dir / "final.csv", sim.particles());
    } catch (const std::exception& e) {
        log->error("could not write the final particles: {}", e.what());
    }
    summary["status"] = result.completed ? "completed" : "failed";
    if (!result.completed) summary["error"] = result.error;
    summary["name"] = c.name;
    summary["final_thickness_um"] = final_found ? nlohmann::json(result.final_thickness * 1e6) : nlohmann::json(nullptr);
    summary["final_thickness_relaxed_um"] = result.completed ? nlohmann::json(result.relaxed_thickness * 1e6) : nlohmann::json(nullptr);
    summary["film_top_p99_um"] = top_percentile(sim.particles(), 0.99) * 1e6;
    summary["density_g_cm3"] = final_found ? nlohmann::json(result.density * 1e-3) : nlohmann::json(nullptr);
    summary["porosity"] = final_found ? nlohmann::json(result.porosity) : nlohmann::json(nullptr);
    summary["areal_loading_mg_cm2"] = areal_mass * 100.0;
    summary["areal_loading_nominal_mg_cm2"] = c.areal_loading * 100.0;
    summary["wet_film_height_um"] = recipe.wet_film_height * 1e6;
    summary["solids_density_g_cm3"] = recipe.solids_density * 1e-3;
    summary["process_time_final_s"] = final_found ? nlohmann::json(result.process_time_final) : nlohmann::json(nullptr);
    summary["process_time_end_s"] = scaled.process_time(sim.time());
    summary["final_gap_um"] = final_gap * 1e6;
    summary["particles"] = {{"ncm", n_ncm}, {"cb", n_cb}};
    summary["box_um"] = {c.box_x * 1e6, c.box_y * 1e6};
    summary["scaling"] = to_json(scaled);
    // Which shrinkage rates drove the liquid level: the config's, or the dryer model's (docs/dryer.md).
    {
        std::vector<double> um;
        for (double r : c.shrinkage_rates) um.push_back(r * 1e6);
        summary["shrinkage_rates_um_s"] = um;
        summary["shrinkage_rates_source"] =
            c.dryer_schedule == "model"
                ? fmt::format("dryer model (preset {}, final porosity {:.4g})", c.dryer_preset, c.dryer_final_porosity)
                : std::string("dryer.shrinkage_rates");
    }
    summary["integrator"] = c.integrator;
    summary["time_step_s"] = time_step_cap;
    summary["time_step_min_s"] = pr.dt_min;
    summary["time_step_mean_s"] = result.steps > 0 ? sim.time() / double(result.steps) : 0.0;
    {
        const PhaseTimes& pt = sim.phase_times();
        summary["wall_time_phases_s"] = {{"pair", pt.pair}, {"neighbor", pt.neighbor},
                                         {"integrate", pt.integrate}, {"guard", guard_wall}};
        summary["neighbor_builds"] = sim.neighbors().builds();
    }
    summary["steps"] = result.steps;
    summary["seed"] = c.seed;
    summary["resumed"] = opt.resume;
    summary["threads"] = sim.threads();
    summary["version"] = fmt::format("{} ({})", DRYDEM_VERSION, DRYDEM_GIT_HASH);
    summary["wall_time_s"] = result.wall_time;
    summary["particle_steps_per_s"] =
        double(sim.particles().size()) * double(result.steps) / std::max(result.wall_time, 1e-9);
    summary["config"] = "config.toml";
    // The structure analysis of the dried film (docs/analysis.md): analysis/ and its plots.
    bool analysed = false;
    if (result.completed && c.analysis_at_end) {
        try {
            analysis::AnalysisOptions ao;
            ao.voxel = c.analysis_voxel_size;
            ao.profile_dz = c.analysis_profile_dz;
            ao.contact_gap = c.analysis_contact_gap;
            ao.pore_top = c.analysis_pore_top;
            analysis::set_transport_options(ao, c);
            ao.timeseries = (opt.output_dir / "timeseries.csv").string();
            ao.log = [&](const std::string& m) { log->info("analysis: {}", m); };
            const analysis::Structure st =
                analysis::structure_from_file(read_particles(opt.output_dir / "final.csv"), c);
            const analysis::AnalysisResult ar = analysis::analyze_structure(st, ao);
            write_analysis(opt.output_dir / "analysis", ar, ao, "final.csv");
            summary["analysis"] = "analysis/analysis.json";
            summary["thickness_half_solid_um"] = ar.bulk.thickness_half_solid * 1e6;
            summary["cb_binder_porosity_eq2"] = ar.bulk.cb_binder_porosity;
            summary["coordination_mean"] = ar.coordination.mean();
            if (ar.voxelized) {
                summary["psd_peak_um"] = ar.psd.peak * 1e6;
                summary["pore_chord_mean_um"] = {{"x", ar.chords[0].mean_voxels() * ar.voxel * 1e6},
                                                 {"y", ar.chords[1].mean_voxels() * ar.voxel * 1e6},
                                                 {"z", ar.chords[2].mean_voxels() * ar.voxel * 1e6}};
            }
            analysed = true;
        } catch (const std::exception& e) {
            log->warn("structure analysis failed: {}", e.what());
        }
    }
    write_file_atomically(opt.output_dir / "summary.json", [&](std::ostream& o) { o << summary.dump(2) << "\n"; });
    if (result.completed)
        log->info("done: final thickness {:.3f} um, density {:.4f} g/cm3, porosity {:.4f}; {} steps "
                  "in {:.1f} s ({:.3g} particle-steps/s); results in {}",
                  result.final_thickness * 1e6, result.density * 1e-3, result.porosity, result.steps,
                  result.wall_time, summary["particle_steps_per_s"].get<double>(), opt.output_dir.string());

    if (opt.plots) {
        const fs::path script = fs::path(DRYDEM_SOURCE_DIR) / "scripts" / "plot_run.py";
        if (fs::exists("/usr/bin/python3") && fs::exists(script)) {
            const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}' >> '{}' 2>&1", script.string(),
                                                opt.output_dir.string(), (opt.output_dir / "log.txt").string());
            if (std::system(cmd.c_str()) != 0) log->warn("plotting failed (see log.txt)");
        }
        const fs::path an_script = fs::path(DRYDEM_SOURCE_DIR) / "scripts" / "plot_analysis.py";
        if (analysed && fs::exists("/usr/bin/python3") && fs::exists(an_script)) {
            const std::string cmd =
                fmt::format("/usr/bin/python3 '{}' '{}' '{}' >> '{}' 2>&1", an_script.string(),
                            (opt.output_dir / "analysis").string(), (opt.output_dir / "plots").string(),
                            (opt.output_dir / "log.txt").string());
            if (std::system(cmd.c_str()) != 0) log->warn("plotting the analysis failed (see log.txt)");
        }
    }
    log->flush();
    return result;
}

} // namespace drydem
