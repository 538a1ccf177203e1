// SPDX-License-Identifier: MIT
// Linear operators on the particles' velocities, assembled from the laws' pair and body forms
// (forces/resistance.hpp):  A x = -(the forces and torques the coefficients give for the
// velocities x),  x and y holding 6 values per particle (v, then ω). The stability guard's R and K
// (stability.cpp) and the quasi-static step's M/Δt + R + Δt K (quasi_static.cpp) are such operators.
// Each thread owns the particles of its rows and the entries they own; every sum runs over the
// threads in a fixed order, so a product is the same run to run for a given thread count.
#pragma once
#include "drydem/forces/resistance.hpp"
#include <omp.h>
#include <cstdint>
#include <vector>

namespace drydem {

struct OperatorPair {
    std::uint32_t i, j;
    Vec3 n;
    PairResistance c; ///< coefficients with lever arms
};
struct OperatorBody {
    std::uint32_t i;
    BodyResistance c;
};
struct Operator {
    std::vector<OperatorPair> pairs;
    std::vector<OperatorBody> bodies;
    void clear() {
        pairs.clear();
        bodies.clear();
    }
};

/// y += A x.
void apply_add(const Operator& a, const double* x, double* y);

/// Particles [lo(t), lo(t + 1)) are the rows of thread t.
struct RowSplit {
    std::size_t n, threads;
    [[nodiscard]] std::size_t lo(std::size_t t) const { return n * t / threads; }
};

/// y = Σ_t A_t x (one operator per thread, its rows' entries), the threads' shares added in
/// thread order; `share` is work space.
void apply_split(const std::vector<Operator>& a, const RowSplit& rows, const std::vector<double>& x,
                 std::vector<double>& y, std::vector<std::vector<double>>& share);

/// Σ_i term(i), each thread over its rows, the threads' sums added in order.
template <class Term>
double ordered_sum(const RowSplit& rows, Term&& term, std::vector<double>& partial) {
    partial.assign(rows.threads, 0.0);
#pragma omp parallel num_threads(int(rows.threads))
    {
        const std::size_t t = std::size_t(omp_get_thread_num());
        double q = 0.0;
        for (std::size_t i = rows.lo(t); i < rows.lo(t + 1); ++i) q += term(i);
        partial[t] = q;
    }
    double q = 0.0;
    for (double v : partial) q += v;
    return q;
}

} // namespace drydem
