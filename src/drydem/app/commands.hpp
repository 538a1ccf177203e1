// SPDX-License-Identifier: MIT
#pragma once
#include "drydem/analysis/analyze.hpp"
#include "drydem/drying/drying_run.hpp"
#include "drydem/io/config.hpp"
#include "drydem/engine/peer_bed.hpp"
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace drydem::app {

/// `drydem check`: prints every derived quantity of the configuration; runs nothing.
void print_check(const Config& c);

/// `drydem bench`: the peers' granular benchmark (bench/peer_bench.sh, README "Performance") in DryDEM.
struct BenchOptions {
    std::string data;
    std::int64_t warmup = 200, steps = 2000;
    int threads = 1;
    PeerBedPhysics physics;
    double dt = 2e-10, skin = 0.3e-6;
    bool whole_list = false; ///< no near list (EngineSettings::near_list)
};
int run_bench(const BenchOptions& o);

/// `drydem study`: loadings x seeds as `drydem run` child processes, then study.csv/.json + plot.
/// Returns 0 when every run completed, 1 otherwise (the table lists the failures).
struct StudyOptions {
    std::filesystem::path output_dir;
    std::vector<double> loadings; ///< [kg/m^2]; empty: study.loadings of the config
    int seeds = 0;                ///< 0: study.seeds of the config
    int threads = 0;              ///< per run; 0: cores / runs, at least 1
    int jobs = 0;                 ///< runs at a time; 0: cores / threads
    bool quiet = false, plots = true;
    bool resume = false; ///< continue a stopped study in output_dir (its finished runs kept)
};
int run_study(const Config& base, const StudyOptions& o);

/// `drydem calibrate`: checks [calibration], prepares DIR (config.toml, calibration.json) and
/// replaces itself with the search driver scripts/calibrate.py (docs/calibration.md).
struct CalibrateOptions {
    std::filesystem::path output_dir;
    int jobs = 1;    ///< local: runs at a time; slurm: evaluations per job array
    int threads = 0; ///< per local run; 0: cores / jobs, at least 1
    bool resume = false, quiet = false, plots = true;
};
int run_calibrate(const Config& c, const CalibrateOptions& o);

/// The path of the running drydem executable (/proc/self/exe).
std::string self_executable();

/// `drydem dryer`: the dryer model alone; writes dryer.json, dryer.csv and plots/dryer.png.
struct DryerOptions {
    std::filesystem::path output_dir;
    bool plots = true;
};
int run_dryer(const Config& c, const DryerOptions& o);

/// `drydem dryer --table2`: paper Table 2 against the dryer model, presets table2 and physical.
void print_table2_comparison(const Config& c);

/// `drydem run --couple-dryer`: the dryer <-> DEM iteration (dryer.md D-6); each DEM run in
/// DIR/iter_N, the iterations in DIR/coupling.json. Returns 0 when converged, 1 otherwise.
int run_coupled(const Config& c, const RunOptions& o);

/// `drydem calender RUN_DIR`: the calendering of a finished drying run (docs/calendering.md).
struct CalenderCommand {
    std::filesystem::path run_dir, output_dir; ///< output_dir empty: RUN_DIR-calendered
    std::filesystem::path resume_dir;          ///< --resume: a stopped calendering's folder
    std::vector<std::string> sets;             ///< --set over the run's config.toml
    int threads = 0;                           ///< 0: run.threads of the config
    bool overwrite = false, quiet = false, plots = true;
    std::optional<std::int64_t> stop_after;
};
int run_calender(const CalenderCommand& o);

/// `drydem analyze SNAPSHOT`: structure analysis into analysis.json, profiles.csv, psd_*.csv, plots,
/// and on request the voxel image (structure.raw/.json/.mhd, structure.tif).
struct AnalyzeOptions {
    std::filesystem::path snapshot, output_dir;
    analysis::AnalysisOptions analysis;
    int cb_type = 0; ///< 0: the config's convention (types 1..n NCM, n + 1 CB)
    bool export_voxels = false, tiff = false, plots = true, quiet = false;
    int threads = 0;
};
int run_analyze(const Config& c, const AnalyzeOptions& o);
/// Runs scripts/SCRIPT_NAME DIR with Debian's /usr/bin/python3 (matplotlib); warns, never fails.
void run_plot_script(const std::string& script_name, const std::filesystem::path& dir);

} // namespace drydem::app
