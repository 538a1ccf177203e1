// SPDX-License-Identifier: MIT
// The paper's time-scaling scheme (Sec. 4.1, model.md M-7) in one place: it maps the physical
// parameters to the values used in the simulation and records both.
//   level speed × k, time ÷ k, gravity × k/b, Stokes viscosity ÷ b, Hamaker × hamaker_factor,
//   capillary force × capillary_factor; lubrication keeps the full viscosity (C-17).
#pragma once
#include "drydem/engine/simulation.hpp"
#include "drydem/forces/force_field.hpp"
#include "drydem/io/config.hpp"
#include "drydem/setup/formulation.hpp"
#include <nlohmann/json_fwd.hpp>
#include <vector>

namespace drydem {

struct ScaledParameters {
    double time_factor, viscosity_reduction, capillary_factor, hamaker_factor;
    double gravity_physical, gravity_scaled;                 ///< [m/s^2]
    double drag_viscosity_physical, drag_viscosity_scaled;   ///< [Pa s]
    double lubrication_viscosity;                            ///< [Pa s]
    double hamaker_cb_cb[2], hamaker_ncm_cb[2], hamaker_ncm_ncm[2]; ///< {physical, scaled} [J]
    double surface_tension_physical, surface_tension_scaled; ///< σ and σ·s_cap [N/m]
    std::vector<double> shrinkage_rates_physical;            ///< [m/s]
    std::vector<double> level_speeds_scaled;                 ///< [m/s]
    double zone_duration_physical, zone_duration_scaled;     ///< [s]

    /// Simulated time ↔ process (physical) time.
    [[nodiscard]] double process_time(double sim_time) const { return sim_time * time_factor; }
    [[nodiscard]] double sim_time(double process_time) const { return process_time / time_factor; }
};

ScaledParameters scale_parameters(const Config& c);

/// numerics.integrator as the engine's enum.
Integrator integrator_of(const Config& c);
nlohmann::json to_json(const ScaledParameters& s);

/// Species pair table and particle forces of the drying simulation, from the recipe's species
/// (NCM classes, then CB) and the scaled parameters.
ForceField make_drying_force_field(const Config& c, const FilmRecipe& recipe,
                                   const ScaledParameters& s);

/// The widest pair of the film's species: the largest centre distance r_i + r_j + the pair laws'
/// range (interaction_range, as the neighbour list reaches) over every species pair [m], and the
/// two diameters of that pair.
struct PairReach {
    double reach = 0.0, diameter_i = 0.0, diameter_j = 0.0;
};
PairReach widest_pair_reach(const ForceField& ff, const FilmRecipe& recipe);

} // namespace drydem
