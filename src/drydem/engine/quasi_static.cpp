// SPDX-License-Identifier: MIT
// The quasi-static step (quasi_static.hpp, docs/model.md M-9.1): assembly at rest, the solve of
// (M/Δt + R + Δt K) [v; ω] = [F; T] + M [v₀; ω₀]/Δt, and the step. Threads own the rows of the
// neighbour list; every sum over threads runs in thread order (linear_operator.hpp), so a run is
// the same run to run for a given thread count.
#include "drydem/core/error.hpp"
#include "drydem/engine/simulation.hpp"
#include <fmt/format.h>
#include <omp.h>
#include <algorithm>
#include <cmath>

namespace drydem {
namespace {

Vec3 part(const std::vector<double>& x, std::size_t i, int k) {
    return {x[6 * i + 3 * k], x[6 * i + 3 * k + 1], x[6 * i + 3 * k + 2]};
}
void add_part(std::vector<double>& x, std::size_t i, int k, const Vec3& v) {
    x[6 * i + 3 * k] += v.x, x[6 * i + 3 * k + 1] += v.y, x[6 * i + 3 * k + 2] += v.z;
}
void set_part(std::vector<double>& x, std::size_t i, int k, const Vec3& v) {
    x[6 * i + 3 * k] = v.x, x[6 * i + 3 * k + 1] = v.y, x[6 * i + 3 * k + 2] = v.z;
}
/// M/Δt of one particle in the body form: isotropic, uncoupled.
BodyResistance inertia_over(double mass, double inertia, double dt) {
    return {mass / dt, mass / dt, 0.0, inertia / dt, inertia / dt};
}
bool any(const PairResistance& c) {
    return c.normal != 0.0 || c.sliding != 0.0 || c.rolling != 0.0 || c.twisting != 0.0;
}

/// The operator M/Δt + R + Δt K of the step and its 6×6 self-blocks, inverted (the
/// preconditioner); each thread builds the entries of its rows.
void build_operator(QuasiStaticSystem& sys, const ParticleStore& p, const RowSplit& rows,
                    double dt) {
    const std::size_t n = rows.n;
    sys.a.resize(rows.threads);
    sys.block.resize(n);
    sys.block_share.resize(rows.threads);
#pragma omp parallel num_threads(int(rows.threads))
    {
        const std::size_t t = std::size_t(omp_get_thread_num());
        Operator& a = sys.a[t];
        a.clear();
        std::vector<SelfBlock>& block = sys.block_share[t];
        block.assign(n, {});
        for (const QuasiStaticSystem::Pair& e : sys.pairs[t]) {
            const PairResistance c = plus_scaled(e.r, e.k, dt);
            if (!any(c)) continue;
            a.pairs.push_back({e.i, e.j, e.g.n, c});
            add_self_block(block[e.i], c, e.g.n, c.lever_i, 1.0);
            add_self_block(block[e.j], c, e.g.n, c.lever_j, -1.0);
        }
        for (std::size_t i = rows.lo(t); i < rows.lo(t + 1); ++i) {
            BodyResistance c = plus_scaled(sys.bodies[i].r, sys.bodies[i].k, dt);
            c += inertia_over(p.mass[i], 1.0 / p.inv_inertia[i], dt);
            a.bodies.push_back({std::uint32_t(i), c});
            add_self_block(block[i], c);
        }
#pragma omp barrier
        for (std::size_t i = rows.lo(t); i < rows.lo(t + 1); ++i) {
            SelfBlock sum{};
            for (std::size_t u = 0; u < rows.threads; ++u) sum += sys.block_share[u][i];
            sys.block[i] = factor_self_block(sum, 1.0, 0.0, 0.0);
        }
    }
}

} // namespace

void Simulation::assemble_quasi_static() {
    if (force_rebuild_) rebuild_neighbors();
    const std::size_t n = p_.size(), threads = std::size_t(threads_);
    const RowSplit rows{n, threads};
    QuasiStaticSystem& sys = qs_;
    sys.pairs.resize(threads);
    sys.bodies.resize(n);
    sys.force.resize(6 * n);
    sys.force_share.resize(threads);
    ParticleStore& p = p_;
    std::size_t contacts = 0, wall_contacts = 0;
    double max_overlap = 0.0;
#pragma omp parallel num_threads(threads_) reduction(+ : contacts, wall_contacts) reduction(max : max_overlap)
    {
        const std::size_t t = std::size_t(omp_get_thread_num());
        std::vector<double>& f = sys.force_share[t];
        f.assign(6 * n, 0.0);
        std::vector<QuasiStaticSystem::Pair>& pairs = sys.pairs[t];
        pairs.clear();
        for (std::size_t i = rows.lo(t); i < rows.lo(t + 1); ++i) {
            const BodyParams& bp = ff_.body_params(p.species[i]);
            const BodyGeometry at_rest = body_geometry(i, {}, {}, 0.0);
            BodyState kept = body_state_[i]; // at rest and Δt = 0: the state does not advance
            const BodyForce bf = BodyLaws::force(at_rest, bp, kept, 0.0);
            add_part(f, i, 0, bf.force);
            add_part(f, i, 1, bf.torque);
            sys.bodies[i] = {BodyLaws::resistance(at_rest, bp, body_state_[i]),
                             BodyLaws::tangent(at_rest, bp, body_state_[i])};
            if (substrate_on_ && p.position[i].z < p.radius[i]) {
                ++wall_contacts;
                max_overlap = std::max(max_overlap, 1.0 - p.position[i].z / p.radius[i]);
            }
            for (std::uint32_t s = nl_.begin(i); s < nl_.end(i); ++s) {
                const std::uint32_t j = nl_.partner(s);
                const Vec3 d = box_.minimum_image(p.position[i], p.position[j]);
                const double dist2 = norm2(d);
                if (dist2 >= nl_.reach2(s)) { // beyond every law's range: nothing is kept
                    if (PairLaws::keeps(nl_.state(s))) nl_.state(s) = PairState{};
                    continue;
                }
                const PairParams& pp = ff_.pair_params(p.species[i], p.species[j]);
                const PairGeometry g =
                    make_pair_geometry(d, std::sqrt(dist2), p.radius[i], p.radius[j], p.mass[i],
                                       p.mass[j], {}, {}, {}, {});
                if (g.gap < 0.0) {
                    ++contacts;
                    max_overlap =
                        std::max(max_overlap, -g.gap / std::min(p.radius[i], p.radius[j]));
                }
                PairState kept_pair = nl_.state(s);
                const PairForce pf = PairLaws::force(g, pp, kept_pair, 0.0);
                add_part(f, i, 0, pf.force_i);
                add_part(f, i, 1, pf.torque_i);
                add_part(f, j, 0, -1.0 * pf.force_i);
                add_part(f, j, 1, pf.torque_j);
                pairs.push_back({std::uint32_t(i), j, s, g,
                                 PairLaws::resistance(g, pp, nl_.state(s)),
                                 PairLaws::tangent(g, pp, nl_.state(s))});
            }
        }
#pragma omp barrier
        for (std::size_t i = rows.lo(t); i < rows.lo(t + 1); ++i) {
            for (std::size_t k = 6 * i; k < 6 * i + 6; ++k) {
                double sum = 0.0;
                for (std::size_t u = 0; u < threads; ++u) sum += sys.force_share[u][k];
                sys.force[k] = sum;
            }
            p.force[i] = part(sys.force, i, 0);
            p.torque[i] = part(sys.force, i, 1);
        }
    }
    stats_.contacts = contacts;
    stats_.wall_contacts = wall_contacts;
    stats_.max_overlap_rel = max_overlap;
}

void Simulation::solve_quasi_static(double dt, QuasiStaticReport& report) {
    const std::size_t n = p_.size(), threads = std::size_t(threads_), m = 6 * n;
    const RowSplit rows{n, threads};
    QuasiStaticSystem& sys = qs_;
    const ParticleStore& p = p_;
    build_operator(sys, p, rows, dt);
    // Right-hand side [F; T] + M [v₀; ω₀]/Δt; the last velocities are the first guess.
    sys.b.resize(m), sys.u.resize(m), sys.r.resize(m), sys.z.resize(m), sys.d.resize(m);
#pragma omp parallel for schedule(static) num_threads(threads_)
    for (std::size_t i = 0; i < n; ++i) {
        const double inertia = 1.0 / p.inv_inertia[i];
        set_part(sys.b, i, 0, part(sys.force, i, 0) + (p.mass[i] / dt) * p.velocity[i]);
        set_part(sys.b, i, 1, part(sys.force, i, 1) + (inertia / dt) * p.omega[i]);
        set_part(sys.u, i, 0, p.velocity[i]);
        set_part(sys.u, i, 1, p.omega[i]);
    }
    auto dot = [&](const std::vector<double>& x, const std::vector<double>& y) {
        return ordered_sum(
            rows,
            [&](std::size_t i) {
                double s = 0.0;
                for (std::size_t k = 6 * i; k < 6 * i + 6; ++k) s += x[k] * y[k];
                return s;
            },
            sys.partial);
    };
    auto precondition = [&] {
#pragma omp parallel for schedule(static) num_threads(threads_)
        for (std::size_t i = 0; i < n; ++i) {
            Vec3 a, w;
            solve_self_block(sys.block[i], part(sys.r, i, 0), part(sys.r, i, 1), a, w);
            set_part(sys.z, i, 0, a);
            set_part(sys.z, i, 1, w);
        }
    };
    const QuasiStaticSettings& s = settings_.quasi_static;
    apply_split(sys.a, rows, sys.u, sys.q, sys.share);
#pragma omp parallel for schedule(static) num_threads(threads_)
    for (std::size_t k = 0; k < m; ++k) sys.r[k] = sys.b[k] - sys.q[k];
    const double norm_b = std::sqrt(dot(sys.b, sys.b));
    report.residual = norm_b > 0.0 ? std::sqrt(dot(sys.r, sys.r)) / norm_b : 0.0;
    if (report.residual <= s.tolerance) return;
    precondition();
    sys.d = sys.z;
    double rz = dot(sys.r, sys.z);
    for (int it = 1; it <= s.max_iterations; ++it) {
        ++report.iterations;
        apply_split(sys.a, rows, sys.d, sys.q, sys.share);
        const double alpha = rz / dot(sys.d, sys.q);
#pragma omp parallel for schedule(static) num_threads(threads_)
        for (std::size_t k = 0; k < m; ++k) {
            sys.u[k] += alpha * sys.d[k];
            sys.r[k] -= alpha * sys.q[k];
        }
        report.residual = std::sqrt(dot(sys.r, sys.r)) / norm_b;
        if (!std::isfinite(report.residual))
            throw RunError(fmt::format("quasi-static step {} (t = {:.6g} s, dt = {:.3g} s): the "
                                       "linear solve diverged; M/dt + R + dt K is not positive "
                                       "definite (a law's resistance or stiffness is negative "
                                       "or not finite)",
                                       step_, time_, dt),
                           "blow_up");
        if (report.residual <= s.tolerance) return;
        precondition();
        const double rz_new = dot(sys.r, sys.z);
        const double beta = rz_new / rz;
        rz = rz_new;
#pragma omp parallel for schedule(static) num_threads(threads_)
        for (std::size_t k = 0; k < m; ++k) sys.d[k] = sys.z[k] + beta * sys.d[k];
    }
}

double Simulation::quasi_static_step_limit() const {
    const QuasiStaticSettings& s = settings_.quasi_static;
    const ParticleStore& p = p_;
    const std::size_t n = p.size();
    double limit = INFINITY;
    auto bound = [&](double closing, double gap, double r_min) { // closing speed over its gap
        if (closing > 0.0)
            limit = std::min(limit, s.approach * std::max(gap, s.approach_floor * r_min) / closing);
    };
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 v = part(qs_.u, i, 0);
        const double speed = norm(v);
        if (speed > 0.0) limit = std::min(limit, s.max_displacement / speed);
        if (substrate_on_ && p.position[i].z > p.radius[i])
            bound(-v.z, p.position[i].z - p.radius[i], p.radius[i]);
    }
    for (const auto& pairs : qs_.pairs)
        for (const QuasiStaticSystem::Pair& e : pairs)
            if (e.g.gap > 0.0)
                bound(dot(part(qs_.u, e.i, 0) - part(qs_.u, e.j, 0), e.g.n), e.g.gap,
                      std::min(e.g.r_i, e.g.r_j));
    return limit;
}

