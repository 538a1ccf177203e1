// SPDX-License-Identifier: MIT
// Extrusion of a carbon-binder agglomerate out of the gaps of dense partners, model.md M-2.13, for
// calendering. A contact with a dense partner (an NCM particle, the substrate, the plate) takes
// its whole lens V_l from the agglomerate's envelope; M-2.12 reads that as pore space pressed out,
// until the rest of the envelope holds the agglomerate's solid at its densest, ε_min. Past that
// no pore is left to press out: the dense carbon-binder domain flows, out of the gap and into the
// pores beside it. A sphere cannot change its shape, so the flow is taken whole when the dense
// partners' lenses together pass that point:
//   Σ_dense V_l ≥ V (1 − (1 − ε_0) / (1 − ε_min))                 the agglomerate is past its densest
// and its solid then joins the nearest agglomerates that have pore room, nearest first:
//   room_k = (ε_k − ε_min) V_k                                     solid volume k can take in
//   ε_k ← ε_k − t_k / V_k,  Σ t_k = (1 − ε) V                     solid and mass kept, envelopes kept
// The extruded sphere leaves the packing. ε_0 is the as-dried porosity, as in M-2.12, so an
// agglomerate extrudes at the depth where its hardening contact reached p_d: for one contact on a
// plane a cap of height 1.13 r (0.75 → 0.383). The receivers keep their radius (no new overlap);
// their density rises with the solid they take in.
#pragma once
#include "drydem/core/sphere.hpp"
#include "drydem/forces/agglomerate_hardening.hpp"
#include <algorithm>
#include <vector>

namespace drydem {

struct AgglomerateExtrusionParams {
    double initial_porosity = 0.75; ///< ε_0, the agglomerate as dried (formulation.cb_porosity)
    double minimal_porosity = 0.5;  ///< ε_min < ε_0, the densest carbon-binder domain
    bool on = false;                ///< calendering.cb_extrusion
};

/// The envelope volume that one dense partner at overlap δ takes from an agglomerate of radius
/// r_agg: the two spheres' whole lens (r_partner = 0: a plane, the agglomerate's cap of height δ).
[[nodiscard]] inline double dense_lens(double r_agg, double r_partner, double overlap) {
    const LensCaps c = lens_caps({r_agg, r_partner}, overlap);
    return c.cap_i + c.cap_j;
}

/// True when the dense partners' lenses, summed, have pressed the agglomerate past its densest.
[[nodiscard]] inline bool extruded(const AgglomerateExtrusionParams& p, double radius,
                                   double dense_lenses) {
    return p.on &&
           dense_lenses >= sphere_volume(radius) *
                               densest_lens_fraction(p.initial_porosity, p.minimal_porosity);
}

/// The solid volume an agglomerate of radius r at inner porosity ε can still take into its pores.
[[nodiscard]] inline double pore_room(const AgglomerateExtrusionParams& p, double radius,
                                      double porosity) {
    return std::max(0.0, (porosity - p.minimal_porosity) * sphere_volume(radius));
}

/// How an extruded solid volume is shared: `room` lists the candidates' pore room, nearest first;
/// the result gives each the solid volume it takes (nearest filled first) and what found no room.
struct ExtrusionShares {
    std::vector<double> taken;
    double left = 0.0;
};
[[nodiscard]] inline ExtrusionShares share_extruded_solid(double solid,
                                                          const std::vector<double>& room) {
    ExtrusionShares s{std::vector<double>(room.size(), 0.0), solid};
    for (std::size_t k = 0; k < room.size() && s.left > 0.0; ++k) {
        s.taken[k] = std::min(room[k], s.left);
        s.left -= s.taken[k];
    }
    return s;
}

} // namespace drydem
