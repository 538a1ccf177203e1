// SPDX-License-Identifier: MIT
#include "drydem/analysis/binder_migration.hpp"
#include "drydem/analysis/profiles.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace drydem::analysis {

namespace {

/// Liquid level at t: linear between the rows, after the last row on at the last rate.
struct Level {
    const DryingHistory& h;
    double late_rate; ///< dh/dt after the last row (< 0)
    double operator()(double t) const {
        const auto& T = h.time;
        if (t >= T.back()) return h.liquid_level.back() + late_rate * (t - T.back());
        const auto it = std::upper_bound(T.begin(), T.end(), t);
        if (it == T.begin()) return h.liquid_level.front();
        const std::size_t k = std::size_t(it - T.begin());
        const double w = (t - T[k - 1]) / (T[k] - T[k - 1]);
        return (1.0 - w) * h.liquid_level[k - 1] + w * h.liquid_level[k];
    }
};

/// When the level reaches H_f: in the run's rows, else on at the late rate after the last one.
double consolidation_time(const DryingHistory& h, double late_rate) {
    for (std::size_t k = 1; k < h.time.size(); ++k)
        if (h.liquid_level[k] <= h.final_height && h.liquid_level[k - 1] > h.final_height) {
            const double w = (h.liquid_level[k - 1] - h.final_height) /
                             (h.liquid_level[k - 1] - h.liquid_level[k]);
            return h.time[k - 1] + w * (h.time[k] - h.time[k - 1]);
        }
    if (h.liquid_level.front() <= h.final_height) return h.time.front();
    return h.time.back() + (h.final_height - h.liquid_level.back()) / late_rate;
}

} // namespace

namespace {

/// A slab profile (slabs of dz from z = 0) averaged over each of the n cells of [0, height]; cells
/// above the profile's top are pure liquid (1).
std::vector<double> cell_average(const std::vector<double>& profile, double dz, double height,
                                 int n) {
    const double dxi = 1.0 / n;
    std::vector<double> eps(std::size_t(n), 0.0);
    for (int i = 0; i < n; ++i) {
        const double a = i * dxi * height, b = (i + 1) * dxi * height;
        double acc = 0.0;
        for (std::size_t k = std::size_t(a / dz); k < profile.size() && k * dz < b; ++k) {
            const double lo = std::max(a, k * dz), hi = std::min(b, (k + 1) * dz);
            if (hi > lo) acc += (hi - lo) * std::clamp(profile[k], 0.0, 1.0);
        }
        const double covered = std::min(b, profile.size() * dz) - a;
        eps[std::size_t(i)] = covered > 0 ? (acc + (b - a - covered)) / (b - a) : 1.0;
        eps[std::size_t(i)] = std::max(eps[std::size_t(i)], 1e-3);
    }
    return eps;
}

/// The solid fraction per cell of the shrinking film (ξ = z/h cells): the run's frames and, at the
/// time the level reaches H_f, the final film; linear in time between them, scaled to the final
/// film's solid volume. Without frames: the affine compression of the final film.
class ShrinkageSolids {
public:
    ShrinkageSolids(const DryingHistory& h, const std::vector<double>& eps, double consolidation,
                    int n)
        : n_(n), height_f_(h.final_height) {
        for (double e : eps) solid_volume_ += (1.0 - e) * h.final_height / n;
        for (const PorosityFrame& f : h.frames) {
            if (!(f.height > h.final_height) || !(f.time < consolidation)) continue;
            if (!times_.empty() && !(f.time > times_.back())) continue;
            std::vector<double> phi = cell_average(f.porosity, h.dz, f.height, n);
            for (double& x : phi) x = 1.0 - x;
            times_.push_back(f.time);
            solids_.push_back(std::move(phi));
        }
        frames_ = int(times_.size());
        if (frames_ == 0) return;
        std::vector<double> phi(eps.size());
        for (std::size_t i = 0; i < eps.size(); ++i) phi[i] = 1.0 - eps[i];
        times_.push_back(consolidation);
        solids_.push_back(std::move(phi));
    }
    [[nodiscard]] int frames() const { return frames_; }

