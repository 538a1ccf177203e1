// SPDX-License-Identifier: MIT
#include "drydem/analysis/random_walk.hpp"
#include "drydem/core/error.hpp"
#include <chrono>
#include <cmath>
#include <vector>

namespace drydem::analysis {

namespace {
/// SplitMix64: a small, fast generator; one stream per walker keeps the result thread-independent.
struct SplitMix {
    std::uint64_t s;
    std::uint64_t next() {
        std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
};
} // namespace

RandomWalkResult random_walk(const ConductionProblem& p, long walkers, long steps,
                             std::uint64_t seed) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::size_t nv = std::size_t(p.nx) * std::size_t(p.ny) * std::size_t(p.nz);
    if (p.sigma.size() != nv || walkers < 1 || steps < 1)
        throw InputError("random walk: one sigma per voxel, at least one walker and one step");
    std::vector<std::size_t> pores;
    for (std::size_t i = 0; i < nv; ++i)
        if (p.sigma[i] > 0.0f) pores.push_back(i);
    RandomWalkResult r;
    r.walkers = walkers;
    r.steps = steps;
    if (pores.empty()) return r;
    const int n[3] = {p.nx, p.ny, p.nz};
    std::array<bool, 3> periodic = p.periodic;
    std::vector<double> sq[3];
    for (auto& v : sq) v.assign(std::size_t(walkers), 0.0);
#pragma omp parallel for schedule(dynamic, 64)
    for (long w = 0; w < walkers; ++w) {
        SplitMix rng{seed * 0x100000001B3ull + std::uint64_t(w)};
        const std::size_t start = pores[rng.next() % pores.size()];
        int c[3] = {int(start % std::size_t(p.nx)),
                    int((start / std::size_t(p.nx)) % std::size_t(p.ny)),
                    int(start / (std::size_t(p.nx) * std::size_t(p.ny)))};
        long disp[3] = {0, 0, 0};
        for (long s = 0; s < steps; ++s) {
            const std::uint64_t u = rng.next() % 6;
            const int d = int(u >> 1), dir = (u & 1) ? 1 : -1;
            int q[3] = {c[0], c[1], c[2]};
            q[d] += dir;
            if (q[d] < 0 || q[d] >= n[d]) {
                if (!periodic[std::size_t(d)]) continue; // a wall: stay
                q[d] = (q[d] + n[d]) % n[d];
            }
            const std::size_t idx =
                (std::size_t(q[2]) * std::size_t(p.ny) + std::size_t(q[1])) * std::size_t(p.nx) +
                std::size_t(q[0]);
            if (!(p.sigma[idx] > 0.0f)) continue; // blind ant: the step into the solid is lost
            c[0] = q[0];
            c[1] = q[1];
            c[2] = q[2];
            disp[d] += dir;
        }
        for (int d = 0; d < 3; ++d) sq[d][std::size_t(w)] = double(disp[d]) * double(disp[d]);
    }
    for (int d = 0; d < 3; ++d) {
        if (!periodic[std::size_t(d)]) continue;
        double mean = 0.0, var = 0.0;
        for (double v : sq[d]) mean += v;
        mean /= double(walkers);
        for (double v : sq[d]) var += (v - mean) * (v - mean);
        var /= double(std::max(1L, walkers - 1));
        const double free = double(steps) / 3.0; // ⟨Δx²⟩ of the free walk, in voxels²
        r.diffusivity[std::size_t(d)] = mean / free;
        r.standard_error[std::size_t(d)] = std::sqrt(var / double(walkers)) / free;
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}

} // namespace drydem::analysis
