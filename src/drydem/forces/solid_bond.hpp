// SPDX-License-Identifier: MIT
// Solid bond of the carbon-binder domain, model.md M-2.10: the parallel bond of Potyondy and
// Cundall (Int. J. Rock Mech. Min. Sci. 41 (2004) 1329), a cylinder of binder of radius
// r_b = λ min(r_i, r_j) between the two centres, of rest length L₀ (their distance when it
// formed), which carries force and moment in every direction until it breaks:
//   k̄_n = E_b / L₀,   k̄_s = G_b / L₀        stiffness per bond area [N/m³]
//   A = π r_b²,   I = π r_b⁴ / 4,   J = 2 I
//   F_i  = k̄_n A (D − L₀) n − k̄_s A u_s          u̇_s = v_t, the contact point's tangential velocity
//   T_i  = c_i n × F_s − k̄_n I θ_b − k̄_s J θ_t n   θ̇_b = (ω_i − ω_j)_⊥,  θ̇_t = (ω_i − ω_j)·n
//   T_j  = c_j n × F_s + k̄_n I θ_b + k̄_s J θ_t n
// u_s and θ_b turn with the pair's normal (as the contact's tangential spring, M-2.3); c_i, c_j
// are the lever arms to the mid-plane of the gap. The elastic stresses at the bond's rim and the
// combined strength criterion (the bond breaks, for good, when it holds):
//   σ = k̄_n (D − L₀) + k̄_n r_b |θ_b|      (tension positive: stretch plus bending)
//   τ = k̄_s |u_s| + k̄_s r_b |θ_t|         (shear plus twist)
//   max(σ, 0) / σ_c + τ / τ_c ≥ 1
// Potyondy and Cundall's two separate criteria (σ ≥ σ_c or τ ≥ τ_c) joined so that a bond loaded
// both ways breaks sooner, as the combined criterion of LAMMPS bond_style bpm/rotational (there
// on forces and moments). Viscous damping with ratio β_b on every mode:
//   a_n = 2 β_b sqrt(m* k̄_n A), a_t = 2 β_b sqrt(m* k̄_s A),
//   a_r = 2 β_b sqrt(I* k̄_n I),  a_w = 2 β_b sqrt(I* k̄_s J),  I* = (2/5) m* min(r_i, r_j)²
// (I* is the reduced moment of inertia I_i I_j / (I_i + I_j) of two equal spheres, (2/5) m r²/2,
// and of a small sphere on a large one, I_small; (2/5) m* r_i r_j would overdamp a CB sphere's
// rotation on an NCM particle √(r_NCM / r_CB)-fold and lower the explicit step). A bond acts
// beside the pair laws (a bonded pair that overlaps is also a contact); it is kept in the
// engine's bond network (engine/bond_network.hpp), not in the neighbour list, because its state
// outlives any gap until it breaks.
#pragma once
#include "drydem/forces/law_limits.hpp"
#include "drydem/forces/pair_geometry.hpp"
#include "drydem/forces/resistance.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string_view>

