// SPDX-License-Identifier: MIT
// The drying driver (paper Sec. 4 and 8, model.md M-8), top to bottom:
//   1. set-up: the film's recipe (M-1), scaled parameters (M-7) and level schedule (M-8.1); the
//      wet film's particles (inserted, read from a file, or the checkpoint's); the engine.
//   2. start: the stability guard's first estimate; the outputs at t = 0, or, resumed, the run's
//      progress loaded and the outputs cut back to the checkpoint.
//   3. drying: step; the end criterion (final thickness, relaxation window; M-8.2); the guard at
//      each neighbour rebuild; every output after each step; stop where asked to.
//   4. end: the results (thickness, density, porosity; M-8.4) and every output's end.
// The outputs are observers (run_outputs.cpp, run_summary.cpp) called from one fixed list.
#include "drydem/drying/law_parameters.hpp"
#include "drydem/drying/derived_checks.hpp"
#include "drydem/drying/drying_run.hpp"
#include "drydem/core/error.hpp"
#include "drydem/core/stop_request.hpp"
#include "drydem/drying/film_setup.hpp"
#include "drydem/drying/run_checkpoint.hpp"
#include "drydem/drying/run_observer.hpp"
#include "drydem/git_hash.hpp"
#include "drydem/io/particle_io.hpp"
#include "drydem/parallel/mpi_world.hpp"
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/logger.h>
#include <exception>
#include <fstream>
#include <iostream>
#include <unistd.h>

namespace drydem {
namespace {

/// StepView::stop of a run stopped by --stop-after-steps (signals are positive).
constexpr int kStopAfterSteps = -1;

class DryingRun {
public:
    DryingRun(const Config& c, const RunOptions& opt);
    DryingResult dry();
    [[nodiscard]] bool decomposed() const { return whole_.decomposed(); }

private:
    [[nodiscard]] std::shared_ptr<spdlog::logger> open_folder();
    [[nodiscard]] Simulation make_simulation();
    void start();
    void step();
    void finish(DryingResult& result);
    void report(EndCriterion::Event event) const;
    [[noreturn]] void stop(const StepView& at) const;
    [[nodiscard]] int stop_reason() const;
    [[nodiscard]] StepView view(bool timeout, int stop) const {
        return {sim_, whole_, end_, guard_, timeout, stop, RunClock::now()};
    }
    template <class Call>
    void on_outputs(Call&& call);
    [[nodiscard]] double wall_total() const {
        return wall_before_ +
               std::chrono::duration<double>(RunClock::now() - session_start_).count();
    }
    void visit_state(StateFields& f);

