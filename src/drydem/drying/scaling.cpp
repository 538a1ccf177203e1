// SPDX-License-Identifier: MIT
#include "drydem/drying/scaling.hpp"
#include <nlohmann/json.hpp>

namespace drydem {

ScaledParameters scale_parameters(const Config& c) {
    ScaledParameters s;
    const double k = c.time_factor, b = c.viscosity_reduction;
    s.time_factor = k;
    s.viscosity_reduction = b;
    s.capillary_factor = c.capillary_factor;
    s.hamaker_factor = c.hamaker_factor;
    s.gravity_physical = c.gravity;
    s.gravity_scaled = c.gravity * k / b;              // Eq. 13 keeps v_level / v_settling
    s.drag_viscosity_physical = c.viscosity;
    s.drag_viscosity_scaled = c.viscosity / b;         // Eq. 10 with η/b
    s.lubrication_viscosity = lubrication_viscosity(c);
    s.hamaker_cb_cb[0] = c.hamaker_cb_cb;
    s.hamaker_ncm_cb[0] = c.hamaker_ncm_cb;
    s.hamaker_ncm_ncm[0] = c.hamaker_ncm_ncm;
    s.hamaker_cb_cb[1] = scaled_hamaker(c.hamaker_cb_cb, c);
    s.hamaker_ncm_cb[1] = scaled_hamaker(c.hamaker_ncm_cb, c);
    s.hamaker_ncm_ncm[1] = scaled_hamaker(c.hamaker_ncm_ncm, c);
    s.surface_tension_physical = c.surface_tension;
    s.surface_tension_scaled = c.surface_tension * c.capillary_factor;
    s.shrinkage_rates_physical = c.shrinkage_rates;
    for (double rate : c.shrinkage_rates) s.level_speeds_scaled.push_back(rate * k);
    s.zone_duration_physical = c.zone_length / c.line_speed;
    s.zone_duration_scaled = s.zone_duration_physical / k;
    return s;
}

nlohmann::json to_json(const ScaledParameters& s) {
    using nlohmann::json;
    auto pair = [](double physical, double scaled) { return json{{"physical", physical}, {"scaled", scaled}}; };
    return json{
        {"time_factor_k", s.time_factor},
        {"viscosity_reduction_b", s.viscosity_reduction},
        {"capillary_factor", s.capillary_factor},
        {"hamaker_factor", s.hamaker_factor},
        {"gravity_m_s2", pair(s.gravity_physical, s.gravity_scaled)},
        {"stokes_viscosity_Pa_s", pair(s.drag_viscosity_physical, s.drag_viscosity_scaled)},
        {"lubrication_viscosity_Pa_s", s.lubrication_viscosity},
        {"hamaker_cb_cb_J", pair(s.hamaker_cb_cb[0], s.hamaker_cb_cb[1])},
        {"hamaker_ncm_cb_J", pair(s.hamaker_ncm_cb[0], s.hamaker_ncm_cb[1])},
        {"hamaker_ncm_ncm_J", pair(s.hamaker_ncm_ncm[0], s.hamaker_ncm_ncm[1])},
        {"surface_tension_N_m", pair(s.surface_tension_physical, s.surface_tension_scaled)},
        {"shrinkage_rates_m_s", {{"physical", s.shrinkage_rates_physical}, {"level_speed_scaled", s.level_speeds_scaled}}},
        {"zone_duration_s", pair(s.zone_duration_physical, s.zone_duration_scaled)},
    };
}

ForceField make_drying_force_field(const Config& c, const FilmRecipe& recipe,
                                   const ScaledParameters& s) {
    ForceField ff;
    const int n = int(recipe.species.size());
    ff.species_count = n;
    ff.pair.resize(std::size_t(n) * n);
    // Each law maps its own keys (its from_config, beside the law).
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            ff.pair[std::size_t(i) * n + j] = PairLaws::from_config(c, recipe.species[i], recipe.species[j]);
    ff.substrate_on = true;
    for (int i = 0; i < n; ++i)
        ff.substrate.push_back(mix_hertz_mindlin(HertzMindlinLaw::youngs_modulus(c, recipe.species[i]), c.poisson_ratio,
                                                 c.substrate_youngs_modulus, c.substrate_poisson_ratio,
                                                 c.restitution, c.substrate_friction, c.rolling_friction));
    ff.substrate_lubrication.viscosity = c.substrate_lubrication ? s.lubrication_viscosity : 0.0;
    ff.substrate_lubrication.kappa_c = c.kappa_c;
    ff.drag.viscosity = s.drag_viscosity_scaled;
    ff.drag.rotational = true; // C-18
    ff.gravity.gravity = s.gravity_scaled;
    ff.gravity.fluid_density = c.solvent_density;
    ff.capillary.surface_tension = c.surface_tension;
    ff.capillary.contact_angle = c.contact_angle;
    ff.capillary.scale = c.capillary_factor;
    return ff;
}

PairReach widest_pair_reach(const ForceField& ff, const FilmRecipe& recipe) {
    PairReach widest;
    for (int i = 0; i < ff.species_count; ++i)
        for (int j = 0; j < ff.species_count; ++j) {
            const double d_i = recipe.species[std::size_t(i)].diameter, d_j = recipe.species[std::size_t(j)].diameter;
            const double reach = 0.5 * (d_i + d_j) + interaction_range(ff.pair_params(i, j), 0.5 * d_i, 0.5 * d_j);
            if (reach > widest.reach) widest = {reach, d_i, d_j};
        }
    return widest;
}

Integrator integrator_of(const Config& c) {
    return c.integrator == "explicit" ? Integrator::explicit_verlet : Integrator::semi_implicit;
}

} // namespace drydem