void Simulation::step_quasi_static() {
    const double t_start = omp_get_wtime();
    const std::size_t n = p_.size();
    const QuasiStaticSettings& s = settings_.quasi_static;
    ParticleStore& p = p_;
    assemble_quasi_static(); // at time_ and the level there: explicit in the level's motion
    // The trial step: the last one grown by at most 2, and what the last velocities allow.
    qs_.u.resize(6 * n);
    for (std::size_t i = 0; i < n; ++i) {
        set_part(qs_.u, i, 0, p.velocity[i]);
        set_part(qs_.u, i, 1, p.omega[i]);
    }
    double dt = settings_.dt > 0.0 ? std::min(s.max_step, 2.0 * settings_.dt) : s.max_step;
    dt = std::min(dt, 0.95 * quasi_static_step_limit());
    QuasiStaticReport rep;
    // Where the solved velocities exceed the linearisation's range, the step is shortened: down
    // to half of it the solve's velocities are kept (first order in Δt, like the solve itself:
    // the shorter step sees the stiffness of the longer one, M/Δt + R + Δt K, a little more
    // resistance), below that the system is solved again at the shorter step.
    for (int attempt = 0;; ++attempt) {
        solve_quasi_static(dt, rep);
        ++rep.solves;
        const double allowed = quasi_static_step_limit();
        if (dt <= allowed * (1.0 + 1e-9)) break;
        if (allowed >= 0.5 * dt || attempt == 7) {
            dt = allowed;
            break;
        }
        dt = 0.9 * allowed;
    }
    double v_max = 0.0;
    for (std::size_t i = 0; i < n; ++i) v_max = std::max(v_max, norm(part(qs_.u, i, 0)));
    rep.max_displacement = dt * v_max;
    rep.dt = dt;
    // The laws' kept states advance with the solved velocities over Δt (springs, Coulomb's cut).
    const RowSplit rows{n, std::size_t(threads_)};
#pragma omp parallel num_threads(threads_)
    {
        const std::size_t t = std::size_t(omp_get_thread_num());
        for (const QuasiStaticSystem::Pair& e : qs_.pairs[t]) {
            PairGeometry g = e.g;
            g.v_rel = part(qs_.u, e.i, 0) - part(qs_.u, e.j, 0);
            g.v_n = dot(g.v_rel, g.n);
            g.omega_i = part(qs_.u, e.i, 1);
            g.omega_j = part(qs_.u, e.j, 1);
            (void)PairLaws::force(g, ff_.pair_params(p.species[e.i], p.species[e.j]),
                                  nl_.state(e.slot), dt);
        }
        for (std::size_t i = rows.lo(t); i < rows.lo(t + 1); ++i) {
            const BodyGeometry g = body_geometry(i, part(qs_.u, i, 0), part(qs_.u, i, 1), 0.0);
            (void)BodyLaws::force(g, ff_.body_params(p.species[i]), body_state_[i], dt);
        }
    }
    const auto& x_build = nl_.positions_at_build();
    double max_disp2 = 0.0, top = -INFINITY;
    bool finite = true;
#pragma omp parallel for schedule(static) num_threads(threads_) reduction(max : max_disp2, top) reduction(&& : finite)
    for (std::size_t i = 0; i < n; ++i) {
        p.velocity[i] = part(qs_.u, i, 0);
        p.omega[i] = part(qs_.u, i, 1);
        p.position[i] += dt * p.velocity[i];
        box_.wrap(p.position[i]);
        max_disp2 = std::max(max_disp2, norm2(box_.minimum_image(x_build[i], p.position[i])));
        top = std::max(top, p.position[i].z + p.radius[i]);
        finite =
            finite && is_finite(p.position[i]) && is_finite(p.velocity[i]) && is_finite(p.omega[i]);
    }
    time_ += dt;
    ++step_;
    settings_.dt = dt;
    if (level_at_) liquid_level_ = level_at_(time_);
    stats_.layer_top = n ? top : 0.0;
    qs_report_ = rep;
    if (!std::isfinite(max_disp2) || nl_.needs_rebuild(max_disp2)) force_rebuild_ = true;
    times_.integrate += omp_get_wtime() - t_start;
    non_finite_ = !finite;
    if (non_finite_ || stats_.max_overlap_rel > settings_.overlap_limit) check_health();
}

} // namespace drydem
