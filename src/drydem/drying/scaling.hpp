// SPDX-License-Identifier: MIT
// Time scaling (docs/model.md M-7) in one place: scale_parameters maps the physical parameters and
// the scheme to the values the laws receive, and records both; simulated_config hands those values
// to the laws' parameter mapping (law_parameters.cpp); the laws never see a factor. Two schemes:
//   paper        level speed × k, time ÷ k, gravity × k/b, Stokes viscosity ÷ b, Hamaker × k_A
//                (0 = k), capillary force × s_cap (0 = 9e3), lubrication at full viscosity (C-17)
//   force_ratio  level speed × k, time ÷ k, every viscosity ÷ b, every conservative force
//                (capillary, van der Waals, double layer, gravity) × f = k/b: the capillary
//                number and every ratio of forces stay the process's; what is left distorted is
//                inertia (Stokes number × k b) and the overlap (× (f/e)^(2/3))
// and in both the Young's moduli × e (scaling.stiffness_factor) and the CB spheres' inertia × S
// (scaling.cb_density_scaling: their Stokes number × S, their weight physical).
#pragma once
#include "drydem/engine/simulation.hpp"
#include "drydem/io/config.hpp"
#include "drydem/setup/formulation.hpp"
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace drydem {

struct ScaledParameters {
    std::string scheme; ///< "paper" or "force_ratio"
    double time_factor, viscosity_reduction, capillary_factor, hamaker_factor, stiffness_factor;
    double cb_density_scaling;               ///< S: the CB spheres' mass and moment of inertia × S
    double gravity_physical, gravity_scaled; ///< [m/s^2]
    double drag_viscosity_physical, drag_viscosity_scaled;          ///< [Pa s]
    double lubrication_viscosity;                                   ///< [Pa s], as simulated
    double hamaker_cb_cb[2], hamaker_ncm_cb[2], hamaker_ncm_ncm[2]; ///< {physical, scaled} [J]
    double surface_tension_physical, surface_tension_scaled;        ///< σ and σ·s_cap [N/m]
    double youngs_ncm[2], youngs_cb[2], youngs_substrate[2];        ///< {physical, scaled} [Pa]
    std::vector<double> shrinkage_rates_physical;                   ///< [m/s]
    std::vector<double> level_speeds_scaled;                        ///< [m/s]
    double zone_duration_physical, zone_duration_scaled;            ///< [s]

    /// Simulated time ↔ process (physical) time.
    [[nodiscard]] double process_time(double sim_time) const { return sim_time * time_factor; }
    [[nodiscard]] double sim_time(double process_time) const { return process_time / time_factor; }
    /// The factor on a sphere's mass and moment of inertia (the CB's density scaling).
    [[nodiscard]] double inertia_factor(const SizeClass& sc) const {
        return sc.is_cb ? cb_density_scaling : 1.0;
    }
    /// The factor on the Stokes drag's force at a given physical velocity field: k/b (both schemes).
    [[nodiscard]] double drag_force_factor() const { return time_factor / viscosity_reduction; }
};

/// Every scaled value of the configuration's scheme (the one place a scaling factor is applied).
ScaledParameters scale_parameters(const Config& c);

/// The configuration as the laws receive it: every law parameter replaced by its simulated value
/// (Hamaker constants, surface tension, Young's moduli, the lubrication viscosity in `viscosity`,
/// the double layer's strength in its permittivity). Only the laws' parameter mapping (law_parameters.cpp) reads it.
Config simulated_config(const Config& c, const ScaledParameters& s);

/// The CB spheres of `p` take their scaled inertia (scaling.cb_density_scaling; density scaling:
/// gravity and buoyancy read the density, which stays physical).
void scale_cb_inertia(ParticleStore& p, const FilmRecipe& recipe, const ScaledParameters& s);

/// numerics.integrator as the engine's enum.
Integrator integrator_of(const Config& c);
/// The largest step of a run [s, simulated]: Config::time_step_cap, and for the quasi-static step
/// also the time the liquid level takes to move numerics.max_displacement in its fastest zone.
double largest_time_step(const Config& c, const ScaledParameters& s);
/// The quasi-static step's settings (numerics.max_displacement, solver_tolerance,
/// solver_max_iterations; the largest step above).
QuasiStaticSettings quasi_static_settings(const Config& c, const ScaledParameters& s);
nlohmann::json to_json(const ScaledParameters& s);

} // namespace drydem
