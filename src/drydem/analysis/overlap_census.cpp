// SPDX-License-Identifier: MIT
#include "drydem/analysis/overlap_census.hpp"
#include "drydem/analysis/pair_search.hpp"
#include "drydem/core/sphere.hpp"
#include <algorithm>
#include <cmath>
#include <numbers>

namespace drydem::analysis {

OverlapStats summarise(std::vector<double>& rel, double lens) {
    OverlapStats o;
    o.pairs = rel.size();
    o.lens_volume = lens;
    if (rel.empty()) return o;
    std::sort(rel.begin(), rel.end());
    const auto rank = [&](double q) {
        return rel[std::size_t(std::ceil(q * double(rel.size()))) - 1];
    };
    double sum = 0.0;
    for (double x : rel) sum += x;
    o.mean = sum / double(rel.size());
    o.median = rel.size() % 2 ? rel[rel.size() / 2]
                              : 0.5 * (rel[rel.size() / 2 - 1] + rel[rel.size() / 2]);
    o.p99 = rank(0.99);
    o.max = rel.back();
    return o;
}

double sphere_lens_volume(double a, double b, double d) {
    if (d >= a + b) return 0.0;
    if (d <= std::abs(a - b)) return sphere_volume(std::min(a, b));
    const double h = a + b - d;
    return std::numbers::pi * h * h * (d * d + 2.0 * d * (a + b) - 3.0 * (a - b) * (a - b)) /
           (12.0 * d);
}

double sphere_cap_volume(double r, double overlap) {
    const double h = std::clamp(overlap, 0.0, 2.0 * r);
    return std::numbers::pi * h * h * (3.0 * r - h) / 3.0;
}

OverlapCensus overlap_census(const Structure& s) {
    enum { cb_cb, ncm_cb, ncm_ncm, cb_sub, ncm_sub, types };
    std::vector<double> rel[types];
    double lens[types] = {};
    OverlapCensus c;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double r = s.radius[i], overlap = r - s.position[i].z;
        c.solid_volume += sphere_volume(r);
        if (overlap <= 0.0) continue;
        const int t = s.phase[i] == Phase::ncm ? ncm_sub : cb_sub;
        rel[t].push_back(overlap / r);
        lens[t] += sphere_cap_volume(r, overlap);
    }
    for_each_close_pair(s, 0.0, [&](std::size_t i, std::size_t j, const Vec3& d) {
        const double a = s.radius[i], b = s.radius[j], dist = norm(d);
        if (dist >= a + b) return;
        const bool ni = s.phase[i] == Phase::ncm, nj = s.phase[j] == Phase::ncm;
        const int t = ni && nj ? ncm_ncm : ni || nj ? ncm_cb : cb_cb;
        rel[t].push_back((a + b - dist) / std::min(a, b));
        lens[t] += sphere_lens_volume(a, b, dist);
    });
    std::vector<double> pooled;
    double pooled_lens = 0.0;
    for (int t = 0; t < types; ++t) {
        pooled.insert(pooled.end(), rel[t].begin(), rel[t].end());
        pooled_lens += lens[t];
    }
    c.cb_cb = summarise(rel[cb_cb], lens[cb_cb]);
    c.ncm_cb = summarise(rel[ncm_cb], lens[ncm_cb]);
    c.ncm_ncm = summarise(rel[ncm_ncm], lens[ncm_ncm]);
    c.cb_substrate = summarise(rel[cb_sub], lens[cb_sub]);
    c.ncm_substrate = summarise(rel[ncm_sub], lens[ncm_sub]);
    c.all = summarise(pooled, pooled_lens);
    return c;
}

} // namespace drydem::analysis
