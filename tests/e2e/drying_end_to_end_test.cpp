// SPDX-License-Identifier: MIT
// End to end on a small box (model.md M-8; issue: film follows the level during the constant-rate
// period, consolidates, ends with a plausible porosity, loses no particle). To stay near 1e8
// particle-steps at the paper's time step, the film is thin (2.5 mg/cm², 16 um wet) in a 36 x 36 um
// box and the NCM is one class of 3 um spheres, so that the film is still ~4 NCM diameters thick
// and the end criterion (top - level > largest diameter) keeps its meaning. Physics, scaling and
// time step are the paper's.
#include "drydem/drying/derived_checks.hpp"
#include "drydem/drying/drying_run.hpp"
#include "drydem/core/stop_request.hpp"
#include "drydem/io/particle_io.hpp"
#include "drydem/setup/formulation.hpp"
#include <gtest/gtest.h>
#include "test_dirs.hpp"
#include <nlohmann/json.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace drydem;

namespace {
std::vector<std::vector<double>> read_csv(const std::filesystem::path& file,
                                          std::vector<std::string>& header) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    std::stringstream h(line);
    for (std::string col; std::getline(h, col, ',');) header.push_back(col);
    std::vector<std::vector<double>> rows;
    while (std::getline(in, line)) {
        std::stringstream s(line);
        std::vector<double> row;
        for (std::string v; std::getline(s, v, ',');) row.push_back(std::stod(v));
        rows.push_back(row);
    }
    return rows;
}
/// The thin film of the stopped runs below (2.5 mg/cm², 36 µm box, one 3 µm NCM class, 2 threads,
/// no snapshots, a time-series row every 0.01 s), with `extra` overrides.
Config thin_film(std::vector<std::string> extra) {
    std::vector<std::string> o{"run.threads=2",
                               "film.box_x=36um",
                               "film.box_y=36um",
                               "film.areal_loading=2.5mg/cm^2",
                               "formulation.ncm_diameters=[\"3 um\"]",
                               "output.snapshot_every=0",
                               "output.timeseries_every=0.01s"};
    o.insert(o.end(), extra.begin(), extra.end());
    return load_config(default_config_toml(), "default", o);
}
/// Runs c into dir, stopped after `steps` steps (--stop-after-steps); its summary.json.
nlohmann::json run_stopped(const Config& c, const std::filesystem::path& dir, std::int64_t steps) {
    RunOptions o;
    o.output_dir = dir;
    o.quiet = true;
    o.plots = false;
    o.stop_after_steps = steps;
    const DryingResult r = run_drying(c, o);
    EXPECT_FALSE(r.completed);
    EXPECT_NE(r.error.find("--stop-after-steps"), std::string::npos) << r.error;
    EXPECT_EQ(r.stop_reason, "stop_after_steps");
    std::ifstream js(dir / "summary.json");
    return nlohmann::json::parse(js);
}
/// The last time-series row's value of `column` (NaN where there is no such column or row).
double last_of(const std::filesystem::path& dir, const std::string& column) {
    std::vector<std::string> h;
    const auto rows = read_csv(dir / "timeseries.csv", h);
    const std::size_t k = std::size_t(std::find(h.begin(), h.end(), column) - h.begin());
    return rows.size() >= 2 && k < h.size() ? rows.back()[k] : NAN;
}
DryingResult run_quietly(const Config& c, const std::filesystem::path& dir) {
    RunOptions o;
    o.output_dir = dir;
    o.quiet = true;
    o.plots = false;
    return run_drying(c, o);
}
} // namespace

