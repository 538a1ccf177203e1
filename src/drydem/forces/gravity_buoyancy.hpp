// SPDX-License-Identifier: MIT
// Weight minus buoyancy of a fully immersed sphere: model.md M-5, paper Eq. 8 minus Eq. 9.
//   F = (4/3)π r³ (ρ_p - ρ_f) g_s (sin θ, 0, -cos θ),   g_s = g k / b (scaled, M-7)
// Buoyancy is kept above the liquid level too (C-19, option "keep"). θ is the substrate's
// inclination from the horizontal, downhill along +x: 0 for the drying film, whose level lies
// flat over it; the frictional incline test (tests/integration/quasi_static_test.cpp) tilts it.
#pragma once
#include "drydem/core/sphere.hpp"
#include "drydem/core/vec3.hpp"
#include "drydem/forces/body_law.hpp"
#include "drydem/forces/law_limits.hpp"
#include <array>
#include <cmath>
#include <string_view>

namespace drydem {

struct GravityBuoyancyParams {
    double gravity = 0.0;       ///< scaled g_s [m/s²], acts along -z; 0 = off
    double fluid_density = 0.0; ///< ρ_f [kg/m³] (NMP 1030)
    double inclination = 0.0;   ///< θ [rad], 0 ≤ θ ≤ π/2
};

inline Vec3 gravity_buoyancy(double r, double particle_density, const GravityBuoyancyParams& p) {
    const double w = sphere_volume(r) * (particle_density - p.fluid_density) * p.gravity;
    if (p.inclination == 0.0) return {0.0, 0.0, -w};
    return {w * std::sin(p.inclination), 0.0, -w * std::cos(p.inclination)};
}

/// Weight and buoyancy as a body law (body_law.hpp): a constant force, no stiffness (the guard
/// has nothing to bound), keeps nothing.
struct GravityBuoyancyLaw {
    using Params = GravityBuoyancyParams;
    struct State {};
    static constexpr std::string_view name = "gravity_buoyancy";
    static constexpr std::array limits{
        ParamLimit<Params>{"gravity", &Params::gravity},
        ParamLimit<Params>{"fluid_density", &Params::fluid_density},
        ParamLimit<Params>{"inclination", &Params::inclination, 0.0, 1.5707963267948966}};

    [[gnu::always_inline]] static inline void add_force(const BodyGeometry& g, const Params& p,
                                                        State&, double, BodyForce& f,
                                                        BodyResistance*) {
        f.force += gravity_buoyancy(g.r, g.density, p);
    }
    static BodyResistance resistance(const BodyGeometry&, const Params&) { return {}; }
    static BodyResistance stiffness(const BodyGeometry&, const Params&) { return {}; }
    static bool keeps(const State&) { return false; }
};

} // namespace drydem
