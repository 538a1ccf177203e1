// SPDX-License-Identifier: MIT
// Hardening of a contact with a carbon-binder agglomerate as the contact's lens compacts it,
// model.md M-2.12, for calendering. A CB sphere's contact flattens at the limiting pressure p_y0
// (Thornton-Ning, M-2.8); the envelope volume it gives up there is not lost solid but pore space
// pressed out of the agglomerate, so the deeper the contact, the denser what is left of it:
//   V_l     the volume the agglomerate gives up: its own cap of the two spheres' lens when both
//           are agglomerates, the whole lens when its partner is dense (NCM, a wall)
//   ε(δ)  = 1 − (1 − ε_0) V / (V − V_l)                   solid kept in the rest of the envelope
//   p_y(δ) = p_y0 + (p_d − p_y0) (ε_0 − max(ε, ε_min)) / (ε_0 − ε_min)
//   1/E*(δ) = (1/E*_0) (1 − Σ s_k + Σ s_k / ρ_k²),  ρ_k = (1 − ε_k) / (1 − ε_0)
// p_y rises from the loose agglomerate's p_y0 to the dense carbon-binder domain's p_d as the
// lens compacts it to ε_min, and stays there: the dense domain flows at p_d. Its modulus rises
// with its relative density ρ as an open-cell porous body's, E ∝ ρ² (Gibson and Ashby,
// Cellular Solids, 1997): s_k is agglomerate k's share of the loose contact's compliance 1/E*_0,
// (1 − ν²)/E_CB × E*_0. Without it the unloading, which gives back ∝ p_y / E* of the overlap
// (M-2.8), would spring back more the harder the contact became.
// p_y is linear in the compaction because the inverse of the compaction curve (M-2.11), p ∝ ln((ε_0 − ε_min) /
// (ε − ε_min)), diverges at ε_min: its slope passes the Hertz slope by orders of magnitude just
// before it, which no explicit contact step follows (measured in model.md M-2.12). With two
// agglomerates the softer one (the larger ε) sets the pressure. ε_0 is the as-dried porosity:
// an agglomerate that its mean stress already compacted (M-2.11) hardens from its new envelope
// as if it were loose, a lower bound of its hardening.
#pragma once
#include "drydem/core/sphere.hpp"
#include <algorithm>
#include <cstdint>
#include <numbers>

namespace drydem {

/// Which spheres of a contact are agglomerates: none, sphere i, sphere j (never a wall), both.
enum class AgglomerateSides : std::uint8_t { none = 0, i = 1, j = 2, both = 3 };

/// The hardening's parameters; p_d = 0 or no agglomerate side: p_y stays p_y0.
struct AgglomerateHardening {
    double initial_porosity = 0.0;     ///< ε_0, the agglomerate as dried
    double minimal_porosity = 0.0;     ///< ε_min < ε_0, the densest carbon-binder domain
    double dense_yield_pressure = 0.0; ///< p_d [Pa], ≥ p_y0
    AgglomerateSides sides = AgglomerateSides::none;
    double compliance_share = 0.0; ///< s: each agglomerate side's share of 1/E*_0, in [0, 1]

