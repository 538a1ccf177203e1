// SPDX-License-Identifier: MIT
// The output folders of `drydem run`, `study`, `dryer` and `analyze`: a new output never mixes its
// files with an older one's (old frames left beside new ones, a study table beside another
// study's runs, a log written by two processes), and two commands never write into one folder at
// the same time.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace drydem {

/// What one command writes into its output folder, and how a folder it wrote is recognised.
struct OutputKind {
    std::string noun; ///< "run", "study", "dryer model run", "analysis"
    std::vector<std::string>
        names; ///< the entries it writes (README "Outputs"); --overwrite removes these
    bool numbered_iterations = false; ///< also iter_N folders (a coupled run, paper Sec. 8)
    bool (*holds)(const std::filesystem::path& dir) = nullptr; ///< the folder holds such an output
    std::string resume_hint;                                   ///< how to continue one, or empty
};

/// The kinds: `drydem run` (also --couple-dryer), `drydem study`, `drydem dryer`, `drydem analyze`,
/// `drydem calender`.
[[nodiscard]] const OutputKind& run_output();
[[nodiscard]] const OutputKind& study_output();
[[nodiscard]] const OutputKind& dryer_output();
[[nodiscard]] const OutputKind& analysis_output();
[[nodiscard]] const OutputKind& calender_output(); ///< `drydem calender`

/// Makes `dir` ready for a new output of `kind`: creates it when missing; an empty folder is used
/// as it is; a folder holding a previous output of this kind is refused (InputError naming
/// --overwrite, and how to continue it where it can be) unless `overwrite`, which removes that
/// output's entries (kind.names, an atomic write's leftover .tmp, iter_N of a coupled run) and
/// nothing else; any other non-empty folder is refused even with `overwrite` (it is not ours to
/// clear). The lock file (OutputLock) and a study's console capture do not count as content.
void prepare_output_folder(const std::filesystem::path& dir, const OutputKind& kind,
                           bool overwrite);

/// An exclusive lock on `dir` (created when missing) for the lifetime of the object: `dir/.drydem.lock`, locked with
/// flock(2), so the kernel releases it when the process ends in any way (SIGKILL included) and a
/// killed run can be resumed at once. A second command into the same folder gets an InputError
/// naming the process that holds it.
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
