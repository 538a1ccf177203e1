// SPDX-License-Identifier: MIT
#include "drydem/drying/analysis_inputs.hpp"
#include "drydem/drying/run_summary.hpp"
#include "drydem/analysis/analyze.hpp"
#include "drydem/drying/dimensionless_groups.hpp"
#include "drydem/drying/film_measures.hpp"
#include "drydem/git_hash.hpp"
#include "drydem/output/analysis_writer.hpp"
#include "drydem/output/python_script.hpp"
#include "drydem/io/particle_io.hpp"
#include <fmt/format.h>
#include <spdlog/logger.h>
#include <algorithm>
#include <cstdlib>

namespace drydem {

nlohmann::json wall_time_phases(const Simulation& sim, const StabilityGuard& guard) {
    const PhaseTimes& pt = sim.phase_times();
    return {{"pair", pt.pair},
            {"neighbor", pt.neighbor},
            {"integrate", pt.integrate},
            {"guard", guard.wall_time()}};
}
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

/// final.csv: the particles where the run ended.
class FinalParticles final : public RunObserver {
public:
    explicit FinalParticles(const RunContext& ctx) : ctx_(ctx) {}
    const char* name() const override { return "final particles"; }
    void finish(const RunEnd& e) override {
        write_particles_csv(ctx_.options.output_dir / "final.csv", e.whole.particles());
    }

private:
    const RunContext& ctx_;
};

/// analysis/: the structure analysis of final.csv (docs/analysis.md) for a completed run with
/// analysis.at_end; its headline numbers go into the summary.
class StructureAnalysis final : public RunObserver {
public:
    explicit StructureAnalysis(const RunContext& ctx) : ctx_(ctx) {}
    const char* name() const override { return "structure analysis"; }
    void finish(const RunEnd& e) override {
        if (!e.result.completed || !ctx_.config.analysis_at_end) return;
        try {
            analyse(e.summary);
        } catch (const std::exception& ex) {
            ctx_.log.warn("structure analysis failed: {}", ex.what());
        }
    }

private:
    void analyse(json& summary) const {
        const Config& c = ctx_.config;
        const fs::path dir = ctx_.options.output_dir;
        analysis::AnalysisOptions ao = end_of_run_analysis_options(c);
        ao.timeseries = (dir / "timeseries.csv").string();
        ao.dump = (dir / "snapshots" / "dump.lammpstrj").string();
        ao.dump_defaults = file_defaults(c);
        ao.log = [this](const std::string& m) { ctx_.log.info("analysis: {}", m); };
        const analysis::Structure st =
            analysis::structure_from_file(read_particles(dir / "final.csv"), file_defaults(c));
        const analysis::AnalysisResult ar = analysis::analyze_structure(st, ao);
        write_analysis(dir / "analysis", ar, ao, "final.csv");
        json add;
        add["analysis"] = "analysis/analysis.json";
        add["thickness_half_solid_um"] = ar.bulk.thickness_half_solid * 1e6;
        add["cb_binder_porosity_eq2"] = ar.bulk.cb_binder_porosity;
        add["coordination_mean"] = ar.coordination.mean();
        if (ar.voxelized) {
            add["psd_peak_um"] = ar.psd.peak * 1e6;
            add["pore_chord_mean_um"] = {{"x", ar.chords[0].mean_voxels() * ar.voxel * 1e6},
                                         {"y", ar.chords[1].mean_voxels() * ar.voxel * 1e6},
                                         {"z", ar.chords[2].mean_voxels() * ar.voxel * 1e6}};
        }
        summary.update(add); // all or nothing: a failed analysis leaves no partial keys
    }

