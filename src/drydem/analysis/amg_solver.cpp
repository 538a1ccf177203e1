// SPDX-License-Identifier: MIT
#include "drydem/analysis/amg_solver.hpp"
#include "drydem/core/error.hpp"
#include "drydem/parallel/mpi_world.hpp"
#include <HYPRE.h>
#include <HYPRE_IJ_mv.h>
#include <HYPRE_krylov.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>
#include <fmt/format.h>
#include <cstdlib>
#include <malloc.h>
#include <mutex>
#include <numeric>

namespace drydem::analysis {

void start_amg_solver() {
    static std::once_flag once;
    std::call_once(once, [] {
        // Serialized MPI: the solves may run in a thread other than the one that started MPI
        // (the analysis overlaps them with the pore sizes), never two at once.
        parallel::start_mpi();
        HYPRE_Init();
    });
}

namespace {

/// Heap bytes in use by this process (glibc's count; 0 where a sanitizer replaces malloc).
std::size_t heap_in_use() {
    const struct mallinfo2 m = mallinfo2();
    return m.uordblks + m.hblkhd;
}

/// hypre's IJ objects with their destroy calls, so that an exception frees them too.
struct HypreSystem {
    HYPRE_IJMatrix A = nullptr;
    HYPRE_IJVector b = nullptr, x = nullptr;
    HYPRE_Solver pcg = nullptr, amg = nullptr;
    HypreSystem() = default;
    HypreSystem(const HypreSystem&) = delete;
    HypreSystem& operator=(const HypreSystem&) = delete;
    ~HypreSystem() {
        if (pcg) HYPRE_ParCSRPCGDestroy(pcg);
        if (amg) HYPRE_BoomerAMGDestroy(amg);
        if (x) HYPRE_IJVectorDestroy(x);
        if (b) HYPRE_IJVectorDestroy(b);
        if (A) HYPRE_IJMatrixDestroy(A);
    }
};

/// 0, 1, ..., n − 1: the rows of this rank, which owns all of them.
std::vector<HYPRE_BigInt> all_rows(int n) {
    std::vector<HYPRE_BigInt> rows(static_cast<std::size_t>(n));
    std::iota(rows.begin(), rows.end(), HYPRE_BigInt{0});
    return rows;
}

HYPRE_IJVector make_vector(int n, const std::vector<double>& values) {
    HYPRE_IJVector v = nullptr;
    HYPRE_IJVectorCreate(MPI_COMM_SELF, 0, n - 1, &v);
    HYPRE_IJVectorSetObjectType(v, HYPRE_PARCSR);
    HYPRE_IJVectorInitialize(v);
    const std::vector<HYPRE_BigInt> rows = all_rows(n);
    HYPRE_IJVectorSetValues(v, n, rows.data(), values.data());
    HYPRE_IJVectorAssemble(v);
    return v;
}

void fill_matrix(HypreSystem& s, const CsrMatrix& A) {
    HYPRE_IJMatrixCreate(MPI_COMM_SELF, 0, A.n - 1, 0, A.n - 1, &s.A);
    HYPRE_IJMatrixSetObjectType(s.A, HYPRE_PARCSR);
    std::vector<HYPRE_Int> ncols(std::size_t(A.n));
    for (int i = 0; i < A.n; ++i) ncols[std::size_t(i)] = A.row_start[i + 1] - A.row_start[i];
    HYPRE_IJMatrixSetRowSizes(s.A, ncols.data());
    HYPRE_IJMatrixInitialize(s.A);
    const std::vector<HYPRE_BigInt> rows = all_rows(A.n);
    static_assert(sizeof(HYPRE_BigInt) == sizeof(int),
                  "hypre built with 32-bit indices (libhypre-dev)");
    HYPRE_IJMatrixSetValues(s.A, A.n, ncols.data(), rows.data(), A.cols, A.values);
    HYPRE_IJMatrixAssemble(s.A);
}

/// BoomerAMG as one V-cycle per CG iteration. HMIS coarsening with extended+i interpolation
/// (truncated to 4 entries) and ℓ1-Gauss-Seidel smoothing: hypre's recommended set for 3D
/// diffusion with jumping coefficients; strong threshold 0.5 for 3D.
void configure(HypreSystem& s, double tolerance, int max_iterations) {
    HYPRE_BoomerAMGCreate(&s.amg);
    HYPRE_BoomerAMGSetPrintLevel(s.amg, 0);
    HYPRE_BoomerAMGSetCoarsenType(s.amg, 10);
    HYPRE_BoomerAMGSetInterpType(s.amg, 6);
    HYPRE_BoomerAMGSetPMaxElmts(s.amg, 4);
    HYPRE_BoomerAMGSetStrongThreshold(s.amg, 0.5);
    HYPRE_BoomerAMGSetRelaxType(s.amg, 8);
    HYPRE_BoomerAMGSetTol(s.amg, 0.0);
    HYPRE_BoomerAMGSetMaxIter(s.amg, 1);
    HYPRE_ParCSRPCGCreate(MPI_COMM_SELF, &s.pcg);
    HYPRE_PCGSetTol(s.pcg, tolerance);
    HYPRE_PCGSetMaxIter(s.pcg, max_iterations);
    HYPRE_PCGSetTwoNorm(s.pcg, 1);
    HYPRE_PCGSetPrintLevel(s.pcg, 0);
    HYPRE_PCGSetPrecond(s.pcg, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                        reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSetup), s.amg);
}

} // namespace

AmgSolve solve_amg_pcg(const CsrMatrix& A, const std::vector<double>& b,
                       const std::vector<double>& guess, double tolerance, int max_iterations) {
    if (A.n < 1 || b.size() != std::size_t(A.n) || guess.size() != std::size_t(A.n))
        throw InputError(
            fmt::format("AMG solve: {} unknowns with {} right-hand sides and {} guesses", A.n,
                        b.size(), guess.size()));
    start_amg_solver();
    const std::size_t heap0 = heap_in_use();
    HypreSystem s;
    fill_matrix(s, A);
    s.b = make_vector(A.n, b);
    s.x = make_vector(A.n, guess);
    HYPRE_ParCSRMatrix pA = nullptr;
    HYPRE_ParVector pb = nullptr, px = nullptr;
    HYPRE_IJMatrixGetObject(s.A, reinterpret_cast<void**>(&pA));
    HYPRE_IJVectorGetObject(s.b, reinterpret_cast<void**>(&pb));
    HYPRE_IJVectorGetObject(s.x, reinterpret_cast<void**>(&px));
    configure(s, tolerance, max_iterations);
    HYPRE_ParCSRPCGSetup(s.pcg, pA, pb, px);
    HYPRE_ParCSRPCGSolve(s.pcg, pA, pb, px);
    HYPRE_ClearAllErrors(); // non-convergence is reported through `converged`, not hypre's flag

    AmgSolve r;
    HYPRE_PCGGetNumIterations(s.pcg, &r.iterations);
    HYPRE_PCGGetFinalRelativeResidualNorm(s.pcg, &r.residual);
    r.converged = r.residual <= tolerance;
    r.x.resize(std::size_t(A.n));
    const std::vector<HYPRE_BigInt> rows = all_rows(A.n);
    HYPRE_IJVectorGetValues(s.x, A.n, rows.data(), r.x.data());
    const std::size_t heap1 = heap_in_use(); // hypre's objects are still alive here
    r.memory_bytes = heap1 > heap0 ? heap1 - heap0 : 0;
    return r;
}

} // namespace drydem::analysis
