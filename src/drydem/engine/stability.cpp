// SPDX-License-Identifier: MIT
// Stability guard (docs/model.md "Stability guard"): the largest rates of the explicitly treated
// forces, estimated on the laws' own linear operators. Both operators have the pair and body
// forms of forces/resistance.hpp:
//   R: every dissipative law's resistance (lubrication, contact damping, substrate lubrication,
//      Stokes drag) — limits the explicit integrator, Δt λ_max(M⁻¹R) < 2;
//   K: the stiffness of the conservative laws — Hertz normal S_n and tangential S_t (with the
//      contact lever arms), the capillary spring 2πσ s_cap of a particle cutting the level —
//      limits every integrator, Δt ω_max < 2 with ω² = λ_max(M_eff⁻¹K), M_eff = M + s D (s = Δt
//      for the semi-implicit kick, whose self-blocks D add to the inertia, 0 for the explicit
//      one). The contact gaps are reduced by the skin: before the next rebuild a gap can close
//      by at most that much, and the Hertz stiffness grows with the overlap.
//      Van der Waals adds |dF/dh| = A R* / (3 h³) (h ≥ h_min) at the current gap. Its true
//      stiffness is negative: linearised, the snap-in grows like exp(ω t) and velocity Verlet
//      follows it with a growth per step 1 + (ωΔt)²/2 + … ≤ e^{ωΔt}, never unstably, so it is
//      an accuracy bound on the snap (Δt ω ≤ 1: 2.6 per step for e = 2.7), not a stability
//      one, and the skin (which would put every pair within 0.3 µm at h_min) does not apply.
//      Adding |K_vdW| to K keeps the estimate an upper bound of both rates.
// λ_max comes from power iteration on M_eff⁻¹ K (a generalised symmetric problem, so the
// eigenvalues are real and ≥ 0) from a random start, so one cluster's plateau does not hide a
// worse one elsewhere.
#include "drydem/engine/simulation.hpp"
#include <omp.h>
#include <algorithm>
#include <cmath>
#include <random>

