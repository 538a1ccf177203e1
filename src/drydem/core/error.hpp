// SPDX-License-Identifier: MIT
// Error types: InputError = bad user input (exit code 2), RunError = a run that failed (exit 1).
#pragma once
#include <stdexcept>
#include <string>

namespace drydem {

/// Bad input: names the key, the value and what is allowed. Exit code 2.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
/// A simulation that cannot continue (blow-up, I/O failure). Exit code 1.
struct RunError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace drydem
