// SPDX-License-Identifier: MIT
// Stokes drag of a sphere in liquid at rest: model.md M-5, paper Eq. 10, plus the rotational
// counterpart (C-18).
//   F_drag = -6π (η/b) r v,   T_drag = -8π (η/b) r³ ω
// The viscosity is the reduced η/b (b = 10, M-7: 0.1801 Pa s); lubrication keeps the full η
// (C-17). Acts on every particle at all times, also above the liquid level (C-19).
#pragma once
#include "drydem/forces/body_law.hpp"
#include "drydem/forces/law_limits.hpp"
#include <array>
#include <numbers>
#include <string_view>

namespace drydem {

struct StokesDragParams {
    double viscosity = 0.0; ///< already the scaled η/b [Pa s]; 0 = off
    bool rotational = true; ///< rotational drag (C-18)
};

/// Translational drag coefficient 6π(η/b) r [kg/s].
inline double stokes_drag_coefficient(double r, const StokesDragParams& p) {
    return 6.0 * std::numbers::pi * p.viscosity * r;
}

/// Relaxation time m / (6π(η/b) r) of the drag [s]; an explicit kick needs Δt < 2 m/(6π(η/b) r).
inline double stokes_relaxation_time(double mass, double r, const StokesDragParams& p) {
    return mass / stokes_drag_coefficient(r, p);
}

/// The law's resistance (resistance.hpp body form): a_z = a_t = 6π(η/b) r, d_t = d_z = 8π(η/b) r³
/// (rotation only when enabled).
inline BodyResistance stokes_drag_resistance(double r, const StokesDragParams& p) {
    const double a = stokes_drag_coefficient(r, p);
    const double d = p.rotational ? 8.0 * std::numbers::pi * p.viscosity * r * r * r : 0.0;
    return {a, a, 0.0, d, d};
}

inline BodyForce stokes_drag(double r, const Vec3& v, const Vec3& omega,
                             const StokesDragParams& p) {
    return resistance_force(stokes_drag_resistance(r, p), v, omega);
}

/// The drag as a body law (body_law.hpp): purely dissipative, keeps nothing, independent of
/// where the particle is.
struct StokesDragLaw {
    using Params = StokesDragParams;
    struct State {};
    static constexpr std::string_view name = "stokes_drag";
    static constexpr std::array limits{ParamLimit<Params>{"viscosity", &Params::viscosity}};

    [[gnu::always_inline]] static inline void add_force(const BodyGeometry& g, const Params& p,
                                                        State&, double, BodyForce& f,
                                                        BodyResistance* r) {
        if (p.viscosity == 0.0) return;
        const BodyResistance drag = stokes_drag_resistance(g.r, p);
        if (r) *r += drag;
        f += resistance_force(drag, g.v, g.omega);
    }
    static BodyResistance resistance(const BodyGeometry& g, const Params& p) {
        return stokes_drag_resistance(g.r, p);
    }
    static BodyResistance stiffness(const BodyGeometry&, const Params&) { return {}; }
    static bool keeps(const State&) { return false; }
};

} // namespace drydem
