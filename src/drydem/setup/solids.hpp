// SPDX-License-Identifier: MIT
// Density of the dry solids, paper Eq. 4: the mass-weighted harmonic mean of the materials,
//   1/ρ_s = w_NCM/ρ_NCM + w_PVDF/ρ_PVDF + w_CB/ρ_CB   (w: mass fractions of the dry film).
// Used by the recipe (setup/formulation), the dryer model and the structure analysis: one formula.
#pragma once

namespace drydem {

[[nodiscard]] inline double solids_density(double w_ncm, double rho_ncm, double w_pvdf,
                                           double rho_pvdf, double w_cb, double rho_cb) {
    return 1.0 / (w_ncm / rho_ncm + w_pvdf / rho_pvdf + w_cb / rho_cb);
}

/// Binder volume per carbon volume when the dissolved PVDF ends up in the carbon-binder domain
/// (model.md M-8.4): b = (w_PVDF/ρ_PVDF) / (w_CB/ρ_CB); 0 without carbon black.
[[nodiscard]] inline double binder_volume_per_carbon(double w_pvdf, double rho_pvdf, double w_cb,
                                                     double rho_cb) {
    return w_cb > 0.0 ? (w_pvdf / rho_pvdf) / (w_cb / rho_cb) : 0.0;
}

/// Density of an uncalendered dry coating [kg/m^3], about what the paper's films reach: used only
/// to plan (the cost estimate of `drydem check`, the derived-quantity checks, the ETA's guess of
/// the final thickness before it is found; model.md M-8.3), never as a result.
inline constexpr double uncalendered_density = 2400.0;

} // namespace drydem
