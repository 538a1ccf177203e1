// SPDX-License-Identifier: MIT
#include "drydem/analysis/voxel_grid.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <cmath>

namespace drydem::analysis {

VoxelDims voxel_dims(const Structure& s, double voxel, double top) {
    if (!(voxel > 0.0)) throw InputError(fmt::format("voxel size {} m: must be positive", voxel));
    const int nx = std::max(1, int(std::lround(s.box.lx / voxel)));
    const int ny = std::max(1, int(std::lround(s.box.ly / voxel)));
    const int nz = std::max(1, int(std::ceil(top / voxel - 1e-9)));
    return {nx, ny, nz};
}

VoxelGrid crop_xy(const VoxelGrid& g, int nx, int ny) {
    if (nx < 1 || ny < 1 || nx > g.nx || ny > g.ny)
        throw InputError(fmt::format("window of {} x {} voxels outside the image of {} x {}", nx,
                                     ny, g.nx, g.ny));
    VoxelGrid w;
    w.nx = nx;
    w.ny = ny;
    w.nz = g.nz;
    w.ax = g.ax;
    w.ay = g.ay;
    w.az = g.az;
    w.label.resize(std::size_t(nx) * std::size_t(ny) * std::size_t(g.nz));
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < ny; ++j)
            std::copy_n(g.label.begin() + std::ptrdiff_t(g.index(0, j, k)), nx,
                        w.label.begin() + std::ptrdiff_t(w.index(0, j, k)));
    return w;
}

std::size_t voxel_count(const Structure& s, double voxel, double top) {
    const VoxelDims d = voxel_dims(s, voxel, top);
    return std::size_t(d.nx) * std::size_t(d.ny) * std::size_t(d.nz);
}

VoxelGrid voxelize(const Structure& s, double voxel, double top) {
    const VoxelDims d = voxel_dims(s, voxel, top);
    VoxelGrid g;
    g.nx = d.nx;
    g.ny = d.ny;
    g.nz = d.nz;
    g.ax = s.box.lx / d.nx;
    g.ay = s.box.ly / d.ny;
    g.az = voxel;
    g.label.assign(std::size_t(d.nx) * std::size_t(d.ny) * std::size_t(d.nz), label_pore);
    // Spheres by the layers they cut: CB first, then NCM painted over them.
    std::vector<std::vector<std::uint32_t>> by_layer(std::size_t(g.nz));
    for (int pass = 0; pass < 2; ++pass) {
        const Phase want = pass == 0 ? Phase::cb : Phase::ncm;
        for (std::size_t i = 0; i < s.size(); ++i) {
            if (s.phase[i] != want) continue;
            const double zc = s.position[i].z, r = s.radius[i];
            const int k0 = std::max(0, int(std::ceil((zc - r) / g.az - 0.5)));
            const int k1 = std::min(g.nz - 1, int(std::floor((zc + r) / g.az - 0.5)));
            for (int k = k0; k <= k1; ++k) by_layer[std::size_t(k)].push_back(std::uint32_t(i));
        }
    }
#pragma omp parallel for schedule(dynamic, 1)
    for (int k = 0; k < g.nz; ++k) {
        const double z = (k + 0.5) * g.az;
        std::uint8_t* layer = g.label.data() + g.index(0, 0, k);
        for (std::uint32_t i : by_layer[std::size_t(k)]) {
            const Vec3& c = s.position[i];
            const double r2 = s.radius[i] * s.radius[i] - (z - c.z) * (z - c.z);
            if (r2 < 0.0) continue;
            const double rd = std::sqrt(r2); // disk radius in this layer
            const std::uint8_t lab = s.phase[i] == Phase::ncm ? label_ncm : label_cb;
            const int j0 = int(std::ceil((c.y - rd) / g.ay - 0.5)),
                      j1 = int(std::floor((c.y + rd) / g.ay - 0.5));
            for (int j = j0; j <= j1; ++j) {
                const double dy = (j + 0.5) * g.ay - c.y;
                const double w2 = r2 - dy * dy;
                if (w2 < 0.0) continue;
                const double w = std::sqrt(w2);
                const int i0 = int(std::ceil((c.x - w) / g.ax - 0.5)),
                          i1 = int(std::floor((c.x + w) / g.ax - 0.5));
                const int jj = ((j % g.ny) + g.ny) % g.ny;
                std::uint8_t* row = layer + std::size_t(jj) * std::size_t(g.nx);
                if (i1 - i0 + 1 >= g.nx) {
                    std::fill(row, row + g.nx, lab);
                    continue;
                }
                for (int ii = i0; ii <= i1; ++ii) row[((ii % g.nx) + g.nx) % g.nx] = lab;
            }
        }
    }
    return g;
}

} // namespace drydem::analysis
