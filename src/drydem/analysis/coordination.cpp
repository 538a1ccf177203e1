// SPDX-License-Identifier: MIT
#include "drydem/analysis/coordination.hpp"
#include "drydem/analysis/pair_search.hpp"

namespace drydem::analysis {

Coordination coordination(const Structure& s, double gap) {
    Coordination c;
    c.gap = gap;
    const std::size_t n = s.size();
    c.per_particle.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        (s.phase[i] == Phase::ncm ? c.n_ncm : c.n_cb) += 1;
        if (s.position[i].z - s.radius[i] <= gap)
            (s.phase[i] == Phase::ncm ? c.ncm_substrate : c.cb_substrate) += 1;
    }
    for_each_close_pair(s, gap, [&](std::size_t i, std::size_t j, const Vec3&) {
        ++c.per_particle[i];
        ++c.per_particle[j];
        const bool ni = s.phase[i] == Phase::ncm, nj = s.phase[j] == Phase::ncm;
        if (ni && nj)
            ++c.ncm_ncm;
        else if (ni || nj)
            ++c.ncm_cb;
        else
            ++c.cb_cb;
    });
    return c;
}

} // namespace drydem::analysis
