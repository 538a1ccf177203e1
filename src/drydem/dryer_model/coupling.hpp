// SPDX-License-Identifier: MIT
// Dryer <-> DEM fixed-point iteration (dryer.md D-6; paper Sec. 8, last paragraph). The dryer
// needs the final thickness h_f (from the DEM) to know when shrinkage ends; the DEM needs the
// shrinkage rates s_k (from the dryer). Starting from a final-porosity guess:
//   ε_f -> dryer model -> s_k (D-4) -> DEM -> h_f -> ε_f = 1 - L/(ρ_s h_f) -> ...
// until the DEM's h_f differs from the h_f the dryer assumed by less than the tolerance.
// The DEM is a callable, so the driver is tested with a mock and used with run_drying.
#pragma once
#include "drydem/dryer_model/film_dryer.hpp"
#include <functional>
#include <string>
#include <vector>

namespace drydem::dryer {

/// One pass of the iteration.
struct CouplingIteration {
    int iteration = 0;               ///< 1-based
    double porosity_in = 0.0;        ///< ε_f assumed by the dryer model
    double final_thickness_in = 0.0; ///< h_f = L/(ρ_s (1 - ε_f)) assumed by the dryer [m]
    std::vector<double> rates;       ///< s_k handed to the DEM [m/s]
    std::optional<double> consolidation_time; ///< dryer model [s]
    double final_thickness_dem = 0.0;         ///< h_f from the DEM [m]
    double porosity_dem = 0.0;                ///< 1 - L/(ρ_s h_f,DEM)
    double change = 0.0;                      ///< h_f,DEM - h_f,in [m]
};

struct CouplingResult {
    bool converged = false;
    std::vector<CouplingIteration> iterations;
    std::string
        message; ///< one line: converged after N / stopped at max iterations (+ last change)
};

/// The DEM: runs with the given shrinkage rates [m/s] (iteration number 1-based and the dryer's
/// ε_f for bookkeeping) and returns the final thickness [m]. May throw (RunError) to abort.
using DemRunner =
    std::function<double(int iteration, const std::vector<double>& rates, double porosity_in)>;

/// Runs the iteration from params.final_porosity. Stops when |h_f,DEM - h_f,in| < tolerance
/// (converged) or after max_iterations (not converged, message says so). on_iteration is called
/// after every pass (logging).
[[nodiscard]] CouplingResult
couple_dryer_dem(FilmDryerParams params, const DemRunner& dem, double tolerance, int max_iterations,
                 const std::function<void(const CouplingIteration&)>& on_iteration = {});

} // namespace drydem::dryer
