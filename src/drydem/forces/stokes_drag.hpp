// SPDX-License-Identifier: MIT
// Stokes drag of a sphere in liquid at rest: model.md M-5, paper Eq. 10, plus the rotational
// counterpart (C-18).
//   F_drag = -6π (η/b) r v,   T_drag = -8π (η/b) r³ ω
// The viscosity is the reduced η/b (b = 10, M-7: 0.1801 Pa s); lubrication keeps the full η
// (C-17). Acts on every particle at all times, also above the liquid level (C-19).
#pragma once
#include "drydem/forces/pair_geometry.hpp"
#include <numbers>

namespace drydem {

struct StokesDragParams {
    double viscosity = 0.0; ///< already the scaled η/b [Pa s]; 0 = off
    bool rotational = true; ///< rotational drag (C-18)
};

/// Translational drag coefficient 6π(η/b) r [kg/s].
inline double stokes_drag_coefficient(double r, const StokesDragParams& p) {
    return 6.0 * std::numbers::pi * p.viscosity * r;
}

inline BodyForce stokes_drag(double r, const Vec3& v, const Vec3& omega,
                             const StokesDragParams& p) {
    BodyForce out;
    out.force = -stokes_drag_coefficient(r, p) * v;
    if (p.rotational) out.torque = (-8.0 * std::numbers::pi * p.viscosity * r * r * r) * omega;
    return out;
}

} // namespace drydem
