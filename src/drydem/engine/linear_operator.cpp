// SPDX-License-Identifier: MIT
#include "drydem/engine/linear_operator.hpp"
#include <algorithm>

namespace drydem {

void apply_add(const Operator& a, const double* x, double* y) {
    auto v = [&](std::uint32_t i) { return Vec3{x[6 * i], x[6 * i + 1], x[6 * i + 2]}; };
    auto w = [&](std::uint32_t i) { return Vec3{x[6 * i + 3], x[6 * i + 4], x[6 * i + 5]}; };
    auto add = [&](std::uint32_t i, const Vec3& f, const Vec3& t) {
        y[6 * i] -= f.x, y[6 * i + 1] -= f.y, y[6 * i + 2] -= f.z; // A x = -(force of x)
        y[6 * i + 3] -= t.x, y[6 * i + 4] -= t.y, y[6 * i + 5] -= t.z;
    };
    for (const OperatorPair& e : a.pairs) {
        const PairForce f = resistance_force(e.c, e.n, v(e.i) - v(e.j), w(e.i), w(e.j));
        add(e.i, f.force_i, f.torque_i);
        add(e.j, -f.force_i, f.torque_j);
    }
    for (const OperatorBody& e : a.bodies) {
        const BodyForce f = resistance_force(e.c, v(e.i), w(e.i));
        add(e.i, f.force, f.torque);
    }
}

void apply_split(const std::vector<Operator>& a, const RowSplit& rows, const std::vector<double>& x,
                 std::vector<double>& y, std::vector<std::vector<double>>& share) {
    const std::size_t threads = rows.threads, m = 6 * rows.n;
    y.resize(m);
    if (threads == 1) {
        std::fill(y.begin(), y.end(), 0.0);
        apply_add(a[0], x.data(), y.data());
        return;
    }
    share.resize(threads);
#pragma omp parallel num_threads(int(threads))
    {
        const std::size_t t = std::size_t(omp_get_thread_num());
        std::vector<double>& y_t = share[t];
        y_t.assign(m, 0.0);
        apply_add(a[t], x.data(), y_t.data());
#pragma omp barrier
        for (std::size_t k = 6 * rows.lo(t); k < 6 * rows.lo(t + 1); ++k) {
            double sum = 0.0;
            for (std::size_t u = 0; u < threads; ++u) sum += share[u][k];
            y[k] = sum;
        }
    }
}

} // namespace drydem