    const Config& c_;
    const RunOptions& opt_;
    const RunClock::time_point session_start_ = RunClock::now();
    const parallel::World world_ = parallel::world(); ///< rank 0 writes the outputs
    std::optional<RunCheckpoint> resumed_;
    StatusLine status_;
    std::shared_ptr<spdlog::logger> log_;
    Film film_;
    Simulation sim_;
    WholeFilm whole_;
    StabilityGuard guard_;
    EndCriterion end_;
    const double t_max_; ///< run.max_process_time [s, simulated]
    RunContext ctx_;
    std::vector<std::unique_ptr<RunObserver>> outputs_;
    double wall_before_ = 0.0;        ///< wall seconds of the sessions before this one
    std::int32_t threads_before_ = 0; ///< threads of the sessions before this one
};

/// The engine's settings for the film's run on `ranks` MPI ranks.
EngineSettings engine_settings(const Config& c, const Film& film, int ranks) {
    EngineSettings es;
    es.integrator = integrator_of(c);
    es.dt = largest_time_step(c, film.scaled);
    es.quasi_static = quasi_static_settings(c, film.scaled);
    es.skin = c.neighbor_skin();
    es.threads = c.threads;
    es.sort_every = c.sort_every;
    es.overlap_limit = c.overlap_limit;
    es.implicit_stiffness = c.implicit_stiffness_on();
    es.ranks = ranks;
    return es;
}

DryingRun::DryingRun(const Config& c, const RunOptions& opt)
    : c_(c), opt_(opt),
      resumed_(opt.resume ? std::optional<RunCheckpoint>(read_run_checkpoint(opt.output_dir))
                          : std::nullopt),
      status_(!opt.quiet && isatty(STDERR_FILENO)), log_(open_folder()), film_(describe_film(c)),
      sim_(make_simulation()), whole_(sim_),
      guard_(guard_policy_of(c.stability_guard),
             {largest_time_step(c, film_.scaled), critical_fraction_for(c, c.integrator),
              stability_bound_for(c.integrator)},
             *log_),
      end_(c.final_gap > 0.0 ? c.final_gap : film_.recipe.largest_diameter(),
           film_.scaled.sim_time(c.relaxation)),
      t_max_(film_.scaled.sim_time(c.max_process_time)), ctx_{c,     opt,     film_,
                                                              *log_, status_, session_start_},
      outputs_(whole_.root() ? make_run_outputs(ctx_, [this](StateFields& f) { visit_state(f); })
                             : std::vector<std::unique_ptr<RunObserver>>{}) {
    if (resumed_) {
        visit_state(resumed_->progress);
        if (whole_.root()) resumed_->progress.check_all_loaded(); // the outputs are the root's
    }
}

/// The output folder: snapshots/, checkpoint/, log.txt, and config.toml of a fresh run. The
/// other ranks of a decomposed run write nothing: their logger is silent.
std::shared_ptr<spdlog::logger> DryingRun::open_folder() {
    if (world_.rank != 0) return silent_logger();
    std::filesystem::create_directories(opt_.output_dir / "snapshots");
    std::filesystem::create_directories(opt_.output_dir / "checkpoint");
    auto log = make_run_logger(opt_.output_dir, opt_.quiet, opt_.resume, status_);
    if (!opt_.resume) std::ofstream(opt_.output_dir / "config.toml") << to_toml(c_);
    return log;
}

/// The engine on the wet film (initial.csv), or on the checkpoint's state.
Simulation DryingRun::make_simulation() {
    ParticleStore particles;
    if (!resumed_) {
        particles = wet_film_particles(c_, opt_, film_, *log_); // the same on every rank
        if (world_.rank == 0) write_particles_csv(opt_.output_dir / "initial.csv", particles);
        scale_cb_inertia(particles, film_.recipe, film_.scaled); // a checkpoint keeps it
    }
    count_species(film_, resumed_ ? resumed_->engine.particles : particles);
    log_->info("DryDEM {} ({}) run '{}': {} NCM + {} CB particles, box {:.4g} x {:.4g} um, H_wet = "
               "{:.4g} um, seed {}",
               DRYDEM_VERSION, DRYDEM_GIT_HASH, c_.name, film_.n_ncm, film_.n_cb, c_.box_x * 1e6,
               c_.box_y * 1e6, film_.recipe.wet_film_height * 1e6, c_.seed);
    EngineSettings es = engine_settings(c_, film_, world_.size);
    // The level is known before the first force evaluation: forces (and contact histories) are
    // computed once at t = 0.
    es.initial_liquid_level = film_.schedule.level(0.0);
    ForceField forces = make_drying_force_field(c_, film_.recipe, film_.scaled);
    Simulation sim = resumed_
                         ? Simulation(std::move(resumed_->engine), film_.box, std::move(forces), es)
                         : Simulation(std::move(particles), film_.box, std::move(forces), es);
    sim.set_liquid_level_schedule(
        [schedule = film_.schedule](double t) { return schedule.level(t); });
    return sim;
}

/// The run's own resume state: threads, seed and wall time, then every part's.
void DryingRun::visit_state(StateFields& f) {
    std::int32_t threads = sim_.threads();
    std::uint64_t seed = c_.seed;
    double wall = wall_total(); // saved: this session's time included
    f("run.threads", threads);
    f("run.seed", seed);
    f("run.wall_time", wall);
    if (f.loading()) {
        threads_before_ = threads;
        wall_before_ = wall;
    }
    end_.fields(f);
    guard_.fields(f);
    for (auto& o : outputs_) o->fields(f);
}

void DryingRun::start() {
    if (resumed_) {
        if (sim_.threads() != threads_before_)
            log_->warn("--resume with {} threads where the run used {}: the continuation is valid "
                       "but not bit-identical to an uninterrupted run",
                       sim_.threads(), threads_before_);
        log_->info("resumed from the checkpoint at step {} (process time {:.4f} s)",
                   sim_.step_count(), film_.scaled.process_time(sim_.time()));
    } else {
        guard_.start(
            sim_); // a resumed run must not: the uninterrupted run only runs it at rebuilds
    }
    log_->info(
        "threads {}, integrator {}, dt = {:.3g} s (scaled, cap {:.3g} s), dt*lambda = {:.3g} "
        "(stable < 2), level speeds {} m/s (scaled)",
        sim_.threads(), c_.integrator, sim_.settings().dt, largest_time_step(c_, film_.scaled),
        guard_.indicator(), fmt::join(film_.scaled.level_speeds_scaled, ", "));
    if (const parallel::Halo* h = sim_.halo()) {
        const parallel::Decomposition& d = h->decomposition();
        log_->info("{} MPI ranks: {} x {} x {} subdomains (x, y, z layers; docs/parallel.md), "
                   "rank 0 owns {} particles and holds {} ghosts",
                   d.ranks(), d.px, d.py, d.pz, h->owned(), sim_.particles().size() - h->owned());
    }
    const DerivedQuantities plan = derived_quantities(c_);
    const double estimate = estimated_wall_time(plan, sim_.threads());
    if (!resumed_ && estimate > wall_time_warning)
        log_->warn("this run is estimated at {:.3g} days on {} threads ({:.3g} particle-steps at "
                   "{:.3g} per second "
                   "and core; the guard may lower the step further): check scaling.time_factor, "
                   "run.time_step and "
                   "the box (`drydem check`)",
                   estimate / 86400.0, sim_.threads(), plan.steps * plan.particles,
                   plan.particle_steps_per_core);
    const StepView at = view(false, 0);
    on_outputs([&](RunObserver& o) { o.open(at, resumed_.has_value()); });
}

/// Calls every output (the root's) while the other ranks answer its requests for the film; an
/// output that fails stops every rank with its message.
template <class Call>
void DryingRun::on_outputs(Call&& call) {
    if (!whole_.root()) {
        whole_.serve();
        return;
    }
    try {
        for (auto& o : outputs_) call(*o);
    } catch (const std::exception& e) {
        whole_.fail(e.what());
        throw;
    }
    whole_.release();
}

void DryingRun::step() {
    sim_.step();
    report(end_.update(sim_.time(), sim_.liquid_level(), sim_.stats().layer_top));
    guard_.after_step(sim_);
    const StepView now = view(sim_.time() >= t_max_, stop_reason());
    on_outputs([&](RunObserver& o) { o.after_step(now); });
    if (!end_.done() && (now.stop != 0 || now.timeout)) stop(now);
}

void DryingRun::report(EndCriterion::Event event) const {
    if (event == EndCriterion::Event::none) return;
    if (event == EndCriterion::Event::final_at_substrate)
        log_->warn(
            "the liquid level reached the substrate before the layer top rose {:.4g} um above "
            "it; final thickness taken there",
            end_.final_gap() * 1e6);
    log_->info("final thickness {:.4f} um at process time {:.3f} s; relaxing for {} s",
               end_.final_thickness() * 1e6, film_.scaled.process_time(end_.time_final()),
               c_.relaxation);
}

/// Ctrl-C, SIGTERM (a batch system's time limit), or --stop-after-steps (for testing). A signal
/// reaches the ranks of a launch at different steps: they stop at the first step any has it.
int DryingRun::stop_reason() const {
    const int sig = whole_.decomposed() ? parallel::all_max(stop_requested()) : stop_requested();
    if (sig) return sig;
    if (opt_.stop_after_steps && sim_.step_count() >= *opt_.stop_after_steps)
        return kStopAfterSteps;
    return 0;
}

void DryingRun::stop(const StepView& at) const {
    const double tp = film_.scaled.process_time(sim_.time());
    const std::string resume =
        fmt::format("the results so far and a checkpoint are written (continue "
                    "with drydem run --resume {})",
                    opt_.output_dir.string());
    if (at.stop == kStopAfterSteps)
        throw RunError(
            fmt::format("stopped after step {} (--stop-after-steps) at process time {:.4g} s; {}",
                        sim_.step_count(), tp, resume),
            "stop_after_steps");
    if (at.stop != 0)
        throw RunError(fmt::format("interrupted by signal {} at process time {:.4g} s; {}", at.stop,
                                   tp, resume),
                       "interrupted");
    throw RunError(
        fmt::format("no final thickness within run.max_process_time = {} s (layer top {:.4g} um, "
                    "level {:.4g} um)",
                    c_.max_process_time, sim_.stats().layer_top * 1e6, sim_.liquid_level() * 1e6),
        "max_process_time");
}

/// The results (also of a failed run: what it reached), then every output's end. An output that
/// fails is logged and the others still run; the summary's failure fails the run.
void DryingRun::finish(DryingResult& r) {
    r.steps = sim_.step_count();
    r.wall_time = wall_total();
    r.final_thickness = end_.final_thickness();
    r.process_time_final = film_.scaled.process_time(end_.time_final());
    if (end_.final_found()) {
        const CoatingDensity d =
            coating_density(film_.areal_mass, r.final_thickness, film_.recipe.solids_density);
        r.density = d.density;
        r.porosity = d.porosity;
    }
    nlohmann::json summary;
    const RunEnd at{sim_, whole_, end_, guard_, r, summary};
    std::exception_ptr required_failed;
    on_outputs([&](RunObserver& o) {
        try {
            o.finish(at);
        } catch (const std::exception& e) {
            log_->error("could not write the {}: {}", o.name(), e.what());
            if (o.required()) required_failed = std::current_exception();
        }
    });
    log_->flush();
    if (required_failed) std::rethrow_exception(required_failed);
}

DryingResult DryingRun::dry() {
    DryingResult result;
    try {
        start();
        while (!end_.done()) step();
        result.completed = true;
        result.stop_reason = "completed";
        result.relaxed_thickness = sim_.stats().layer_top;
    } catch (const RunError& e) {
        result.error = e.what();
        result.stop_reason = e.reason;
        log_->error("run failed: {}", e.what());
    }
    finish(result);
    return result;
}

} // namespace

void check_rank_count(const Config& c, int ranks) {
    if (ranks < 2) return;
    const Film film = describe_film(c);
    const ForceField forces = make_drying_force_field(c, film.recipe, film.scaled);
    // The largest sphere of each class bounds what its particles reach; the wet film's height
    // bounds their centres.
    double r_max = 0.0, range_max = 0.0;
    for (std::size_t s = 0; s < film.recipe.species.size(); ++s) {
        const double r = 0.5 * film.recipe.species[s].diameter;
        r_max = std::max(r_max, r);
        range_max = std::max(range_max, owner_range_bound(forces, int(s), r));
    }
    (void)plan_decomposition(film.box, r_max, range_max, film.recipe.wet_film_height,
                             engine_settings(c, film, ranks));
}

Config resume_config(const std::filesystem::path& output_dir) {
    RunCheckpoint ck = read_run_checkpoint(output_dir);
    if (ck.progress.has("calender.run_dir"))
        throw InputError(fmt::format("{}: holds a calendering run's checkpoint, not a drying "
                                     "run's; continue it with drydem calender --resume {}",
                                     output_dir.string(), output_dir.string()));
    Config c = load_config(ck.config_toml, checkpoint_file(output_dir).string());
    std::int32_t threads = 0;
    ck.progress("run.threads", threads);
    c.threads = threads;
    return c;
}

DryingResult run_drying(const Config& c, const RunOptions& opt) {
    DryingRun run(c, opt);
    if (!run.decomposed()) return run.dry();
    // A failure on one rank that the others cannot learn of (an output's I/O, memory) would leave
    // them waiting in an exchange: it ends the launch.
    try {
        return run.dry();
    } catch (const std::exception& e) {
        std::cerr << fmt::format("error: rank {}: {}\n", parallel::world().rank, e.what());
        parallel::abort_all(dynamic_cast<const InputError*>(&e) ? 2 : 1);
    }
}

} // namespace drydem
