// SPDX-License-Identifier: MIT
// Overlap census of a particle set: how far the soft contacts of the DEM let spheres interpenetrate.
// Per pair type (CB-CB, NCM-CB, NCM-NCM) and per phase on the substrate, over the overlapping pairs:
// the overlap δ = r_i + r_j - d (substrate: r - z) as a fraction of the smaller radius (mean,
// median, p99, max), and the solid volume counted twice in the lens of each overlap:
//   two spheres  V = π (r_i + r_j - d)² (d² + 2d (r_i + r_j) - 3 (r_i - r_j)²) / (12 d)
//   sphere/plane V = π δ² (3r - δ) / 3
// Good DEM practice keeps δ/r near 1 %; the drying run warns above 5 % at the 99th percentile.
#pragma once
#include "drydem/analysis/structure.hpp"
#include <cstdint>
#include <vector>

namespace drydem::analysis {

/// δ / r_smaller over the overlapping pairs of one type (all zero when there are none).
struct OverlapStats {
    std::uint64_t pairs = 0;
    double mean = 0.0, median = 0.0, p99 = 0.0, max = 0.0;
    double lens_volume = 0.0; ///< [m^3]
};

struct OverlapCensus {
    OverlapStats cb_cb, ncm_cb, ncm_ncm, cb_substrate, ncm_substrate;
    OverlapStats all;          ///< every overlap above, pooled
    double solid_volume = 0.0; ///< Σ sphere volumes [m^3]
    /// Solid volume lost to overlap lenses, as a fraction of the spheres' volume.
    [[nodiscard]] double lens_fraction() const {
        return solid_volume > 0.0 ? all.lens_volume / solid_volume : 0.0;
    }
};

/// Lens volume of two spheres of radii a and b at centre distance d (0 apart, the smaller sphere's
/// volume when one holds the other) [m^3].
[[nodiscard]] double sphere_lens_volume(double a, double b, double d);
/// Volume of the cap of a sphere of radius r that a plane cuts at overlap δ [m^3].
[[nodiscard]] double sphere_cap_volume(double r, double overlap);

[[nodiscard]] OverlapCensus overlap_census(const Structure& s);

/// Mean, median, p99 (nearest rank) and max of relative overlaps `rel` (sorted in place), with
/// their lens volume: one OverlapStats.
[[nodiscard]] OverlapStats summarise(std::vector<double>& rel, double lens_volume = 0.0);

} // namespace drydem::analysis
