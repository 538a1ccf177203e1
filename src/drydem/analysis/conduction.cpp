// SPDX-License-Identifier: MIT
#include "drydem/analysis/conduction.hpp"
#include "drydem/analysis/amg_solver.hpp"
#include "drydem/core/error.hpp"
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>
#include <fmt/format.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace drydem::analysis {

namespace {

/// The grid seen along one axis: extents, edges and side conditions, neighbour lookup.
struct Lattice {
    std::array<int, 3> n;
    std::array<double, 3> a;
    std::array<bool, 3> periodic;
    int axis;
    explicit Lattice(const ConductionProblem& p)
        : n{p.nx, p.ny, p.nz}, a{p.ax, p.ay, p.az}, periodic(p.periodic), axis(p.axis) {
        periodic[std::size_t(axis)] = false; // the two fixed faces
    }
    [[nodiscard]] std::size_t size() const {
        return std::size_t(n[0]) * std::size_t(n[1]) * std::size_t(n[2]);
    }
    [[nodiscard]] std::array<int, 3> coords(std::size_t idx) const {
        const int i = int(idx % std::size_t(n[0]));
        const std::size_t rest = idx / std::size_t(n[0]);
        return {i, int(rest % std::size_t(n[1])), int(rest / std::size_t(n[1]))};
    }
    [[nodiscard]] std::size_t index(const std::array<int, 3>& c) const {
        return (std::size_t(c[2]) * std::size_t(n[1]) + std::size_t(c[1])) * std::size_t(n[0]) +
               std::size_t(c[0]);
    }
    /// Neighbour of c one step along d in direction s (±1); false where the side is closed.
    bool neighbour(std::array<int, 3> c, int d, int s, std::size_t& out) const {
        int& x = c[std::size_t(d)];
        const int m = n[std::size_t(d)];
        x += s;
        if (x < 0 || x >= m) {
            if (!periodic[std::size_t(d)] || m < 2) return false;
            x = (x + m) % m;
        }
        out = index(c);
        return true;
    }
    /// Face area over centre distance of a face normal to d [m].
    [[nodiscard]] double shape(int d) const {
        const double prod = a[0] * a[1] * a[2];
        return prod / (a[std::size_t(d)] * a[std::size_t(d)]);
    }
};

void validate(const ConductionProblem& p) {
    if (p.nx < 1 || p.ny < 1 || p.nz < 1 || !(p.ax > 0.0) || !(p.ay > 0.0) || !(p.az > 0.0))
        throw InputError(fmt::format("conduction: grid {} x {} x {} with edges {} / {} / {} m",
                                     p.nx, p.ny, p.nz, p.ax, p.ay, p.az));
    if (p.axis < 0 || p.axis > 2)
        throw InputError(fmt::format("conduction: axis {} (0, 1 or 2)", p.axis));
    if (p.sigma.size() != std::size_t(p.nx) * std::size_t(p.ny) * std::size_t(p.nz))
        throw InputError("conduction: sigma has not one value per voxel");
    for (float s : p.sigma)
        if (!(s >= 0.0f) || !std::isfinite(s))
            throw InputError("conduction: sigma must be finite and >= 0");
}

/// Flood fill of the conducting voxels from the layer at `layer` of the axis; sets `bit` in mask.
void flood(const Lattice& L, const std::vector<float>& sigma, int layer, std::uint8_t bit,
           std::vector<std::uint8_t>& mask) {
    std::vector<std::size_t> stack;
    const int d = L.axis, e1 = (d + 1) % 3, e2 = (d + 2) % 3;
    for (int u = 0; u < L.n[std::size_t(e1)]; ++u)
        for (int v = 0; v < L.n[std::size_t(e2)]; ++v) {
            std::array<int, 3> c{};
            c[std::size_t(d)] = layer;
            c[std::size_t(e1)] = u;
            c[std::size_t(e2)] = v;
            const std::size_t idx = L.index(c);
            if (sigma[idx] > 0.0f && !(mask[idx] & bit)) {
                mask[idx] |= bit;
                stack.push_back(idx);
            }
        }
    while (!stack.empty()) {
        const std::size_t idx = stack.back();
        stack.pop_back();
        const auto c = L.coords(idx);
        for (int dd = 0; dd < 3; ++dd)
            for (int s : {-1, 1}) {
                std::size_t q = 0;
                if (!L.neighbour(c, dd, s, q)) continue;
                if (sigma[q] > 0.0f && !(mask[q] & bit)) {
                    mask[q] |= bit;
                    stack.push_back(q);
                }
            }
    }
}

double harmonic(double p, double q) { return p + q > 0.0 ? 2.0 * p * q / (p + q) : 0.0; }

} // namespace

