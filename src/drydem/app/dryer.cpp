// SPDX-License-Identifier: MIT
// `drydem dryer` (the dryer model alone), the Table 2 comparison, and `drydem run --couple-dryer`
// (the dryer <-> DEM iteration of paper Sec. 8, dryer.md D-6).
#include "drydem/app/commands.hpp"
#include "drydem/core/error.hpp"
#include "drydem/dryer_model/coupling.hpp"
#include "drydem/dryer_model/dryer_config.hpp"
#include "drydem/dryer_model/dryer_report.hpp"
#include "drydem/drying/drying_run.hpp"
#include "drydem/git_hash.hpp"
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>
#include <cmath>
#include <cstdlib>
#include <fstream>

namespace drydem::app {

using namespace drydem::dryer;

namespace {

std::string rate_text(const std::optional<double>& r) {
    return r ? fmt::format("{:.3f}", *r * 1e6) : std::string("  -  ");
}

} // namespace

int run_dryer(const Config& c, const DryerOptions& o) {
    const FilmDryerParams p = film_dryer_params(c);
    const DryerRun run = simulate_film_dryer(p);
    const auto sections = fit_section_rates(p, run);
    write_dryer_outputs(o.output_dir, p, run, sections);
    const FilmGeometry& g = run.geometry;
    fmt::print("dryer model, preset '{}' (analogy exponent n = {:.4g}), L = {:.4g} mg/cm2\n",
               p.preset, p.analogy_exponent, p.areal_loading * 100);
    fmt::print("  wet film {:.2f} um -> final {:.2f} um (porosity {:.3f})\n", g.wet_height * 1e6,
               g.final_height * 1e6, p.final_porosity);
    fmt::print("  zone  x [m]        T_air [C]  alpha [W/m2K]  s_k [um/s]  s_k [um/m]  T_wet [C]  "
               "wet-film rate [um/s]\n");
    double x0 = 0.0;
    for (std::size_t k = 0; k < p.zones.size(); ++k) {
        const WetFilmSteadyState w = wet_film_steady_state(p, k);
        const auto& s = sections[k];
        fmt::print("  {:>4}  {:4.2f}-{:4.2f}    {:7.2f}    {:9.1f}      {:>7}    {:>8}   {:8.2f}   "
                   "{:8.3f}\n",
                   k + 1, x0, x0 + p.zones[k].length, p.zones[k].air_temperature - 273.15,
                   p.zones[k].heat_transfer_top, rate_text(s.rate),
                   s.rate ? fmt::format("{:.2f}", *s.rate * 1e6 / p.line_speed)
                          : std::string("  -  "),
                   w.temperature - 273.15, w.shrinkage_rate * 1e6);
        x0 += p.zones[k].length;
    }
    if (run.consolidation_time)
        fmt::print("  consolidation at x = {:.3f} m (t = {:.2f} s)\n",
                   *run.consolidation_time * p.line_speed, *run.consolidation_time);
    else
        fmt::print("  no consolidation inside the dryer\n");
    if (run.dry_time)
        fmt::print("  dry at x = {:.3f} m (t = {:.2f} s)\n", *run.dry_time * p.line_speed,
                   *run.dry_time);
    else
        fmt::print("  not dry at the dryer exit: {:.3g} g/m2 NMP left\n",
                   run.samples.back().liquid_mass * 1e3);
    for (const std::string& w : run.warnings) fmt::print(stderr, "warning: {}\n", w);
    fmt::print("  written: {}/dryer.json, dryer.csv\n", o.output_dir.string());
    if (o.plots) run_plot_script("plot_dryer.py", o.output_dir);
    return 0;
}

void print_table2_comparison(const Config& c) {
    fmt::print(
        "Paper Table 2 vs the dryer model (fit per section, dryer.md D-4; other settings from "
        "the configuration, final porosity {:.3g})\n",
        c.dryer_final_porosity);
    for (const char* preset : {"table2", "physical"}) {
        Config cc = c;
        cc.dryer_preset = preset;
        double sum = 0, worst = 0;
        int n = 0;
        fmt::print("\npreset '{}'\n  L [mg/cm2] | s1 model  paper   err   | s2 model  paper   err  "
                   " | t_cons [s]  x_cons [m]\n",
                   preset);
        for (const Table2Row& row : paper_table2) {
            cc.areal_loading = row.areal_loading;
            const FilmDryerParams p = film_dryer_params(cc);
            const DryerRun run = simulate_film_dryer(p);
            const auto s = fit_section_rates(p, run);
            auto err = [&](const std::optional<double>& m, double paper) {
                if (!m) return std::string("  n/a ");
                const double e = 100.0 * (*m - paper) / paper;
                sum += std::abs(e), worst = std::max(worst, std::abs(e)), ++n;
                return fmt::format("{:+5.1f}%", e);
            };
            fmt::print("  {:10.1f} | {:>7}  {:6.3f} {} | {:>7}  {:6.3f} {} | {:9.1f}  {:9.2f}\n",
                       row.areal_loading * 100, rate_text(s[0].rate), row.s1 * 1e6,
                       err(s[0].rate, row.s1), rate_text(s.size() > 1 ? s[1].rate : std::nullopt),
                       row.s2 * 1e6, err(s.size() > 1 ? s[1].rate : std::nullopt, row.s2),
                       run.consolidation_time.value_or(NAN),
                       run.consolidation_time.value_or(NAN) * p.line_speed);
        }
        fmt::print("  mean |err| = {:.2f} %, max |err| = {:.2f} % over {} values\n",
                   n ? sum / n : NAN, worst, n);
    }
}

int run_coupled(const Config& c, const RunOptions& o) {
    namespace fs = std::filesystem;
    fs::create_directories(o.output_dir);
    std::ofstream log(o.output_dir / "log.txt", std::ios::app);
    auto say = [&](const std::string& line) {
        fmt::print(stderr, "{}\n", line);
        log << line << "\n";
        log.flush();
    };
    const FilmDryerParams p = film_dryer_params(c);
    say(fmt::format("dryer <-> DEM coupling (dryer.md D-6): preset '{}', start porosity {:.4g}, "
                    "tolerance {:.3g} um, at most {} iterations",
                    p.preset, p.final_porosity, c.coupling_tolerance * 1e6,
                    c.coupling_max_iterations));
    nlohmann::json iterations = nlohmann::json::array();
    auto dem = [&](int i, const std::vector<double>& rates, double porosity_in) {
        Config ci = c;
        ci.shrinkage_rates = rates;
        ci.dryer_schedule = "model";
        ci.dryer_final_porosity = porosity_in;
        ci.name = fmt::format("{}-iter{}", c.name, i);
        RunOptions oi = o;
        oi.output_dir = o.output_dir / fmt::format("iter_{}", i);
        std::vector<double> um;
        for (double r : rates) um.push_back(r * 1e6);
        say(fmt::format("iteration {}: porosity {:.4f} -> dryer rates {::.4f} um/s -> DEM in {}", i,
                        porosity_in, um, oi.output_dir.string()));
        const DryingResult r = run_drying(ci, oi);
        if (!r.completed)
            throw RunError(
                fmt::format("coupling iteration {}: the DEM run failed: {}", i, r.error));
        return r.final_thickness;
    };
    auto on_iteration = [&](const CouplingIteration& it) {
        std::vector<double> um;
        for (double r : it.rates) um.push_back(r * 1e6);
        say(fmt::format(
            "iteration {}: rates {::.4f} um/s, h_f assumed {:.3f} um -> DEM h_f {:.3f} um, "
            "porosity {:.4f}, change {:+.3f} um",
            it.iteration, um, it.final_thickness_in * 1e6, it.final_thickness_dem * 1e6,
            it.porosity_dem, it.change * 1e6));
        iterations.push_back(
            {{"iteration", it.iteration},
             {"output_dir", fmt::format("iter_{}", it.iteration)},
             {"porosity_in", it.porosity_in},
             {"final_thickness_in_um", it.final_thickness_in * 1e6},
             {"shrinkage_rates_um_s", um},
             {"consolidation_time_s", it.consolidation_time ? nlohmann::json(*it.consolidation_time)
                                                            : nlohmann::json(nullptr)},
             {"final_thickness_dem_um", it.final_thickness_dem * 1e6},
             {"porosity_dem", it.porosity_dem},
             {"change_um", it.change * 1e6}});
    };
    nlohmann::json out;
    int code = 0;
    try {
        const CouplingResult res =
            couple_dryer_dem(p, dem, c.coupling_tolerance, c.coupling_max_iterations, on_iteration);
        say(res.message);
        out["status"] = res.converged ? "converged" : "not_converged";
        out["message"] = res.message;
        if (!res.iterations.empty()) {
            out["final_thickness_um"] = res.iterations.back().final_thickness_dem * 1e6;
            out["porosity"] = res.iterations.back().porosity_dem;
        }
        code = res.converged ? 0 : 1;
    } catch (const RunError& e) {
        say(fmt::format("coupling failed: {}", e.what()));
        out["status"] = "failed";
        out["message"] = e.what();
        code = 1;
    }
    out["iterations"] = iterations;
    out["tolerance_um"] = c.coupling_tolerance * 1e6;
    out["max_iterations"] = c.coupling_max_iterations;
    out["dryer_inputs"] = inputs_json(p);
    out["version"] = fmt::format("{} ({})", DRYDEM_VERSION, DRYDEM_GIT_HASH);
    std::ofstream(o.output_dir / "coupling.json") << out.dump(2) << "\n";
    return code;
}

} // namespace drydem::app
