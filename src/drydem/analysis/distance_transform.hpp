// SPDX-License-Identifier: MIT
// Exact Euclidean distance transform of the pore space (Felzenszwalb & Huttenlocher 2012, "Distance
// transforms of sampled functions": the lower envelope of parabolas, one linear-time 1D pass per
// axis). Distances are in voxel units, between voxel centres; x and y periodic, the substrate is a
// solid plane of voxel centres at k = -1, nothing solid above the last layer.
#pragma once
#include "drydem/analysis/voxel_grid.hpp"
#include <cstdint>
#include <vector>

namespace drydem::analysis {

/// Squared distances fit 16 bits (0.5 bytes per voxel more than the labels): exact below
/// `squared_distance_cap`, which means "at least 255.99 voxels" (25.6 µm at 0.1 µm voxels).
inline constexpr std::uint32_t squared_distance_cap = 65535;

/// For every voxel the squared distance (voxel units) from its centre to the nearest solid voxel
/// centre (label ≠ 0, or the substrate plane); 0 for solid voxels. OpenMP over lines.
[[nodiscard]] std::vector<std::uint16_t> squared_distance_to_solid(const VoxelGrid& g);

/// 1D squared distance transform of a sampled function (exposed for tests): out[q] =
/// min_p (q - p)² + f[p] over p with f[p] < `absent`; `periodic` takes the images p ± n as well,
/// `solid_before` adds a zero at p = -1. Results at or above `cap` are stored as `cap`.
void distance_transform_1d(const std::uint32_t* f, int n, bool periodic, bool solid_before,
                           std::uint32_t absent, std::uint32_t cap, std::uint32_t* out,
                           std::vector<double>& work_z, std::vector<int>& work_v,
                           std::vector<std::uint32_t>& work_f);

} // namespace drydem::analysis
