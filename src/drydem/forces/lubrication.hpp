// SPDX-License-Identifier: MIT
// Pair lubrication of the liquid film between two nearby spheres: model.md M-4.1-M-4.3; paper
// Eq. 6 (Kroupa et al. 2016 / Dance & Maxey 2003 squeeze term) times the Vinogradova (1995)
// factor Eq. 7; tangential and rotational terms from the leading equal-sphere resistance functions.
//   r_L = 2R* (C-15),  κ = h/r_L,  κ_e = max(κ, κ_c),  active for κ ≤ 1 (h ≤ r_L)
//   X(κ)   = 1/(4κ) - (9/40) ln κ - (3/112) κ ln κ
//   f*(κ)  = (κ/(3κ_c)) [(1 + κ/(6κ_c)) ln(1 + 6κ_c/κ) - 1]
//   F_nl,i = -6πη r_L X(κ_e) f*(κ_e) v_n n                       (f* on this term only, C-16)
//   L = ln(1/κ_e),  v_s = v_i - v_j + (c_i ω_i + c_j ω_j) × n,   F_tl,i = -πη r_L L (v_s)_⊥
//   T_i = c_i n × F_tl,i - 8πη r_L³ [(3/40) L (ω_r)_⊥ + (1/8) κ_e L (ω_r·n) n],  ω_r = ω_i - ω_j
//   T_j = c_j n × F_tl,i + 8πη r_L³ [(3/40) L (ω_r)_⊥ + (1/8) κ_e L (ω_r·n) n]
// Lever arms: c_i = r_i + h/2, c_j = r_j + h/2 (centres to the mid-plane of the gap; r - δ/2 in
// overlap, as in M-2.3). M-4.3 prints r_i, r_j; those differ by O(h) and give the pair moving as
// one rigid body a spurious sliding velocity -h Ω × n. With c_i + c_j = D the rigid-body check
// of M-4.3 / V-7 holds exactly, and so does conservation of angular momentum; for touching
// spheres both forms agree. Beyond κ = 1 the pair feels nothing (I-7: the normal force jumps
// there).
// Viscosity: as simulated (drying/scaling.cpp): the unreduced liquid η = 1.801 Pa s in the paper's
// scheme (C-17), η/b in force_ratio.
#pragma once
#include "drydem/forces/pair_geometry.hpp"
#include "drydem/forces/resistance.hpp"
#include "drydem/forces/law_limits.hpp"
#include <array>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string_view>

