// SPDX-License-Identifier: MIT
// Tortuosity factor by random walks, a second method beside the conduction solve (docs/analysis.md):
// "blind ant" walkers on the conducting voxels (σ > 0) — each step picks one of the six faces at
// random and moves there if that voxel conducts, else stays. Along a periodic axis the long-time
// mean squared displacement gives the self-diffusivity D_w, and by the Nernst–Einstein relation for
// walkers started uniformly in the pore space (isolated pores and dead ends contribute nothing at
// long times):
//     D_eff = ε D_w,   τ = ε D₀ / D_eff = D₀ / D_w,    D₀ = a² / (6 Δt) (free lattice walk),
// so D_w/D₀ = ⟨Δx²⟩ / (n a²/3) after n steps. The same lattice operator as the finite volumes with
// harmonic-mean faces (uniform σ inside the phase), so both methods must agree up to the walkers'
// statistics and the boundary conditions (fixed faces there, periodic here).
#pragma once
#include "drydem/analysis/conduction.hpp"
#include <array>
#include <cstdint>

namespace drydem::analysis {

struct RandomWalkResult {
    std::array<double, 3> diffusivity{0.0, 0.0,
                                      0.0}; ///< D_w/D₀ per axis (periodic axes only, else 0)
    std::array<double, 3> standard_error{0.0, 0.0, 0.0}; ///< of D_w/D₀ over the walkers
    long walkers = 0, steps = 0;
    double seconds = 0.0;
};

/// Walkers start on uniformly drawn conducting voxels (σ > 0; σ is only tested against 0). Axes
/// that are not periodic are walls. Deterministic for a given seed (OpenMP over walkers).
[[nodiscard]] RandomWalkResult random_walk(const ConductionProblem& p, long walkers, long steps,
                                           std::uint64_t seed = 12345);

} // namespace drydem::analysis
