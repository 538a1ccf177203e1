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

} // namespace drydem
