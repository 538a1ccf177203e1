// SPDX-License-Identifier: MIT
#include "drydem/analysis/pore_size.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace drydem::analysis {

namespace {

/// A ball to paint: position within its layer (j nx + i) and squared radius; 8 bytes.
struct Center {
    std::uint32_t in_layer;
    std::uint32_t r2;
};

/// floor(sqrt(v)) for every 16-bit v.
const std::vector<std::uint8_t>& isqrt_table() {
    static const std::vector<std::uint8_t> t = [] {
        std::vector<std::uint8_t> v(65536);
        for (std::uint32_t x = 0; x < 65536; ++x) {
            std::uint32_t s = std::uint32_t(std::sqrt(double(x)));
            while (s * s > x) --s;
            while ((s + 1) * (s + 1) <= x) ++s;
            v[x] = std::uint8_t(s);
        }
        return v;
    }();
    return t;
}

/// Neighbour offsets of the ridge test: all o ≠ 0 with |o|² ≤ 6 (a 5 x 5 x 5 block without its
/// corners and edges' ends), with their lengths.
struct Offset {
    int di, dj, dk;
    float length;
};
const std::vector<Offset>& ridge_offsets() {
    static const std::vector<Offset> o = [] {
        std::vector<Offset> v;
        for (int dk = -2; dk <= 2; ++dk)
            for (int dj = -2; dj <= 2; ++dj)
                for (int di = -2; di <= 2; ++di) {
                    const int n2 = di * di + dj * dj + dk * dk;
                    if (n2 > 0 && n2 <= 6) v.push_back({di, dj, dk, float(std::sqrt(double(n2)))});
                }
        std::sort(v.begin(), v.end(),
                  [](const Offset& a, const Offset& b) { return a.length < b.length; });
        return v;
    }();
    return o;
}

/// Centres whose ball lies inside a neighbour's ball with at least the same value are dropped: the
/// neighbour paints at least as much everywhere. The lattice points of the ball {|p - c|² < v} are
/// within sqrt(v - 1) of c, so B(c) ⊂ B(n) when sqrt(v - 1) + |n - c| < sqrt(w).
std::vector<std::vector<Center>> ridge(const VoxelGrid& g, const std::vector<std::uint16_t>& r2) {
    std::vector<float> root(65536);
    for (std::size_t x = 0; x < root.size(); ++x) root[x] = float(std::sqrt(double(x)));
    const auto& offsets = ridge_offsets();
    // Away from the periodic seams and the bottom and top layers every offset is a fixed step in
    // memory; there the test needs no wrapping (two integer divisions per offset cost more than
    // the rest of the test, and this runs on every pore voxel of a 5e8-voxel film).
    const std::ptrdiff_t nx = g.nx, nxy = nx * g.ny;
    std::vector<std::ptrdiff_t> step(offsets.size());
    for (std::size_t a = 0; a < offsets.size(); ++a)
        step[a] = offsets[a].di + offsets[a].dj * nx + offsets[a].dk * nxy;
    std::vector<std::vector<Center>> by_layer(std::size_t(g.nz));
#pragma omp parallel for schedule(dynamic, 1)
    for (int k = 0; k < g.nz; ++k) {
        auto& out = by_layer[std::size_t(k)];
        const bool k_inner = k >= 2 && k + 2 < g.nz;
        for (int j = 0; j < g.ny; ++j) {
            const bool j_inner = k_inner && j >= 2 && j + 2 < g.ny;
            for (int i = 0; i < g.nx; ++i) {
                const std::size_t idx = g.index(i, j, k);
                const std::uint16_t v = r2[idx];
                if (v == 0) continue;
                // A small margin keeps float rounding from dropping a centre that is not covered.
                const float inner = root[v - 1u] + 1e-3f;
                // B(c) ⊂ B(n) for a neighbour n at distance `length` with value w.
                auto contains = [&](std::uint16_t w, float length) {
                    return w >= v && root[w] > inner + length;
                };
                bool covered = false;
                if (j_inner && i >= 2 && i + 2 < g.nx) {
                    const std::uint16_t* here = r2.data() + idx;
                    for (std::size_t a = 0; a < offsets.size() && !covered; ++a) {
                        const std::uint16_t w = here[step[a]];
                        covered = contains(w, offsets[a].length);
                    }
                } else {
                    for (const Offset& o : offsets) {
                        const int kk = k + o.dk;
                        if (kk < 0 || kk >= g.nz) continue;
                        const int jj = (j + o.dj + g.ny) % g.ny, ii = (i + o.di + g.nx) % g.nx;
                        const std::uint16_t w = r2[g.index(ii, jj, kk)];
                        if (contains(w, o.length)) {
                            covered = true;
                            break;
                        }
                    }
                }
                if (!covered) out.push_back({std::uint32_t(j * g.nx + i), v});
            }
        }
    }
    return by_layer;
}

/// out[x] = max(out[x], v) over the periodic row segment [c - h, c + h].
inline void paint_row(std::uint16_t* row, int nx, int c, int h, std::uint16_t v) {
    auto seg = [row, v](int a, int b) { // [a, b)
        for (int x = a; x < b; ++x) row[x] = std::max(row[x], v);
    };
    if (2 * h + 1 >= nx) {
        seg(0, nx);
        return;
    }
    int a = c - h, b = c + h + 1;
    if (a < 0) {
        seg(a + nx, nx);
        a = 0;
    }
    if (b > nx) {
        seg(0, b - nx);
        b = nx;
    }
    seg(a, b);
}

} // namespace

