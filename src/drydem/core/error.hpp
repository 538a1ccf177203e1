// SPDX-License-Identifier: MIT
// Error types: InputError = bad user input (exit code 2), RunError = a run that failed (exit 1).
#pragma once
#include <stdexcept>
#include <string>
#include <utility>

namespace drydem {

/// Bad input: names the key, the value and what is allowed. Exit code 2.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
/// A simulation that cannot continue (blow-up, I/O failure). Exit code 1. `reason` is the run's
/// machine-readable stop reason (summary.json `stop_reason`): "blow_up", "runaway_overlap",
/// "stability_guard", "interrupted", "stop_after_steps", "max_process_time", or "error".
struct RunError : std::runtime_error {
    explicit RunError(const std::string& what, std::string stop_reason = "error")
        : std::runtime_error(what), reason(std::move(stop_reason)) {}
    std::string reason;
};

} // namespace drydem
