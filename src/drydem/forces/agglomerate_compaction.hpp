// SPDX-License-Identifier: MIT
// Compaction of a carbon-binder agglomerate under load, model.md M-2.11. A CB sphere is an
// agglomerate of carbon black and binder whose envelope holds inner pores (formulation.cb_porosity,
// M-1.3). Pressed hard enough, the carbon-binder domain compacts: its inner porosity falls, its
// solid stays, so its envelope shrinks. With σ the agglomerate's mean stress from its contacts
// (Love-Weber over its own volume, compression positive; Simulation::particle_mean_stress):
//   ε*(σ) = ε_min + (ε_0 − ε_min) exp(−σ / p_c)       the inner porosity that σ compacts to
//   ε    ← min(ε, ε*(σ))                               plastic: the pores never reopen
//   r    ← r ((1 − ε) / (1 − ε'))^{1/3}                solid kept (core/sphere.hpp envelope_ratio)
// The exponential is the form of a powder's (and a whole electrode's) compaction curve; ε_0 is the
// agglomerate as dried, ε_min the densest carbon-binder domain, p_c its compaction pressure. The
// binder sits in the agglomerate's pores (M-8.4), b = binder volume per carbon volume, so the
// pores cannot close below the binder's share: ε_min ≥ b / (1 + b), the binder-filled domain.
// The mass is kept, so a compacted sphere's density rises as 1/r³; that density is what the
// particle file carries, and the agglomerate's inner porosity follows from it:
//   1 − ε = (1 − ε_0) ρ / ρ_0                         ρ_0 the agglomerate's density as dried
// Its elastic contacts unload as the envelope gives way: the springback is theirs alone.
#pragma once
#include "drydem/core/sphere.hpp"
#include <algorithm>
#include <cmath>

namespace drydem {

struct AgglomerateCompactionParams {
    double initial_porosity = 0.75; ///< ε_0, the agglomerate as dried (formulation.cb_porosity)
    double minimal_porosity = 0.5;  ///< ε_min < ε_0, ≥ the binder-filled porosity
    double pressure = 0.0;          ///< p_c [Pa]; 0 = the agglomerate does not compact

    [[nodiscard]] bool compacts() const { return pressure > 0.0; }
};

/// b / (1 + b): the inner porosity of an agglomerate whose pores hold only its binder, b the binder
/// volume per carbon volume (setup/solids.hpp binder_volume_per_carbon).
[[nodiscard]] inline double binder_filled_porosity(double binder_per_carbon) {
    return binder_per_carbon / (1.0 + binder_per_carbon);
}

/// ε' = min(ε, ε*(σ)): the inner porosity after the mean stress σ [Pa] on an agglomerate at ε.
[[nodiscard]] inline double compacted_porosity(const AgglomerateCompactionParams& p,
                                               double porosity, double mean_stress) {
    if (!p.compacts() || !(mean_stress > 0.0)) return porosity;
    const double target = p.minimal_porosity + (p.initial_porosity - p.minimal_porosity) *
                                                   std::exp(-mean_stress / p.pressure);
    return std::min(porosity, target);
}

/// The radius of an agglomerate of radius r at porosity ε once it is at porosity ε'.
[[nodiscard]] inline double compacted_radius(double radius, double porosity, double new_porosity) {
    return radius * std::cbrt(envelope_ratio(porosity, new_porosity));
}

/// The inner porosity of an agglomerate of density ρ, dried at ε_0 with density ρ_0.
[[nodiscard]] inline double agglomerate_porosity(double dried_porosity, double density,
                                                 double dried_density) {
    return 1.0 - (1.0 - dried_porosity) * density / dried_density;
}

} // namespace drydem
