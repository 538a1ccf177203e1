// SPDX-License-Identifier: MIT
// Reference clusters of the stability guard (docs/model.md "Stability guard"): the small
// packings in which the damping and stiffness rates of a drying film peak. `drydem check` runs
// the guard's own estimate on them, and the tests compare that estimate with the exact largest
// eigenvalue of the laws' operators.
#pragma once
#include "drydem/core/particles.hpp"
#include "drydem/drying/scaling.hpp"
#include "drydem/engine/simulation.hpp"
#include "drydem/setup/formulation.hpp"
#include <string>
#include <vector>

namespace drydem {

struct ReferenceCluster {
    std::string name;
    ParticleStore particles;
};

/// CB spheres (the recipe's CB species) and its largest NCM spheres, touching with overlap
/// `overlap` [m]: a CB on one NCM, a CB in the neck between two touching NCM, a close-packed fcc
/// cluster of 13 CB, and a CB on the substrate under an NCM. All but the last float far above
/// the substrate.
std::vector<ReferenceCluster> reference_clusters(const FilmRecipe& recipe, double overlap);

/// The run's engine (its force field, integrator and time-step cap, liquid level far above) on
/// one cluster; `skin` replaces the configured neighbour skin when ≥ 0.
Simulation cluster_simulation(const Config& c, const FilmRecipe& recipe, const ReferenceCluster& k,
                              double skin = -1.0);

/// The step the guard settles at on `sim` from its present step (the cap): guarded_time_step of
/// its estimate, and for the semi-implicit kick, whose rate depends on the step through
/// M + Δt D, iterated to the fixed point Δt ω(Δt) = 2 f as a run's guard settles over its
/// rebuilds. `e` receives the last estimate.
double settle_guarded_step(Simulation& sim, double cap, double fraction,
                           Simulation::StabilityEstimate& e);

/// The guard's estimate on one reference cluster and the step it gives.
struct ClusterEstimate {
    std::string name;
    Simulation::StabilityEstimate estimate;
    double dt = 0.0; ///< guarded_time_step(cap, estimate) [s]
};

/// The guard on every reference cluster, touching at 2 % of the CB radius, with `integrator`
/// ("explicit" or "semi_implicit") in place of the configured one: what `drydem check` prints and
/// load_config checks for finiteness. Semi-implicit: the step where the guard settles (its rate
/// depends on the step through M + Δt D), iterated from the cap as a run's guard does.
std::vector<ClusterEstimate> guard_on_reference_clusters(const Config& c, const FilmRecipe& recipe,
                                                         const std::string& integrator);

} // namespace drydem
