// SPDX-License-Identifier: MIT
// The Python helpers in scripts/ (plots with Debian's matplotlib) run with /usr/bin/python3, not
// the first python3 on PATH, which may not see Debian's packages. Started without a shell, so
// no path or run name needs quoting.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace drydem {

enum class ScriptRun {
    ok,
    unavailable, ///< no /usr/bin/python3 or no such script: the plots are optional, not an error
    failed,      ///< it ran and exited non-zero (or died)
};

/// Runs scripts/`script` with `args`; its stdout and stderr are appended to `log` (empty: they go
/// to this process's own). Waits for it.
ScriptRun run_python_script(const std::string& script, const std::vector<std::string>& args,
                            const std::filesystem::path& log = {});

} // namespace drydem
