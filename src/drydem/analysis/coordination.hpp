// SPDX-License-Identifier: MIT
// Coordination numbers per pair type (NCM-NCM, NCM-CB, CB-CB, each phase with the substrate).
// Two spheres are in contact when their surface gap d - r_i - r_j is at most `gap` (0 = touching
// or overlapping); a sphere touches the substrate when z - r ≤ gap.
#pragma once
#include "drydem/analysis/structure.hpp"
#include <cstdint>
#include <vector>

namespace drydem::analysis {

struct Coordination {
    double gap = 0.0;
    std::uint64_t ncm_ncm = 0, ncm_cb = 0, cb_cb = 0;  ///< contact counts
    std::uint64_t ncm_substrate = 0, cb_substrate = 0; ///< spheres on the substrate
    std::uint64_t n_ncm = 0, n_cb = 0;                 ///< sphere counts
    std::vector<std::uint32_t> per_particle;           ///< contacts of each sphere (no substrate)
    // Mean coordination: partners of a type per sphere of a type.
    [[nodiscard]] double ncm_with_ncm() const {
        return n_ncm ? 2.0 * double(ncm_ncm) / double(n_ncm) : 0.0;
    }
    [[nodiscard]] double ncm_with_cb() const {
        return n_ncm ? double(ncm_cb) / double(n_ncm) : 0.0;
    }
    [[nodiscard]] double cb_with_ncm() const { return n_cb ? double(ncm_cb) / double(n_cb) : 0.0; }
    [[nodiscard]] double cb_with_cb() const {
        return n_cb ? 2.0 * double(cb_cb) / double(n_cb) : 0.0;
    }
    [[nodiscard]] double mean() const {
        const double n = double(n_ncm + n_cb);
        return n > 0 ? 2.0 * double(ncm_ncm + ncm_cb + cb_cb) / n : 0.0;
    }
};

/// Contacts by a cell search, periodic in x and y (spheres must be wrapped into the box).
[[nodiscard]] Coordination coordination(const Structure& s, double gap = 0.0);

} // namespace drydem::analysis