    /// θ = 1 − φ_s per cell at time t for a film of height H (> H_f).
    void solvent(double t, double height, const std::vector<double>& eps,
                 std::vector<double>& theta) const {
        if (frames_ == 0) {
            for (int i = 0; i < n_; ++i)
                theta[std::size_t(i)] = 1.0 - (1.0 - eps[std::size_t(i)]) * height_f_ / height;
            return;
        }
        const auto it = std::upper_bound(times_.begin(), times_.end(), t);
        const std::size_t k1 =
            std::min<std::size_t>(std::size_t(it - times_.begin()), times_.size() - 1);
        const std::size_t k0 = k1 == 0 ? 0 : k1 - 1;
        const double w =
            k1 == k0 ? 0.0 : std::clamp((t - times_[k0]) / (times_[k1] - times_[k0]), 0.0, 1.0);
        double volume = 0.0;
        for (int i = 0; i < n_; ++i) {
            const double phi =
                (1.0 - w) * solids_[k0][std::size_t(i)] + w * solids_[k1][std::size_t(i)];
            theta[std::size_t(i)] = phi;
            volume += phi * height / n_;
        }
        const double scale = volume > 0.0 ? solid_volume_ / volume : 0.0;
        for (int i = 0; i < n_; ++i)
            theta[std::size_t(i)] = 1.0 - std::min(0.999, theta[std::size_t(i)] * scale);
    }

private:
    int n_ = 0, frames_ = 0;
    double height_f_ = 0.0, solid_volume_ = 0.0;
    std::vector<double> times_;
    std::vector<std::vector<double>> solids_;
};

/// Implicit diffusion of the dissolved binder over one step: solves, for the cell concentrations c,
/// (θ₁ H₁ Δξ) c - Δt ∂/∂z (D₀ θ^α ∂c/∂z) = r (the convected amounts) with the Thomas algorithm.
void diffuse(const std::vector<double>& th1, double H1, double dt, const BinderParams& p,
             std::vector<double>& lo, std::vector<double>& di, std::vector<double>& up,
             std::vector<double>& r, std::vector<double>& c) {
    const int n = p.cells;
    const double dxi = 1.0 / n, alpha = p.bruggeman;
    const double dz = H1 * dxi;
    for (int i = 0; i < n; ++i) {
        lo[std::size_t(i)] = up[std::size_t(i)] = 0.0;
        di[std::size_t(i)] = th1[std::size_t(i)] * H1 * dxi;
    }
    for (int i = 0; i + 1 < n; ++i) {
        const double tf = 0.5 * (th1[std::size_t(i)] + th1[std::size_t(i) + 1]);
        const double k = dt * p.diffusivity * std::pow(tf, alpha) / dz;
        di[std::size_t(i)] += k;
        di[std::size_t(i) + 1] += k;
        up[std::size_t(i)] = -k;
        lo[std::size_t(i) + 1] = -k;
    }
    // Thomas algorithm.
    for (int i = 1; i < n; ++i) {
        const double w = lo[std::size_t(i)] / di[std::size_t(i) - 1];
        di[std::size_t(i)] -= w * up[std::size_t(i) - 1];
        r[std::size_t(i)] -= w * r[std::size_t(i) - 1];
    }
    c[std::size_t(n) - 1] = r[std::size_t(n) - 1] / di[std::size_t(n) - 1];
    for (int i = n - 2; i >= 0; --i)
        c[std::size_t(i)] =
            (r[std::size_t(i)] - up[std::size_t(i)] * c[std::size_t(i) + 1]) / di[std::size_t(i)];
}

/// The profile normalised by its mean, the bottom and top tenths, the evaporation rate and Pe.
void summarize(BinderProfile& out, const std::vector<double>& m, double mass, double Hf,
               const DryingHistory& h, double h_start, double late, const BinderParams& p) {
    const int n = p.cells;
    const double dxi = 1.0 / n;
    out.z.resize(std::size_t(n));
    out.binder.resize(std::size_t(n));
    for (int i = 0; i < n; ++i) {
        out.z[std::size_t(i)] = (i + 0.5) * dxi * Hf;
        out.binder[std::size_t(i)] = m[std::size_t(i)] * n / mass;
    }
    const int tenth = std::max(1, int(std::lround(0.1 * n)));
    for (int i = 0; i < tenth; ++i) {
        out.bottom10 += out.binder[std::size_t(i)] / tenth;
        out.top10 += out.binder[std::size_t(n - 1 - i)] / tenth;
    }
    if (out.consolidation_time > h.time.front() && h_start > Hf) {
        out.evaporation_rate = (h_start - Hf) / (out.consolidation_time - h.time.front());
        out.peclet = p.diffusivity > 0 ? out.evaporation_rate * h_start / p.diffusivity : INFINITY;
    } else {
        out.evaporation_rate = -late;
        out.peclet = p.diffusivity > 0 ? -late * Hf / p.diffusivity : INFINITY;
    }
}
} // namespace

