// SPDX-License-Identifier: MIT
// Chord length distribution of the pore space along x, y and z (as GeoDict PoroDict): a chord is a
// maximal run of pore voxels on a grid line. Along x and y the lines are periodic (a run may wrap;
// a line that is pore throughout has no chord and is counted apart); along z a run starting at the
// substrate is a chord, a run reaching the top of the analysed region is cut and left out.
#pragma once
#include "drydem/analysis/voxel_grid.hpp"
#include <array>
#include <cstdint>
#include <vector>

namespace drydem::analysis {

struct ChordHistogram {
    std::vector<std::uint64_t> count; ///< count[n] = chords of n voxels (n ≥ 1)
    std::uint64_t open_lines = 0;     ///< lines without any solid (x, y) / runs cut at the top (z)
    [[nodiscard]] std::uint64_t chords() const;
    [[nodiscard]] double mean_voxels() const; ///< number-weighted mean length [voxels]
    [[nodiscard]] double length_weighted_mean_voxels() const;
};

/// Histograms along x, y, z of the layers k < k_top (the analysed region).
[[nodiscard]] std::array<ChordHistogram, 3> chord_lengths(const VoxelGrid& g, int k_top);

} // namespace drydem::analysis
