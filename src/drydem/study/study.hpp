// SPDX-License-Identifier: MIT
// A study (paper Sec. 9, Fig. 6): the drying run repeated over areal loadings x random seeds,
// reduced to mean and standard deviation per loading. The plan and the statistics live here; the
// front end (app/study.cpp) runs each case as its own `drydem run` process, so one failed run
// (blow-up, bad set-up) is recorded and the others go on.
#pragma once
#include "drydem/io/config.hpp"
#include <nlohmann/json.hpp>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace drydem {

struct StudyCase {
    double areal_loading = 0.0; ///< [kg/m^2]
    std::uint64_t seed = 0;
    std::string name; ///< also the run's folder name, e.g. "L20.10_s12345", "L3.00_r0.5_s12345"
    double shrinkage_rate_factor =
        1.0; ///< on every dryer.shrinkage_rates entry (study.shrinkage_rate_factors)
};

/// loadings x shrinkage-rate factors x seeds; an empty `loadings` means the config's own loading,
/// empty study.shrinkage_rate_factors the config's rates. Seeds are the config's run.seed,
/// run.seed + 1, ... Throws InputError for no seeds, a non-positive loading, or rate factors
/// without dryer.schedule = "rates" (the dryer model sets its own rates).
/// What scripts/slurm_array.py reads of the [scheduler] section (study and calibration alike).
/// InputError when scheduler.ranks_per_run > 1 with the local scheduler (its runs are one
/// process each).
nlohmann::json scheduler_settings(const Config& c);

std::vector<StudyCase> plan_study(const Config& base, const std::vector<double>& loadings,
                                  int seeds);

/// The outcome of one case, as read back from its summary.json.
struct StudyRow {
    StudyCase c;
    std::string status; ///< "completed", "failed" or "not started"
    std::string error;
    std::optional<double> thickness_um, density_g_cm3, porosity, process_time_final_s;
    double wall_time_s = 0.0;
    /// From the run's analysis/analysis.json where it has them (docs/analysis.md): tortuosity factor
    /// through-plane and in-plane, Bruggeman exponent, electronic conductivity [S/m], CB percolation
    /// (1/0), binder in the bottom 10 % of the film over the mean.
    std::optional<double> tortuosity_z, tortuosity_in_plane, bruggeman_z, electronic_conductivity,
        cb_percolates, binder_bottom10;
};

/// Reads `run_dir/summary.json` (missing or unreadable: status "failed" with the reason).
StudyRow read_study_row(const StudyCase& c, const std::filesystem::path& run_dir, int exit_code);

struct LoadingStats {
    double areal_loading_mg_cm2 = 0.0;
    double shrinkage_rate_factor = 1.0;
    int completed = 0, failed = 0;
    double thickness_mean_um = 0, thickness_std_um = 0;
    double density_mean_g_cm3 = 0, density_std_g_cm3 = 0;
    double porosity_mean = 0, porosity_std = 0;
};

/// Mean and sample standard deviation (n - 1; 0 for a single run) per loading and shrinkage-rate
/// factor over completed runs, in the order they first appear.
std::vector<LoadingStats> study_statistics(const std::vector<StudyRow>& rows);

/// Writes study.csv (one row per case) and study.json (cases, statistics per loading and the
/// measured values of [study] in the config) into `dir`.
void write_study_results(const std::filesystem::path& dir, const Config& base,
                         const std::vector<StudyRow>& rows);

} // namespace drydem
