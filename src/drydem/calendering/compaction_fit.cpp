// SPDX-License-Identifier: MIT
#include "drydem/calendering/compaction_fit.hpp"
#include <algorithm>
#include <cmath>

namespace drydem {
namespace {

/// The best ε_min, amplitude A = ε_0 - ε_min for a given p_c (normal equations of a two-column
/// least-squares problem), and its sum of squared residuals.
struct LinearFit {
    double floor = 0.0, amplitude = 0.0, sse = INFINITY;
};
LinearFit fit_at(double p_c, std::span<const double> p, std::span<const double> e) {
    double s1 = 0, sx = 0, sxx = 0, sy = 0, sxy = 0;
    for (std::size_t k = 0; k < p.size(); ++k) {
        const double x = std::exp(-p[k] / p_c);
        s1 += 1, sx += x, sxx += x * x, sy += e[k], sxy += x * e[k];
    }
    const double det = s1 * sxx - sx * sx;
    if (!(det > 1e-14 * s1 * sxx)) return {}; // every point at the same exp(-p/p_c)
    LinearFit f;
    f.amplitude = (s1 * sxy - sx * sy) / det;
    f.floor = (sy - f.amplitude * sx) / s1;
    f.sse = 0.0;
    for (std::size_t k = 0; k < p.size(); ++k) {
        const double r = e[k] - f.floor - f.amplitude * std::exp(-p[k] / p_c);
        f.sse += r * r;
    }
    if (f.amplitude <= 0.0) f.sse = INFINITY; // porosity must fall with pressure
    return f;
}

} // namespace

CompactionFit fit_compaction(std::span<const double> pressure, std::span<const double> porosity) {
    CompactionFit out;
    out.points = int(pressure.size());
    if (pressure.size() != porosity.size() || pressure.size() < 4) return out;
    const double p_max = *std::max_element(pressure.begin(), pressure.end());
    if (!(p_max > 0.0)) return out;
    // Grid over log p_c, then golden section between the best point's neighbours.
    constexpr int grid = 200;
    const double lo = std::log(1e-3 * p_max), hi = std::log(1e2 * p_max);
    auto sse_at = [&](double log_pc) { return fit_at(std::exp(log_pc), pressure, porosity).sse; };
    int best = 0;
    double best_sse = INFINITY;
    for (int k = 0; k <= grid; ++k) {
        const double s = sse_at(lo + (hi - lo) * k / grid);
        if (s < best_sse) best_sse = s, best = k;
    }
    if (!std::isfinite(best_sse)) return out;
    double a = lo + (hi - lo) * std::max(best - 1, 0) / grid;
    double b = lo + (hi - lo) * std::min(best + 1, grid) / grid;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double c = b - g * (b - a), d = a + g * (b - a);
    for (int it = 0; it < 100 && b - a > 1e-10; ++it) {
        if (sse_at(c) < sse_at(d))
            b = d;
        else
            a = c;
        c = b - g * (b - a), d = a + g * (b - a);
    }
    const double p_c = std::exp(0.5 * (a + b));
    const LinearFit f = fit_at(p_c, pressure, porosity);
    if (!std::isfinite(f.sse)) return out;
    out.ok = true;
    out.porosity_min = f.floor;
    out.porosity_zero = f.floor + f.amplitude;
    out.resistance = p_c;
    out.rms = std::sqrt(f.sse / double(pressure.size()));
    return out;
}

} // namespace drydem
