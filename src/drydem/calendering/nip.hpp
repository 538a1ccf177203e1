// SPDX-License-Identifier: MIT
// The roll's nip as the plate stands in for it (docs/calendering.md "Line load"). A roll of
// radius R that presses the coating from its thickness h₀ to h touches it, on the entry side,
// over the horizontal length where its surface z(x) = h + R − sqrt(R² − x²) ≈ h + x²/(2R) lies
// below h₀:
//   l = sqrt(2 R (h₀ − h))
// (the coating on its foil rests on the lower roll, which does not compress it; the film's
// springback behind the nip is left out). A line load q (roll force per coating width) spread
// evenly over l is the mean nip pressure
//   p = q / l = q / sqrt(2 R (h₀ − h))
// which the plate must carry at the gap h. Where the article's own convention differs (a contact
// length sqrt(R Δh) of a coating pressed from both sides, or a peak pressure 4/π above the mean
// of an elliptic distribution), the pressures differ by √2 or 4/π: state which when comparing.
#pragma once
#include <cmath>

namespace drydem {

/// The mean nip pressure [Pa] of line load q [N/m] at gap h for a coating of thickness h0 [m]
/// under a roll of radius R [m]; +inf before the roll has pressed it (h ≥ h0).
inline double nip_pressure(double line_load, double roll_radius, double h0, double h) {
    if (h >= h0) return INFINITY;
    return line_load / std::sqrt(2.0 * roll_radius * (h0 - h));
}

} // namespace drydem
