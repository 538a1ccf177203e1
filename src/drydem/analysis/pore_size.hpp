// SPDX-License-Identifier: MIT
// Pore sizes from the distance map: the local thickness (continuous PSD: at each pore voxel the
// diameter of the largest inscribed sphere that covers it, Hildebrand & Rüegsegger 1997) and a
// simulated mercury intrusion (the pore volume a sphere of diameter d reaches from the top through
// throats at least d wide, as in PoreSpy's porosimetry) — both exact on the voxel grid.
//
// Both are max-paintings of balls: voxel p gets max r² over the centres c with |p - c|² < r²(c). For
// the local thickness r²(c) is the squared distance to the solid; for intrusion it is the invasion
// level of c, the largest r² such that a sphere of that size travels from the top layer to c through
// centres all at least that far from the solid (a widest-path problem, solved with a bucket queue).
// Centres whose ball lies inside a neighbour's ball are dropped first (the distance ridge).
#pragma once
#include "drydem/analysis/voxel_grid.hpp"
#include <cstdint>
#include <vector>

namespace drydem::analysis {

/// Local thickness as the painted squared radius per voxel (voxel units; 0 = solid). The diameter
/// of voxel p is 2 sqrt(value) voxels. `d2` = squared_distance_to_solid(g).
[[nodiscard]] std::vector<std::uint16_t> local_thickness(const VoxelGrid& g,
                                                         const std::vector<std::uint16_t>& d2);

/// Invasion level per voxel for mercury entering through the top layer (0 = solid or never reached):
/// a sphere of squared radius r² (voxel units) reaches every centre c with level(c) ≥ r².
[[nodiscard]] std::vector<std::uint16_t> invasion_levels(const VoxelGrid& g,
                                                         const std::vector<std::uint16_t>& d2);

/// Intrusion map: the squared radius of the largest intruding sphere covering each voxel (0: never
/// intruded) from the invasion levels.
[[nodiscard]] std::vector<std::uint16_t> intrusion_map(const VoxelGrid& g,
                                                       const std::vector<std::uint16_t>& levels);

/// Max-painting of the balls {p : |p - c|² < r²(c)} for all c with r² > 0 (periodic in x, y; cut at
/// the grid's bottom and top); the generic step behind local thickness and intrusion.
[[nodiscard]] std::vector<std::uint16_t> paint_balls(const VoxelGrid& g,
                                                     const std::vector<std::uint16_t>& r2);

} // namespace drydem::analysis
