// SPDX-License-Identifier: MIT
// Every pair of spheres whose surface gap d - r_i - r_j is at most `gap`, by a cell search periodic
// in x and y (spheres wrapped into the box). Shared by the coordination count and the overlap
// census, so that both see the same pairs.
#pragma once
#include "drydem/analysis/structure.hpp"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace drydem::analysis {

/// Calls visit(i, j, d) once per pair i < j within the gap, d the minimum-image vector i -> j.
template <class Visit>
void for_each_close_pair(const Structure& s, double gap, Visit&& visit) {
    const std::size_t n = s.size();
    if (n < 2) return;
    double r_max = 0.0, z_min = INFINITY, z_max = -INFINITY;
    for (std::size_t i = 0; i < n; ++i) {
        r_max = std::max(r_max, s.radius[i]);
        z_min = std::min(z_min, s.position[i].z);
        z_max = std::max(z_max, s.position[i].z);
    }
    // Cells at least as wide as the longest contact distance; at least 3 per periodic side so a
    // pair is seen through exactly one neighbouring cell.
    const double reach = 2.0 * r_max + std::max(0.0, gap);
    const int nx = std::max(1, int(s.box.lx / reach)), ny = std::max(1, int(s.box.ly / reach));
    const int nz = std::max(1, int((z_max - z_min) / reach) + 1);
    const double cx = s.box.lx / nx, cy = s.box.ly / ny;
    auto cell_xyz = [&](const Vec3& a, int& ix, int& iy, int& iz) {
        ix = std::min(nx - 1, int(a.x / cx));
        iy = std::min(ny - 1, int(a.y / cy));
        iz = std::min(nz - 1, int((a.z - z_min) / reach));
    };
    const int ncell = nx * ny * nz;
    std::vector<std::uint32_t> start(std::size_t(ncell) + 1, 0), members(n), cell(n);
    for (std::size_t i = 0; i < n; ++i) {
        int ix, iy, iz;
        cell_xyz(s.position[i], ix, iy, iz);
        cell[i] = std::uint32_t((iz * ny + iy) * nx + ix);
        ++start[std::size_t(cell[i]) + 1];
    }
    for (int k = 0; k < ncell; ++k) start[std::size_t(k) + 1] += start[std::size_t(k)];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) members[fill[cell[i]]++] = std::uint32_t(i);

    // Distinct neighbouring cell offsets per axis (fewer than 3 cells: each cell once).
    auto offsets = [](int cells) {
        std::vector<int> o;
        for (int d = -1; d <= 1; ++d)
            if (std::find_if(o.begin(), o.end(), [&](int e) {
                    return ((e - d) % cells + cells) % cells == 0;
                }) == o.end())
                o.push_back(d);
        return o;
    };
    const auto ox = offsets(nx), oy = offsets(ny);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& a = s.position[i];
        int ix, iy, iz;
        cell_xyz(a, ix, iy, iz);
        for (int dz = -1; dz <= 1; ++dz) {
            const int jz = iz + dz;
            if (jz < 0 || jz >= nz) continue;
            for (int dy : oy)
                for (int dx : ox) {
                    const int jx = (ix + dx + nx) % nx, jy = (iy + dy + ny) % ny;
                    const int c = (jz * ny + jy) * nx + jx;
                    for (std::uint32_t m = start[std::size_t(c)]; m < start[std::size_t(c) + 1];
                         ++m) {
                        const std::size_t j = members[m];
                        if (j <= i) continue;
                        const Vec3 d = s.box.minimum_image(a, s.position[j]);
                        const double limit = s.radius[i] + s.radius[j] + gap;
                        if (d.x * d.x + d.y * d.y + d.z * d.z > limit * limit) continue;
                        visit(i, j, d);
                    }
                }
        }
    }
}

} // namespace drydem::analysis
