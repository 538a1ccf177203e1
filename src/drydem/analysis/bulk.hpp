// SPDX-License-Identifier: MIT
// Thickness, dry masses, coating density and porosity of a structure (paper Sec. 5, model.md
// M-8.2 / M-8.4), and the CB-binder porosity of Eq. 2 (Mayer/Bockholt) as the simulation analogue.
#pragma once
#include "drydem/analysis/structure.hpp"

namespace drydem::analysis {

struct Masses {
    double ncm = 0.0;       ///< NCM spheres [kg]
    double cb_carbon = 0.0; ///< carbon of the CB agglomerates, Σ (1 - ε_i) ρ_CB V_i [kg]
    double pvdf = 0.0; ///< binder, from the formulation: w_PVDF / (w_NCM + w_CB) (m_NCM + m_CB)
    double ncm_volume = 0.0;         ///< Σ V of NCM spheres [m^3]
    double cb_envelope_volume = 0.0; ///< Σ V of CB spheres [m^3]
    [[nodiscard]] double dry() const { return ncm + cb_carbon + pvdf; }
};
[[nodiscard]] Masses masses(const Structure& s);

/// Highest particle top max(z + r): the paper's film thickness (M-8.2).
[[nodiscard]] double highest_top(const Structure& s);

struct Bulk {
    double thickness = 0.0; ///< highest top [m] (the paper's definition)
    double thickness_half_solid =
        0.0; ///< robust: where the solid fraction falls below half its bulk value [m]
    double bulk_solid_fraction = 0.0; ///< NCM + CB envelope volume fraction of the bulk
    double areal_loading = 0.0;       ///< dry mass / base area [kg/m^2]
    double density = 0.0;             ///< L / thickness [kg/m^3] (M-8.4)
    double porosity = 0.0;            ///< 1 - ρ/ρ_s
    double density_half_solid = 0.0,
           porosity_half_solid = 0.0; ///< the same with the robust thickness
    double solids_density = 0.0;      ///< ρ_s [kg/m^3]
    /// Eq. 2 with ε_C = porosity, C_v,NMC = V_NCM/V_coat, ε_C,NMC = 1 - (V_NCM + V_CB,env)/V_coat.
    double cb_binder_porosity = 0.0;
    double ncm_volume_fraction = 0.0,
           cb_envelope_volume_fraction = 0.0; ///< of the coating (thickness)
    Masses mass;
};

/// `profile_solid` is the NCM + CB envelope solid fraction per slab of width dz from z = 0 (the
/// profiles' `solid` column); the robust thickness is read off it.
[[nodiscard]] Bulk bulk_properties(const Structure& s, const std::vector<double>& profile_solid,
                                   double dz);

} // namespace drydem::analysis
