// SPDX-License-Identifier: MIT
// Pressing to a porosity after springback (calendering.mode = "unloaded_porosity",
// docs/calendering.md "Pressing to a porosity after unloading"): a plant sets the roll gap, the
// film springs back, and the gap is closed further on the next pass until the calendered film
// has its target. Each pass here is a real press, hold, unload and relaxation of the same film
// (its plastic flattening, broken bonds and compacted agglomerates carried on), so the result is
// that of multi-pass calendering, not an inverse of one pass.
//
// The next pass's peak porosity ε_peak,n+1 from the passes so far, aiming the unloaded porosity
// ε_u at the target ε_t:
//   one pass:  ε_peak,n+1 = ε_peak,n − (ε_u,n − ε_t)          (the springback taken as unchanged)
//   two on:    the shallower of that and the secant
//              ε_peak,n + (ε_t − ε_u,n) / m,  m = (ε_u,n − ε_u,n−1) / (ε_peak,n − ε_peak,n−1),
//              the secant only when 1/4 ≤ m ≤ 4 (two passes that moved the unloaded film too
//              little or the wrong way carry no slope worth following).
// A deeper press springs back more (Sangros film: +0.039 from 0.369, +0.084 from 0.173), so the
// first rule lands above the target and the passes close in from above. The secant is exact for
// a springback linear in the peak, but its first point is the virgin press, which flattens and
// crushes what a repeated press only re-loads: on the end-to-end test's film the first pass
// sprang back 0.018 and the next two 0.030 each, so the secant (slope 0.37) would have pressed
// the third pass ~0.02 past the target, the shift to 0.001 of it. A film cannot be un-pressed and
// another pass only costs a pass, so the deeper of the two estimates is never taken.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace drydem {

struct CalenderPass {
    double peak_target = 0.0;        ///< the porosity the plate pressed to
    double peak_porosity = 0.0;      ///< at the plate's height at the end of the hold
    double peak_pressure = 0.0;      ///< the largest plate pressure of the pass [Pa]
    double unloaded_porosity = 0.0;  ///< after unloading and relaxation
    double unloaded_thickness = 0.0; ///< [m]
    bool at_rest = false;            ///< the relaxation reached rest
    std::int64_t steps = 0;          ///< engine steps from the load's start to the relaxed end
    double wall_time = 0.0;          ///< wall seconds of the same (the cost of one pass)
};

/// The peak porosity for the pass after `done` (not empty) that aims at the unloaded `target`.
[[nodiscard]] inline double next_peak_porosity(const std::vector<CalenderPass>& done,
                                               double target) {
    const CalenderPass& last = done.back();
    const double shift = last.peak_porosity - (last.unloaded_porosity - target);
    if (done.size() < 2) return shift;
    const CalenderPass& before = done[done.size() - 2];
    const double dp = last.peak_porosity - before.peak_porosity;
    if (dp == 0.0) return shift;
    const double m = (last.unloaded_porosity - before.unloaded_porosity) / dp;
    if (!(m >= 0.25 && m <= 4.0)) return shift;
    return std::max(shift, last.peak_porosity + (target - last.unloaded_porosity) / m);
}

/// What follows a relaxed pass in unloaded_porosity mode.
enum class PassOutcome {
    done,          ///< the unloaded porosity is within the tolerance of the target
    again,         ///< another pass, to next_peak
    pressed_past,  ///< below the target by more than the tolerance: a film cannot be un-pressed
    out_of_passes, ///< above it after the last pass allowed
    out_of_reach   ///< the next peak would lie at or below the densest the spheres allow
};
struct PassDecision {
    PassOutcome outcome = PassOutcome::done;
    double next_peak = 0.0; ///< the porosity to press to next (again, out_of_reach)
};

/// The decision after the passes `done` (not empty), for the unloaded `target` ± `tolerance`,
/// at most `max_passes`, the spheres filling the whole gap at porosity `densest`.
[[nodiscard]] inline PassDecision decide_next_pass(const std::vector<CalenderPass>& done,
                                                   double target, double tolerance, int max_passes,
                                                   double densest) {
    const double u = done.back().unloaded_porosity;
    if (std::abs(u - target) <= tolerance) return {PassOutcome::done};
    if (u < target) return {PassOutcome::pressed_past};
    if (int(done.size()) >= max_passes) return {PassOutcome::out_of_passes};
    const double next = next_peak_porosity(done, target);
    return {next > densest ? PassOutcome::again : PassOutcome::out_of_reach, next};
}

} // namespace drydem
