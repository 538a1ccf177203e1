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
    s.lubrication_viscosity = c.lubrication_uses_reduced_viscosity ? c.viscosity / b : c.viscosity;
    s.hamaker_cb_cb[0] = c.hamaker_cb_cb;
    s.hamaker_ncm_cb[0] = c.hamaker_ncm_cb;
    s.hamaker_ncm_ncm[0] = c.hamaker_ncm_ncm;
    s.hamaker_cb_cb[1] = c.hamaker_cb_cb * c.hamaker_factor;
    s.hamaker_ncm_cb[1] = c.hamaker_ncm_cb * c.hamaker_factor;
    s.hamaker_ncm_ncm[1] = c.hamaker_ncm_ncm * c.hamaker_factor;
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
    auto modulus = [&](int sp) { return recipe.species[sp].is_cb ? c.cb_youngs_modulus : c.ncm_youngs_modulus; };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const SizeClass &a = recipe.species[i], &b = recipe.species[j];
            PairParams& p = ff.pair[std::size_t(i) * n + j];
            p.contact = mix_hertz_mindlin(modulus(i), c.poisson_ratio, modulus(j), c.poisson_ratio,
                                          c.restitution, c.friction, c.rolling_friction);
            // M-3: Hamaker constant and minimum gap by material pair.
            if (a.is_cb && b.is_cb) {
                p.van_der_waals.hamaker = s.hamaker_cb_cb[1];
                p.van_der_waals.min_gap = c.min_gap_cb_cb;
            } else if (a.is_cb || b.is_cb) {
                p.van_der_waals.hamaker = s.hamaker_ncm_cb[1];
                p.van_der_waals.min_gap = c.min_gap_ncm_cb;
            } else {
                p.van_der_waals.hamaker = s.hamaker_ncm_ncm[1];
                p.van_der_waals.min_gap = c.min_gap_ncm_ncm;
            }
            // C-13: default cut-off = the pair's lubrication radius r_L = 2R* (C-15).
            const double ra = 0.5 * a.diameter, rb = 0.5 * b.diameter;
            p.van_der_waals.cutoff_gap = c.vdw_cutoff > 0.0 ? c.vdw_cutoff : 2.0 * ra * rb / (ra + rb);
            p.lubrication.viscosity = c.lubrication ? s.lubrication_viscosity : 0.0;
            p.lubrication.kappa_c = c.kappa_c;
        }
    ff.substrate_on = true;
    for (int i = 0; i < n; ++i)
        ff.substrate.push_back(mix_hertz_mindlin(modulus(i), c.poisson_ratio,
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

Integrator integrator_of(const Config& c) {
    return c.integrator == "explicit" ? Integrator::explicit_verlet : Integrator::semi_implicit;
}

} // namespace drydem
