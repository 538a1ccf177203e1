// SPDX-License-Identifier: MIT
// Weight minus buoyancy of a fully immersed sphere: model.md M-5, paper Eq. 8 minus Eq. 9.
//   F = -(4/3)π r³ (ρ_p - ρ_f) g_s ẑ,   g_s = g k / b = 9.81e6 m/s² (scaled, M-7)
// Buoyancy is kept above the liquid level too (C-19, option "keep").
#pragma once
#include "drydem/core/sphere.hpp"
#include "drydem/core/vec3.hpp"
#include "drydem/forces/body_law.hpp"
#include "drydem/forces/law_limits.hpp"
#include <array>
#include <string_view>

namespace drydem {

struct GravityBuoyancyParams {
    double gravity = 0.0;       ///< scaled g_s [m/s²], acts along -z; 0 = off
    double fluid_density = 0.0; ///< ρ_f [kg/m³] (NMP 1030)
};

inline Vec3 gravity_buoyancy(double r, double particle_density, const GravityBuoyancyParams& p) {
    return {0.0, 0.0, -sphere_volume(r) * (particle_density - p.fluid_density) * p.gravity};
}

/// Weight and buoyancy as a body law (body_law.hpp): a constant force, no stiffness (the guard
/// has nothing to bound), keeps nothing.
struct GravityBuoyancyLaw {
    using Params = GravityBuoyancyParams;
    struct State {};
    static constexpr std::string_view name = "gravity_buoyancy";
    static constexpr std::array limits{ParamLimit<Params>{"gravity", &Params::gravity},
                                       ParamLimit<Params>{"fluid_density", &Params::fluid_density}};

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
