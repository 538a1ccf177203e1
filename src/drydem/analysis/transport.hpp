// SPDX-License-Identifier: MIT
// Transport properties of the dried film on its voxel image (docs/analysis.md, "Transport"):
//   tortuosity factor of the pore phase   τ = ε D₀ / D_eff            (TauFactor, Cooper et al. 2016)
//   MacMullin number                      N_M = D₀ / D_eff = τ / ε
//   implied Bruggeman exponent            τ = ε^(1−α)  ⇔  α = 1 − ln τ / ln ε
//   effective electronic conductivity     σ_eff of the solid (NCM σ_NCM, CB σ_CB) through-plane
//   CB percolation                        a face-connected CB voxel cluster joins substrate and top
// all from steady conduction solves (conduction.hpp) on the coating z ∈ [0, top) — top the pore top of
// the analysis (the half-solid height by default): through-plane (z, periodic x, y, the substrate and
// the top plane as the fixed faces) and in-plane (x and y, cut open at the box side, periodic in the
// other in-plane axis, closed at substrate and top). Each voxel size of the list is a separate
// voxelization of the spheres, so the list shows the convergence in voxel size.
#pragma once
#include "drydem/analysis/conduction.hpp"
#include "drydem/analysis/random_walk.hpp"
#include "drydem/analysis/structure.hpp"
#include <functional>
#include <string>
#include <vector>

namespace drydem::analysis {

/// Peak bytes of one solve per voxel of its image (AMG hierarchy, matrix, vectors, labels): the
/// main job's solid solve at 0.4 um held 2.58 GB for 7.7e6 voxels (335 B), rounded up.
inline constexpr double transport_bytes_per_voxel = 400.0;

struct TransportOptions {
    std::vector<double> voxels{0.4e-6,
                               0.2e-6}; ///< voxel edges [m]; the last one is reported; empty = none
    double sigma_ncm = 1.0e-2;          ///< electronic conductivity of NCM [S/m] (input)
    double sigma_cb =
        100.0; ///< electronic conductivity of a CB agglomerate (carbon + binder + pores) [S/m] (input)
    double tolerance = 1e-7; ///< CG relative residual
    /// A voxel size whose image has more voxels is skipped (and said so): one solve holds ~400
    /// bytes per voxel at its peak (AMG hierarchy, transport_bytes_per_voxel), so 2.5e7 voxels
    /// stay near 10 GB.
    std::size_t max_voxels = 25'000'000;
    bool in_plane = true; ///< also τ along x and y
    /// Lateral side of the window the solves run on [m] (its corner at the origin, sides closed
    /// instead of periodic, no random walks): a finer voxel size fits in memory on a part of a
    /// large film. 0 = the whole box.
    double window = 0.0;
    /// Second method at the reported voxel size: random walks in the pores, in-plane (x, y
    /// periodic, substrate and top walls; random_walk.hpp). 0 walkers = none.
    long walkers = 20000, walk_steps = 20000;
    std::function<void(const std::string&)> log;
};

/// All solves at one voxel size.
struct TransportLevel {
    double voxel = 0.0; ///< [m]
    int nx = 0, ny = 0, nz = 0;
    double porosity = 0.0; ///< pore voxels / voxels of the coating
    double tau_z = 0.0, tau_x = 0.0,
           tau_y = 0.0; ///< tortuosity factors (0 where the pores do not percolate)
    ConductionResult pore_z, pore_x, pore_y;
    ConductionResult electronic_z; ///< NCM + CB with their conductivities
    ConductionResult cb_z;         ///< CB alone (σ_CB), for the percolation of the CB network
    RandomWalkResult walk;         ///< in the pores, at the reported (last) level only
    double seconds = 0.0;          ///< voxelization and all solves
    std::size_t memory_bytes = 0;  ///< peak of one solve plus the image
};

/// A voxel size of the list over `max_voxels`: not solved.
struct SkippedLevel {
    double voxel = 0.0;     ///< [m]
    std::size_t voxels = 0; ///< of its image
};

struct Transport {
    std::vector<TransportLevel>
        levels;                        ///< the solved ones, in the order of the options' voxel list
    std::vector<SkippedLevel> skipped; ///< over the voxel limit
    std::size_t max_voxels = 0;
    double top = 0.0; ///< top of the solved coating [m]
    double sigma_ncm = 0.0, sigma_cb = 0.0;
    /// Solved alongside the pore sizes (analyze.cpp): the levels' seconds are then shared cores and
    /// their memory_bytes, the heap's growth during a solve, includes the pore sizes' (an upper bound).
    bool alongside_pore_sizes = false;
    double window = 0.0; ///< lateral side of the solved window [m]; 0 = whole box
    [[nodiscard]] bool solved() const { return !levels.empty(); }
    /// The finest solved level; only where solved().
    [[nodiscard]] const TransportLevel& reported() const { return levels.back(); }
};

/// Richardson extrapolation to zero voxel size of values v at voxel sizes h (coarse to fine), with
/// the order p observed on the last three levels (equal ratios needed), accepted in [0.5, 3] with
/// monotone changes. `value` NaN where it cannot be done — also for two levels: an assumed order
/// from 0.8 and 0.4 µm extrapolates the quick film to τ = 1.36 where three levels give 1.59.
struct Extrapolation {
    double value = 0.0;
    double order = 0.0;
    bool order_observed = false;
};
[[nodiscard]] Extrapolation extrapolate_to_zero_voxel(const std::vector<double>& h,
                                                      const std::vector<double>& v);

/// τ = ε D₀/D_eff from σ_eff of a pore phase with σ = 1 inside (D₀ = 1): 0 when it does not percolate.
[[nodiscard]] double tortuosity_factor(double porosity, double sigma_eff);
/// α of τ = ε^(1−α); NaN where ε or τ make it undefined (ε ∉ (0, 1), τ ≤ 0).
[[nodiscard]] double bruggeman_exponent(double porosity, double tau);

[[nodiscard]] Transport film_transport(const Structure& s, double top, const TransportOptions& o);

/// Peak bytes of `film_transport(s, top, o)`: its largest solvable image times
/// transport_bytes_per_voxel (the levels are solved one after the other).
[[nodiscard]] double transport_peak_bytes(const Structure& s, double top,
                                          const TransportOptions& o);

} // namespace drydem::analysis
