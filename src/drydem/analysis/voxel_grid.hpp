// SPDX-License-Identifier: MIT
// Labelled voxel image of a structure: 0 pore, 1 NCM, 2 CB (docs/analysis.md, voxel export), x fastest
// then y then z, voxel (i, j, k) centred at ((i + ½) a, (j + ½) a, (k + ½) a). Periodic in x and y
// (the box side is divided into whole voxels: a is adjusted per axis by < 1/n), substrate below
// k = 0, open above the last layer.
#pragma once
#include "drydem/analysis/structure.hpp"
#include <cstddef>
#include <cstdint>
#include <vector>

namespace drydem::analysis {

enum : std::uint8_t { label_pore = 0, label_ncm = 1, label_cb = 2 };

struct VoxelGrid {
    int nx = 0, ny = 0, nz = 0;
    double ax = 0.0, ay = 0.0, az = 0.0; ///< voxel edge per axis [m]
    std::vector<std::uint8_t> label;

    [[nodiscard]] std::size_t index(int i, int j, int k) const {
        return (std::size_t(k) * std::size_t(ny) + std::size_t(j)) * std::size_t(nx) +
               std::size_t(i);
    }
    [[nodiscard]] std::size_t size() const { return label.size(); }
};

/// Voxelizes z ∈ [0, top) at voxel size `voxel` (x, y: the nearest size that tiles the box). A voxel
/// is solid when its centre lies inside a sphere; where NCM and CB overlap, NCM wins (it is dense,
/// the agglomerate is not). OpenMP over z layers.
[[nodiscard]] VoxelGrid voxelize(const Structure& s, double voxel, double top);

/// Bytes the grid of `voxelize(s, voxel, top)` takes, for the memory estimate before the work.
[[nodiscard]] std::size_t voxel_count(const Structure& s, double voxel, double top);

/// Voxels per axis of `voxelize(s, voxel, top)`.
struct VoxelDims {
    int nx, ny, nz;
};
[[nodiscard]] VoxelDims voxel_dims(const Structure& s, double voxel, double top);

/// The columns i < nx, j < ny of g (all layers): a lateral window with its corner at the origin.
[[nodiscard]] VoxelGrid crop_xy(const VoxelGrid& g, int nx, int ny);

} // namespace drydem::analysis
