// SPDX-License-Identifier: MIT
// A calibration (docs/calibration.md): the [calibration] section checked for a search and written
// as the specification the search driver (scripts/calibrate.py) reads. The search itself (SciPy
// qmc start, scikit-learn Gaussian processes, expected improvement) runs in Python; each
// evaluation is `drydem run` processes, as in a study.
#pragma once
#include "drydem/io/config.hpp"
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace drydem {

/// The space-filling start: calibration.initial_points, or with 0 max(4, 2 x parameters), at most
/// calibration.evaluations.
int calibration_initial_points(const Config& c);

/// Checks that `c` can be calibrated: at least one parameter and one target, a first surrogate
/// fit (initial points >= 2), and every parameter at its min and at its max a valid run
/// configuration (the derived-quantity checks: a bound that empties the film or breaks the
/// time step is named). Throws InputError; returns the warnings (fewer independent targets than
/// parameters, a base value outside the bounds).
std::vector<std::string> check_calibration(const Config& c);

/// The specification DIR/calibration.json for scripts/calibrate.py: parameters (SI bounds),
/// targets (in the unit of their summary.json key), seeds, budget, scheduler, the drydem executable.
nlohmann::json calibration_spec(const Config& c, const std::string& drydem_executable);

} // namespace drydem
