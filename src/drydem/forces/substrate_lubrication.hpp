// SPDX-License-Identifier: MIT
// Lubrication between a particle and the substrate: model.md M-4.4, sphere-plane near-contact
// asymptotics (Cox & Brenner 1967, Goldman, Cox & Brenner 1967) with the Vinogradova factor
// (Eq. 7) on the normal term.
//   h = z - r, κ = h/r, κ_e = max(κ, κ_c), active for κ ≤ 1, L = ln(1/κ_e)
//   X_w = 1/κ_e - (1/5) ln κ_e - (1/21) κ_e ln κ_e
//   A_w = (8/15) L + (64/375) κ_e L,  B_w = (2/15) L + (86/375) κ_e L,
//   D_w = (2/5) L + (66/125) κ_e L
//   F = -6πη r X_w f* v_z ẑ - 6πη r A_w v_t + 6πη r² B_w (ω × ẑ)
//   T =  6πη r² B_w (ẑ × v_t) - 8πη r³ D_w ω_t - 8πη r³ (1/2) κ_e L ω_z ẑ
//   The two coupling terms share 6πη r² B_w, so the resistance matrix is symmetric (dissipative).
#pragma once
#include "drydem/forces/body_law.hpp"
#include "drydem/forces/law_limits.hpp"
#include "drydem/forces/lubrication.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string_view>

namespace drydem {

struct SubstrateLubricationParams {
    double viscosity = 0.0; ///< η [Pa s], as simulated (C-17); 0 = off
    double kappa_c = 0.1;   ///< κ_c = h_c / r
};

/// Squeeze resistance X_w(κ) in units of 6πη r (sphere-plane), given ln κ.
inline double substrate_lubrication_x(double kappa, double log_kappa) {
    return 1.0 / kappa - 0.2 * log_kappa - (1.0 / 21.0) * kappa * log_kappa;
}
inline double substrate_lubrication_x(double kappa) {
    return substrate_lubrication_x(kappa, std::log(kappa));
}

/// The law's resistance (resistance.hpp body form): a_z = 6πη r X_w f*, a_t = 6πη r A_w,
/// b = 6πη r² B_w, d_t = 8πη r³ D_w, d_z = 8πη r³ κ_e L / 2. Zero beyond κ = 1.
inline BodyResistance substrate_lubrication_resistance(double z, double r,
                                                       const SubstrateLubricationParams& p) {
    if (p.viscosity <= 0.0) return {};
    const double kappa = (z - r) / r;
    if (kappa > 1.0) return {};
    const double k_e = std::max(kappa, p.kappa_c);
    const double log_k = std::log(k_e), l = -log_k;
    const double a_w = (8.0 / 15.0) * l + (64.0 / 375.0) * k_e * l;
    const double b_w = (2.0 / 15.0) * l + (86.0 / 375.0) * k_e * l;
    const double d_w = 0.4 * l + (66.0 / 125.0) * k_e * l;
    const double c_f = 6.0 * std::numbers::pi * p.viscosity * r;         // 6πη r
    const double c_r = 8.0 * std::numbers::pi * p.viscosity * r * r * r; // 8πη r³
    return {c_f * substrate_lubrication_x(k_e, log_k) * vinogradova_factor(k_e, p.kappa_c),
            c_f * a_w, c_f * r * b_w, c_r * d_w, c_r * 0.5 * k_e * l};
}

inline BodyForce substrate_lubrication(double z, double r, const Vec3& v, const Vec3& omega,
                                       const SubstrateLubricationParams& p) {
    return resistance_force(substrate_lubrication_resistance(z, r, p), v, omega);
}

/// Largest gap z - r at which the substrate lubrication acts: r; 0 when disabled.
inline double substrate_lubrication_range(const SubstrateLubricationParams& p, double r) {
    return p.viscosity > 0.0 ? r : 0.0;
}

/// The law as a body law (body_law.hpp): purely dissipative, keeps nothing.
struct SubstrateLubricationLaw {
    using Params = SubstrateLubricationParams;
    struct State {};
    static constexpr std::string_view name = "substrate_lubrication";
    static constexpr std::array limits{
        ParamLimit<Params>{"viscosity", &Params::viscosity},
        ParamLimit<Params>{"kappa_c", &Params::kappa_c, 0.0, 1.0, true, false}};

    [[gnu::always_inline]] static inline void add_force(const BodyGeometry& g, const Params& p,
                                                        State&, double, BodyForce& f,
                                                        BodyResistance* r) {
        const BodyResistance lub = substrate_lubrication_resistance(g.x.z, g.r, p);
        if (lub.normal == 0.0) return; // off, or beyond κ = 1: adds nothing (not zeros)
        if (r) *r += lub;
        f += resistance_force(lub, g.v, g.omega);
    }
    /// At the narrowest gap within g.reach (the resistance grows as the gap closes).
    static BodyResistance resistance(const BodyGeometry& g, const Params& p) {
        return substrate_lubrication_resistance(g.x.z - g.reach, g.r, p);
    }
    static BodyResistance stiffness(const BodyGeometry&, const Params&) { return {}; }
    static bool keeps(const State&) { return false; }
};

} // namespace drydem
