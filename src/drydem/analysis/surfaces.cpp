// SPDX-License-Identifier: MIT
#include "drydem/analysis/surfaces.hpp"
#include "drydem/analysis/pair_search.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace drydem::analysis {

namespace {
/// Fibonacci lattice on the unit sphere: m equal-area points (z uniform in [-1, 1], golden angle).
std::vector<Vec3> fibonacci_sphere(int m) {
    std::vector<Vec3> unit(static_cast<std::size_t>(m));
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int q = 0; q < m; ++q) {
        const double z = 1.0 - (2.0 * q + 1.0) / m, rho = std::sqrt(std::max(0.0, 1.0 - z * z));
        unit[std::size_t(q)] = {rho * std::cos(golden * q), rho * std::sin(golden * q), z};
    }
    return unit;
}

/// A sphere whose (gap-inflated) sphere reaches an NCM sphere: offset from its centre (minimum
/// image), squared radius, squared radius plus the CB gap, and whether it is NCM.
struct Partner {
    Vec3 d;
    double r2, r2gap;
    bool ncm;
};

/// The partners of every NCM sphere (the same cell search as the coordination).
std::vector<std::vector<Partner>> ncm_partners(const Structure& s, double cb_gap) {
    std::vector<std::vector<Partner>> near(s.size());
    auto add = [&](std::size_t a, std::size_t b, const Vec3& d) {
        if (s.phase[a] != Phase::ncm) return;
        const bool ncm = s.phase[b] == Phase::ncm;
        const double rb = s.radius[b], reach = rb + (ncm ? 0.0 : cb_gap);
        if (norm2(d) >= (s.radius[a] + reach) * (s.radius[a] + reach)) return;
        near[a].push_back({d, rb * rb, reach * reach, ncm});
    };
    for_each_close_pair(s, cb_gap, [&](std::size_t i, std::size_t j, const Vec3& d) {
        add(i, j, d);
        add(j, i, -d);
    });
    return near;
}
} // namespace

Surfaces ncm_surfaces(const Structure& s, const SurfaceOptions& o) {
    Surfaces out;
    out.gap = o.cb_gap;
    if (o.points <= 0 || s.size() == 0) return out;
    if (!(o.cb_gap >= 0.0))
        throw InputError(fmt::format("surfaces: CB gap {} m must be >= 0", o.cb_gap));
    out.computed = true;
    const std::size_t n = s.size();
    const std::vector<std::vector<Partner>> partners = ncm_partners(s, o.cb_gap);
    const int m = o.points;
    const std::vector<Vec3> unit = fibonacci_sphere(m);
    double total = 0, contact = 0, substrate = 0, overlap = 0, covered = 0, free = 0;
#pragma omp parallel for schedule(dynamic, 16) reduction(+ : total, contact, substrate, overlap, covered, free)
    for (std::size_t i = 0; i < n; ++i) {
        if (s.phase[i] != Phase::ncm) continue;
        const Vec3 c = s.position[i];
        const double r = s.radius[i];
        const std::vector<Partner>& near = partners[i];
        const double w = 4.0 * std::numbers::pi * r * r / m;
        total += 4.0 * std::numbers::pi * r * r;
        for (const Vec3& u : unit) {
            const Vec3 p{r * u.x, r * u.y, r * u.z}; // relative to c
            if (c.z + p.z < 0.0) {
                substrate += w;
                continue;
            }
            bool in_ncm = false, in_cb = false, near_cb = false;
            for (const Partner& q : near) {
                const double ex = p.x - q.d.x, ey = p.y - q.d.y, ez = p.z - q.d.z;
                const double e2 = ex * ex + ey * ey + ez * ez;
                if (q.ncm)
                    in_ncm |= e2 < q.r2;
                else {
                    in_cb |= e2 < q.r2;
                    near_cb |= e2 < q.r2gap;
                }
            }
            if (in_ncm)
                contact += w;
            else if (near_cb) {
                covered += w;
                if (in_cb) overlap += w;
            } else
                free += w;
        }
    }
    out.total = total;
    out.ncm_contact = contact;
    out.substrate = substrate;
    out.cb_overlap = overlap;
    out.cb_covered = covered;
    out.electrolyte = free;
    return out;
}

} // namespace drydem::analysis