    [[nodiscard]] bool hardens() const {
        return dense_yield_pressure > 0.0 && sides != AgglomerateSides::none;
    }
};

/// The spheres of a contact: radii [m]; r_j = 0 for a plane (substrate, plate).
struct ContactSpheres {
    double r_i = 0.0, r_j = 0.0;
};

/// Each sphere's cap of the lens two spheres at overlap δ share (a plane: sphere i's cap of
/// height δ), and its rate d(cap)/dδ = π h (2r − h) dh/dδ [m³, m²].
struct LensCaps {
    double cap_i = 0.0, cap_j = 0.0;
    double rate_i = 0.0, rate_j = 0.0;
};

/// Cap of height h of a sphere of radius r: π h² (3r − h) / 3, and d/dh = π h (2r − h).
inline double sphere_cap(double r, double h) { return std::numbers::pi * h * h * (3 * r - h) / 3; }
inline double sphere_cap_rate(double r, double h) { return std::numbers::pi * h * (2 * r - h); }

/// The caps: the plane of the two spheres' intersection circle lies at x_i = (D² + r_i² − r_j²)
/// / 2D from i's centre, D = r_i + r_j − δ; h_i = r_i − x_i, h_j = r_j − (D − x_i), each kept
/// within its sphere (a sphere pressed wholly into the other).
inline LensCaps lens_caps(const ContactSpheres& s, double overlap) {
    if (overlap <= 0.0) return {};
    if (s.r_j == 0.0) {
        const double h = std::min(overlap, 2 * s.r_i);
        return {sphere_cap(s.r_i, h), 0.0, h < 2 * s.r_i ? sphere_cap_rate(s.r_i, h) : 0.0, 0.0};
    }
    const double d = std::max(s.r_i + s.r_j - overlap, 1e-3 * std::min(s.r_i, s.r_j));
    const double x_i = (d * d + s.r_i * s.r_i - s.r_j * s.r_j) / (2 * d);
    const double dx_dd = 0.5 - (s.r_i * s.r_i - s.r_j * s.r_j) / (2 * d * d);
    const double h_i = std::clamp(s.r_i - x_i, 0.0, 2 * s.r_i);
    const double h_j = std::clamp(s.r_j - (d - x_i), 0.0, 2 * s.r_j);
    // dh_i/dδ = dx_i/dD, dh_j/dδ = 1 − dx_i/dD (dD/dδ = −1); both sum to the lens' rate.
    return {sphere_cap(s.r_i, h_i), sphere_cap(s.r_j, h_j),
            sphere_cap_rate(s.r_i, h_i) * std::max(dx_dd, 0.0),
            sphere_cap_rate(s.r_j, h_j) * std::max(1.0 - dx_dd, 0.0)};
}

/// The share of an agglomerate's envelope that a lens takes when it has compacted the rest from
/// ε_0 to ε_min with the solid kept: V_l / V = 1 − (1 − ε_0) / (1 − ε_min) (0.6 for 0.75 → 0.383).
[[nodiscard]] inline double densest_lens_fraction(double initial_porosity,
                                                  double minimal_porosity) {
    return 1.0 - (1.0 - initial_porosity) / (1.0 - minimal_porosity);
}

/// An agglomerate's porosity after a lens of volume V_l is pressed into it, and dε/dδ for a lens
/// growing at dV_l/dδ; at and beyond ε_min: ε_min and 0.
struct LensPorosity {
    double porosity = 0.0;
    double rate = 0.0; ///< dε/dδ [1/m], ≤ 0
};
inline LensPorosity lens_porosity(const AgglomerateHardening& h, double radius, double lens,
                                  double lens_rate) {
    const double v = sphere_volume(radius);
    const double solid = 1.0 - h.initial_porosity;
    if (lens >= v * densest_lens_fraction(h.initial_porosity, h.minimal_porosity))
        return {h.minimal_porosity, 0.0};
    const double left = v - lens;
    return {1.0 - solid * v / left, -solid * v / (left * left) * lens_rate};
}

/// The contact's limiting pressure at its deepest overlap δ_max and dp_y/dδ_max (Pa, Pa/m), and
/// E*(δ_max) / E*_0.
struct HardenedYield {
    double pressure = 0.0;
    double slope = 0.0;
    double modulus_factor = 1.0;
};

/// E* / E*_0 with agglomerate sides at porosities ε_i, ε_j (a side that is not one: ε_0).
inline double hardened_modulus_factor(const AgglomerateHardening& h, double porosity_i,
                                      double porosity_j) {
    auto softening = [&](double porosity) { // s (1/ρ² − 1) of one side
        const double rho = (1.0 - porosity) / (1.0 - h.initial_porosity);
        return h.compliance_share * (1.0 / (rho * rho) - 1.0);
    };
    return 1.0 / (1.0 + softening(porosity_i) + softening(porosity_j));
}
inline HardenedYield hardened_yield(const AgglomerateHardening& h, double yield_pressure,
                                    const ContactSpheres& s, double max_overlap) {
    if (!h.hardens() || max_overlap <= 0.0) return {yield_pressure, 0.0};
    const LensCaps c = lens_caps(s, max_overlap);
    const bool both = h.sides == AgglomerateSides::both;
    const double lens = c.cap_i + c.cap_j, rate = c.rate_i + c.rate_j;
    const LensPorosity loose{h.initial_porosity, 0.0};
    const LensPorosity e_i =
        h.sides == AgglomerateSides::j
            ? loose
            : lens_porosity(h, s.r_i, both ? c.cap_i : lens, both ? c.rate_i : rate);
    const LensPorosity e_j =
        h.sides == AgglomerateSides::i
            ? loose
            : lens_porosity(h, s.r_j, both ? c.cap_j : lens, both ? c.rate_j : rate);
    // The softer agglomerate (the larger ε) sets p_y.
    const bool i_sets = h.sides == AgglomerateSides::i ||
                        (h.sides == AgglomerateSides::both && e_i.porosity >= e_j.porosity);
    const LensPorosity& e = i_sets ? e_i : e_j;
    const double per_porosity =
        (h.dense_yield_pressure - yield_pressure) / (h.initial_porosity - h.minimal_porosity);
    return {yield_pressure + per_porosity * (h.initial_porosity - e.porosity),
            -per_porosity * e.rate, hardened_modulus_factor(h, e_i.porosity, e_j.porosity)};
}

} // namespace drydem
