// SPDX-License-Identifier: MIT
#include "drydem/analysis/distance_transform.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace drydem::analysis {

void distance_transform_1d(const std::uint32_t* f, int n, bool periodic, bool solid_before,
                           std::uint32_t absent, std::uint32_t cap, std::uint32_t* out,
                           std::vector<double>& z, std::vector<int>& v,
                           std::vector<std::uint32_t>& fv) {
    // Sample positions: [0, n), with the periodic images within half a period on either side
    // (the nearest image of any point is closer than n/2), and the substrate at -1.
    const int halo = periodic ? n / 2 + 1 : 0;
    const int lo = -halo, hi = n + halo;
    const std::size_t cap_n = std::size_t(hi - lo) + 2;
    if (v.size() < cap_n) {
        v.resize(cap_n);
        fv.resize(cap_n);
        z.resize(cap_n + 1);
    }
    int k = -1; // index of the rightmost parabola of the lower envelope
    auto push = [&](int q, double fq) {
        // Eq. of the intersection of the parabolas rooted at q and v[k]:
        // s = ((f(q) + q²) - (f(v) + v²)) / (2q - 2v).
        while (k >= 0) {
            const double vk = v[std::size_t(k)];
            const double s =
                ((fq + double(q) * q) - (double(fv[std::size_t(k)]) + vk * vk)) / (2.0 * (q - vk));
            if (s <= z[std::size_t(k)]) {
                --k;
                continue;
            }
            ++k;
            v[std::size_t(k)] = q;
            fv[std::size_t(k)] = std::uint32_t(fq);
            z[std::size_t(k)] = s;
            z[std::size_t(k) + 1] = std::numeric_limits<double>::infinity();
            return;
        }
        k = 0;
        v[0] = q;
        fv[0] = std::uint32_t(fq);
        z[0] = -std::numeric_limits<double>::infinity();
        z[1] = std::numeric_limits<double>::infinity();
    };
    if (solid_before) push(-1, 0.0);
    for (int p = lo; p < hi; ++p) {
        const int pm = periodic ? ((p % n) + n) % n : p;
        const std::uint32_t fp = f[pm];
        if (fp < absent) push(p, double(fp));
    }
    if (k < 0) {
        std::fill(out, out + n, cap);
        return;
    }
    int j = 0;
    for (int q = 0; q < n; ++q) {
        while (z[std::size_t(j) + 1] < q) ++j;
        const double dq = double(q) - v[std::size_t(j)];
        const double val = dq * dq + double(fv[std::size_t(j)]);
        out[q] = val >= double(cap) ? cap : std::uint32_t(val);
    }
}

namespace {

/// Applies the 1D transform along an axis with `stride` between samples, on tiles of `tile`
/// lines adjacent in memory (stride 1 along x), so the gathers read whole cache lines.
template <class Get>
void pass(std::vector<std::uint16_t>& d, std::size_t lines_outer, std::size_t lines_inner,
          std::size_t outer_step, int n, std::size_t stride, bool periodic, bool solid_before,
          Get get_input) {
    constexpr std::size_t tile = 16;
    const std::uint32_t cap = squared_distance_cap;
    const std::uint32_t absent = cap; // a capped value stands for "at least cap": never the nearest
#pragma omp parallel
    {
        std::vector<std::uint32_t> in(std::size_t(n) * tile);
        std::vector<std::uint32_t> res(static_cast<std::size_t>(n));
        std::vector<double> wz;
        std::vector<int> wv;
        std::vector<std::uint32_t> wf;
        const std::size_t tiles_inner = (lines_inner + tile - 1) / tile;
#pragma omp for schedule(dynamic, 4)
        for (std::size_t t = 0; t < lines_outer * tiles_inner; ++t) {
            const std::size_t o = t / tiles_inner, i0 = (t % tiles_inner) * tile;
            const std::size_t w = std::min(tile, lines_inner - i0);
            const std::size_t base = o * outer_step + i0;
            for (int q = 0; q < n; ++q)
                for (std::size_t l = 0; l < w; ++l)
                    in[l * std::size_t(n) + std::size_t(q)] =
                        get_input(base + std::size_t(q) * stride + l);
            for (std::size_t l = 0; l < w; ++l) {
                distance_transform_1d(in.data() + l * std::size_t(n), n, periodic, solid_before,
                                      absent, cap, res.data(), wz, wv, wf);
                for (int q = 0; q < n; ++q)
                    d[base + std::size_t(q) * stride + l] = std::uint16_t(res[std::size_t(q)]);
            }
        }
    }
}

} // namespace

std::vector<std::uint16_t> squared_distance_to_solid(const VoxelGrid& g) {
    std::vector<std::uint16_t> d(g.size());
    const std::size_t nx = std::size_t(g.nx), ny = std::size_t(g.ny), nz = std::size_t(g.nz);
    const std::uint32_t cap = squared_distance_cap;
    // x: lines along x, one per (j, k); inner "tile" of 1 (x is the contiguous axis itself).
    {
#pragma omp parallel
        {
            std::vector<std::uint32_t> in(nx), res(nx);
            std::vector<double> wz;
            std::vector<int> wv;
            std::vector<std::uint32_t> wf;
#pragma omp for schedule(static)
            for (std::size_t row = 0; row < ny * nz; ++row) {
                const std::size_t base = row * nx;
                for (std::size_t i = 0; i < nx; ++i)
                    in[i] = g.label[base + i] != label_pore ? 0u : cap;
                distance_transform_1d(in.data(), g.nx, true, false, cap, cap, res.data(), wz, wv,
                                      wf);
                for (std::size_t i = 0; i < nx; ++i) d[base + i] = std::uint16_t(res[i]);
            }
        }
    }
    const auto read = [&d](std::size_t idx) { return std::uint32_t(d[idx]); };
    // y: for each k, lines along y (stride nx), tiles across x.
    pass(d, nz, nx, nx * ny, g.ny, nx, true, false, read);
    // z: lines along z (stride nx ny), tiles across x, one outer index per y; substrate below.
    pass(d, ny, nx, nx, g.nz, nx * ny, false, true, read);
    return d;
}

} // namespace drydem::analysis
