// SPDX-License-Identifier: MIT
#include "drydem/analysis/transport.hpp"
#include "drydem/analysis/voxel_grid.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace drydem::analysis {

double tortuosity_factor(double porosity, double sigma_eff) {
    return sigma_eff > 0.0 ? porosity / sigma_eff : 0.0;
}

double bruggeman_exponent(double porosity, double tau) {
    if (!(porosity > 0.0 && porosity < 1.0 && tau > 0.0))
        return std::numeric_limits<double>::quiet_NaN();
    return 1.0 - std::log(tau) / std::log(porosity);
}

Extrapolation extrapolate_to_zero_voxel(const std::vector<double>& h,
                                        const std::vector<double>& v) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    const std::size_t n = std::min(h.size(), v.size());
    if (n < 2) return {nan, 0.0, false};
    const double h1 = h[n - 2], h2 = h[n - 1], v1 = v[n - 2], v2 = v[n - 1];
    if (!(h1 > h2 && h2 > 0.0) || !std::isfinite(v1) || !std::isfinite(v2))
        return {nan, 0.0, false};
    const double r = h1 / h2;
    if (n == 2) return {nan, 0.0, false};
    const double h0 = h[n - 3], v0 = v[n - 3];
    const double d1 = v1 - v0, d2 = v2 - v1;
    if (!(h0 > h1) || std::abs(h0 / h1 - r) > 0.01 * r || d1 == 0.0 || d2 == 0.0 ||
        (d1 > 0) != (d2 > 0))
        return {nan, 0.0, false};
    const double p = std::log(d1 / d2) / std::log(r);
    if (!(p >= 0.5 && p <= 3.0)) return {nan, p, true};
    return {v2 + d2 / (std::pow(r, p) - 1.0), p, true};
}

namespace {

ConductionProblem problem_of(const VoxelGrid& g, int axis, double tolerance) {
    ConductionProblem p;
    p.nx = g.nx;
    p.ny = g.ny;
    p.nz = g.nz;
    p.ax = g.ax;
    p.ay = g.ay;
    p.az = g.az;
    p.axis = axis;
    // x, y periodic (the box); z closed (substrate below, the cut top plane above) unless it is the axis.
    p.periodic = {true, true, false};
    p.tolerance = tolerance;
    return p;
}

/// Voxels per axis the solves at voxel size `a` use: the whole image, or its window.
VoxelDims solved_dims(const Structure& s, double a, double top, const TransportOptions& o) {
    VoxelDims d = voxel_dims(s, a, top);
    if (o.window > 0.0) {
        d.nx = std::min(d.nx, std::max(1, int(std::lround(o.window / (s.box.lx / d.nx)))));
        d.ny = std::min(d.ny, std::max(1, int(std::lround(o.window / (s.box.ly / d.ny)))));
    }
    return d;
}

std::size_t solved_count(const Structure& s, double a, double top, const TransportOptions& o) {
    const VoxelDims d = solved_dims(s, a, top, o);
    return std::size_t(d.nx) * std::size_t(d.ny) * std::size_t(d.nz);
}

/// The last voxel size of the list within the voxel limit (the reported level), 0 if none.
double finest_solvable(const Structure& s, double top, const TransportOptions& o) {
    double finest = 0.0;
    for (double a : o.voxels)
        if (solved_count(s, a, top, o) <= o.max_voxels) finest = a;
    return finest;
}

/// A window must lie inside the box and span a few voxels at every solved size.
void check_window(const Structure& s, const TransportOptions& o) {
    if (!(o.window >= 0.0))
        throw InputError(fmt::format(
            "analysis.transport_window = {} um: must be >= 0 (0 = the whole box)", o.window * 1e6));
    const double side = std::min(s.box.lx, s.box.ly);
    if (o.window > side * (1.0 + 1e-9))
        throw InputError(fmt::format(
            "analysis.transport_window = {:.4g} um is wider than the box ({:.4g} x {:.4g} um); "
            "allowed: 0 (the whole box) up to {:.4g} um",
            o.window * 1e6, s.box.lx * 1e6, s.box.ly * 1e6, side * 1e6));
    for (double a : o.voxels)
        if (o.window > 0.0 && o.window < 8.0 * a)
            throw InputError(fmt::format(
                "analysis.transport_window = {:.4g} um spans fewer than 8 voxels of {:.3g} um; "
                "allowed: 0 or at least 8 voxels of the coarsest transport voxel size",
                o.window * 1e6, a * 1e6));
}

} // namespace

double transport_peak_bytes(const Structure& s, double top, const TransportOptions& o) {
    std::size_t largest = 0;
    for (double a : o.voxels) {
        const std::size_t count = solved_count(s, a, top, o);
        if (count <= o.max_voxels) largest = std::max(largest, count);
    }
    return transport_bytes_per_voxel * double(largest);
}