std::vector<std::uint16_t> paint_balls(const VoxelGrid& g, const std::vector<std::uint16_t>& r2) {
    const auto& isq = isqrt_table();
    const auto centers = ridge(g, r2);
    std::uint32_t max_r2 = 0;
    for (const auto& layer : centers)
        for (const Center& c : layer) max_r2 = std::max(max_r2, c.r2);
    const int reach = int(isq[std::min<std::uint32_t>(max_r2, 65535)]) + 1;
    std::vector<std::uint16_t> out(g.size(), 0);
    // Each thread owns a slab of layers and paints the parts of the balls inside it: no races.
    constexpr int slab = 4;
    const int slabs = (g.nz + slab - 1) / slab;
#pragma omp parallel for schedule(dynamic, 1)
    for (int s = 0; s < slabs; ++s) {
        const int z0 = s * slab, z1 = std::min(g.nz, z0 + slab);
        for (int kc = std::max(0, z0 - reach); kc < std::min(g.nz, z1 + reach); ++kc) {
            for (const Center& c : centers[std::size_t(kc)]) {
                const int ci = int(c.in_layer % std::uint32_t(g.nx)),
                          cj = int(c.in_layer / std::uint32_t(g.nx));
                const int r = isq[c.r2 - 1]; // |dk| ≤ r with dk² < r²
                const int k_lo = std::max(z0, kc - r), k_hi = std::min(z1 - 1, kc + r);
                for (int k = k_lo; k <= k_hi; ++k) {
                    const std::uint32_t rem_k = c.r2 - std::uint32_t((k - kc) * (k - kc));
                    const int hj = isq[rem_k - 1];
                    for (int dj = -hj; dj <= hj; ++dj) {
                        const std::uint32_t rem = rem_k - std::uint32_t(dj * dj);
                        const int hi = isq[rem - 1];
                        int jj = cj + dj; // |dj| < ny wraps once; a larger ball needs the modulo
                        if (hj < g.ny)
                            jj += jj < 0 ? g.ny : (jj >= g.ny ? -g.ny : 0);
                        else
                            jj = (jj % g.ny + g.ny) % g.ny;
                        paint_row(out.data() + g.index(0, jj, k), g.nx, ci, hi,
                                  std::uint16_t(c.r2));
                    }
                }
            }
        }
    }
    return out;
}

std::vector<std::uint16_t> local_thickness(const VoxelGrid& g,
                                           const std::vector<std::uint16_t>& d2) {
    return paint_balls(g, d2);
}

std::vector<std::uint16_t> invasion_levels(const VoxelGrid& g,
                                           const std::vector<std::uint16_t>& d2) {
    if (g.size() >= std::numeric_limits<std::uint32_t>::max())
        throw InputError(
            fmt::format("voxel image of {} voxels: intrusion supports fewer than 2^32; "
                        "use a coarser voxel size",
                        g.size()));
    std::vector<std::uint16_t> level(g.size(), 0);
    // Bucket queue of the widest-path search, highest level first: a voxel's first level is final,
    // because every later pop has a level no higher than the one that reached it.
    std::vector<std::vector<std::uint32_t>> bucket(65536);
    int top_bucket = 0;
    const int kt = g.nz - 1;
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const std::size_t idx = g.index(i, j, kt);
            if (d2[idx] == 0) continue;
            level[idx] = d2[idx];
            bucket[d2[idx]].push_back(std::uint32_t(idx));
            top_bucket = std::max(top_bucket, int(d2[idx]));
        }
    const std::size_t nx = std::size_t(g.nx), nxy = nx * std::size_t(g.ny);
    const std::uint32_t nx32 = std::uint32_t(nx), nxy32 = std::uint32_t(nxy);
    for (int b = top_bucket; b > 0; --b) {
        auto& q = bucket[std::size_t(b)];
        while (!q.empty()) {
            const std::uint32_t idx = q.back();
            q.pop_back();
            // 32-bit divisions: two of them, not four 64-bit ones, per popped voxel.
            const std::uint32_t k32 = idx / nxy32, rem = idx - k32 * nxy32, j32 = rem / nx32;
            const std::size_t k = k32, j = j32, i = rem - j32 * nx32;
            std::array<std::size_t, 6> nb;
            int m = 0;
            nb[std::size_t(m++)] = idx - i + (i + 1) % nx;
            nb[std::size_t(m++)] = idx - i + (i + nx - 1) % nx;
            nb[std::size_t(m++)] = idx - j * nx + ((j + 1) % std::size_t(g.ny)) * nx;
            nb[std::size_t(m++)] =
                idx - j * nx + ((j + std::size_t(g.ny) - 1) % std::size_t(g.ny)) * nx;
            if (k + 1 < std::size_t(g.nz)) nb[std::size_t(m++)] = idx + nxy;
            if (k > 0) nb[std::size_t(m++)] = idx - nxy;
            for (int a = 0; a < m; ++a) {
                const std::size_t n = nb[std::size_t(a)];
                if (d2[n] == 0 || level[n] != 0) continue;
                const std::uint16_t l = std::min<std::uint16_t>(std::uint16_t(b), d2[n]);
                level[n] = l;
                bucket[l].push_back(std::uint32_t(n));
            }
        }
        std::vector<std::uint32_t>().swap(q); // give the bucket's memory back
    }
    return level;
}

std::vector<std::uint16_t> intrusion_map(const VoxelGrid& g,
                                         const std::vector<std::uint16_t>& levels) {
    return paint_balls(g, levels);
}

} // namespace drydem::analysis
