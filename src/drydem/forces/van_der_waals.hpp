// SPDX-License-Identifier: MIT
// Van der Waals attraction between two spheres: model.md M-3, paper Eq. 5 (Hamaker, Derjaguin
// sphere-sphere limit, valid for h ≪ R*).
//   h_e     = max(h, h_min)                       (also in overlap: the force stays finite)
//   F_vdW,i = + A^s R* / (6 h_e²) n   for h ≤ h_cut, else 0      (i is pulled toward j)
// A^s is the Hamaker constant as simulated (M-7: k·A in the paper's scheme; NCM-CB 9.5e-20 J
// physical, C-12); the law receives it scaled (drying/scaling.cpp) and applies no factor.
// h_cut defaults to the lubrication range r_L of the pair (C-13, chosen by the caller); no van der
// Waals with the substrate (C-14). Conservative and central: no torque.
#pragma once
#include "drydem/forces/pair_geometry.hpp"
#include "drydem/forces/resistance.hpp"
#include "drydem/forces/law_limits.hpp"
#include <array>
#include <algorithm>
#include <string_view>

namespace drydem {

struct VanDerWaalsParams {
    double hamaker = 0.0;    ///< scaled Hamaker constant A^s [J]; 0 = off
    double min_gap = 0.0;    ///< h_min [m], > 0 when enabled (5 / 10 / 50 nm, M-3 table)
    double cutoff_gap = 0.0; ///< h_cut [m] (C-13: r_L of the pair)
};

inline PairForce van_der_waals(const PairGeometry& g, const VanDerWaalsParams& p) {
    if (p.hamaker == 0.0 || g.gap > p.cutoff_gap) return {};
    const double h_e = std::max(g.gap, p.min_gap);
    return {(p.hamaker * g.r_eff / (6.0 * h_e * h_e)) * g.n, {}, {}};
}

/// Largest gap h at which the law acts (for the neighbour search); 0 when disabled.
inline double van_der_waals_range(const VanDerWaalsParams& p, double /*r_i*/, double /*r_j*/) {
    return p.hamaker != 0.0 ? p.cutoff_gap : 0.0;
}

/// |dF/dh| = A^s R* / (3 h_e³), h_e = max(h, h_min), for 0 ≤ h ≤ h_cut: the snap-in's rate; below
/// h_min the force is constant and h_min's value is kept as a bound; 0 in overlap and beyond h_cut.
inline double van_der_waals_stiffness(const PairGeometry& g, const VanDerWaalsParams& p) {
    if (p.hamaker == 0.0 || g.gap < 0.0 || g.gap > p.cutoff_gap) return 0.0;
    const double h = std::max(g.gap, p.min_gap);
    return p.hamaker * g.r_eff / (3.0 * h * h * h);
}

/// The law as a pair law (pair_law.hpp): conservative, keeps nothing.
struct VanDerWaalsLaw {
    using Params = VanDerWaalsParams;
    struct State {};
    static constexpr std::string_view name = "van_der_waals";
    static constexpr std::array limits{ParamLimit<Params>{"hamaker", &Params::hamaker},
                                       ParamLimit<Params>{"min_gap", &Params::min_gap},
                                       ParamLimit<Params>{"cutoff_gap", &Params::cutoff_gap}};
    static double range(const Params& p, double r_i, double r_j) {
        return van_der_waals_range(p, r_i, r_j);
    }
    /// Central: only the force, no torques to add; `tangent` receives the snap-in's rate at the
    /// present gap (as `stiffness` below).
    [[gnu::always_inline]] static inline void add_force(const PairGeometry& g, const Params& p,
                                                        State&, double, PairForce& f,
                                                        PairResistance*,
                                                        PairResistance* tangent = nullptr) {
        if (p.hamaker == 0.0 || g.gap > p.cutoff_gap) return;
        f.force_i += van_der_waals(g, p).force_i;
        if (tangent) tangent->normal += van_der_waals_stiffness(g, p);
    }
    static PairResistance resistance(const PairGeometry&, const Params&) { return {}; }
    /// The snap-in at the present gap: its stiffness is negative (the attraction grows as the gap
    /// closes), so it cannot make the kick unstable, only the snap inaccurate; |dF/dh| bounds the
    /// snap's growth rate (docs/model.md "Stability guard"). Taken at the skin-reduced gap it
    /// would put every pair within the skin at h_min and hold the step far below what the
    /// contacts need.
    static PairResistance stiffness(const PairGeometry&, const PairGeometry& now, const Params& p) {
        return {van_der_waals_stiffness(now, p), 0.0, 0.0, 0.0, 0.0, 0.0};
    }
    static bool keeps(const State&) { return false; }
};

} // namespace drydem
