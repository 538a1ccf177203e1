// SPDX-License-Identifier: MIT
// The output folder of `drydem run`: a new run never mixes its files with another run's (old
// frames left beside new ones, a log written by two processes), and two runs never write into one
// folder at the same time.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace drydem {

/// The files and folders a run writes into its output folder (README "Outputs"); --overwrite
/// removes exactly these.
[[nodiscard]] const std::vector<std::string>& run_output_names();

/// Makes `dir` ready for a new run: creates it when missing; an empty folder is used as it is; a
/// folder holding a previous run is refused (InputError naming --overwrite and --resume) unless
/// `overwrite`, which removes that run's outputs (run_output_names(), also iter_N of a coupled
/// run) and nothing else; a non-empty folder without a run is refused even with `overwrite` (it
/// is not ours to clear). The lock file (OutputLock) does not count as content.
void prepare_output_folder(const std::filesystem::path& dir, bool overwrite);

/// An exclusive lock on `dir` (created when missing) for the lifetime of the object: `dir/.drydem.lock`, locked with
/// flock(2), so the kernel releases it when the process ends in any way (SIGKILL included) and a
/// killed run can be resumed at once. A second run into the same folder gets an InputError naming
/// the process that holds it.
class OutputLock {
public:
    explicit OutputLock(const std::filesystem::path& dir);
    ~OutputLock();
    OutputLock(const OutputLock&) = delete;
    OutputLock& operator=(const OutputLock&) = delete;

private:
    int fd_ = -1;
};

inline constexpr const char* output_lock_name = ".drydem.lock";

} // namespace drydem
