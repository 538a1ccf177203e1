// SPDX-License-Identifier: MIT
#include "drydem/parallel/decomposition.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <limits>

namespace drydem::parallel {

namespace {

int wrap_index(int i, int n) { return ((i % n) + n) % n; }

/// Distance along one periodic axis of length l from coordinate x to the interval [x0, x0 + w).
double axis_distance(double x, double x0, double w, double l) {
    double u = std::fmod(x - x0, l);
    if (u < 0.0) u += l;
    return u < w ? 0.0 : std::min(u - w, l - u);
}

} // namespace

int Decomposition::rank_at(int ix, int iy, int iz) const {
    return (iz * py + wrap_index(iy, py)) * px + wrap_index(ix, px);
}

double Decomposition::z_lo(int iz) const { return iz <= 0 ? -INFINITY : cut_z.at(std::size_t(iz)); }

namespace {
/// The part of an axis cut at `cuts` (empty: `parts` equal ones over [0, l)) that holds u; below
/// the first inner cut the lowest, above the last the highest (so z's layers are open at the ends).
int part_of(double u, const std::vector<double>& cuts, int parts, double l) {
    if (parts < 2) return 0;
    if (cuts.empty()) return std::clamp(int(u / (l / parts)), 0, parts - 1);
    const auto it = std::upper_bound(cuts.begin() + 1, cuts.end() - 1, u);
    return int(it - cuts.begin()) - 1;
}
double narrowest(const std::vector<double>& cuts, int parts, double l) {
    if (cuts.empty()) return l / parts;
    double w = l;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) w = std::min(w, cuts[k + 1] - cuts[k]);
    return w;
}
} // namespace

double Decomposition::width_x() const { return narrowest(cut_x, px, box.lx); }
double Decomposition::width_y() const { return narrowest(cut_y, py, box.ly); }
double Decomposition::width_z() const {
    return pz < 2 ? INFINITY : narrowest(cut_z, pz, cut_z.back());
}

int Decomposition::owner(const Vec3& x) const {
    Vec3 w = x;
    box.wrap(w);
    return rank_at(part_of(w.x, cut_x, px, box.lx), part_of(w.y, cut_y, py, box.ly),
                   part_of(w.z, cut_z, pz, cut_z.empty() ? 0.0 : cut_z.back()));
}

