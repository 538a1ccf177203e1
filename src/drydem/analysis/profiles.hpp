// SPDX-License-Identifier: MIT
// Volume fractions over the height from exact sphere-slab intersections (not centre counting):
// the volume of a sphere of radius r centred at z_c between the planes a < b is
// π [r² u - u³/3] evaluated from u = max(a - z_c, -r) to u = min(b - z_c, r).
#pragma once
#include "drydem/analysis/structure.hpp"
#include <vector>

namespace drydem::analysis {

/// Volume of the part of a sphere (centre height zc, radius r) between z = a and z = b (a < b).
[[nodiscard]] double sphere_slab_volume(double zc, double r, double a, double b);

struct Profiles {
    double dz = 0.0;                 ///< slab width [m], slabs [k dz, (k+1) dz) from the substrate
    std::vector<double> ncm;         ///< NCM volume fraction
    std::vector<double> cb_envelope; ///< CB agglomerate envelope volume fraction
    std::vector<double> cb_carbon;   ///< carbon only: Σ (1 - ε_i) × envelope
    std::vector<double> cbd;         ///< carbon + binder, binder inside the agglomerates (M-8.4)
    std::vector<double> pore;        ///< 1 - NCM - CB envelope (pores between the spheres)
    std::vector<double> pore_total;  ///< 1 - NCM - carbon - binder (incl. the pores inside CB)
    [[nodiscard]] std::size_t size() const { return ncm.size(); }
    [[nodiscard]] std::vector<double> solid() const; ///< NCM + CB envelope
};

/// Profiles in slabs of width dz from z = 0 up to `top` (the last slab may be partial and is
/// normalised by its own height). Overlapping spheres count twice (DEM overlaps are small).
[[nodiscard]] Profiles volume_fraction_profiles(const Structure& s, double dz, double top);

} // namespace drydem::analysis
