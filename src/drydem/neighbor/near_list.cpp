// SPDX-License-Identifier: MIT
#include "drydem/neighbor/near_list.hpp"
#include <cmath>
#include <omp.h>

namespace drydem {

void NearList::neighbors_rebuilt(std::int64_t step) {
    stale_ = true;
    if (outer_step_ >= 0 && step > outer_step_) {
        // f = 32 / lifetime as a power of two: a near list then lives ~32 steps.
        const double f = std::exp2(std::floor(std::log2(32.0 / double(step - outer_step_))));
        fraction_ = std::max(finest, f);
        on_ = enabled_ && fraction_ <= coarsest;
    }
    outer_step_ = step;
}

void NearList::moved(double max_displacement2, std::int64_t step) {
    const double s = skin();
    if (stale_ || max_displacement2 <= 0.25 * s * s) return;
    stale_ = true;
    const std::int64_t lived = step - near_step_;
    if (lived < 8) {
        fraction_ *= 2.0;
        on_ = enabled_ && fraction_ <= coarsest;
    } else if (lived > 128) {
        fraction_ = std::max(finest, 0.5 * fraction_);
    }
}

void NearList::build(NeighborList& nl, const ParticleStore& p, const Box& box, int threads,
                     std::int64_t step) {
    const std::size_t rows = nl.owners();
    const double s_near = skin();
    offset_.assign(rows + 1, 0);
    near_.resize(nl.pairs()); // the test's outcome, from the counting pass to the filling one
#pragma omp parallel for schedule(dynamic, 512) num_threads(threads)
    for (std::size_t i = 0; i < rows; ++i) {
        std::uint32_t count = 0;
        for (std::uint32_t s = nl.begin(i); s < nl.end(i); ++s) {
            const double dist2 = norm2(box.minimum_image(p.position[i], p.position[nl.partner(s)]));
            const double reach = std::sqrt(nl.reach2(s)) + s_near;
            near_[s] = dist2 < reach * reach;
            if (near_[s]) {
                ++count;
            } else if (PairLaws::keeps(nl.state(s))) {
                nl.state(s) = PairState{}; // beyond reach: the pair loop would clear it now
            }
        }
        offset_[i + 1] = count;
    }
    for (std::size_t i = 0; i < rows; ++i) offset_[i + 1] += offset_[i];
    slot_.resize(offset_[rows]);
    partner_.resize(offset_[rows]);
#pragma omp parallel for schedule(dynamic, 512) num_threads(threads)
    for (std::size_t i = 0; i < rows; ++i) {
        std::uint32_t k = offset_[i];
        for (std::uint32_t s = nl.begin(i); s < nl.end(i); ++s)
            if (near_[s]) {
                slot_[k] = s;
                partner_[k++] = nl.partner(s);
            }
    }
    x_build_ = p.position;
    stale_ = false;
    near_step_ = step;
    ++builds_;
}

} // namespace drydem
