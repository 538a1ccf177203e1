// SPDX-License-Identifier: MIT
// The drying simulation (paper Sec. 4 and 8, model.md M-8): set-up from the formulation, the
// descending liquid level, final-thickness detection with a relaxation window, and the outputs of
// README "Outputs" (summary.json, timeseries.csv, snapshots, final particles, log, plots).
#pragma once
#include "drydem/io/config.hpp"
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace drydem {

struct RunOptions {
    std::filesystem::path output_dir;
    std::optional<std::filesystem::path> particles_file; ///< start from these instead of insertion
    bool quiet = false;
    bool plots = true; ///< run scripts/plot_run.py with Debian's python3 at the end
    /// Continue the run whose output folder is output_dir from its checkpoint
    /// (output_dir/checkpoint/state.bin); the config must be the checkpoint's (resume_config()).
    bool resume = false;
    /// For testing: stop after this step (counted from the run's start, also when resumed) as a
    /// stop request would: checkpoint, results so far, completed = false.
    std::optional<std::int64_t> stop_after_steps;
};

/// Outcome of a drying run (also written to summary.json).
struct DryingResult {
    bool completed = false;
    std::string error;
    /// Why the run stopped (summary.json `stop_reason`): "completed", or a RunError's reason.
    std::string stop_reason;
    double final_thickness = 0.0;   ///< H_final at t* [m] (M-8.2)
    double relaxed_thickness = 0.0; ///< H_layer at the end of the relaxation window [m]
    double density = 0.0;           ///< [kg/m^3]
    double porosity = 0.0;
    double process_time_final = 0.0; ///< t* [s physical]
    std::int64_t steps = 0;
    double wall_time = 0.0; ///< [s]
};

/// Runs the drying simulation; writes every output into options.output_dir. Throws InputError for
/// bad input detected before the run (exit code 2); a run that fails (blow-up, I/O) returns a
/// result with completed = false after writing what it has (exit code 1).
DryingResult run_drying(const Config& config, const RunOptions& options);

/// Refuses (InputError, with the numbers) a rank count whose subdomains the inserted film of `c`
/// would not fill at least one reach wide, or what does not run on several ranks: before a run
/// on `ranks` MPI ranks makes its output folder (docs/parallel.md). Nothing on one rank.
void check_rank_count(const Config& c, int ranks);

/// The resolved config stored in the checkpoint of the run in `output_dir` (InputError if there is
/// no valid checkpoint). run.threads is the thread count the run used, so that the resumed run
/// continues bit for bit; override it only knowingly.
Config resume_config(const std::filesystem::path& output_dir);

/// Where a run keeps its checkpoint.
std::filesystem::path checkpoint_file(const std::filesystem::path& output_dir);

} // namespace drydem