namespace drydem {

struct LubricationParams {
    double viscosity;   ///< η [Pa s]; 0 = off
    double kappa_c;     ///< κ_c = h_c / r_L: below it every coefficient is frozen
    double log_kappa_c; ///< ln κ_c, kept with κ_c by the constructor
    LubricationParams() : LubricationParams(0.0, 0.1) {}
    LubricationParams(double eta, double kc)
        : viscosity(eta), kappa_c(kc), log_kappa_c(std::log(kc)) {}
};

/// r_L = 2R* = 2 r_i r_j / (r_i + r_j) (C-15).
inline double lubrication_radius(double r_i, double r_j) { return 2.0 * r_i * r_j / (r_i + r_j); }

/// Squeeze resistance X(κ) of Eq. 6 in units of 6πη r_L (singular part of X^A_11), given ln κ.
inline double lubrication_x(double kappa, double log_kappa) {
    return 0.25 / kappa - (9.0 / 40.0) * log_kappa - (3.0 / 112.0) * kappa * log_kappa;
}
inline double lubrication_x(double kappa) { return lubrication_x(kappa, std::log(kappa)); }

/// Vinogradova slip factor f* of Eq. 7 with h/h_c = κ/κ_c. At κ_c (the frozen range) it is the
/// constant (1/3)[(7/6) ln 7 - 1] = 0.42341, which saves a logarithm per pair in contact (log
/// evaluations dominate the cost of a dense packing). ln(1 + 6/q) as ln((q + 6)/q) where that is
/// as exact (one rounding of the quotient: relative error ~1e-16 q/6, so up to q = 60, which
/// covers every pair at the default κ_c = 0.1): log costs 0.6× log1p (4.7 against 7.6 % of a
/// dense main-job film's steps, perf).
inline double vinogradova_factor(double kappa, double kappa_c) {
    constexpr double frozen = 0.42340950241039954;
    const double q = kappa / kappa_c;
    if (q == 1.0) return frozen;
    const double ln = q < 60.0 ? std::log((q + 6.0) / q) : std::log1p(6.0 / q);
    return (q / 3.0) * ((1.0 + q / 6.0) * ln - 1.0);
}

/// The law's resistance (resistance.hpp pair form): a_n = 6πη r_L X f*, a_t = πη r_L L,
/// a_r = 8πη r_L³ (3/40) L, a_w = 8πη r_L³ (1/8) κ_e L, levers r + h/2. Zero beyond κ = 1.
inline PairResistance lubrication_resistance(const PairGeometry& g, const LubricationParams& p) {
    if (p.viscosity <= 0.0) return {};
    const double r_l = 2.0 * g.r_eff;
    const double kappa = g.gap / r_l;
    if (kappa > 1.0) return {};
    const double k_e = std::max(kappa, p.kappa_c); // freeze below h_c and in overlap
    // Pairs in contact or within h_c all have κ_e = κ_c: their logarithm is the stored one (the
    // same bits), which saves a log per such pair (logs dominate the cost of a dense packing).
    const double log_k = k_e == p.kappa_c ? p.log_kappa_c : std::log(k_e), l = -log_k;
    const double pi_eta = std::numbers::pi * p.viscosity;
    const double rot = 8.0 * pi_eta * r_l * r_l * r_l * l;
    return {6.0 * pi_eta * r_l * lubrication_x(k_e, log_k) * vinogradova_factor(k_e, p.kappa_c),
            pi_eta * r_l * l,
            (3.0 / 40.0) * rot,
            0.125 * k_e * rot,
            g.r_i + 0.5 * g.gap,
            g.r_j + 0.5 * g.gap};
}

inline PairForce lubrication(const PairGeometry& g, const LubricationParams& p) {
    return resistance_force(lubrication_resistance(g, p), g.n, g.v_rel, g.omega_i, g.omega_j);
}

/// Largest gap h at which the law acts: r_L (h ≤ r_L); 0 when disabled.
inline double lubrication_range(const LubricationParams& p, double r_i, double r_j) {
    return p.viscosity > 0.0 ? lubrication_radius(r_i, r_j) : 0.0;
}

/// The law as a pair law (pair_law.hpp): purely dissipative, keeps nothing.
struct LubricationLaw {
    using Params = LubricationParams;
    struct State {};
    static constexpr std::string_view name = "lubrication";
    static constexpr std::array limits{
        ParamLimit<Params>{"viscosity", &Params::viscosity},
        ParamLimit<Params>{"kappa_c", &Params::kappa_c, 0.0, 1.0, true, false},
        ParamLimit<Params>{"log_kappa_c", &Params::log_kappa_c, -INFINITY, 0.0}};
    static double range(const Params& p, double r_i, double r_j) {
        return lubrication_range(p, r_i, r_j);
    }
    [[gnu::always_inline]] static inline void add_force(const PairGeometry& g, const Params& p,
                                                        State&, double, PairForce& f,
                                                        PairResistance* r) {
        // Off, or beyond κ = 1: nothing to add (the force of a zero resistance still costs ~60
        // flops a pair, 8 % of the peers' contact-only bed).
        if (p.viscosity <= 0.0 || g.gap / (2.0 * g.r_eff) > 1.0) return; // as in the resistance
        const PairResistance lub = lubrication_resistance(g, p);
        if (r) *r += lub;
        f += resistance_force(lub, g.n, g.v_rel, g.omega_i, g.omega_j);
    }
    static PairResistance resistance(const PairGeometry& g, const Params& p) {
        return lubrication_resistance(g, p);
    }
    static PairResistance stiffness(const PairGeometry&, const PairGeometry&, const Params&) {
        return {};
    }
    static bool keeps(const State&) { return false; }
};

} // namespace drydem