/// InputError for a history or parameters the model cannot run on.
static void check_binder_inputs(const DryingHistory& h, const BinderParams& p) {
    if (h.time.size() < 2 || h.time.size() != h.liquid_level.size())
        throw InputError(
            "binder migration: the history needs at least two (time, liquid level) rows");
    if (!(h.final_height > 0.0) || !(h.dz > 0.0) || h.porosity.empty())
        throw InputError(
            "binder migration: final height, slab width and porosity profile must be given");
    if (!(p.diffusivity >= 0.0) || p.cells < 4 ||
        !(p.residual_saturation > 0.0 && p.residual_saturation < 1.0))
        throw InputError(
            "binder migration: diffusivity >= 0, cells >= 4, residual saturation in (0, 1)");
}

BinderProfile binder_migration(const DryingHistory& h, const BinderParams& p) {
    check_binder_inputs(h, p);
    const int n = p.cells;
    const double Hf = h.final_height, dxi = 1.0 / n;
    const std::vector<double> eps = cell_average(h.porosity, h.dz, Hf, n);
    double pore_volume = 0.0; // ∫₀^H ε_f dz
    for (double e : eps) pore_volume += e * dxi * Hf;

    // The level after the run: its last descent rate, else the mean shrinkage rate.
    const std::size_t last = h.time.size() - 1;
    double late =
        (h.liquid_level[last] - h.liquid_level[last - 1]) / (h.time[last] - h.time[last - 1]);
    const double mean_rate =
        (h.liquid_level[last] - h.liquid_level[0]) / (h.time[last] - h.time[0]);
    if (!(late < 0.0)) late = mean_rate;
    if (!(late < 0.0)) throw InputError("binder migration: the liquid level does not descend");
    const Level level{h, late};
    const ShrinkageSolids solids(h, eps, consolidation_time(h, late), n);

    BinderProfile out;
    out.porosity_frames = solids.frames();
    // Solvent fraction per cell and domain height at time t; S the saturation (1 while shrinking).
    auto state = [&](double t, std::vector<double>& theta, double& height, double& S) {
        const double lv = level(t);
        if (lv > Hf) {
            height = lv;
            S = 1.0;
            solids.solvent(t, lv, eps, theta);
        } else {
            height = Hf;
            double liquid = 0.0; // ∫₀^level ε_f dz
            for (int i = 0; i < n; ++i) {
                const double a = i * dxi * Hf, b = (i + 1) * dxi * Hf;
                if (lv > a) liquid += eps[std::size_t(i)] * (std::min(lv, b) - a);
            }
            S = std::max(0.0, liquid / pore_volume);
            for (int i = 0; i < n; ++i) theta[std::size_t(i)] = eps[std::size_t(i)] * S;
        }
    };
    const std::size_t N = static_cast<std::size_t>(n);
    std::vector<double> th0(N), th1(N), m(N), c(N), G(N + 1), r(N), lo(N), di(N), up(N);
    double t = h.time.front(), H0 = 0.0, H1 = 0.0, S0 = 1.0, S1 = 1.0;
    state(t, th0, H0, S0);
    const double h_start = H0;
    for (int i = 0; i < n; ++i) m[std::size_t(i)] = th0[std::size_t(i)] * H0 * dxi; // c₀ = 1
    double mass0 = 0.0;
    for (double v : m) mass0 += v;
    out.consolidation_time = h_start > Hf ? -1.0 : t;
    int steps = 0;
    while (S0 > p.residual_saturation) {
        if (++steps > 50000000) throw InputError("binder migration: no end after 5e7 steps");
        double dt = p.max_step;
        for (int attempt = 0;; ++attempt) {
            state(t + dt, th1, H1, S1);
            // Face-relative solvent flux from the change of each cell's solvent volume (upward +).
            G[0] = 0.0;
            for (int i = 0; i < n; ++i)
                G[std::size_t(i) + 1] =
                    G[std::size_t(i)] -
                    (th1[std::size_t(i)] * H1 - th0[std::size_t(i)] * H0) * dxi / dt;
            bool ok = true;
            for (int i = 1; i < n && ok; ++i) {
                const double g = G[std::size_t(i)];
                const double donor = g > 0 ? th0[std::size_t(i) - 1] : th0[std::size_t(i)];
                ok = std::abs(g) * dt <= p.cfl * donor * H0 * dxi;
            }
            if (ok || attempt > 60) break;
            dt *= 0.5;
        }
        // Explicit upwind convection of the dissolved binder; the top face lets only solvent out.
        for (int i = 0; i < n; ++i)
            c[std::size_t(i)] = m[std::size_t(i)] / (th0[std::size_t(i)] * H0 * dxi);
        for (int i = 0; i < n; ++i) r[std::size_t(i)] = m[std::size_t(i)];
        for (int i = 1; i < n; ++i) {
            const double g = G[std::size_t(i)];
            const double flux = dt * g * (g > 0 ? c[std::size_t(i) - 1] : c[std::size_t(i)]);
            r[std::size_t(i) - 1] -= flux;
            r[std::size_t(i)] += flux;
        }
        diffuse(th1, H1, dt, p, lo, di, up, r, c);
        for (int i = 0; i < n; ++i)
            m[std::size_t(i)] = c[std::size_t(i)] * th1[std::size_t(i)] * H1 * dxi;
        if (out.consolidation_time < 0.0 && H1 <= Hf) out.consolidation_time = t + dt;
        t += dt;
        std::swap(th0, th1);
        H0 = H1;
        S0 = S1;
    }
    double mass = 0.0;
    for (double v : m) mass += v;
    out.mass_balance = std::abs(mass - mass0) / mass0;
    out.end_time = t;
    out.steps = steps;
    summarize(out, m, mass, Hf, h, h_start, late, p);
    return out;
}

