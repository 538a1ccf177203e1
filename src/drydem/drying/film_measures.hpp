// SPDX-License-Identifier: MIT
// Measures of the film read off the particles during a run (time series, summary).
#pragma once
#include "drydem/analysis/overlap_census.hpp"
#include "drydem/analysis/structure.hpp"
#include "drydem/core/box.hpp"
#include "drydem/core/particles.hpp"
#include "drydem/forces/force_field.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace drydem {

/// Quantile q of the particle tops z + r; q = 0.99 is a robust thickness that ignores stray
/// particles. 0 for no particles.
inline double top_percentile(const ParticleStore& p, double q) {
    std::vector<double> tops(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) tops[i] = p.position[i].z + p.radius[i];
    if (tops.empty()) return 0.0;
    const std::size_t k = std::min(tops.size() - 1, std::size_t(q * double(tops.size())));
    std::nth_element(tops.begin(), tops.begin() + std::ptrdiff_t(k), tops.end());
    return tops[k];
}

/// Particles that the liquid level at height `level` cuts.
inline std::size_t particles_cutting_level(const ParticleStore& p, double level) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < p.size(); ++i) n += std::abs(level - p.position[i].z) < p.radius[i];
    return n;
}

/// The level's load on the film, measured on the particles (docs/model.md "Dimensionless groups"):
///   push number  Π = U Σ_{z_i < level} 6π η_d r_i / Σ_{i in the level} F_cap(r_i)
///                (the drag of the submerged film carried at the level speed U over the most the
///                particles in the level can push, F_cap = 2πσ r cos²(θ/2))
///   inertial     I = (U / level) d sqrt(ρ A / Σ_{i in the level} F_cap(r_i)), d and ρ of the
///                largest particle
/// Both 0 while no particle is in the level (it carries nothing).
struct LevelLoad {
    double push_number = 0.0, inertial_number = 0.0;
};
inline LevelLoad level_load(const ParticleStore& p, const ForceField& ff, double level,
                            double level_speed, double base_area) {
    double drag = 0.0, push = 0.0, d = 0.0, rho = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double r = p.radius[i], z = p.position[i].z;
        const BodyParams& body = ff.body_params(p.species[i]);
        if (z < level) drag += stokes_drag_coefficient(r, law<StokesDragLaw>(body));
        if (std::abs(level - z) < r) push += capillary_max_force(r, law<CapillaryFrontLaw>(body));
        if (2.0 * r > d) {
            d = 2.0 * r;
            rho = p.density[i];
        }
    }
    if (!(push > 0.0) || !(level > 0.0)) return {};
    return {level_speed * drag / push,
            (level_speed / level) * d * std::sqrt(rho * base_area / push)};
}

/// The particles as the structure analysis sees them (species `cb_species` is CB, the rest NCM).
inline analysis::Structure as_structure(const ParticleStore& p, const Box& box, int cb_species) {
    analysis::Structure s;
    s.box = box;
    for (std::size_t i = 0; i < p.size(); ++i)
        s.add(p.position[i], p.radius[i],
              p.species[i] == cb_species ? analysis::Phase::cb : analysis::Phase::ncm,
              p.density[i]);
    return s;
}

} // namespace drydem