std::vector<std::uint8_t> spanning_clusters(const ConductionProblem& p) {
    validate(p);
    const Lattice L(p);
    std::vector<std::uint8_t> mask(L.size(), 0);
    flood(L, p.sigma, 0, 1, mask);
    flood(L, p.sigma, L.n[std::size_t(L.axis)] - 1, 2, mask);
    for (auto& m : mask) m = m == 3 ? 1 : 0;
    return mask;
}

namespace {

/// The finite-volume system of one conduction problem over the spanning clusters `keep`: the
/// conductance matrix in CSR (symmetric), the inlet right-hand side, the homogeneous first guess
/// and the conductances of the fixed faces.
struct ConductionSystem {
    int n = 0;
    std::vector<int> outer, inner;
    std::vector<double> values;
    Eigen::VectorXd b, guess, g_in, g_out;
};

ConductionSystem assemble(const ConductionProblem& p, const Lattice& L,
                          const std::vector<std::uint8_t>& keep, std::size_t kept) {
    const std::size_t nv = L.size();
    // Unknowns in voxel order.
    std::vector<int> row_of(nv, -1);
    std::vector<std::size_t> voxel_of(kept);
    {
        int row = 0;
        for (std::size_t i = 0; i < nv; ++i)
            if (keep[i]) {
                voxel_of[std::size_t(row)] = i;
                row_of[i] = row++;
            }
    }
    const int n = int(kept);
    ConductionSystem sys;
    sys.n = n;
    std::vector<int>& outer = sys.outer;
    std::vector<int>& inner = sys.inner;
    std::vector<double>& values = sys.values;
    const int d_axis = L.axis, last = L.n[std::size_t(d_axis)] - 1;
    const double g_face_axis = L.shape(d_axis);
    outer.assign(std::size_t(n) + 1, 0);
    inner.reserve(std::size_t(n) * 7);
    values.reserve(std::size_t(n) * 7);
    sys.b = Eigen::VectorXd::Zero(n);
    sys.guess.resize(n);
    sys.g_in = Eigen::VectorXd::Zero(n);
    sys.g_out = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd &b = sys.b, &guess = sys.guess, &g_in = sys.g_in, &g_out = sys.g_out;
    std::array<std::pair<int, double>, 7> entries{};
    for (int row = 0; row < n; ++row) {
        const std::size_t idx = voxel_of[std::size_t(row)];
        const auto c = L.coords(idx);
        const double sp = p.sigma[idx];
        int m = 0;
        double diag = 0.0;
        for (int d = 0; d < 3; ++d)
            for (int s : {-1, 1}) {
                std::size_t q = 0;
                if (!L.neighbour(c, d, s, q) || !keep[q] || q == idx) continue;
                const double g = harmonic(sp, p.sigma[q]) * L.shape(d);
                diag += g;
                entries[std::size_t(m++)] = {row_of[q], -g};
            }
        // Fixed faces: half a voxel of this voxel's own conductivity.
        const int x = c[std::size_t(d_axis)];
        if (x == 0) {
            g_in[row] = 2.0 * sp * g_face_axis;
            diag += g_in[row];
            b[row] += g_in[row]; // φ = 1 on the inlet face
        }
        if (x == last) {
            g_out[row] = 2.0 * sp * g_face_axis;
            diag += g_out[row];
        }
        entries[std::size_t(m++)] = {row, diag};
        std::sort(entries.begin(), entries.begin() + m,
                  [](const auto& u, const auto& v) { return u.first < v.first; });
        for (int e = 0; e < m; ++e) {
            if (!inner.empty() && int(inner.size()) > outer[std::size_t(row)] &&
                inner.back() == entries[std::size_t(e)].first)
                values.back() +=
                    entries[std::size_t(e)].second; // a periodic side of two voxels: both faces
            else {
                inner.push_back(entries[std::size_t(e)].first);
                values.push_back(entries[std::size_t(e)].second);
            }
        }
        outer[std::size_t(row) + 1] = int(inner.size());
        guess[row] = 1.0 - (x + 0.5) / double(last + 1); // the homogeneous solution
    }
    return sys;
}

} // namespace