namespace drydem {
namespace {

struct PairEntry {
    std::uint32_t i, j;
    Vec3 n;
    PairResistance c; ///< resistance or stiffness coefficients, with lever arms
};
struct BodyEntry {
    std::uint32_t i;
    BodyResistance c;
};
struct Operator {
    std::vector<PairEntry> pairs;
    std::vector<BodyEntry> bodies;
    void clear() {
        pairs.clear();
        bodies.clear();
    }
};

/// y = A x for the operator A (x, y: 6 values per particle, translation then rotation).
void apply(const Operator& a, const std::vector<double>& x, std::vector<double>& y) {
    std::fill(y.begin(), y.end(), 0.0);
    auto v = [&](std::uint32_t i) { return Vec3{x[6 * i], x[6 * i + 1], x[6 * i + 2]}; };
    auto w = [&](std::uint32_t i) { return Vec3{x[6 * i + 3], x[6 * i + 4], x[6 * i + 5]}; };
    auto add = [&](std::uint32_t i, const Vec3& f, const Vec3& t) {
        y[6 * i] -= f.x, y[6 * i + 1] -= f.y, y[6 * i + 2] -= f.z; // A x = -(force of x)
        y[6 * i + 3] -= t.x, y[6 * i + 4] -= t.y, y[6 * i + 5] -= t.z;
    };
    for (const PairEntry& e : a.pairs) {
        const PairForce f = resistance_force(e.c, e.n, v(e.i) - v(e.j), w(e.i), w(e.j));
        add(e.i, f.force_i, f.torque_i);
        add(e.j, -f.force_i, f.torque_j);
    }
    for (const BodyEntry& e : a.bodies) {
        const BodyForce f = resistance_force(e.c, v(e.i), w(e.i));
        add(e.i, f.force, f.torque);
    }
}

double quadratic(const SelfBlock& d, const Vec3& v, const Vec3& w) {
    const Sym3& a = d.a;
    const Sym3& b = d.b;
    const double va = a.xx * v.x * v.x + a.yy * v.y * v.y + a.zz * v.z * v.z +
                      2 * (a.xy * v.x * v.y + a.xz * v.x * v.z + a.yz * v.y * v.z);
    const double wb = b.xx * w.x * w.x + b.yy * w.y * w.y + b.zz * w.z * w.z +
                      2 * (b.xy * w.x * w.y + b.xz * w.x * w.z + b.yz * w.y * w.z);
    return va + wb + 2.0 * dot(w, cross(d.k, v)); // w^T [k]× v appears twice
}

} // namespace

Simulation::StabilityEstimate Simulation::stability_estimate() const {
    const ParticleStore& p = p_;
    const std::size_t n = p.size();
    StabilityEstimate out;
    if (n == 0 || nl_.owners() != n) return out;
    const double skin = nl_.skin();
    const bool semi = semi_implicit();
    Operator damping, stiffness;
    std::vector<SelfBlock> blocks(semi ? n : 0); // D_i at the current gaps (semi-implicit)

    for (std::size_t i = 0; i < n; ++i) {
        const double r = p.radius[i], z = p.position[i].z;
        const int si = p.species[i];
        // Body laws. Dissipative: drag, substrate lubrication and contact damping.
        BodyResistance fluid = stokes_drag_resistance(r, ff_.drag);
        BodyResistance fluid_now = fluid;
        BodyResistance spring;
        if (ff_.substrate_on) {
            fluid += substrate_lubrication_resistance(z - skin, r, ff_.substrate_lubrication);
            fluid_now += substrate_lubrication_resistance(z, r, ff_.substrate_lubrication);
            const double overlap = r - (z - skin);
            if (overlap > 0.0) {
                const HertzMindlinCoefficients co =
                    hertz_mindlin_coefficients(r, overlap, p.mass[i], ff_.substrate[si]);
                fluid += wall_pair_resistance(co.gamma_n, co.gamma_t, r - overlap);
                spring += wall_pair_resistance(co.s_n, co.s_t, r - overlap);
            }
            if (r - z > 0.0) {
                const HertzMindlinCoefficients co =
                    hertz_mindlin_coefficients(r, r - z, p.mass[i], ff_.substrate[si]);
                fluid_now += wall_pair_resistance(co.gamma_n, co.gamma_t, z);
            }
        }
        if (std::abs(liquid_level_ - z) < r + skin) spring.normal += capillary_stiffness(ff_.capillary);
        if (!semi) damping.bodies.push_back({std::uint32_t(i), fluid});
        else add_self_block(blocks[i], fluid_now);
        if (spring.normal > 0.0) stiffness.bodies.push_back({std::uint32_t(i), spring});

        for (std::uint32_t s = nl_.begin(i); s < nl_.end(i); ++s) {
            const std::uint32_t j = nl_.partner(s);
            const PairParams& pp = ff_.pair_params(si, p.species[j]);
            const Vec3 d = box_.minimum_image(p.position[i], p.position[j]);
            const double dist = norm(d);
            const PairGeometry now = make_pair_geometry(d, dist, r, p.radius[j], p.mass[i],
                                                        p.mass[j], {}, {}, {}, {});
            PairGeometry g = now;
            g.gap -= skin; // the closest this pair can come before the next rebuild
            auto dissipative = [&](const PairGeometry& at) {
                PairResistance c = lubrication_resistance(at, pp.lubrication);
                if (at.gap < 0.0) {
                    const HertzMindlinCoefficients co =
                        hertz_mindlin_coefficients(at.r_eff, -at.gap, at.m_eff, pp.contact);
                    c.normal += co.gamma_n;
                    c.sliding += co.gamma_t;
                }
                c.lever_i = at.r_i + 0.5 * at.gap;
                c.lever_j = at.r_j + 0.5 * at.gap;
                return c;
            };
            if (!semi) {
                const PairResistance c = dissipative(g);
                if (c.normal > 0.0 || c.sliding > 0.0)
                    damping.pairs.push_back({std::uint32_t(i), j, g.n, c});
            } else if (now.gap <= 2.0 * now.r_eff || now.gap < 0.0) {
                const PairResistance c = dissipative(now);
                add_self_block(blocks[i], c, now.n, c.lever_i, 1.0);
                add_self_block(blocks[j], c, now.n, c.lever_j, -1.0);
            }
            PairResistance k;
            k.lever_i = g.r_i + 0.5 * g.gap;
            k.lever_j = g.r_j + 0.5 * g.gap;
            if (g.gap < 0.0) { // a contact, or one the pair can reach before the next rebuild
                const HertzMindlinCoefficients co =
                    hertz_mindlin_coefficients(g.r_eff, -g.gap, g.m_eff, pp.contact);
                k.normal = co.s_n;
                k.sliding = co.s_t;
            }
            // Van der Waals snap-in at the current gap: its stiffness is negative (the attraction
            // grows as the gap closes), so it cannot make the kick unstable, only the snap
            // inaccurate; |dF/dh| bounds the snap's growth rate (see the file header).
            if (pp.van_der_waals.hamaker != 0.0 && now.gap >= 0.0 &&
                now.gap <= pp.van_der_waals.cutoff_gap) {
                const double h = std::max(now.gap, pp.van_der_waals.min_gap);
                k.normal += pp.van_der_waals.hamaker * now.r_eff / (3.0 * h * h * h);
            }
            if (k.normal > 0.0) stiffness.pairs.push_back({std::uint32_t(i), j, g.n, k});
        }
    }

    // Power iteration on M_eff⁻¹ A; returns λ_max (Rayleigh quotient in the M_eff norm).
    auto largest = [&](const Operator& a, double s, std::vector<double>& x) {
        std::vector<double> y(6 * n);
        std::mt19937_64 rng(0x5eed ^ std::uint64_t(step_));
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        // A fresh random start (seeded by the step) every call, never the last call's vector: the
        // estimate must follow from the engine state alone, so that a resumed run is bit-identical.
        x.resize(6 * n);
        for (double& v : x) v = u(rng);
        const SelfBlock none{};
        auto block = [&](std::size_t i) -> const SelfBlock& { return semi ? blocks[i] : none; };
        auto mass_norm2 = [&]() {
            double q = 0.0;
            for (std::size_t i = 0; i < n; ++i) {
                const Vec3 v{x[6 * i], x[6 * i + 1], x[6 * i + 2]};
                const Vec3 w{x[6 * i + 3], x[6 * i + 4], x[6 * i + 5]};
                q += p.mass[i] * norm2(v) + norm2(w) / p.inv_inertia[i] + s * quadratic(block(i), v, w);
            }
            return q;
        };
        double lambda = 0.0;
        int it = 0;
        for (; it < 60; ++it) {
            const double q = mass_norm2();
            if (!(q > 0.0)) break;
            const double scale = 1.0 / std::sqrt(q);
            for (double& v : x) v *= scale;
            apply(a, x, y);
            double rayleigh = 0.0;
            for (std::size_t k = 0; k < 6 * n; ++k) rayleigh += x[k] * y[k];
            const bool converged = it >= 8 && std::abs(rayleigh - lambda) < 1e-3 * rayleigh;
            lambda = rayleigh;
            if (converged) break;
            for (std::size_t i = 0; i < n; ++i) {
                Vec3 av, aw;
                solve_self_block(block(i), s, p.mass[i], 1.0 / p.inv_inertia[i],
                                 {y[6 * i], y[6 * i + 1], y[6 * i + 2]},
                                 {y[6 * i + 3], y[6 * i + 4], y[6 * i + 5]}, av, aw);
                x[6 * i] = av.x, x[6 * i + 1] = av.y, x[6 * i + 2] = av.z;
                x[6 * i + 3] = aw.x, x[6 * i + 4] = aw.y, x[6 * i + 5] = aw.z;
            }
        }
        out.iterations += it;
        return lambda;
    };
    auto peak = [&](const std::vector<double>& x) {
        std::size_t best = 0;
        double top = -1.0;
        for (std::size_t i = 0; i < n; ++i) {
            double e = 0.0;
            for (int k = 0; k < 6; ++k) e += x[6 * i + k] * x[6 * i + k];
            if (e > top) top = e, best = i;
        }
        return p.id[best];
    };
    if (!semi) out.damping_rate = largest(damping, 0.0, guard_vector_[0]);
    const double omega2 = largest(stiffness, semi ? settings_.dt : 0.0, guard_vector_[1]);
    out.stiffness_rate = std::sqrt(std::max(omega2, 0.0));
    const bool damping_limits = !semi && out.damping_rate * 2.0 > out.stiffness_rate;
    out.particle_id = peak(damping_limits ? guard_vector_[0] : guard_vector_[1]);
    return out;
}

double stability_indicator(double dt, const Simulation::StabilityEstimate& e) {
    return dt * std::max(e.damping_rate, e.stiffness_rate);
}

double guarded_time_step(double cap, const Simulation::StabilityEstimate& e) {
    constexpr double damping_margin = 1.5;   // of the bound 2 (as the old guard)
    constexpr double stiffness_margin = 1.0; // of the bound 2
    double dt = cap;
    if (e.damping_rate > 0.0) dt = std::min(dt, damping_margin / e.damping_rate);
    if (e.stiffness_rate > 0.0) dt = std::min(dt, stiffness_margin / e.stiffness_rate);
    return dt;
}

} // namespace drydem
