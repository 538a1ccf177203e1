// SPDX-License-Identifier: MIT
#include "drydem/study/study.hpp"
#include "drydem/core/error.hpp"
#include "drydem/io/particle_io.hpp"
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <cmath>
#include <fstream>
#include <map>

namespace drydem {

nlohmann::json scheduler_settings(const Config& c) {
    if (c.slurm_ranks_per_run > 1 && c.scheduler != "slurm")
        throw InputError(fmt::format(
            "config key 'scheduler.ranks_per_run' = {}: runs of several MPI ranks need "
            "scheduler.type = \"slurm\" (local runs are one process each; start a single run "
            "with mpirun instead)",
            c.slurm_ranks_per_run));
    return {{"type", c.scheduler},
            {"partition", c.slurm_partition},
            {"time_limit_s", c.slurm_time_limit},
            {"cpus_per_task", c.slurm_cpus_per_task},
            {"ranks_per_run", c.slurm_ranks_per_run},
            {"resubmits", c.slurm_resubmits}};
}

std::vector<StudyCase> plan_study(const Config& base, const std::vector<double>& loadings,
                                  int seeds) {
    if (seeds < 1) throw InputError(fmt::format("--seeds {}: allowed 1 or more", seeds));
    const std::vector<double> ls =
        loadings.empty() ? std::vector<double>{base.areal_loading} : loadings;
    const std::vector<double>& factors = base.study_shrinkage_rate_factors;
    if (!factors.empty() && base.dryer_schedule != "rates")
        throw InputError(fmt::format(
            "study.shrinkage_rate_factors needs dryer.schedule = \"rates\" (it is \"{}\": "
            "the dryer model computes its own rates; vary its air temperatures instead)",
            base.dryer_schedule));
    const std::vector<double> fs = factors.empty() ? std::vector<double>{1.0} : factors;
    std::vector<StudyCase> cases;
    for (double l : ls) {
        if (!(l > 0.0) || !std::isfinite(l))
            throw InputError(fmt::format("study loading {} kg/m^2: allowed > 0", l));
        for (double f : fs)
            for (int k = 0; k < seeds; ++k) {
                const std::uint64_t seed = base.seed + std::uint64_t(k);
                const std::string rate = factors.empty() ? "" : fmt::format("_r{:g}", f);
                cases.push_back({l, seed, fmt::format("L{:.2f}{}_s{}", l * 100.0, rate, seed), f});
            }
    }
    return cases;
}

StudyRow read_study_row(const StudyCase& c, const std::filesystem::path& run_dir, int exit_code) {
    StudyRow row{c, "failed", "", {}, {}, {}, {}, 0.0, {}, {}, {}, {}, {}, {}};
    std::ifstream in(run_dir / "summary.json");
    if (!in) {
        row.error = fmt::format("no summary.json (exit code {}; see {})", exit_code,
                                (run_dir / "log.txt").string());
        return row;
    }
    try {
        const nlohmann::json s = nlohmann::json::parse(in);
        row.status = s.value("status", "failed");
        row.error = s.value("error", "");
        auto num = [&](const char* key) -> std::optional<double> {
            if (s.contains(key) && s[key].is_number()) return s[key].get<double>();
            return std::nullopt;
        };
        row.thickness_um = num("final_thickness_um");
        row.density_g_cm3 = num("density_g_cm3");
        row.porosity = num("porosity");
        row.process_time_final_s = num("process_time_final_s");
        row.wall_time_s = num("wall_time_s").value_or(0.0);
        if (row.status == "completed" && !row.thickness_um) {
            row.status = "failed";
            row.error = "completed without a final thickness";
        }
    } catch (const std::exception& e) {
        row.status = "failed";
        row.error = fmt::format("unreadable summary.json: {}", e.what());
    }
    // The film's transport and binder numbers, where the run's analysis has them.
    if (std::ifstream an(run_dir / "analysis" / "analysis.json"); an) try {
            const nlohmann::json a = nlohmann::json::parse(an);
            auto at = [&](std::initializer_list<const char*> path) -> std::optional<double> {
                const nlohmann::json* v = &a;
                for (const char* k : path) {
                    if (!v->is_object() || !v->contains(k)) return std::nullopt;
                    v = &(*v)[k];
                }
                if (v->is_boolean()) return v->get<bool>() ? 1.0 : 0.0;
                if (v->is_number()) return v->get<double>();
                return std::nullopt;
            };
            row.tortuosity_z = at({"transport", "tortuosity_factor", "through_plane"});
            row.tortuosity_in_plane = at({"transport", "tortuosity_factor", "in_plane"});
            row.bruggeman_z = at({"transport", "bruggeman_exponent", "through_plane"});
            row.electronic_conductivity = at({"transport", "electronic_conductivity_S_m"});
            row.cb_percolates = at({"transport", "cb_percolates"});
            row.binder_bottom10 = at({"binder_migration", "bottom10_over_mean"});
        } catch (const std::exception&) {
            // an unreadable analysis leaves the columns empty; the run itself stands
        }
    return row;
}

std::vector<LoadingStats> study_statistics(const std::vector<StudyRow>& rows) {
    std::vector<LoadingStats> out;
    auto mean_std = [](const std::vector<double>& v, double& mean, double& sd) {
        mean = sd = 0.0;
        if (v.empty()) return;
        for (double x : v) mean += x;
        mean /= double(v.size());
        if (v.size() < 2) return;
        for (double x : v) sd += (x - mean) * (x - mean);
        sd = std::sqrt(sd / double(v.size() - 1));
    };
    std::vector<std::pair<double, double>> groups; // (loading, shrinkage-rate factor)
    for (const auto& r : rows)
        if (const std::pair g{r.c.areal_loading, r.c.shrinkage_rate_factor};
            std::find(groups.begin(), groups.end(), g) == groups.end())
            groups.push_back(g);
    for (const auto& [l, f] : groups) {
        LoadingStats s;
        s.areal_loading_mg_cm2 = l * 100.0;
        s.shrinkage_rate_factor = f;
        std::vector<double> h, rho, eps;
        for (const auto& r : rows) {
            if (r.c.areal_loading != l || r.c.shrinkage_rate_factor != f) continue;
            if (r.status != "completed") {
                ++s.failed;
                continue;
            }
            ++s.completed;
            h.push_back(*r.thickness_um);
            if (r.density_g_cm3) rho.push_back(*r.density_g_cm3);
            if (r.porosity) eps.push_back(*r.porosity);
        }
        mean_std(h, s.thickness_mean_um, s.thickness_std_um);
        mean_std(rho, s.density_mean_g_cm3, s.density_std_g_cm3);
        mean_std(eps, s.porosity_mean, s.porosity_std);
        out.push_back(s);
    }
    return out;
}

void write_study_results(const std::filesystem::path& dir, const Config& base,
                         const std::vector<StudyRow>& rows) {
    auto opt = [](const std::optional<double>& v) {
        return v ? fmt::format("{:.10g}", *v) : std::string();
    };
    auto csv_text = [](std::string s) {
        for (char& ch : s)
            if (ch == ',' || ch == '\n' || ch == '"') ch = ch == '"' ? '\'' : ';';
        return s;
    };
    write_file_atomically(dir / "study.csv", [&](std::ostream& o) {
        o << "areal_loading_mg_cm2,seed,status,final_thickness_um,density_g_cm3,porosity,"
             "process_time_final_s,wall_time_s,run_dir,error,tortuosity_through_plane,tortuosity_"
             "in_plane,"
             "bruggeman_exponent,electronic_conductivity_S_m,cb_percolates,binder_bottom10_over_"
             "mean,"
             "shrinkage_rate_factor\n";
        for (const auto& r : rows)
            o << fmt::format("{:.10g},{},{},{},{},{},{},{:.4g},runs/{},{},{},{},{},{},{},{},{:g}\n",
                             r.c.areal_loading * 100.0, r.c.seed, r.status, opt(r.thickness_um),
                             opt(r.density_g_cm3), opt(r.porosity), opt(r.process_time_final_s),
                             r.wall_time_s, r.c.name, csv_text(r.error), opt(r.tortuosity_z),
                             opt(r.tortuosity_in_plane), opt(r.bruggeman_z),
                             opt(r.electronic_conductivity), opt(r.cb_percolates),
                             opt(r.binder_bottom10), r.c.shrinkage_rate_factor);
    });
    nlohmann::json j;
    j["name"] = base.name;
    auto jopt = [](const std::optional<double>& v) {
        return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
    };
    for (const auto& r : rows)
        j["cases"].push_back({{"areal_loading_mg_cm2", r.c.areal_loading * 100.0},
                              {"shrinkage_rate_factor", r.c.shrinkage_rate_factor},
                              {"seed", r.c.seed},
                              {"status", r.status},
                              {"error", r.error},
                              {"final_thickness_um", jopt(r.thickness_um)},
                              {"density_g_cm3", jopt(r.density_g_cm3)},
                              {"porosity", jopt(r.porosity)},
                              {"process_time_final_s", jopt(r.process_time_final_s)},
                              {"wall_time_s", r.wall_time_s},
                              {"tortuosity_through_plane", jopt(r.tortuosity_z)},
                              {"tortuosity_in_plane", jopt(r.tortuosity_in_plane)},
                              {"bruggeman_exponent", jopt(r.bruggeman_z)},
                              {"electronic_conductivity_S_m", jopt(r.electronic_conductivity)},
                              {"cb_percolates", jopt(r.cb_percolates)},
                              {"binder_bottom10_over_mean", jopt(r.binder_bottom10)},
                              {"run_dir", "runs/" + r.c.name}});
    for (const auto& s : study_statistics(rows))
        j["loadings"].push_back({{"areal_loading_mg_cm2", s.areal_loading_mg_cm2},
                                 {"shrinkage_rate_factor", s.shrinkage_rate_factor},
                                 {"completed", s.completed},
                                 {"failed", s.failed},
                                 {"thickness_mean_um", s.thickness_mean_um},
                                 {"thickness_std_um", s.thickness_std_um},
                                 {"density_mean_g_cm3", s.density_mean_g_cm3},
                                 {"density_std_g_cm3", s.density_std_g_cm3},
                                 {"porosity_mean", s.porosity_mean},
                                 {"porosity_std", s.porosity_std}});
    nlohmann::json measured = nlohmann::json::array();
    for (std::size_t k = 0; k < base.measured_loadings.size(); ++k) {
        nlohmann::json m = {{"areal_loading_mg_cm2", base.measured_loadings[k] * 100.0},
                            {"thickness_um", base.measured_thickness[k] * 1e6}};
        if (!base.measured_thickness_std.empty())
            m["thickness_std_um"] = base.measured_thickness_std[k] * 1e6;
        if (!base.measured_density.empty()) m["density_g_cm3"] = base.measured_density[k] * 1e-3;
        if (!base.measured_density_std.empty())
            m["density_std_g_cm3"] = base.measured_density_std[k] * 1e-3;
        measured.push_back(m);
    }
    j["measured"] = measured;
    const int failed = int(std::count_if(
        rows.begin(), rows.end(), [](const StudyRow& r) { return r.status != "completed"; }));
    j["completed"] = int(rows.size()) - failed;
    j["failed"] = failed;
    write_file_atomically(dir / "study.json", [&](std::ostream& o) { o << j.dump(2) << "\n"; });
}

} // namespace drydem