DryingHistory read_drying_history(const std::string& timeseries_csv, double final_height, double dz,
                                  const std::vector<double>& porosity) {
    std::ifstream in(timeseries_csv);
    if (!in) throw InputError(fmt::format("binder migration: cannot read {}", timeseries_csv));
    std::string line;
    std::getline(in, line);
    int col_t = -1, col_h = -1, col_s = -1, col = 0;
    {
        std::stringstream ss(line);
        std::string name;
        while (std::getline(ss, name, ',')) {
            if (name == "process_time_s") col_t = col;
            if (name == "liquid_level_um") col_h = col;
            if (name == "step") col_s = col;
            ++col;
        }
    }
    if (col_t < 0 || col_h < 0)
        throw InputError(
            fmt::format("{}: no process_time_s / liquid_level_um columns", timeseries_csv));
    DryingHistory h;
    h.final_height = final_height;
    h.dz = dz;
    h.porosity = porosity;
    while (std::getline(in, line)) {
        std::stringstream ss(line);
        std::string cell;
        double t = NAN, lv = NAN, step = NAN;
        for (int k = 0; std::getline(ss, cell, ','); ++k) {
            if (k == col_t) t = std::stod(cell);
            if (k == col_h) lv = std::stod(cell) * 1e-6;
            if (k == col_s) step = std::stod(cell);
        }
        if (!std::isfinite(t) || !std::isfinite(lv)) continue;
        if (!h.time.empty() && t <= h.time.back()) continue;
        h.time.push_back(t);
        h.liquid_level.push_back(lv);
        if (col_s >= 0) h.step.push_back(step);
    }
    if (h.step.size() != h.time.size()) h.step.clear();
    return h;
}

std::vector<PorosityFrame> porosity_frames(const std::filesystem::path& dump,
                                           const DryingHistory& h, const FileDefaults& defaults,
                                           const PhaseRule& rule) {
    std::vector<PorosityFrame> frames;
    if (h.step.size() != h.time.size() || h.time.size() < 2) return frames;
    const auto at_step = [&](double step, const std::vector<double>& y) -> double {
        const auto it = std::lower_bound(h.step.begin(), h.step.end(), step);
        if (it == h.step.end()) return NAN;
        const std::size_t k = std::size_t(it - h.step.begin());
        if (*it == step || k == 0) return *it == step ? y[k] : NAN;
        const double w = (step - h.step[k - 1]) / (h.step[k] - h.step[k - 1]);
        return (1.0 - w) * y[k - 1] + w * y[k];
    };
    for_each_dump_frame(dump, [&](DumpSnapshot&& d) {
        const double t = at_step(double(d.step), h.time),
                     level = at_step(double(d.step), h.liquid_level);
        if (!std::isfinite(t) || !std::isfinite(level) || !(level > h.final_height)) return;
        const Structure s = structure_from_file(d.particles, defaults, rule);
        frames.push_back({t, level, volume_fraction_profiles(s, h.dz, level).pore_total});
    });
    return frames;
}

} // namespace drydem::analysis
