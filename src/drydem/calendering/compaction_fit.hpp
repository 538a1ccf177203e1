// SPDX-License-Identifier: MIT
// The compaction curve of a calendered film (docs/calendering.md "Compaction curve"): porosity
// against the plate's pressure on the loading branch, fitted with
//   ε(p) = ε_min + (ε_0 - ε_min) exp(-p / p_c)
// ε_min the porosity the film tends to under any load, p_c its compaction resistance. This is our
// reading of the "exponential model converging to a minimal porosity" of Meyer et al. (J. Mater.
// Process. Technol. 249, 2017), written in the pressure; the article's own form is not confirmed.
#pragma once
#include <span>

namespace drydem {

struct CompactionFit {
    bool ok = false;            ///< false: fewer than 4 points, or no decreasing exponential fits
    double porosity_min = 0.0;  ///< ε_min
    double porosity_zero = 0.0; ///< ε_0 = ε(p = 0)
    double resistance = 0.0;    ///< p_c [Pa]
    double rms = 0.0;           ///< root-mean-square residual of the porosity
    int points = 0;
};

/// Least squares over the points (p_k, ε_k), p in Pa: for each p_c the model is linear in ε_min
/// and ε_0 - ε_min (solved exactly), and p_c is searched on a logarithmic grid from 1e-3 to 1e2
/// times the largest pressure, then refined by golden section.
CompactionFit fit_compaction(std::span<const double> pressure, std::span<const double> porosity);

} // namespace drydem
