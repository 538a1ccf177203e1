// SPDX-License-Identifier: MIT
#include "drydem/drying/law_parameters.hpp"
#include "drydem/drying/stability_clusters.hpp"
#include "drydem/drying/stability_guard.hpp"
#include <algorithm>
#include <cmath>

namespace drydem {

std::vector<ReferenceCluster> reference_clusters(const FilmRecipe& recipe, double overlap) {
    const int cb = recipe.cb_species();
    int ncm = 0; // the largest NCM class
    for (int s = 0; s < cb; ++s)
        if (recipe.species[s].diameter > recipe.species[ncm].diameter) ncm = s;
    const double rc = 0.5 * recipe.species[cb].diameter, rn = 0.5 * recipe.species[ncm].diameter;
    const double rho_c = recipe.species[cb].density, rho_n = recipe.species[ncm].density;
    const double x0 = 20e-6, y0 = 20e-6, z0 = 30e-6; // far from the substrate
    std::vector<ReferenceCluster> out;

    ReferenceCluster on_ncm{"CB on one NCM", {}};
    on_ncm.particles.add(1, std::uint8_t(ncm), rn, rho_n, {x0, y0, z0});
    on_ncm.particles.add(2, std::uint8_t(cb), rc, rho_c, {x0, y0, z0 + rn + rc - overlap});
    out.push_back(std::move(on_ncm));

    ReferenceCluster neck{"CB between two NCM", {}};
    const double a = rn - 0.5 * overlap; // half the NCM-NCM centre distance (touching)
    const double y = std::sqrt(std::pow(rn + rc - overlap, 2) - a * a);
    neck.particles.add(1, std::uint8_t(ncm), rn, rho_n, {x0 - a, y0, z0});
    neck.particles.add(2, std::uint8_t(ncm), rn, rho_n, {x0 + a, y0, z0});
    neck.particles.add(3, std::uint8_t(cb), rc, rho_c, {x0, y0 + y, z0});
    out.push_back(std::move(neck));

    ReferenceCluster fcc{"fcc cluster of 13 CB", {}};
    const double d = (2.0 * rc - overlap) / std::sqrt(2.0); // nearest neighbours at 2r - δ
    fcc.particles.add(1, std::uint8_t(cb), rc, rho_c, {x0, y0, z0});
    std::uint32_t id = 2;
    for (int u = -1; u <= 1; u += 2)
        for (int v = -1; v <= 1; v += 2) {
            fcc.particles.add(id++, std::uint8_t(cb), rc, rho_c, {x0 + u * d, y0 + v * d, z0});
            fcc.particles.add(id++, std::uint8_t(cb), rc, rho_c, {x0 + u * d, y0, z0 + v * d});
            fcc.particles.add(id++, std::uint8_t(cb), rc, rho_c, {x0, y0 + u * d, z0 + v * d});
        }
    out.push_back(std::move(fcc));

    ReferenceCluster wall{"CB on the substrate under an NCM", {}};
    const double zc = rc - overlap;
    wall.particles.add(1, std::uint8_t(cb), rc, rho_c, {x0, y0, zc});
    wall.particles.add(2, std::uint8_t(ncm), rn, rho_n, {x0, y0, zc + rc + rn - overlap});
    out.push_back(std::move(wall));
    return out;
}

Simulation cluster_simulation(const Config& c, const FilmRecipe& recipe, const ReferenceCluster& k,
                              double skin) {
    EngineSettings es;
    es.integrator = integrator_of(c);
    es.implicit_stiffness = c.implicit_stiffness_on();
    es.dt = c.time_step_cap();
    es.skin = skin >= 0.0 ? skin : c.neighbor_skin();
    es.threads = 1;
    return Simulation(k.particles, Box{std::max(c.box_x, 60e-6), std::max(c.box_y, 60e-6)},
                      make_drying_force_field(c, recipe, scale_parameters(c)), es);
}

double settle_guarded_step(Simulation& sim, double cap, double fraction,
                           Simulation::StabilityEstimate& e) {
    e = sim.stability_estimate();
    double dt = guarded_time_step(cap, e, fraction);
    if (sim.settings().integrator != Integrator::semi_implicit) return dt;
    // The rate is that of M + Δt D, so it depends on the step; a run's guard re-estimates at
    // every rebuild and settles where Δt ω(Δt) = 2 f. Iterated from the cap, the steps fall
    // monotonically to that fixed point (ω falls as Δt grows).
    for (int it = 0; it < 50; ++it) {
        // A step that is not positive and finite is left for the caller to refuse.
        if (!(dt > 0.0 && std::isfinite(dt)) || std::abs(dt - sim.settings().dt) <= 1e-3 * dt)
            break;
        sim.set_time_step(dt);
        e = sim.stability_estimate();
        dt = guarded_time_step(cap, e, fraction);
    }
    return dt;
}

std::vector<ClusterEstimate> guard_on_reference_clusters(const Config& c, const FilmRecipe& recipe,
                                                         const std::string& integrator) {
    Config ci = c;
    ci.integrator = integrator;
    const double overlap = 0.02 * 0.5 * recipe.species[std::size_t(recipe.cb_species())].diameter;
    const ScaledParameters scaled = scale_parameters(c);
    const double fraction = critical_fraction_for(c, integrator);
    std::vector<ClusterEstimate> out;
    for (ReferenceCluster& k : reference_clusters(recipe, overlap)) {
        scale_cb_inertia(k.particles, recipe, scaled);
        Simulation sim = cluster_simulation(ci, recipe, k);
        Simulation::StabilityEstimate e;
        const double dt = settle_guarded_step(sim, ci.time_step_cap(), fraction, e);
        out.push_back({k.name, e, dt});
    }
    return out;
}

} // namespace drydem
