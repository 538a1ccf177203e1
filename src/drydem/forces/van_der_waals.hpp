// SPDX-License-Identifier: MIT
// Van der Waals attraction between two spheres: model.md M-3, paper Eq. 5 (Hamaker, Derjaguin
// sphere-sphere limit, valid for h ≪ R*).
//   h_e     = max(h, h_min)                       (also in overlap: the force stays finite)
//   F_vdW,i = + A^s R* / (6 h_e²) n   for h ≤ h_cut, else 0      (i is pulled toward j)
// A^s is the scaled Hamaker constant k·A (k = 1e7, M-7; NCM-CB 9.5e-20 J physical, C-12).
// h_cut defaults to the lubrication range r_L of the pair (C-13, chosen by the caller); no van der
// Waals with the substrate (C-14). Conservative and central: no torque.
#pragma once
#include "drydem/forces/pair_geometry.hpp"
#include <algorithm>

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

} // namespace drydem
