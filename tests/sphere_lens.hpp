// SPDX-License-Identifier: MIT
// The lens two intersecting spheres share, written out apart from the laws' caps
// (forces/agglomerate_hardening.hpp) so that the tests check those against an independent form.
#pragma once
#include <numbers>

namespace drydem::testing_support {

/// Volume of the lens of two spheres of radii r_i, r_j at centre distance d (Weisstein,
/// "Sphere-Sphere Intersection", MathWorld) [m³].
inline double lens_volume(double ri, double rj, double d) {
    const double s = ri + rj - d;
    return std::numbers::pi * s * s *
           (d * d + 2 * d * rj - 3 * rj * rj + 2 * d * ri + 6 * ri * rj - 3 * ri * ri) / (12 * d);
}

} // namespace drydem::testing_support