TEST(DryingEndToEnd, ThinFilmFollowsLevelConsolidatesAndKeepsEveryParticle) {
    const Config c = load_config(default_config_toml(), "default",
                                 {"run.name=e2e", "run.threads=2", "film.box_x=36um",
                                  "film.box_y=36um", "film.areal_loading=2.5mg/cm^2",
                                  "formulation.ncm_diameters=[\"3 um\"]", "drying.relaxation=1s",
                                  "output.snapshot_every=0", "output.timeseries_every=0.25s"});
    const FilmRecipe recipe = make_recipe(c);
    const auto dir = testing_support::temp_dir();
    const DryingResult r = run_quietly(c, dir);
    ASSERT_TRUE(r.completed) << r.error;

    // No particle lost, below the substrate or above the wet film.
    const ParticleFile final_particles = read_particles(dir / "final.csv");
    ASSERT_EQ(int(final_particles.particles.size()), recipe.particle_count());
    for (const ParticleRecord& p : final_particles.particles) {
        EXPECT_GT(p.position.z, 0.5 * p.radius) << "particle " << p.id;
        EXPECT_LT(p.position.z + p.radius, recipe.wet_film_height) << "particle " << p.id;
    }

    // Constant-rate period: while the level is in its upper half, the bulk top (99th percentile)
    // follows it within about one CB diameter.
    std::vector<std::string> h;
    const auto rows = read_csv(dir / "timeseries.csv", h);
    auto col = [&](const std::string& name) {
        return std::size_t(std::find(h.begin(), h.end(), name) - h.begin());
    };
    const std::size_t t_col = col("process_time_s"), level_col = col("liquid_level_um"),
                      p99_col = col("film_top_p99_um");
    ASSERT_LT(p99_col, h.size());
    int checked = 0;
    const double h_wet = recipe.wet_film_height * 1e6;
    for (const auto& row : rows) {
        if (row[t_col] < 1.0 || row[level_col] < 0.5 * (h_wet + r.final_thickness * 1e6)) continue;
        EXPECT_NEAR(row[p99_col], row[level_col], 1.5) << "process time " << row[t_col];
        ++checked;
    }
    EXPECT_GE(checked, 5);

    // Consolidation: a film well below the wet height, a plausible porosity, and at rest.
    EXPECT_LT(r.final_thickness, 0.85 * recipe.wet_film_height);
    EXPECT_GT(r.porosity, 0.35);
    EXPECT_LT(r.porosity, 0.60);
    // Self-supporting structure: while the level keeps sinking through it during the relaxation
    // window, the film no longer follows (only the slight rebound the paper notes).
    EXPECT_NEAR(r.relaxed_thickness, r.final_thickness, 0.05 * r.final_thickness);
    const double level_end = rows.back()[level_col];
    EXPECT_LT(level_end, r.final_thickness * 1e6 - 3.0);

    std::ifstream js(dir / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(js);
    EXPECT_EQ(summary["status"], "completed");
    EXPECT_EQ(summary["stop_reason"], "completed");
    EXPECT_NEAR(summary["porosity"].get<double>(), r.porosity, 1e-12);

    // The structure analysis of final.csv (docs/analysis.md): its thickness is the relaxed top, its
    // mass the run's areal loading, and the pore statistics are there.
    std::ifstream as(dir / "analysis" / "analysis.json");
    ASSERT_TRUE(as.good());
    const nlohmann::json a = nlohmann::json::parse(as);
    EXPECT_NEAR(a["thickness_um"].get<double>(), r.relaxed_thickness * 1e6, 1e-6);
    EXPECT_NEAR(a["areal_loading_mg_cm2"].get<double>(),
                summary["areal_loading_mg_cm2"].get<double>(),
                2e-3 * summary["areal_loading_mg_cm2"].get<double>());
    EXPECT_LE(a["thickness_half_solid_um"].get<double>(), a["thickness_um"].get<double>());
    EXPECT_GT(a["voxel_porosity"].get<double>(), 0.1);
    EXPECT_GT(a["psd_peak_um"].get<double>(), 0.1);
    EXPECT_GT(a["coordination"]["mean"].get<double>(), 2.0);
    for (const char* f : {"profiles.csv", "psd_chord.csv", "psd_local_thickness.csv"})
        EXPECT_TRUE(std::filesystem::exists(dir / "analysis" / f)) << f;
    EXPECT_NEAR(summary["psd_peak_um"].get<double>(), a["psd_peak_um"].get<double>(), 1e-12);

    // What a cell model needs (issue 15), from the default transport solves and the binder model:
    // pores that percolate with τ > 1 and a Bruggeman exponent of a granular film, a conducting
    // solid, every voxel size of the default list solved (the film is small), the binder profile.
    const nlohmann::json& t = a["transport"];
    ASSERT_TRUE(t.contains("tortuosity_factor")) << t.dump();
    EXPECT_GT(t["tortuosity_factor"]["through_plane"].get<double>(), 1.0);
    EXPECT_LT(t["tortuosity_factor"]["through_plane"].get<double>(), 5.0);
    EXPECT_GT(t["tortuosity_factor"]["in_plane"].get<double>(), 1.0);
    EXPECT_GT(t["bruggeman_exponent"]["through_plane"].get<double>(), 1.0);
    EXPECT_LT(t["bruggeman_exponent"]["through_plane"].get<double>(), 3.0);
    EXPECT_GT(t["electronic_conductivity_S_m"].get<double>(), 0.0);
    EXPECT_TRUE(t["solver"]["converged"].get<bool>());
    EXPECT_EQ(t["convergence"].size(), c.analysis_transport_voxel_sizes.size());
    EXPECT_TRUE(t["skipped"].empty());
    EXPECT_TRUE(std::isfinite(
        t["relative_change_from_coarser_voxels"]["tortuosity_through_plane"].get<double>()));
    const nlohmann::json& b = a["binder_migration"];
    EXPECT_GT(b["bottom10_over_mean"].get<double>(), 0.0);
    EXPECT_NEAR(b["mass_balance"].get<double>(), 0.0, 1e-9);
    for (const char* f : {"transport_convergence.csv", "binder_profile.csv"})
        EXPECT_TRUE(std::filesystem::exists(dir / "analysis" / f)) << f;

    // The overlap census of final.csv (docs/analysis.md) is the census of the last time-series row
    // (the same particles, written to 10 digits), and the run's groups are in the summary.
    const nlohmann::json& ov = a["overlap"];
    for (const char* type : {"cb_cb", "ncm_cb", "ncm_ncm", "cb_substrate", "ncm_substrate", "all"})
        ASSERT_TRUE(ov.contains(type)) << type;
    EXPECT_GT(ov["all"]["pairs"].get<int>(), 0);
    EXPECT_GE(ov["all"]["max"].get<double>(), ov["all"]["p99"].get<double>());
    EXPECT_NEAR(ov["all"]["p99"].get<double>(), rows.back()[col("overlap_p99_rel")], 1e-6);
    for (const auto& row : rows) {
        EXPECT_GE(row[col("push_number")], 0.0);
        EXPECT_GE(row[col("inertial_number")], 0.0);
    }
    ASSERT_EQ(summary["dimensionless_groups"]["zones"].size(), 2u);
    EXPECT_GT(summary["dimensionless_groups"]["zones"][0]["simulated"]["push_number"].get<double>(),
              0.0);
}

// The force-ratio scheme through a run (docs/model.md M-7), on the same thin film for 3,000 steps
// (a full drying costs ~10x the paper scheme's: docs/validation.md): the summary records the scheme,
// the laws got the scaled values, and every force ratio of the simulated film is the process's.
TEST(DryingEndToEnd, ForceRatioSchemeRunsAndKeepsTheForceRatios) {
    const Config c =
        thin_film({"run.name=e2e-fr", "scaling.scheme=\"force_ratio\"", "scaling.time_factor=1e6",
                   "scaling.viscosity_reduction=100", "scaling.stiffness_factor=2"});
    const auto dir = testing_support::temp_dir();
    const nlohmann::json s = run_stopped(c, dir, 3000);
    EXPECT_EQ(s["scaling"]["scheme"], "force_ratio");
    EXPECT_EQ(s["implicit_stiffness"], false); // "auto": off in the force-ratio scheme
    EXPECT_NEAR(s["scaling"]["capillary_factor"].get<double>(), 1e4, 1e-6);
    EXPECT_NEAR(s["scaling"]["hamaker_cb_cb_J"]["scaled"].get<double>(), 4.64e-16, 1e-24);
    EXPECT_NEAR(s["scaling"]["youngs_modulus_cb_Pa"]["scaled"].get<double>(), 2.84e11, 1.0);
    EXPECT_NEAR(s["scaling"]["lubrication_viscosity_Pa_s"].get<double>(), 0.01801, 1e-12);
    for (const auto& zone : s["dimensionless_groups"]["zones"])
        for (const char* g : {"capillary_number_drag", "push_number", "vdw_over_capillary_cb_cb",
                              "bond_number_largest_ncm"})
            EXPECT_NEAR(zone["simulated"][g].get<double>(), zone["physical"][g].get<double>(),
                        1e-9 * zone["physical"][g].get<double>())
                << g;
    // The time series measures the level's load from the first row on.
    EXPECT_GT(last_of(dir, "push_number"), 0.0);
}

// The quasi-static step in the drying run at the process's own settings (k = b = e = 1): the step
// is set by the displacement and the level's motion, the guard reports the solver, the summary
// and the time series carry it.
TEST(DryingEndToEnd, QuasiStaticStepRunsAtTheProcessSettings) {
    const Config c =
        thin_film({"run.name=e2e-qs", "scaling.scheme=\"force_ratio\"", "scaling.time_factor=1",
                   "scaling.viscosity_reduction=1", "numerics.integrator=\"quasi_static\""});
    const auto dir = testing_support::temp_dir();
    const nlohmann::json s = run_stopped(c, dir, 200);
    EXPECT_EQ(s["integrator"], "quasi_static");
    // No step above the level's 37.5 nm (5 % of the 0.75 um CB radius) at its fastest, 1.193 um/s.
    const double cap = 0.05 * 0.75e-6 / 1.193e-6;
    EXPECT_NEAR(s["time_step_s"].get<double>(), cap, 1e-9 * cap);
    EXPECT_LE(s["time_step_min_s"].get<double>(), cap);
    EXPECT_GT(s["time_step_mean_s"].get<double>(), 1e-6); // ~1e5 x the explicit contact step
    const auto& q = s["quasi_static"];
    EXPECT_GE(q["solves"].get<double>(), 200.0);
    EXPECT_GT(q["cg_iterations"].get<double>(), 0.0);
    EXPECT_LE(q["residual_max"].get<double>(), 1e-4);
    EXPECT_GT(last_of(dir, "solver_iterations"), 0.0);
}

// A run that blows up (explicit integrator, time step far above the damping bound, guard set to
// warn only; the semi-implicit kick stays stable at this step) stops with
// a diagnosis naming the particle and the cause, and keeps what it wrote: summary.json with
// "failed", the time series so far and the particles at the failure.
TEST(DryingEndToEnd, BlowUpStopsWithDiagnosisAndKeepsOutputs) {
    const Config c =
        load_config(default_config_toml(), "default",
                    {"run.name=blowup", "run.threads=1", "run.time_step=5e-10s",
                     "numerics.stability_guard=\"warn\"", "numerics.integrator=\"explicit\"",
                     "film.box_x=36um", "film.box_y=36um", "film.areal_loading=2.5mg/cm^2",
                     "formulation.ncm_diameters=[\"3 um\"]", "output.snapshot_every=0"});
    const auto dir = testing_support::temp_dir();
    const DryingResult r = run_quietly(c, dir);
    ASSERT_FALSE(r.completed);
    EXPECT_NE(r.error.find("particle"), std::string::npos) << r.error;
    EXPECT_TRUE(r.error.find("non-finite") != std::string::npos ||
                r.error.find("runaway overlap") != std::string::npos)
        << r.error;
    std::ifstream js(dir / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(js);
    EXPECT_EQ(summary["status"], "failed");
    EXPECT_EQ(summary["error"], r.error);
    // The machine-readable reason matches the prose (summary.json stop_reason, core/error.hpp).
    EXPECT_EQ(summary["stop_reason"],
              r.error.find("non-finite") != std::string::npos ? "blow_up" : "runaway_overlap");
    EXPECT_TRUE(std::filesystem::exists(dir / "timeseries.csv"));
    EXPECT_TRUE(std::filesystem::exists(dir / "final.csv"));
}

// A stop request (what Ctrl-C / SIGTERM send) ends the run after the current step with the
// results so far written, like a failure; the flag is cleared afterwards for the other tests.
TEST(DryingEndToEnd, StopRequestEndsTheRunAndKeepsOutputs) {
    const Config c =
        load_config(default_config_toml(), "default",
                    {"run.name=stop", "run.threads=1", "film.box_x=36um", "film.box_y=36um",
                     "film.areal_loading=2.5mg/cm^2", "formulation.ncm_diameters=[\"3 um\"]",
                     "output.snapshot_every=0"});
    const auto dir = testing_support::temp_dir();
    request_stop(2);
    const DryingResult r = run_quietly(c, dir);
    request_stop(0);
    ASSERT_FALSE(r.completed);
    EXPECT_NE(r.error.find("interrupted by signal 2"), std::string::npos) << r.error;
    EXPECT_EQ(r.steps, 1);
    std::ifstream js(dir / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(js);
    EXPECT_EQ(summary["status"], "failed");
    EXPECT_EQ(summary["stop_reason"], "interrupted");
    EXPECT_TRUE(std::filesystem::exists(dir / "final.csv"));
    // The paper's scheme: "auto" turned the implicit self-stiffness on, and the record says so.
    EXPECT_EQ(summary["implicit_stiffness"], true);
}
