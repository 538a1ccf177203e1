// SPDX-License-Identifier: MIT
// Capillary force of the descending liquid surface on a particle that pierces it: model.md M-6,
// paper Eq. 11-12 (Breinlinger & Kraft 2014), with the radius restored (I-1) and the sign of h_s
// fixed (C-20 / I-2).
//   h_s = z_L - z,  u = h_s / r,  cos ω = -u,  sin ω = sqrt(1 - u²)
//   F = -2πσ s_cap r sin ω sin(ω + θ) ẑ = -2πσ s_cap r [(1 - u²) cos θ - u sqrt(1 - u²) sin θ] ẑ
// for |h_s| < r, else 0. The force passes through the centre (no torque); it vanishes at u = cos θ
// (floating equilibrium of a hydrophilic sphere) with spring stiffness 2πσ s_cap, and pulls
// slightly upward for cos θ < u < 1 (I-8). The law receives σ s_cap as simulated (M-7,
// drying/scaling.cpp: s_cap = 9e3 in the paper's scheme) and applies no factor.
#pragma once
#include "drydem/core/vec3.hpp"
#include "drydem/forces/body_law.hpp"
#include "drydem/forces/law_limits.hpp"
#include <array>
#include <cmath>
#include <numbers>
#include <string_view>

namespace drydem {

struct CapillaryParams {
    double surface_tension = 0.0; ///< σ s_cap [N/m], as simulated; 0 = off
    double contact_angle = 40.0 * std::numbers::pi / 180.0; ///< θ [rad]
};

/// Stiffness of the force about its equilibrium, 2πσ s_cap [N/m] (2318 N/m scaled, M-6).
inline double capillary_stiffness(const CapillaryParams& p) {
    return 2.0 * std::numbers::pi * p.surface_tension;
}

/// The largest push the level can give a sphere of radius r, at ω = (π - θ)/2:
/// 2πσ s_cap r cos²(θ/2) [N] (the maximum of sin ω sin(ω + θ)).
inline double capillary_max_force(double r, const CapillaryParams& p) {
    const double c = std::cos(0.5 * p.contact_angle);
    return capillary_stiffness(p) * r * c * c;
}

inline Vec3 capillary_front(double z, double r, double liquid_level, const CapillaryParams& p) {
    const double u = (liquid_level - z) / r;
    if (capillary_stiffness(p) == 0.0 || !(std::abs(u) < 1.0)) return {};
    const double s2 = 1.0 - u * u; // sin² ω
    const double shape =
        s2 * std::cos(p.contact_angle) - u * std::sqrt(s2) * std::sin(p.contact_angle);
    return {0.0, 0.0, -capillary_stiffness(p) * r * shape};
}

/// The liquid level's pull as a body law (body_law.hpp): conservative, keeps nothing.
struct CapillaryFrontLaw {
    using Params = CapillaryParams;
    struct State {};
    static constexpr std::string_view name = "capillary_front";
    static constexpr std::array limits{
        ParamLimit<Params>{"surface_tension", &Params::surface_tension},
        ParamLimit<Params>{"contact_angle", &Params::contact_angle, 0.0, std::numbers::pi}};

    [[gnu::always_inline]] static inline void add_force(const BodyGeometry& g, const Params& p,
                                                        State&, double, BodyForce& f,
                                                        BodyResistance*) {
        if (p.surface_tension == 0.0) return;
        f.force.z += capillary_front(g.x.z, g.r, g.liquid_level, p).z;
    }
    static BodyResistance resistance(const BodyGeometry&, const Params&) { return {}; }
    /// -dF/dz = 2πσ s_cap at the floating equilibrium u = cos θ, while the particle can reach
    /// the level within g.reach: the rate of the oscillation the level can drive (M-6). The
    /// slope grows without bound towards |u| = 1, where the particle leaves the force behind
    /// rather than oscillates in it, so it does not bound the step.
    static BodyResistance stiffness(const BodyGeometry& g, const Params& p) {
        if (!(std::abs(g.liquid_level - g.x.z) < g.r + g.reach)) return {};
        BodyResistance k;
        k.normal = capillary_stiffness(p);
        return k;
    }
    static bool keeps(const State&) { return false; }
};

} // namespace drydem
