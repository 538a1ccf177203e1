// SPDX-License-Identifier: MIT
// Steady conduction (or diffusion) through a voxel image, as TauFactor defines it (Cooper et al.,
// SoftwareX 5 (2016) 203):
//     ∇·(σ ∇φ) = 0   in the image,  φ = 1 on the inlet face, φ = 0 on the outlet face,
// no flux through the other sides (or periodic ones), σ ≥ 0 per voxel. The effective conductivity is
//     σ_eff = (I / A) / (Δφ / L),
// I the current through the inlet face, A its area, L the length between the faces. For a pore
// phase of volume fraction ε with σ = D₀ inside, the tortuosity factor is τ = ε D₀ / D_eff.
// Finite volumes on the voxel grid: the conductance between face neighbours p, q is the series of
// their half voxels, 2 σp σq / (σp + σq) × (face area / voxel edge) — exact for layered media — and
// a voxel on a fixed face connects to it over half a voxel, 2 σ × face area / edge.
// Only voxels in clusters that touch both faces carry current; the others are left out before the
// solve (they would make the matrix singular). Solved by conjugate gradients with an algebraic
// multigrid preconditioner (amg_solver.hpp); Eigen's Jacobi-preconditioned CG stays as a second
// solver for the tests.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace drydem::analysis {

enum class Preconditioner { amg, jacobi };

struct ConductionProblem {
    int nx = 0, ny = 0, nz = 0;
    double ax = 0.0, ay = 0.0, az = 0.0; ///< voxel edges [m]
    std::vector<float> sigma;            ///< per voxel, x fastest then y then z; 0 = insulating
    int axis = 2;                        ///< direction of the applied gradient: 0 x, 1 y, 2 z
    std::array<bool, 3> periodic{true, true, false}; ///< side conditions of the two other axes
    double tolerance = 1e-8;                         ///< CG relative residual |b − A x| / |b|
    int max_iterations = 20000;
    Preconditioner preconditioner = Preconditioner::amg;
};

struct ConductionResult {
    double sigma_eff = 0.0;            ///< effective conductivity along the axis [unit of σ]
    bool percolates = false;           ///< a conducting path joins the two faces
    double conducting_fraction = 0.0;  ///< voxels with σ > 0 / all voxels
    double percolating_fraction = 0.0; ///< voxels in clusters touching both faces / all voxels
    double flux_balance = 0.0;         ///< |I_in − I_out| / I_in (conservation check)
    std::size_t unknowns = 0;
    int iterations = 0;
    double residual = 0.0; ///< CG's estimate of the relative residual
    bool converged = false;
    const char* preconditioner = ""; ///< "BoomerAMG" or "Jacobi"
    std::size_t memory_bytes = 0; ///< masks, matrix, vectors and the solver's own (AMG hierarchy)
    double seconds = 0.0;
};

/// Solves the problem above. σ_eff = 0 (percolates = false) when no cluster joins the faces.
[[nodiscard]] ConductionResult solve_conduction(const ConductionProblem& p);

/// Voxels of clusters (face neighbours with σ > 0, periodic sides as given) that touch both the
/// inlet and the outlet face of `axis`: 1 there, else 0.
[[nodiscard]] std::vector<std::uint8_t> spanning_clusters(const ConductionProblem& p);

} // namespace drydem::analysis