    const RunContext& ctx_;
};

/// A value known only once the final thickness is found (null before).
json if_found(bool found, double value) { return found ? json(value) : json(nullptr); }

/// The summary's results: thickness, density, porosity, times.
void add_results(const RunContext& ctx, const RunEnd& e, json& s) {
    const DryingResult& r = e.result;
    const Film& film = ctx.film;
    const bool found = e.end.final_found();
    s["status"] = r.completed ? "completed" : "failed";
    s["stop_reason"] = r.stop_reason;
    if (!r.completed) s["error"] = r.error;
    s["name"] = ctx.config.name;
    s["final_thickness_um"] = if_found(found, r.final_thickness * 1e6);
    s["final_thickness_relaxed_um"] = if_found(r.completed, r.relaxed_thickness * 1e6);
    s["film_top_p99_um"] = top_percentile(e.whole.particles(), 0.99) * 1e6;
    s["density_g_cm3"] = if_found(found, r.density * 1e-3);
    s["porosity"] = if_found(found, r.porosity);
    s["areal_loading_mg_cm2"] = film.areal_mass * 100.0;
    s["areal_loading_nominal_mg_cm2"] = ctx.config.areal_loading * 100.0;
    s["wet_film_height_um"] = film.recipe.wet_film_height * 1e6;
    s["solids_density_g_cm3"] = film.recipe.solids_density * 1e-3;
    s["process_time_final_s"] = if_found(found, r.process_time_final);
    s["process_time_end_s"] = film.scaled.process_time(e.sim.time());
    s["final_gap_um"] = e.end.final_gap() * 1e6;
    s["particles"] = {{"ncm", film.n_ncm}, {"cb", film.n_cb}};
    s["box_um"] = {ctx.config.box_x * 1e6, ctx.config.box_y * 1e6};
}

/// A decomposed run: its grid, rank 0's share and traffic, and every rank's share and waits
/// (docs/parallel.md "Scaling"): the rank that waited least set the pace.
void add_decomposition(const parallel::Halo& h, const Simulation& sim, const WholeFilm& whole,
                       json& s) {
    const parallel::HaloCounters& n = h.counters();
    json owned = json::array(), ghosts = json::array(), waited = json::array();
    for (const RankLoad& l : whole.rank_loads()) {
        owned.push_back(l.owned);
        ghosts.push_back(l.ghosts);
        waited.push_back(l.waited_s);
    }
    s["ranks"] = h.decomposition().ranks();
    s["mpi"] = {{"grid", {h.decomposition().px, h.decomposition().py, h.decomposition().pz}},
                {"rank0_owned", sim.owned()},
                {"rank0_ghosts", sim.particles().size() - sim.owned()},
                {"rank0_messages", n.messages},
                {"rank0_bytes", n.bytes},
                {"rank0_exchange_s", n.seconds},
                {"rank0_migrated", n.migrated},
                {"rank0_exchanges", n.exchanges},
                {"owned", owned},
                {"ghosts", ghosts},
                {"waited_s", waited}};
}

/// The summary's record of how the run was made: scaling, level, integration, cost, build.
void add_method(const RunContext& ctx, const RunEnd& e, json& s) {
    const Config& c = ctx.config;
    const Simulation& sim = e.sim;
    s["scaling"] = to_json(ctx.film.scaled);
    s["dimensionless_groups"] = to_json(dimensionless_groups(c));
    // Which shrinkage rates drove the liquid level: the config's, or the dryer model's (docs/dryer.md).
    std::vector<double> um;
    for (double r : c.shrinkage_rates) um.push_back(r * 1e6);
    s["shrinkage_rates_um_s"] = um;
    s["shrinkage_rates_source"] =
        c.dryer_schedule == "model" ? fmt::format("dryer model (preset {}, final porosity {:.4g})",
                                                  c.dryer_preset, c.dryer_final_porosity)
                                    : std::string("dryer.shrinkage_rates");
    s["integrator"] = c.integrator;
    // "auto" resolved: whether the self-stiffness joined the kick (docs/model.md M-9.1).
    s["implicit_stiffness"] = sim.settings().implicit_stiffness;
    s["time_step_s"] = largest_time_step(c, ctx.film.scaled);
    s["time_step_min_s"] = e.guard.min_time_step();
    if (sim.settings().integrator == Integrator::quasi_static) {
        const StabilityGuard::SolverTotals& q = e.guard.solver_totals();
        s["quasi_static"] = {
            {"max_displacement_m", sim.settings().quasi_static.max_displacement},
            {"solves", q.solves},
            {"cg_iterations", q.iterations},
            {"cg_iterations_per_step", q.steps ? double(q.iterations) / double(q.steps) : 0.0},
            {"residual_max", q.residual_max}};
    }
    const std::int64_t steps = e.result.steps;
    s["time_step_mean_s"] = steps > 0 ? sim.time() / double(steps) : 0.0;
    s["wall_time_phases_s"] = wall_time_phases(sim, e.guard);
    s["neighbor_builds"] = sim.neighbors().builds();
    s["steps"] = steps;
    s["seed"] = c.seed;
    s["resumed"] = ctx.options.resume;
    s["threads"] = sim.threads();
    s["ranks"] = 1;
    if (const parallel::Halo* h = sim.halo()) add_decomposition(*h, sim, e.whole, s);
    s["version"] = fmt::format("{} ({})", DRYDEM_VERSION, DRYDEM_GIT_HASH);
    s["wall_time_s"] = e.result.wall_time;
    s["particle_steps_per_s"] =
        double(e.whole.size()) * double(steps) / std::max(e.result.wall_time, 1e-9);
    s["config"] = "config.toml";
}

/// summary.json (atomically), and the closing log line of a completed run.
class Summary final : public RunObserver {
public:
    explicit Summary(const RunContext& ctx) : ctx_(ctx) {}
    const char* name() const override { return "summary"; }
    bool required() const override { return true; }
    void finish(const RunEnd& e) override {
        add_results(ctx_, e, e.summary);
        add_method(ctx_, e, e.summary);
        const fs::path dir = ctx_.options.output_dir;
        write_file_atomically(dir / "summary.json",
                              [&](std::ostream& o) { o << e.summary.dump(2) << "\n"; });
        const DryingResult& r = e.result;
        if (r.completed)
            ctx_.log.info(
                "done: final thickness {:.3f} um, density {:.4f} g/cm3, porosity {:.4f}; {} "
                "steps in {:.1f} s ({:.3g} particle-steps/s); results in {}",
                r.final_thickness * 1e6, r.density * 1e-3, r.porosity, r.steps, r.wall_time,
                e.summary["particle_steps_per_s"].get<double>(), dir.string());
    }

private:
    const RunContext& ctx_;
};

/// plots/ by scripts/plot_run.py (and plot_analysis.py after an analysis) with Debian's python3;
/// their output goes to log.txt.
class Plots final : public RunObserver {
public:
    explicit Plots(const RunContext& ctx) : ctx_(ctx) {}
    const char* name() const override { return "plots"; }
    void finish(const RunEnd& e) override {
        if (!ctx_.options.plots) return;
        const fs::path dir = ctx_.options.output_dir;
        const std::string log = (dir / "log.txt").string();
        if (run_python_script("plot_run.py", {dir.string()}, log) == ScriptRun::failed)
            ctx_.log.warn("plotting failed (see log.txt)");
        if (e.summary.contains("analysis") &&
            run_python_script("plot_analysis.py",
                              {(dir / "analysis").string(), (dir / "plots").string()},
                              log) == ScriptRun::failed)
            ctx_.log.warn("plotting the analysis failed (see log.txt)");
    }

private:
    const RunContext& ctx_;
};

} // namespace

void append_end_outputs(const RunContext& ctx, std::vector<std::unique_ptr<RunObserver>>& list) {
    list.push_back(std::make_unique<FinalParticles>(ctx));
    list.push_back(std::make_unique<StructureAnalysis>(ctx));
    list.push_back(std::make_unique<Summary>(ctx));
    list.push_back(std::make_unique<Plots>(ctx));
}

} // namespace drydem
