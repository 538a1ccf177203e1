// SPDX-License-Identifier: MIT
// Elastic-perfectly-plastic normal contact of Thornton and Ning (Powder Technol. 99 (1998) 154),
// model.md M-2.8, for compaction (calendering): Hertz until the mean contact pressure's peak
// reaches the limiting pressure p_y, then a contact that flattens at constant pressure, and a
// Hertzian unloading with an enlarged radius, so that springback and the permanent set follow
// from the law.
//   loading, δ ≤ δ_y:   F = (4/3) E* sqrt(R*) δ^{3/2},   δ_y = (π p_y / (2 E*))² R*
//   loading, δ > δ_y:   F = F_y + π p_y R* (δ - δ_y),     F_y = (4/3) E* sqrt(R*) δ_y^{3/2}
//   unloading from δ_max (F_max) and reloading up to it:
//                       F = (4/3) E* sqrt(R_p) (δ - δ_p)^{3/2} for δ > δ_p, else 0
//                       R_p = (4 E* / (3 F_max)) ((2 F_max + F_y) / (2 π p_y))^{3/2}
//                       δ_p = δ_max - (3 F_max / (4 E* sqrt(R_p)))^{2/3}
// p_y = 0 switches the plasticity off: plain Hertz. What a contact keeps is δ_max, the deepest
// overlap it has reached (erased when it opens, as the tangential spring).
#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>

namespace drydem {

/// The normal force of the law at an overlap and its slope dF/dδ (the quasi-static step's normal
/// stiffness and the stability guard's bound).
struct ElasticPlasticNormal {
    double force = 0.0;     ///< F [N], ≥ 0
    double stiffness = 0.0; ///< dF/dδ [N/m]
};

/// δ_y = (π p_y / (2 E*))² R*: the overlap at which the Hertz pressure peak 2 E* a / (π R*)
/// reaches p_y [m].
inline double yield_overlap(double e_star, double r_eff, double yield_pressure) {
    const double a = std::numbers::pi * yield_pressure / (2.0 * e_star);
    return a * a * r_eff;
}

/// The inverse: the limiting pressure at which a contact of R* yields at overlap δ_y [Pa]
/// (calendering.yield_displacement, given as an overlap, maps to p_y through this).
inline double yield_pressure_at(double e_star, double r_eff, double overlap_at_yield) {
    return 2.0 * e_star / std::numbers::pi * std::sqrt(overlap_at_yield / r_eff);
}

/// The Hertz force (4/3) E* sqrt(R) δ^{3/2} and its slope 2 E* sqrt(R δ).
inline ElasticPlasticNormal hertz_normal(double e_star, double radius, double overlap) {
    if (overlap <= 0.0) return {};
    const double s = 2.0 * e_star * std::sqrt(radius * overlap);
    return {(2.0 / 3.0) * s * overlap, s};
}

/// The unloading branch after loading to δ_max beyond yield: R_p and δ_p of the header.
struct PlasticUnloading {
    double radius = 0.0;   ///< R_p [m]
    double residual = 0.0; ///< δ_p, the permanent set of the contact [m]
};
inline PlasticUnloading plastic_unloading(double e_star, double r_eff, double yield_pressure,
                                          double max_overlap) {
    const double d_y = yield_overlap(e_star, r_eff, yield_pressure);
    const double f_y = hertz_normal(e_star, r_eff, d_y).force;
    const double f_max = f_y + std::numbers::pi * yield_pressure * r_eff * (max_overlap - d_y);
    const double a_max2 = (2.0 * f_max + f_y) / (2.0 * std::numbers::pi * yield_pressure);
    const double r_p = 4.0 * e_star / (3.0 * f_max) * a_max2 * std::sqrt(a_max2);
    // δ_max - a_max²/R_p: the overlap the unloaded Hertz contact of R_p gives back.
    return {r_p, max_overlap - a_max2 / r_p};
}

/// The law's normal force at overlap δ after a deepest overlap max_overlap (≥ δ; the caller keeps
/// it). Without plasticity (p_y = 0) the Hertz force. A p_y that hardens with δ_max
/// (agglomerate_hardening.hpp, M-2.12) comes as its value at δ_max and its slope dp_y/dδ_max: the
/// plastic line F_y + π p_y R* (δ − δ_y) = π p_y R* (δ − δ_y / 3) then stiffens by
/// ∂F/∂p_y dp_y/dδ = π R* (δ − δ_y) dp_y/dδ while it loads.
inline ElasticPlasticNormal thornton_ning_normal(double e_star, double r_eff, double yield_pressure,
                                                 double overlap, double max_overlap,
                                                 double yield_slope = 0.0) {
    if (overlap <= 0.0) return {};
    if (yield_pressure <= 0.0) return hertz_normal(e_star, r_eff, overlap);
    const double d_y = yield_overlap(e_star, r_eff, yield_pressure);
    if (max_overlap <= d_y) return hertz_normal(e_star, r_eff, overlap); // never yielded
    if (overlap >= max_overlap) {                                        // plastic loading
        const double f_y = hertz_normal(e_star, r_eff, d_y).force;
        const double slope = std::numbers::pi * yield_pressure * r_eff;
        return {f_y + slope * (overlap - d_y),
                slope + std::numbers::pi * r_eff * (overlap - d_y) * yield_slope};
    }
    const PlasticUnloading u = plastic_unloading(e_star, r_eff, yield_pressure, max_overlap);
    return hertz_normal(e_star, u.radius, overlap - u.residual);
}

} // namespace drydem
