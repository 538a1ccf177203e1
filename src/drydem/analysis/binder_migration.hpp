// SPDX-License-Identifier: MIT
// Binder migration during drying, the paper's Eq. 1 (docs/analysis.md, "Binder migration"):
//     J = F c − D_eff ∂c/∂z,      ∂(θ c)/∂t + ∂J/∂z = 0,      ∂θ/∂t + ∂F/∂z = 0,
// c the dissolved PVDF per solvent volume, θ the solvent volume fraction, F the volume-averaged
// solvent flux, D_eff = D₀ θ^(α−1) (pore diffusion with the Bruggeman exponent α, so the flux per
// film area is θ D₀/τ ∂c/∂z with τ = θ^(1−α)), over the film height z, 1D, after Font et al. (J.
// Power Sources 395 (2018) 128: convection–diffusion of the dissolved binder, Pe = E H/D) and the
// drying picture of Jaiser et al. (J. Power Sources 318 (2016) 210: shrinkage, then capillary
// transport of solvent to the top while the pores empty).
// Coupled to the DEM run:
//   - film shrinkage: the liquid level h(t) of the run's time series is the film top; the descending
//     surface sweeps the binder (binder cannot evaporate). The solid profile φ_s(z, t) is the run's
//     own: the porosity profiles of its dump frames, in the coordinate ξ = z/h scaled by the level,
//     interpolated linearly in time and, after the last frame, toward the final profile at the time
//     the level reaches H_f; scaled so that the solid volume stays the final film's. Without frames
//     the solids are compressed affinely, φ_s(z, t) = φ_s,f(z H_f/h) H_f/h. The solvent flux follows
//     from the change of the solvent in each cell;
//   - pore emptying (h below the final height H_f): the liquid volume is the run's, ∫₀^h ε_f dz, but
//     capillary pressure keeps the saturation S uniform over the height (small pores stay filled),
//     θ = ε_f(z) S(t): the solvent flows to the top, F(z) = E/ρ_l ∫₀^z ε_f / ∫₀^H ε_f, and carries
//     the binder there. After the run's last row the level goes on at its last rate (the dryer's);
//     the model stops at S = residual_saturation (binder immobile), where the binder is left in place.
// Finite volumes on a grid that stretches with the film top, upwind convection (explicit, CFL),
// implicit diffusion (tridiagonal), no binder flux through substrate and top. Mass is conserved to
// round-off.
#pragma once
#include "drydem/analysis/structure.hpp"
#include "drydem/io/particle_io.hpp"
#include <cstdint>
#include <string>
#include <vector>

namespace drydem::analysis {

struct BinderParams {
    double diffusivity =
        6.5e-12; ///< D₀ of dissolved PVDF in NMP [m²/s] (Stokes–Einstein, see docs)
    double bruggeman =
        1.5; ///< α of D_eff = D₀ θ^(α−1) (or the film's own, from the transport solve)
    int cells = 200;
    /// Stop when the pores hold this fraction of their solvent: the binder is taken as immobile
    /// from there (the solution has concentrated 1/S-fold — ~5 wt% PVDF in NMP at the start, a gel
    /// near 20-25 wt%: an assumption, not a measured value). Below, the pore diffusion fades as
    /// θ^(α−1) while the capillary flow F/θ grows, and the result would hinge on this cut.
    double residual_saturation = 0.2;
    double cfl = 0.4;
    double max_step = 0.01; ///< [s]
};

/// The solvent-accessible porosity over the height of the film at one time of its shrinkage.
struct PorosityFrame {
    double time = 0.0;            ///< process time [s]
    double height = 0.0;          ///< the liquid level then, the top of the wet film [m]
    std::vector<double> porosity; ///< per slab of DryingHistory::dz from z = 0 up to `height`
};

/// What the DEM run gives the model.
struct DryingHistory {
    std::vector<double> time;         ///< process time [s], increasing
    std::vector<double> liquid_level; ///< [m]
    std::vector<double> step;         ///< the run's step at each row (empty when the file has none)
    double final_height = 0.0;        ///< H_f [m]
    double dz = 0.0;                  ///< slab width of the profile [m]
    std::vector<double>
        porosity; ///< ε_f per slab of the final film from z = 0 (solvent-accessible)
    std::vector<PorosityFrame> frames; ///< during the shrinkage, increasing time; empty: affine
};

struct BinderProfile {
    std::vector<double> z;      ///< cell centres in the final film [m]
    std::vector<double> binder; ///< binder per film volume / its mean (1 = uniform)
    double bottom10 = 0.0;      ///< mean of `binder` over the lowest 10 % of the height
    double top10 = 0.0;         ///< ... over the highest 10 %
    double peclet = 0.0; ///< E H₀ / D₀ with the mean evaporation velocity of the shrinkage
    double evaporation_rate = 0.0;   ///< mean of −dh/dt over the shrinkage [m/s]
    double consolidation_time = 0.0; ///< when h reached H_f [s]
    double end_time = 0.0;           ///< when S reached the residual saturation [s]
    double mass_balance = 0.0;       ///< |M_end − M_0| / M_0
    int steps = 0;
    int porosity_frames = 0; ///< frames of the run that shaped the shrinkage (0: affine)
};

[[nodiscard]] BinderProfile binder_migration(const DryingHistory& h, const BinderParams& p);

/// The history of a run folder: timeseries.csv (process_time_s, liquid_level_um, step), the final
/// height H_f and the solvent-accessible porosity profile (profiles' pore_total) given by the caller.
[[nodiscard]] DryingHistory read_drying_history(const std::string& timeseries_csv,
                                                double final_height, double dz,
                                                const std::vector<double>& porosity);

/// The frames of a run's dump (snapshots/dump.lammpstrj) taken while the film shrinks, as porosity
/// profiles (pore_total of profiles.hpp, slabs of h.dz up to the level): each frame's time and
/// level interpolated from the history's (step, time, level) rows. Frames before the first row,
/// after the last or with the level at or below H_f are left out; no step column, no frames.
[[nodiscard]] std::vector<PorosityFrame> porosity_frames(const std::filesystem::path& dump,
                                                         const DryingHistory& h,
                                                         const FileDefaults& defaults,
                                                         const PhaseRule& rule = {});

} // namespace drydem::analysis
