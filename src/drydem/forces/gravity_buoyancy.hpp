// SPDX-License-Identifier: MIT
// Weight minus buoyancy of a fully immersed sphere: model.md M-5, paper Eq. 8 minus Eq. 9.
//   F = -(4/3)π r³ (ρ_p - ρ_f) g_s ẑ,   g_s = g k / b = 9.81e6 m/s² (scaled, M-7)
// Buoyancy is kept above the liquid level too (C-19, option "keep").
#pragma once
#include "drydem/core/sphere.hpp"
#include "drydem/core/vec3.hpp"

namespace drydem {

struct GravityBuoyancyParams {
    double gravity = 0.0;       ///< scaled g_s [m/s²], acts along -z; 0 = off
    double fluid_density = 0.0; ///< ρ_f [kg/m³] (NMP 1030)
};

inline Vec3 gravity_buoyancy(double r, double particle_density, const GravityBuoyancyParams& p) {
    return {0.0, 0.0, -sphere_volume(r) * (particle_density - p.fluid_density) * p.gravity};
}

} // namespace drydem
