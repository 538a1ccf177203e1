// SPDX-License-Identifier: MIT
#include "drydem/drying/scaling.hpp"
#include <nlohmann/json.hpp>
#include <algorithm>

namespace drydem {

namespace {

/// The paper's capillary factor when scaling.capillary_factor is 0 (Sec. 4.1).
constexpr double paper_capillary_factor = 9e3;

} // namespace

ScaledParameters scale_parameters(const Config& c) {
    ScaledParameters s;
    const double k = c.time_factor, b = c.viscosity_reduction;
    const bool force_ratio = c.scaling_scheme == "force_ratio";
    s.scheme = c.scaling_scheme;
    s.time_factor = k;
    s.viscosity_reduction = b;
    // force_ratio: every conservative force × k/b, as the viscous ones at velocities × k and η / b.
    s.capillary_factor = force_ratio                ? k / b
                         : c.capillary_factor > 0.0 ? c.capillary_factor
                                                    : paper_capillary_factor;
    s.hamaker_factor = force_ratio ? k / b : c.hamaker_factor > 0.0 ? c.hamaker_factor : k;
    s.stiffness_factor = c.stiffness_factor;
    s.cb_density_scaling = c.drying_cb_density_scaling;
    s.gravity_physical = c.gravity;
    s.gravity_scaled = c.gravity * k / b; // Eq. 13 keeps v_level / v_settling
    s.drag_viscosity_physical = c.viscosity;
    s.drag_viscosity_scaled = c.viscosity / b; // Eq. 10 with η/b
    s.lubrication_viscosity =
        force_ratio || c.lubrication_uses_reduced_viscosity ? c.viscosity / b : c.viscosity; // C-17
    const auto scaled = [](double(&v)[2], double physical, double factor) {
        v[0] = physical;
        v[1] = physical * factor;
    };
    scaled(s.hamaker_cb_cb, c.hamaker_cb_cb, s.hamaker_factor);
    scaled(s.hamaker_ncm_cb, c.hamaker_ncm_cb, s.hamaker_factor);
    scaled(s.hamaker_ncm_ncm, c.hamaker_ncm_ncm, s.hamaker_factor);
    s.surface_tension_physical = c.surface_tension;
    s.surface_tension_scaled = c.surface_tension * s.capillary_factor;
    scaled(s.youngs_ncm, c.ncm_youngs_modulus, s.stiffness_factor);
    scaled(s.youngs_cb, c.cb_youngs_modulus, s.stiffness_factor);
    scaled(s.youngs_substrate, c.substrate_youngs_modulus, s.stiffness_factor);
    s.shrinkage_rates_physical = c.shrinkage_rates;
    for (double rate : c.shrinkage_rates) s.level_speeds_scaled.push_back(rate * k);
    s.zone_duration_physical = c.zone_length / c.line_speed;
    s.zone_duration_scaled = s.zone_duration_physical / k;
    return s;
}

Config simulated_config(const Config& c, const ScaledParameters& s) {
    Config sim = c;
    sim.hamaker_cb_cb = s.hamaker_cb_cb[1];
    sim.hamaker_ncm_cb = s.hamaker_ncm_cb[1];
    sim.hamaker_ncm_ncm = s.hamaker_ncm_ncm[1];
    sim.surface_tension = s.surface_tension_scaled;
    sim.ncm_youngs_modulus = s.youngs_ncm[1];
    sim.cb_youngs_modulus = s.youngs_cb[1];
    sim.substrate_youngs_modulus = s.youngs_substrate[1];
    sim.viscosity = s.lubrication_viscosity;
    // The double layer's strength ε_r ε_0 ψ₀² scales like van der Waals (the balance of the two
    // surface forces stays the physical one); ε_r carries the factor.
    sim.double_layer_permittivity = c.double_layer_permittivity * s.hamaker_factor;
    sim.gravity = s.gravity_scaled;
    return sim;
}

nlohmann::json to_json(const ScaledParameters& s) {
    using nlohmann::json;
    auto pair = [](double physical, double scaled) {
        return json{{"physical", physical}, {"scaled", scaled}};
    };
    return json{
        {"scheme", s.scheme},
        {"time_factor_k", s.time_factor},
        {"viscosity_reduction_b", s.viscosity_reduction},
        {"capillary_factor", s.capillary_factor},
        {"hamaker_factor", s.hamaker_factor},
        {"stiffness_factor_e", s.stiffness_factor},
        {"cb_density_scaling", s.cb_density_scaling},
        {"gravity_m_s2", pair(s.gravity_physical, s.gravity_scaled)},
        {"stokes_viscosity_Pa_s", pair(s.drag_viscosity_physical, s.drag_viscosity_scaled)},
        {"lubrication_viscosity_Pa_s", s.lubrication_viscosity},
        {"hamaker_cb_cb_J", pair(s.hamaker_cb_cb[0], s.hamaker_cb_cb[1])},
        {"hamaker_ncm_cb_J", pair(s.hamaker_ncm_cb[0], s.hamaker_ncm_cb[1])},
        {"hamaker_ncm_ncm_J", pair(s.hamaker_ncm_ncm[0], s.hamaker_ncm_ncm[1])},
        {"surface_tension_N_m", pair(s.surface_tension_physical, s.surface_tension_scaled)},
        {"youngs_modulus_ncm_Pa", pair(s.youngs_ncm[0], s.youngs_ncm[1])},
        {"youngs_modulus_cb_Pa", pair(s.youngs_cb[0], s.youngs_cb[1])},
        {"youngs_modulus_substrate_Pa", pair(s.youngs_substrate[0], s.youngs_substrate[1])},
        {"shrinkage_rates_m_s",
         {{"physical", s.shrinkage_rates_physical}, {"level_speed_scaled", s.level_speeds_scaled}}},
        {"zone_duration_s", pair(s.zone_duration_physical, s.zone_duration_scaled)},
    };
}

void scale_cb_inertia(ParticleStore& p, const FilmRecipe& recipe, const ScaledParameters& s) {
    const int cb = recipe.cb_species();
    if (const double f = s.inertia_factor(recipe.species[std::size_t(cb)]); f != 1.0)
        p.scale_inertia(std::uint8_t(cb), f);
}

Integrator integrator_of(const Config& c) {
    if (c.integrator == "quasi_static") return Integrator::quasi_static;
    return c.integrator == "explicit" ? Integrator::explicit_verlet : Integrator::semi_implicit;
}

double largest_time_step(const Config& c, const ScaledParameters& s) {
    double cap = c.time_step_cap();
    if (c.integrator != "quasi_static") return cap;
    for (double v : s.level_speeds_scaled) cap = std::min(cap, c.max_displacement_value() / v);
    return cap;
}

QuasiStaticSettings quasi_static_settings(const Config& c, const ScaledParameters& s) {
    QuasiStaticSettings q;
    q.max_step = largest_time_step(c, s);
    q.max_displacement = c.max_displacement_value();
    q.tolerance = c.solver_tolerance;
    q.max_iterations = c.solver_max_iterations;
    return q;
}

} // namespace drydem