std::vector<int> Decomposition::neighbors(int rank) const {
    const int ix = rank % px, iy = (rank / px) % py, iz = rank / (px * py);
    std::vector<int> out;
    for (int dz = -1; dz <= 1; ++dz) {
        if (iz + dz < 0 || iz + dz >= pz) continue; // z is not periodic
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int r = rank_at(ix + dx, iy + dy, iz + dz);
                if (r != rank) out.push_back(r);
            }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

double Decomposition::distance2(int rank, const Vec3& x) const {
    const int ix = rank % px, iy = (rank / px) % py, iz = rank / (px * py);
    const double dx = axis_distance(x.x, x_lo(ix), x_hi(ix) - x_lo(ix), box.lx);
    const double dy = axis_distance(x.y, y_lo(iy), y_hi(iy) - y_lo(iy), box.ly);
    const double dz = std::max({z_lo(iz) - x.z, 0.0, x.z - z_hi(iz)});
    return dx * dx + dy * dy + dz * dz;
}

Decomposition decompose(const Box& box, int ranks, double reach, double height,
                        std::array<int, 3> grid) {
    if (ranks < 1) throw InputError(fmt::format("MPI: {} ranks; at least 1 is needed", ranks));
    if (!(reach > 0.0) || !std::isfinite(reach))
        throw InputError(fmt::format("MPI: the reach between subdomains is {} m; it must be a "
                                     "positive length (interaction range plus skin)",
                                     reach));
    if (!(height >= 0.0) || !std::isfinite(height))
        throw InputError(
            fmt::format("MPI: the film is {} m thick; it must be a length >= 0", height));
    Decomposition best{box, 0, 0};
    double best_cut = std::numeric_limits<double>::infinity();
    for (int px = ranks; px >= 1; --px) {
        if (ranks % px != 0) continue;
        for (int py = ranks / px; py >= 1; --py) {
            if ((ranks / px) % py != 0) continue;
            const int pz = ranks / px / py;
            const bool chosen = (grid[0] == 0 || grid[0] == px) &&
                                (grid[1] == 0 || grid[1] == py) && (grid[2] == 0 || grid[2] == pz);
            const bool fits = chosen && (px == 1 || box.lx / px >= reach) &&
                              (py == 1 || box.ly / py >= reach) &&
                              (pz == 1 || height / pz >= reach);
            if (!fits) continue;
            // Ghost volume per rank: its subdomain grown by `reach` across each cut face, less
            // itself; in z the outer layers have one cut face, the inner ones two.
            const double w = box.lx / px, h = box.ly / py, t = std::max(height, reach) / pz;
            const double grown_t = t + 2.0 * reach * (pz - 1) / pz;
            const double cut =
                (w + (px > 1 ? 2.0 * reach : 0.0)) * (h + (py > 1 ? 2.0 * reach : 0.0)) * grown_t -
                w * h * t;
            if (cut < best_cut * (1.0 - 1e-12)) {
                best_cut = cut;
                best = {box, px, py, {}, {}, pz, {}};
            }
        }
    }
    if (best.px == 0) {
        const int max_x = std::max(1, int(box.lx / reach)),
                  max_y = std::max(1, int(box.ly / reach)),
                  max_z = std::max(1, int(height / reach));
        throw InputError(fmt::format(
            "MPI: {} ranks cannot split the {:.4g} x {:.4g} um cell and its {:.4g} um thick film "
            "into subdomains at least {:.4g} um wide (the reach at which a neighbouring rank must "
            "see a particle: the largest interaction range plus skin plus the radii). Allowed: "
            "px x py x pz ranks with px <= {}, py <= {} and pz <= {} (at most {} ranks); use "
            "fewer ranks or a wider cell{}",
            ranks, box.lx * 1e6, box.ly * 1e6, height * 1e6, reach * 1e6, max_x, max_y, max_z,
            max_x * max_y * max_z,
            grid == std::array<int, 3>{0, 0, 0}
                ? ""
                : fmt::format(" (the grid asked for: {} x {} x {}, 0 = any)", grid[0], grid[1],
                              grid[2])));
    }
    if (best.pz > 1)
        for (int k = 0; k <= best.pz; ++k) best.cut_z.push_back(height * k / best.pz);
    return best;
}

std::vector<double> balanced_cuts(const std::vector<double>& weight, double length,
                                  const std::vector<double>& now, double min_width,
                                  double max_shift) {
    const int parts = int(now.size()) - 1;
    if (parts < 2 || weight.empty()) return now;
    double total = 0.0;
    for (double w : weight) total += w;
    if (!(total > 0.0)) return now;
    // Where the cumulative weight reaches k/parts of the total (linear within a bin).
    const double bin = length / double(weight.size());
    std::vector<double> cuts = now;
    std::size_t b = 0;
    double below = 0.0; // weight of the bins before b
    for (int k = 1; k < parts; ++k) {
        const double target = total * k / parts;
        while (b < weight.size() && below + weight[b] < target) below += weight[b++];
        const double inside =
            b < weight.size() && weight[b] > 0.0 ? (target - below) / weight[b] : 0.0;
        const double ideal = (double(b) + inside) * bin;
        cuts[std::size_t(k)] =
            std::clamp(ideal, now[std::size_t(k)] - max_shift, now[std::size_t(k)] + max_shift);
    }
    // No part narrower than min_width: push the cuts apart from the left, then from the right.
    for (int k = 1; k < parts; ++k)
        cuts[std::size_t(k)] = std::max(cuts[std::size_t(k)], cuts[std::size_t(k - 1)] + min_width);
    for (int k = parts - 1; k >= 1; --k)
        cuts[std::size_t(k)] = std::min(cuts[std::size_t(k)], cuts[std::size_t(k + 1)] - min_width);
    return cuts;
}

} // namespace drydem::parallel