ConductionResult solve_conduction(const ConductionProblem& p) {
    const auto t0 = std::chrono::steady_clock::now();
    ConductionResult r;
    const std::vector<std::uint8_t> keep = spanning_clusters(p);
    const Lattice L(p);
    const std::size_t nv = L.size();
    std::size_t conducting = 0, kept = 0;
    for (std::size_t i = 0; i < nv; ++i) {
        conducting += p.sigma[i] > 0.0f;
        kept += keep[i];
    }
    r.conducting_fraction = double(conducting) / double(nv);
    r.percolating_fraction = double(kept) / double(nv);
    r.percolates = kept > 0;
    r.memory_bytes = nv * (sizeof(float) + 1);
    auto finish = [&] {
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return r;
    };
    if (!r.percolates) return finish();
    if (kept >= std::size_t(std::numeric_limits<int>::max() / 8))
        throw InputError(fmt::format(
            "conduction: {} unknowns, too many for one solve; coarsen the voxels", kept));

    ConductionSystem sys = assemble(p, L, keep, kept);
    const int n = sys.n;
    const int d_axis = L.axis, last = L.n[std::size_t(d_axis)] - 1;
    std::vector<int>& outer = sys.outer;
    std::vector<int>& inner = sys.inner;
    std::vector<double>& values = sys.values;
    const Eigen::VectorXd &b = sys.b, &guess = sys.guess, &g_in = sys.g_in, &g_out = sys.g_out;
    // The matrix is symmetric: its row-major arrays are also its column-major ones.
    using ColMat = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
    Eigen::Map<ColMat> A(n, n, int(values.size()), outer.data(), inner.data(), values.data());
    Eigen::VectorXd phi;
    std::size_t solver_bytes = 0;
    if (p.preconditioner == Preconditioner::amg) {
        const CsrMatrix csr{n, outer.data(), inner.data(), values.data()};
        AmgSolve amg = solve_amg_pcg(csr, std::vector<double>(b.data(), b.data() + n),
                                     std::vector<double>(guess.data(), guess.data() + n),
                                     p.tolerance, p.max_iterations);
        phi = Eigen::Map<const Eigen::VectorXd>(amg.x.data(), n);
        r.iterations = amg.iterations;
        r.residual = amg.residual;
        r.converged = amg.converged;
        r.preconditioner = "BoomerAMG";
        solver_bytes = amg.memory_bytes;
    } else {
        // Eigen's incomplete Cholesky (tried) halved Jacobi's iterations, but its factorization
        // cost 10-20x a whole Jacobi solve on the pores (measured on the tiny film at 0.4 um).
        Eigen::ConjugateGradient<ColMat, Eigen::Lower | Eigen::Upper,
                                 Eigen::DiagonalPreconditioner<double>>
            cg;
        cg.setTolerance(p.tolerance);
        cg.setMaxIterations(p.max_iterations);
        cg.compute(A);
        phi = cg.solveWithGuess(b, guess);
        r.iterations = int(cg.iterations());
        r.residual = cg.error();
        r.converged = cg.info() == Eigen::Success;
        r.preconditioner = "Jacobi";
        solver_bytes = std::size_t(n) * 5 * sizeof(double); // residual, p, z, tmp, scaling
    }
    r.unknowns = std::size_t(n);
    const double i_in = g_in.dot(Eigen::VectorXd::Ones(n) - phi), i_out = g_out.dot(phi);
    r.flux_balance = i_in > 0.0 ? std::abs(i_in - i_out) / i_in : 0.0;
    const int e1 = (d_axis + 1) % 3, e2 = (d_axis + 2) % 3;
    const double area =
        L.n[std::size_t(e1)] * L.a[std::size_t(e1)] * L.n[std::size_t(e2)] * L.a[std::size_t(e2)];
    const double length = (last + 1) * L.a[std::size_t(d_axis)];
    r.sigma_eff = 0.5 * (i_in + i_out) / area * length; // Δφ = 1
    // masks + the matrix (CSR) + b, guess, φ, g_in, g_out + what the solver held.
    r.memory_bytes += nv * sizeof(int) + outer.size() * sizeof(int) +
                      values.size() * (sizeof(int) + sizeof(double)) +
                      std::size_t(n) * 5 * sizeof(double) + solver_bytes;
    return finish();
}

} // namespace drydem::analysis
