// SPDX-License-Identifier: MIT
// Spheres settling on the substrate in a viscous liquid under a strong gravity, the set-up of the
// exact quasi-static tests (quasi_static_test.cpp, implicit_stiffness_test.cpp): one species of
// r = 5 µm, E = 10 GPa, ν = 0.3, with Stokes drag (η = 0.18 Pa s) and gravity g = 1e7 m/s² so
// that the Hertz overlaps are resolvable. A column of them carries its weight through its
// contacts at δ = (3F / (4 E* sqrt(R*)))^(2/3).
#pragma once
#include "drydem/forces/force_field.hpp"
#include <cmath>

namespace drydem::testing_support {

constexpr double kR = 5e-6, kRho = 4740.0, kG = 1e7;

inline ForceField settling_field() {
    ForceField ff = uniform_contact_force_field(1, 1e10, 0.3, 0.5, 0.5);
    ff.set_body_law<StokesDragLaw>({0.18, true});
    ff.set_body_law<GravityBuoyancyLaw>({kG, 0.0});
    return ff;
}

/// The Hertz overlap that carries `force` at R* and E*.
inline double hertz_overlap_of(double force, double r_eff, double e_star) {
    return std::pow(3.0 * force / (4.0 * e_star * std::sqrt(r_eff)), 2.0 / 3.0);
}

} // namespace drydem::testing_support
