// SPDX-License-Identifier: MIT
#include "drydem/analysis/surfaces.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace drydem::analysis {

namespace {
/// Fibonacci lattice on the unit sphere: m equal-area points (z uniform in [-1, 1], golden angle).
std::vector<Vec3> fibonacci_sphere(int m) {
    std::vector<Vec3> unit(static_cast<std::size_t>(m));
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int q = 0; q < m; ++q) {
        const double z = 1.0 - (2.0 * q + 1.0) / m, rho = std::sqrt(std::max(0.0, 1.0 - z * z));
        unit[std::size_t(q)] = {rho * std::cos(golden * q), rho * std::sin(golden * q), z};
    }
    return unit;
}
} // namespace

Surfaces ncm_surfaces(const Structure& s, const SurfaceOptions& o) {
    Surfaces out;
    out.gap = o.cb_gap;
    if (o.points <= 0 || s.size() == 0) return out;
    if (!(o.cb_gap >= 0.0)) throw InputError(fmt::format("surfaces: CB gap {} m must be >= 0", o.cb_gap));
    out.computed = true;
    const std::size_t n = s.size();
    double r_max = 0.0, z_min = INFINITY, z_max = -INFINITY;
    for (std::size_t i = 0; i < n; ++i) {
        r_max = std::max(r_max, s.radius[i]);
        z_min = std::min(z_min, s.position[i].z);
        z_max = std::max(z_max, s.position[i].z);
    }
    // Cells at least as wide as the farthest partner (2 r_max + gap), at least 3 per periodic side.
    const double reach = 2.0 * r_max + o.cb_gap;
    const int nx = std::max(1, int(s.box.lx / reach)), ny = std::max(1, int(s.box.ly / reach));
    const int nz = std::max(1, int((z_max - z_min) / reach) + 1);
    const double cx = s.box.lx / nx, cy = s.box.ly / ny;
    auto cell = [&](const Vec3& p, int& ix, int& iy, int& iz) {
        ix = std::clamp(int(p.x / cx), 0, nx - 1);
        iy = std::clamp(int(p.y / cy), 0, ny - 1);
        iz = std::clamp(int((p.z - z_min) / reach), 0, nz - 1);
    };
    std::vector<std::vector<std::uint32_t>> cells(std::size_t(nx) * ny * nz);
    for (std::size_t i = 0; i < n; ++i) {
        int ix, iy, iz;
        cell(s.position[i], ix, iy, iz);
        cells[(std::size_t(iz) * ny + iy) * nx + ix].push_back(std::uint32_t(i));
    }
    const int m = o.points;
    const std::vector<Vec3> unit = fibonacci_sphere(m);
    auto wrap = [](double d, double l) { return d - l * std::round(d / l); };
    double total = 0, contact = 0, substrate = 0, overlap = 0, covered = 0, free = 0;
#pragma omp parallel for schedule(dynamic, 16) reduction(+ : total, contact, substrate, overlap, covered, free)
    for (std::size_t i = 0; i < n; ++i) {
        if (s.phase[i] != Phase::ncm) continue;
        const Vec3 c = s.position[i];
        const double r = s.radius[i];
        // Partners whose (gap-inflated) sphere reaches this one; offsets as minimum images.
        struct Partner {
            Vec3 d;
            double r2, r2gap;
            bool ncm;
        };
        std::vector<Partner> near;
        int ix, iy, iz;
        cell(c, ix, iy, iz);
        for (int dz = -1; dz <= 1; ++dz) {
            const int jz = iz + dz;
            if (jz < 0 || jz >= nz) continue;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    if ((ny < 3 && dy != 0 && (dy == 1 || ny == 1)) || (nx < 3 && dx != 0 && (dx == 1 || nx == 1)))
                        continue; // fewer than 3 cells: each cell once
                    const int jx = (ix + dx + nx) % nx, jy = (iy + dy + ny) % ny;
                    for (std::uint32_t j : cells[(std::size_t(jz) * ny + jy) * nx + jx]) {
                        if (j == i) continue;
                        const Vec3 d{wrap(s.position[j].x - c.x, s.box.lx), wrap(s.position[j].y - c.y, s.box.ly),
                                     s.position[j].z - c.z};
                        const bool ncm = s.phase[j] == Phase::ncm;
                        const double rj = s.radius[j], reach_j = rj + (ncm ? 0.0 : o.cb_gap);
                        if (d.x * d.x + d.y * d.y + d.z * d.z >= (r + reach_j) * (r + reach_j)) continue;
                        near.push_back({d, rj * rj, reach_j * reach_j, ncm});
                    }
                }
        }
        const double w = 4.0 * std::numbers::pi * r * r / m;
        total += 4.0 * std::numbers::pi * r * r;
        for (const Vec3& u : unit) {
            const Vec3 p{r * u.x, r * u.y, r * u.z}; // relative to c
            if (c.z + p.z < 0.0) {
                substrate += w;
                continue;
            }
            bool in_ncm = false, in_cb = false, near_cb = false;
            for (const Partner& q : near) {
                const double ex = p.x - q.d.x, ey = p.y - q.d.y, ez = p.z - q.d.z;
                const double e2 = ex * ex + ey * ey + ez * ez;
                if (q.ncm) in_ncm |= e2 < q.r2;
                else {
                    in_cb |= e2 < q.r2;
                    near_cb |= e2 < q.r2gap;
                }
            }
            if (in_ncm) contact += w;
            else if (near_cb) {
                covered += w;
                if (in_cb) overlap += w;
            } else free += w;
        }
    }
    out.total = total;
    out.ncm_contact = contact;
    out.substrate = substrate;
    out.cb_overlap = overlap;
    out.cb_covered = covered;
    out.electrolyte = free;
    return out;
}

} // namespace drydem::analysis