namespace drydem {

/// The bond of one species pair; youngs_modulus = 0 means the pair never bonds.
struct SolidBondParams {
    double youngs_modulus = 0.0;   ///< E_b of the binder bridge [Pa]
    double shear_modulus = 0.0;    ///< G_b [Pa]
    double radius_ratio = 0.0;     ///< λ: r_b = λ min(r_i, r_j)
    double tensile_strength = 0.0; ///< σ_c [Pa]
    double shear_strength = 0.0;   ///< τ_c [Pa]
    double damping_ratio = 0.0;    ///< β_b
};

/// What a bond keeps: its rest length and the accumulated shear, bending and twist.
struct SolidBondState {
    Vec3 shear;               ///< u_s [m]
    Vec3 bending;             ///< θ_b [rad]
    double twist = 0.0;       ///< θ_t [rad]
    double rest_length = 0.0; ///< L₀ [m]; 0 before it formed
    bool broken = false;      ///< it broke: no force from then on
    [[nodiscard]] bool intact() const { return rest_length > 0.0 && !broken; }
};

/// The bond's cross-section: r_b, A, I, J.
struct BondSection {
    double radius, area, inertia, polar;
};
inline BondSection bond_section(const SolidBondParams& p, double r_i, double r_j) {
    const double rb = p.radius_ratio * std::min(r_i, r_j);
    const double rb2 = rb * rb;
    const double inertia = 0.25 * std::numbers::pi * rb2 * rb2;
    return {rb, std::numbers::pi * rb2, inertia, 2.0 * inertia};
}

/// The bond's spring constants (pair form of resistance.hpp: N/m for normal and sliding, N m/rad
/// for rolling and twisting) at rest length L₀, with the lever arms of the geometry g.
inline PairResistance solid_bond_stiffness(const PairGeometry& g, const SolidBondParams& p,
                                           double rest_length) {
    const BondSection b = bond_section(p, g.r_i, g.r_j);
    const double kn = p.youngs_modulus / rest_length, ks = p.shear_modulus / rest_length;
    return {kn * b.area,  ks * b.area,         kn * b.inertia,
            ks * b.polar, g.r_i + 0.5 * g.gap, g.r_j + 0.5 * g.gap};
}

/// Its damping (pair form) at rest length L₀.
inline PairResistance solid_bond_resistance(const PairGeometry& g, const SolidBondParams& p,
                                            double rest_length) {
    const PairResistance k = solid_bond_stiffness(g, p, rest_length);
    const double r_min = std::min(g.r_i, g.r_j);
    const double m = g.m_eff, inertia = 0.4 * g.m_eff * r_min * r_min;
    const double two_beta = 2.0 * p.damping_ratio;
    return {two_beta * std::sqrt(m * k.normal),
            two_beta * std::sqrt(m * k.sliding),
            two_beta * std::sqrt(inertia * k.rolling),
            two_beta * std::sqrt(inertia * k.twisting),
            k.lever_i,
            k.lever_j};
}

/// The elastic stresses at the bond's rim (header): σ (tension positive) and τ [Pa].
struct BondStress {
    double tensile = 0.0, shear = 0.0;
};
inline BondStress solid_bond_stress(const PairGeometry& g, const SolidBondParams& p,
                                    const SolidBondState& s) {
    const double rb = bond_section(p, g.r_i, g.r_j).radius;
    const double kn = p.youngs_modulus / s.rest_length, ks = p.shear_modulus / s.rest_length;
    return {kn * (g.distance - s.rest_length) + kn * rb * norm(s.bending),
            ks * norm(s.shear) + ks * rb * std::abs(s.twist)};
}

/// The combined criterion max(σ, 0)/σ_c + τ/τ_c: the bond breaks at 1.
inline double solid_bond_failure(const BondStress& st, const SolidBondParams& p) {
    return std::max(st.tensile, 0.0) / p.tensile_strength + st.shear / p.shear_strength;
}

/// Advances the bond by dt, breaks it when the criterion is met, and returns its force and
/// torques (elastic plus damping; nothing once broken). `damping` receives its resistance.
inline PairForce solid_bond(const PairGeometry& g, const SolidBondParams& p, SolidBondState& s,
                            double dt, PairResistance* damping = nullptr) {
    if (!s.intact()) return {};
    const Vec3& n = g.n;
    const PairResistance k = solid_bond_stiffness(g, p, s.rest_length);
    const Vec3 w_r = g.omega_i - g.omega_j;
    const Vec3 v_c = g.v_rel + cross(k.lever_i * g.omega_i + k.lever_j * g.omega_j, n);
    s.shear = onto_plane(s.shear, n) + perp(v_c, n) * dt;
    s.bending = onto_plane(s.bending, n) + perp(w_r, n) * dt;
    s.twist += dot(w_r, n) * dt;
    if (solid_bond_failure(solid_bond_stress(g, p, s), p) >= 1.0) {
        s.broken = true;
        return {};
    }
    const Vec3 f_shear = -k.sliding * s.shear;
    const Vec3 lever = cross(n, f_shear);
    const Vec3 moment = -k.rolling * s.bending - (k.twisting * s.twist) * n; // on i
    PairForce f{k.normal * (g.distance - s.rest_length) * n + f_shear, k.lever_i * lever + moment,
                k.lever_j * lever - moment};
    const PairResistance c = solid_bond_resistance(g, p, s.rest_length);
    if (p.damping_ratio > 0.0) f += resistance_force(c, n, g.v_rel, g.omega_i, g.omega_j);
    if (damping) *damping += c;
    return f;
}

/// The bond as a pair law (pair_law.hpp contract): a bond has no reach of its own (range 0): it
/// joins the pair it was made for, at any distance, until it breaks; the bond network, not the
/// neighbour list, holds it. Where the contract gives no state, L₀ is taken as the present
/// distance (within the bond's small strain of it).
struct SolidBondLaw {
    using Params = SolidBondParams;
    using State = SolidBondState;
    static constexpr std::string_view name = "solid_bond";
    static constexpr std::array limits{
        ParamLimit<Params>{"youngs_modulus", &Params::youngs_modulus},
        ParamLimit<Params>{"shear_modulus", &Params::shear_modulus},
        ParamLimit<Params>{"radius_ratio", &Params::radius_ratio, 0.0, 1.0},
        ParamLimit<Params>{"tensile_strength", &Params::tensile_strength, 0.0, INFINITY, true},
        ParamLimit<Params>{"shear_strength", &Params::shear_strength, 0.0, INFINITY, true},
        ParamLimit<Params>{"damping_ratio", &Params::damping_ratio, 0.0, 1.0}};
    static double range(const Params&, double, double) { return 0.0; }
    static void add_force(const PairGeometry& g, const Params& p, State& s, double dt, PairForce& f,
                          PairResistance* damping) {
        if (s.intact()) f += solid_bond(g, p, s, dt, damping);
    }
    static PairResistance resistance(const PairGeometry& g, const Params& p) {
        return p.youngs_modulus > 0.0 ? solid_bond_resistance(g, p, g.distance) : PairResistance{};
    }
    static PairResistance stiffness(const PairGeometry&, const PairGeometry& now, const Params& p) {
        return p.youngs_modulus > 0.0 ? solid_bond_stiffness(now, p, now.distance)
                                      : PairResistance{};
    }
    static bool keeps(const State& s) { return s.intact(); }
};

} // namespace drydem
