// SPDX-License-Identifier: MIT
// Volume of a sphere, V = 4/3 π r³: one definition for the recipe (particle counts from volume
// fractions), the particle store (masses), the file readers (density from a mass column) and the
// analysis (volume and mass balances), so that their numbers agree to the last bit.
#pragma once
#include <numbers>

namespace drydem {

/// V of a sphere of radius `radius` [m³].
[[nodiscard]] constexpr double sphere_volume(double radius) {
    return 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
}

/// A porous agglomerate's envelope volume when its inner porosity goes from `from` to `to` with
/// its solid kept (M-1.3: V_env = V_solid / (1 - ε)), as a ratio V_to / V_from.
[[nodiscard]] constexpr double envelope_ratio(double from, double to) {
    return (1.0 - from) / (1.0 - to);
}

} // namespace drydem
