// SPDX-License-Identifier: MIT
// Measures of the film read off the particles during a run (time series, summary).
#pragma once
#include "drydem/core/particles.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace drydem {

/// Quantile q of the particle tops z + r; q = 0.99 is a robust thickness that ignores stray
/// particles. 0 for no particles.
inline double top_percentile(const ParticleStore& p, double q) {
    std::vector<double> tops(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) tops[i] = p.position[i].z + p.radius[i];
    if (tops.empty()) return 0.0;
    const std::size_t k = std::min(tops.size() - 1, std::size_t(q * double(tops.size())));
    std::nth_element(tops.begin(), tops.begin() + std::ptrdiff_t(k), tops.end());
    return tops[k];
}

/// Particles that the liquid level at height `level` cuts.
inline std::size_t particles_cutting_level(const ParticleStore& p, double level) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < p.size(); ++i) n += std::abs(level - p.position[i].z) < p.radius[i];
    return n;
}

} // namespace drydem
