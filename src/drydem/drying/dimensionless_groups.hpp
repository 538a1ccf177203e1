// SPDX-License-Identifier: MIT
// The dimensionless groups of the drying film (docs/model.md "Dimensionless groups"), physical and
// as simulated, from the same force field a run uses. With F_cap(r) = 2πσ r cos²(θ/2) the largest
// push of the level on a sphere, U the level speed, H the film's thickness (estimated dry
// thickness, where the film leaves the level), N_s the count of species s:
//   capillary number, drag       Ca   = 6πη_d r U / F_cap(r) = 3 η_d U / (σ cos²(θ/2))
//   capillary number, lubrication      a_n(CB-CB at the freeze gap κ_c r_L) U / F_cap(r_CB)
//   push number                  Π    = Ca H / ℓ*,  ℓ* = 2 Σ N_s r_s² / Σ N_s r_s
//                                (drag of the whole film carried at U over the level's push per
//                                area, Σ 2 N_s r_s F_cap(r_s) / (A H))
//   van der Waals / capillary    F_vdW(contact, h_min) / F_cap(smaller radius): CB-CB, NCM-CB
//   Bond number, largest NCM     (ρ - ρ_f) g V / F_cap(r)
//   Stokes number                τ_p U / r,  τ_p = m / (6π η_d r): largest NCM, CB
//   inertial number              I = (U/H) d sqrt(ρ / P), P = Σ 2 N_s r_s F_cap(r_s) / (A H),
//                                d, ρ of the largest NCM
//   expected Hertz overlap δ/r   CB-CB under van der Waals at contact; the largest NCM on one CB
//                                and on the substrate under its capillary push (δ over the
//                                smaller radius; hertz_overlap)
// "Physical" is the force_ratio scheme at k = b = e = 1: every value as in the process.
#pragma once
#include "drydem/drying/scaling.hpp"
#include "drydem/forces/force_field.hpp"
#include "drydem/io/config.hpp"
#include "drydem/setup/formulation.hpp"
#include <nlohmann/json_fwd.hpp>
#include <vector>

namespace drydem {

/// A run warns above these (docs/validation.md): a push number where the level can no longer carry
/// the film, and a 99th-percentile overlap beyond what DEM practice accepts (~1 %).
inline constexpr double push_number_warning = 0.1;
inline constexpr double overlap_p99_warning = 0.05;

/// The groups of one parameter set (physical or as simulated) at one level speed.
struct Groups {
    double capillary_drag = 0.0, capillary_lubrication = 0.0, push = 0.0;
    double stokes_ncm = 0.0, stokes_cb = 0.0, inertial = 0.0;
    double vdw_capillary_cb_cb = 0.0, vdw_capillary_ncm_cb = 0.0, bond_ncm = 0.0;
    double overlap_cb_cb = 0.0, overlap_ncm_cb = 0.0, overlap_ncm_substrate = 0.0;
};

struct DimensionlessGroups {
    double push_length = 0.0;                  ///< ℓ* [m]
    double film_thickness = 0.0;               ///< H [m]
    std::vector<double> level_speeds_physical; ///< per dryer zone [m/s]
    std::vector<Groups> physical, simulated;   ///< per dryer zone
};

/// The groups of one force field (the laws' parameters) at level speed U and thickness H, the CB
/// spheres' inertia × cb_inertia (scaling.cb_density_scaling; 1 for the process).
Groups groups_of(const ForceField& ff, const FilmRecipe& recipe, double level_speed,
                 double thickness, double cb_inertia);

/// ℓ* = 2 Σ N_s r_s² / Σ N_s r_s of the recipe [m].
double push_length(const FilmRecipe& recipe);

/// Every zone's groups, physical and as simulated by the configuration's scheme.
DimensionlessGroups dimensionless_groups(const Config& c);

nlohmann::json to_json(const DimensionlessGroups& g);

} // namespace drydem
