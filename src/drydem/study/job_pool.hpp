// SPDX-License-Identifier: MIT
// One local job pool for every command that runs several `drydem run` processes: `drydem study`
// and, through `drydem pool`, the calibration's evaluations (scripts/calibrate.py keeps the
// surrogate and hands its runs here). A run folder's state is read from its files in the same
// vocabulary the Slurm path uses (scripts/slurm_array.py run_state), so a study, a calibration
// and a job array agree on what is finished, what resumes and what starts again.
#pragma once
#include <sys/types.h>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace drydem {

/// A run folder's state: new (nothing there), partial (a config but no checkpoint or summary:
/// restarted with --overwrite), stopped (a checkpoint to continue: stopped on request or killed),
/// failed (for good), completed.
enum class RunFolder { fresh, partial, stopped, failed, completed };
RunFolder run_folder_state(const std::filesystem::path& dir);
std::string_view to_string(RunFolder s);

/// The summary.json stop reasons of a run that stopped on request and resumes from its
/// checkpoint (scripts/slurm_array.py STOPPED_REASONS lists the same).
bool resumable_stop_reason(std::string_view reason);

/// One run: its folder, the `drydem run` arguments that start it (after the executable), and
/// what the log says when it starts.
struct PoolTask {
    std::filesystem::path dir;
    std::vector<std::string> args;
    std::string label;
};

struct PoolOptions {
    int jobs = 1;    ///< runs at a time
    int threads = 1; ///< per run
    bool plots = true;
};

/// Brings every task to its end with the drydem executable `exe`, up to `jobs` at a time, by its folder's state: a completed or
/// failed one is reported as it is (exit code -1), a stopped one resumed, a partial one restarted,
/// a new one started. On SIGINT/SIGTERM (install_stop_handlers) no new run starts and the
/// running ones get SIGTERM: they checkpoint and stop. `done(k, code)` is called as task k ends.
/// Returns how many tasks were not started because of a stop.
std::size_t run_job_pool(const std::string& exe, const std::vector<PoolTask>& tasks,
                         const PoolOptions& o, const std::function<void(const std::string&)>& say,
                         const std::function<void(std::size_t, int)>& done);

/// SIGINT/SIGTERM request a stop (core/stop_request.hpp) without SA_RESTART, so that they
/// interrupt the pool's wait.
void install_stop_handlers();

/// Starts `args` (args[0] the executable) with stdout and stderr into `console_log`.
pid_t spawn_process(const std::vector<std::string>& args, const std::filesystem::path& console_log);

/// `drydem pool TASKS.json`: the tasks of a JSON file ({"tasks": [{"dir": DIR, "args": [...]}]},
/// the format of scripts/slurm_array.py) through run_job_pool. Exit 0 when every task completed,
/// 1 otherwise, 2 for a bad file.
int run_pool_command(const std::string& exe, const std::filesystem::path& tasks_file,
                     const PoolOptions& o, bool quiet);

} // namespace drydem
