// SPDX-License-Identifier: MIT
// Where the NCM surface is (docs/analysis.md, "Surfaces"): each NCM sphere's surface Σ 4π r² split
// into the parts inside another NCM sphere (contacts), below the substrate, covered by CB (within
// `cb_gap` of a CB agglomerate's surface: the agglomerate's reach, the binder film around it) and
// the rest, wetted by the free electrolyte in the pores. Exact geometry of the spheres, integrated
// with a Fibonacci lattice of points on each sphere (area error ~1/points; for one cap of height h
// the area is 2π r h, the check in the tests). The specific surface
//     a_s = A_electrolyte / (base area × thickness)   [m²/m³]
// is the interfacial area per electrode volume of porous-electrode (Newman) cell models.
#pragma once
#include "drydem/analysis/structure.hpp"

namespace drydem::analysis {

struct SurfaceOptions {
    int points = 400;       ///< lattice points per NCM sphere; 0 = no surface analysis
    double cb_gap = 0.1e-6; ///< a point within this distance of a CB surface counts as covered [m]
};

struct Surfaces {
    bool computed = false;
    double gap = 0.0;         ///< the cb_gap used [m]
    double total = 0.0;       ///< Σ 4π r² of the NCM spheres [m²]
    double ncm_contact = 0.0; ///< inside another NCM sphere [m²]
    double substrate = 0.0;   ///< below z = 0 [m²]
    double cb_overlap = 0.0;  ///< inside a CB sphere (no gap) and not in the two above [m²]
    double cb_covered = 0.0;  ///< within cb_gap of a CB sphere (includes cb_overlap) [m²]
    double electrolyte = 0.0; ///< the rest: in contact with the free electrolyte [m²]
    [[nodiscard]] double cb_covered_fraction() const {
        return total > 0 ? cb_covered / total : 0.0;
    }
    [[nodiscard]] double electrolyte_fraction() const {
        return total > 0 ? electrolyte / total : 0.0;
    }
};

[[nodiscard]] Surfaces ncm_surfaces(const Structure& s, const SurfaceOptions& o);

} // namespace drydem::analysis