Transport film_transport(const Structure& s, double top, const TransportOptions& o) {
    Transport t;
    t.top = top;
    t.sigma_ncm = o.sigma_ncm;
    t.sigma_cb = o.sigma_cb;
    if (!(top > 0.0))
        throw InputError(fmt::format("transport: coating top {} m must be positive", top));
    if (!(o.sigma_ncm >= 0.0) || !(o.sigma_cb >= 0.0))
        throw InputError("transport: the NCM and CB conductivities must be >= 0");
    auto say = [&](const std::string& m) {
        if (o.log) o.log(m);
    };
    t.max_voxels = o.max_voxels;
    check_window(s, o);
    const bool windowed = o.window > 0.0;
    for (double a : o.voxels) {
        const auto t0 = std::chrono::steady_clock::now();
        const std::size_t count = solved_count(s, a, top, o);
        if (count > o.max_voxels) {
            t.skipped.push_back({a, count});
            say(fmt::format(
                "transport {:.3g} um: skipped, {} voxels > analysis.transport_max_voxels = {}",
                a * 1e6, count, o.max_voxels));
            continue;
        }
        TransportLevel L;
        const VoxelDims w = solved_dims(s, a, top, o);
        const VoxelGrid g =
            windowed ? crop_xy(voxelize(s, a, top), w.nx, w.ny) : voxelize(s, a, top);
        L.voxel = g.az;
        L.nx = g.nx;
        L.ny = g.ny;
        L.nz = g.nz;
        const std::size_t nv = g.size();
        ConductionProblem p = problem_of(g, 2, o.tolerance);
        if (windowed) {
            p.periodic = {false, false, false}; // the window's sides are cut: no flux through them
            t.window = g.nx * g.ax;
        }
        p.sigma.resize(nv);
        std::size_t pores = 0;
        for (std::size_t i = 0; i < nv; ++i) {
            const bool pore = g.label[i] == label_pore;
            pores += pore;
            p.sigma[i] = pore ? 1.0f : 0.0f;
        }
        L.porosity = double(pores) / double(nv);
        std::size_t peak = 0;
        auto solve = [&](int axis, const char* what) {
            p.axis = axis;
            ConductionResult r = solve_conduction(p);
            peak = std::max(peak, r.memory_bytes);
            say(fmt::format("transport {:.3g} um, {}: sigma_eff {:.5g}, {} unknowns, {} CG "
                            "iterations{}, {:.1f} s",
                            a * 1e6, what, r.sigma_eff, r.unknowns, r.iterations,
                            r.converged ? "" : " (NOT converged)", r.seconds));
            return r;
        };
        L.pore_z = solve(2, "pores through-plane");
        L.tau_z = tortuosity_factor(L.porosity, L.pore_z.sigma_eff);
        if (o.in_plane) {
            L.pore_x = solve(0, "pores in-plane x");
            L.pore_y = solve(1, "pores in-plane y");
            L.tau_x = tortuosity_factor(L.porosity, L.pore_x.sigma_eff);
            L.tau_y = tortuosity_factor(L.porosity, L.pore_y.sigma_eff);
        }
        if (o.walkers > 0 && o.walk_steps > 0 && !windowed && a == finest_solvable(s, top, o)) {
            p.periodic = {true, true, false};
            L.walk = random_walk(p, o.walkers, o.walk_steps);
            say(fmt::format(
                "transport {:.3g} um, random walks in the pores: tau x {:.4g} +- {:.2g}, y {:.4g} "
                "+- {:.2g} "
                "({} walkers x {} steps, {:.1f} s)",
                a * 1e6, 1.0 / L.walk.diffusivity[0],
                L.walk.standard_error[0] / (L.walk.diffusivity[0] * L.walk.diffusivity[0]),
                1.0 / L.walk.diffusivity[1],
                L.walk.standard_error[1] / (L.walk.diffusivity[1] * L.walk.diffusivity[1]),
                o.walkers, o.walk_steps, L.walk.seconds));
        }
        for (std::size_t i = 0; i < nv; ++i)
            p.sigma[i] = g.label[i] == label_ncm  ? float(o.sigma_ncm)
                         : g.label[i] == label_cb ? float(o.sigma_cb)
                                                  : 0.0f;
        L.electronic_z = solve(2, "solid (NCM + CB) through-plane");
        for (std::size_t i = 0; i < nv; ++i)
            p.sigma[i] = g.label[i] == label_cb ? float(o.sigma_cb) : 0.0f;
        L.cb_z = solve(2, "CB network through-plane");
        L.memory_bytes = peak + nv; // + the labels
        L.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        t.levels.push_back(L);
    }
    return t;
}

} // namespace drydem::analysis
