// SPDX-License-Identifier: MIT
// Conjugate gradients preconditioned by algebraic multigrid (hypre's BoomerAMG, Debian
// libhypre-dev) for the symmetric positive definite systems  A x = b  of the voxel conduction
// solves (conduction.hpp). Multigrid makes the iteration count independent of the grid size and
// of the conductivity contrast: the NCM/CB contrast of 1e4 took Jacobi-CG thousands of iterations,
// BoomerAMG-PCG takes ~10 (docs/analysis.md, "Solver and voxel size").
//
// hypre is built on MPI; this process is a one-rank MPI job (MPI_COMM_SELF), initialised on the
// first solve (a singleton: no mpirun needed) and never finalised — OpenMPI's finalize unloads its
// plugins, exit frees the rest.
#pragma once
#include <cstddef>
#include <vector>

namespace drydem::analysis {

/// A square matrix in compressed sparse rows; symmetric positive definite.
struct CsrMatrix {
    int n = 0;
    const int* row_start = nullptr; ///< n + 1 offsets into cols/values
    const int* cols = nullptr;
    const double* values = nullptr;
};

struct AmgSolve {
    std::vector<double> x;
    int iterations = 0;
    double residual = 0.0; ///< final |b − A x| / |b| (two-norm)
    bool converged = false;
    std::size_t memory_bytes =
        0; ///< heap held by hypre at the end: matrix copy, hierarchy, vectors
};

/// Starts MPI (one rank, for hypre) and hypre once per process; solve_amg_pcg calls it too. Call it
/// from the main thread before solving in another one.
void start_amg_solver();

/// Solves A x = b from the first guess to the relative residual `tolerance`.
[[nodiscard]] AmgSolve solve_amg_pcg(const CsrMatrix& A, const std::vector<double>& b,
                                     const std::vector<double>& guess, double tolerance,
                                     int max_iterations);

} // namespace drydem::analysis
