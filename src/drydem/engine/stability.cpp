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
//      one; the semi-implicit bound falls to sqrt(2) for an overdamped mode, docs/model.md). The contact gaps are reduced by the skin: before the next rebuild a gap can close
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
#include "drydem/engine/linear_operator.hpp"
#include "drydem/engine/simulation.hpp"
#include <omp.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace drydem {
namespace {

double quadratic(const SelfBlock& d, const Vec3& v, const Vec3& w) {
    const Sym3& a = d.a;
    const Sym3& b = d.b;
    const double va = a.xx * v.x * v.x + a.yy * v.y * v.y + a.zz * v.z * v.z +
                      2 * (a.xy * v.x * v.y + a.xz * v.x * v.z + a.yz * v.y * v.z);
    const double wb = b.xx * w.x * w.x + b.yy * w.y * w.y + b.zz * w.z * w.z +
                      2 * (b.xy * w.x * w.y + b.xz * w.x * w.z + b.yz * w.y * w.z);
    return va + wb + 2.0 * dot(w, cross(d.k, v)); // w^T [k]× v appears twice
}

/// |(v, w)|² in the inertia norm: translations weigh the mass, rotations the moment of inertia.
double inertia_norm2(const ParticleStore& p, std::size_t i, const Vec3& v, const Vec3& w) {
    return p.mass[i] * norm2(v) + norm2(w) / p.inv_inertia[i];
}

/// The guard's operators: per thread, the damping R (explicit only; at the skin-reduced gaps)
/// and the stiffness K entries of its rows; the semi-implicit self-blocks D at the current gaps.
struct GuardOperators {
    std::vector<Operator> damping, stiffness;
    std::vector<SelfBlock> blocks; ///< semi-implicit only
};

/// What the estimate reads of the engine.
struct GuardInputs {
    const ParticleStore& p;
    const NeighborList& nl;
    const Box& box;
    const ForceField& ff;
    double liquid_level;
    double plate; ///< the calendering plate's height (+inf: none)
    const BondNetwork& bonds;
    bool semi;
    std::size_t threads;
    std::size_t owned;    ///< the rows this rank owns; the rest are ghosts (docs/parallel.md)
    parallel::Halo* halo; ///< the decomposition's exchanges, or nullptr
    [[nodiscard]] RowSplit rows() const { return {p.size(), threads}; }
    [[nodiscard]] std::size_t lo_of(std::size_t t) const { return rows().lo(t); }
};

/// Thread t collects the entries of the rows [lo_t, hi_t) in its own operators and self-block
/// shares; every sum runs over the threads in a fixed order, so the operators are the same run to
/// run (and bit for bit the serial ones with one thread).
GuardOperators assemble_operators(const GuardInputs& in) {
    const ParticleStore& p = in.p;
    const std::size_t n = p.size(), threads = in.threads;
    const double skin = in.nl.skin();
    const bool semi = in.semi;
    auto lo_of = [&](std::size_t t) { return in.lo_of(t); };
    GuardOperators op{std::vector<Operator>(threads), std::vector<Operator>(threads),
                      std::vector<SelfBlock>(semi ? n : 0)};
    // D_i at the current gaps (semi-implicit): thread t's share of every particle's block.
    std::vector<std::vector<SelfBlock>> share(semi ? threads : 0, std::vector<SelfBlock>(n));
#pragma omp parallel num_threads(int(threads))
    {
        const std::size_t t = std::size_t(omp_get_thread_num());
        Operator& damping_t = op.damping[t];
        Operator& stiffness_t = op.stiffness[t];
        std::vector<SelfBlock>* blocks_t = semi ? &share[t] : nullptr;
        for (std::size_t i = lo_of(t); i < lo_of(t + 1); ++i) {
            const double r = p.radius[i];
            const int si = p.species[i];
            // Body laws: their resistance and stiffness where the particle can be before the
            // next rebuild (within the skin); the semi-implicit kick's self-block at the present
            // state, as the kick sees it.
            const BodyParams& bp = in.ff.body_params(si);
            const BodyGeometry within{p.position[i],   {},   {},      r, p.mass[i], p.density[i],
                                      in.liquid_level, skin, in.plate};
            const BodyResistance spring = BodyLaws::stiffness(within, bp);
            if (!semi) {
                damping_t.bodies.push_back({std::uint32_t(i), BodyLaws::resistance(within, bp)});
            } else {
                BodyGeometry now = within;
                now.reach = 0.0;
                add_self_block((*blocks_t)[i], BodyLaws::resistance(now, bp));
            }
            if (spring.normal > 0.0) stiffness_t.bodies.push_back({std::uint32_t(i), spring});

            for (std::uint32_t s = in.nl.begin(i); s < in.nl.end(i); ++s) {
                const std::uint32_t j = in.nl.partner(s);
                const PairParams& pp = in.ff.pair_params(si, p.species[j]);
                const Vec3 d = in.box.minimum_image(p.position[i], p.position[j]);
                const double dist = norm(d);
                const PairGeometry now = make_pair_geometry(d, dist, r, p.radius[j], p.mass[i],
                                                            p.mass[j], {}, {}, {}, {});
                PairGeometry g = now;
                g.gap -= skin; // the closest this pair can come before the next rebuild
                if (!semi) {
                    const PairResistance c = PairLaws::resistance(g, pp);
                    if (c.normal > 0.0 || c.sliding > 0.0)
                        damping_t.pairs.push_back({std::uint32_t(i), j, g.n, c});
                } else {
                    const PairResistance c = PairLaws::resistance(now, pp);
                    if (c.normal > 0.0 || c.sliding > 0.0 || c.rolling > 0.0 || c.twisting > 0.0) {
                        add_self_block((*blocks_t)[i], c, now.n, c.lever_i, 1.0);
                        add_self_block((*blocks_t)[j], c, now.n, c.lever_j, -1.0);
                    }
                }
                // Each law's stiffness where it bounds its rate (pair_law.hpp): the contact springs
                // at the skin-reduced gap, the van der Waals snap-in at the present one.
                const PairResistance k = PairLaws::stiffness(g, now, pp);
                if (k.normal > 0.0) stiffness_t.pairs.push_back({std::uint32_t(i), j, g.n, k});
            }
        }
        if (semi) {
#pragma omp barrier
            for (std::size_t i = lo_of(t); i < lo_of(t + 1); ++i)
                for (std::size_t u = 0; u < threads; ++u) op.blocks[i] += share[u][i];
        }
    }
    // The solid bonds (explicit integrator only): their springs and damping at the present state;
    // a bond's stiffness does not change with its stretch.
    for (const Bond& b : in.bonds.bonds) {
        if (!b.state.intact()) continue;
        const PairGeometry g = bond_geometry(b, p, in.box, false);
        const SolidBondParams& bp = in.bonds.pair(p.species[b.i], p.species[b.j]);
        op.stiffness[0].pairs.push_back(
            {b.i, b.j, g.n, solid_bond_stiffness(g, bp, b.state.rest_length)});
        if (!semi)
            op.damping[0].pairs.push_back(
                {b.i, b.j, g.n, solid_bond_resistance(g, bp, b.state.rest_length)});
    }
    return op;
}

/// The power iteration's start: random, seeded by the step, so that the estimate follows from
/// the engine state alone and a resumed run is bit-identical. With `warm` (the last estimate's
/// vector by particle id) a particle that had an entry starts from it plus a tenth of the random
/// vector (both normalised in the mass norm, where rotations weigh their inertia): the limiting
/// mode moves little between two estimates a few dozen steps apart, and the random part keeps a
/// stiffer mode elsewhere in reach.
void start_vector(const GuardInputs& in, std::uint64_t step, const std::vector<double>* warm,
                  std::vector<double>& x) {
    const ParticleStore& p = in.p;
    std::mt19937_64 rng(0x5eed ^ step);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    x.resize(6 * p.size());
    for (double& v : x) v = u(rng);
    if (warm == nullptr || warm->empty()) return;
    const auto entry = [&](std::size_t i) -> const double* {
        const std::size_t at = 6 * std::size_t(p.id[i]);
        return at + 6 <= warm->size() && !std::isnan((*warm)[at]) ? &(*warm)[at] : nullptr;
    };
    const auto norm2_of = [&](std::size_t i, const double* v) {
        return inertia_norm2(p, i, {v[0], v[1], v[2]}, {v[3], v[4], v[5]});
    };
    double warm2 = 0.0, random2 = 0.0;
    for (std::size_t i = 0; i < in.owned; ++i) {
        random2 += norm2_of(i, &x[6 * i]);
        if (const double* w = entry(i)) warm2 += norm2_of(i, w);
    }
    if (in.halo) warm2 = in.halo->all_sum(warm2), random2 = in.halo->all_sum(random2);
    if (!(warm2 > 0.0) || !(random2 > 0.0)) return;
    const double a = 1.0 / std::sqrt(warm2), b = 0.1 / std::sqrt(random2);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double* w = entry(i);
        for (int k = 0; k < 6; ++k) x[6 * i + k] = (w ? a * w[k] : 0.0) + b * x[6 * i + k];
    }
}

/// Keeps the owned rows of the last iterate x by particle id, for the next warm start.
void keep_by_id(const ParticleStore& p, std::size_t owned, const std::vector<double>& x,
                std::vector<double>& by_id) {
    std::uint32_t top = 0;
    for (std::size_t i = 0; i < owned; ++i) top = std::max(top, p.id[i]);
    by_id.assign(6 * (std::size_t(top) + 1), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < owned; ++i)
        std::copy_n(x.begin() + std::ptrdiff_t(6 * i), 6,
                    by_id.begin() + std::ptrdiff_t(6 * std::size_t(p.id[i])));
}

/// λ_max of M_eff⁻¹ A by power iteration (Rayleigh quotient in the M_eff norm, M_eff = M + s D)
/// from start_vector; x keeps the last iterate (for the peak particle).
double largest_rate(const GuardInputs& in, const std::vector<Operator>& a,
                    const std::vector<SelfBlock>& blocks, double s, std::uint64_t step,
                    std::vector<double>& x, std::vector<double>* warm, int& iterations) {
    const ParticleStore& p = in.p;
    const std::size_t n = p.size(), threads = in.threads;
    const bool semi = in.semi;
    std::vector<double> y(6 * n), partial;
    std::vector<std::vector<double>> y_share;
    const RowSplit rows = in.rows();
    start_vector(in, step, warm, x);
    // Under a decomposition the sums run over owned rows only, then over the ranks; a ghost's
    // entries follow its owner's after every update (the products read them).
    auto all_sum = [&](double v) { return in.halo ? in.halo->all_sum(v) : v; };
    if (in.halo) in.halo->update_ghost_values(x, 6);
    const SelfBlock none{};
    auto block = [&](std::size_t i) -> const SelfBlock& { return semi ? blocks[i] : none; };
    auto mass_norm2 = [&](std::size_t i) {
        const Vec3 v{x[6 * i], x[6 * i + 1], x[6 * i + 2]};
        const Vec3 w{x[6 * i + 3], x[6 * i + 4], x[6 * i + 5]};
        if (i >= in.owned) return 0.0;
        return inertia_norm2(p, i, v, w) + s * quadratic(block(i), v, w);
    };
    double lambda = 0.0;
    int it = 0;
    for (; it < 60; ++it) {
        const double q = all_sum(ordered_sum(rows, mass_norm2, partial));
        if (!(q > 0.0)) break;
        const double scale = 1.0 / std::sqrt(q);
#pragma omp parallel for schedule(static) num_threads(int(threads))
        for (std::size_t k = 0; k < 6 * n; ++k) x[k] *= scale;
        apply_split(a, rows, x, y, y_share);
        const double rayleigh = all_sum(ordered_sum(
            rows,
            [&](std::size_t i) {
                double r = 0.0;
                if (i >= in.owned) return r;
                for (std::size_t k = 6 * i; k < 6 * i + 6; ++k) r += x[k] * y[k];
                return r;
            },
            partial));
        const bool converged = it >= 8 && std::abs(rayleigh - lambda) < 1e-3 * rayleigh;
        lambda = rayleigh;
        if (converged) break;
#pragma omp parallel for schedule(static) num_threads(int(threads))
        for (std::size_t i = 0; i < n; ++i) {
            Vec3 av, aw;
            solve_self_block(block(i), s, p.mass[i], 1.0 / p.inv_inertia[i],
                             {y[6 * i], y[6 * i + 1], y[6 * i + 2]},
                             {y[6 * i + 3], y[6 * i + 4], y[6 * i + 5]}, av, aw);
            x[6 * i] = av.x, x[6 * i + 1] = av.y, x[6 * i + 2] = av.z;
            x[6 * i + 3] = aw.x, x[6 * i + 4] = aw.y, x[6 * i + 5] = aw.z;
        }
        if (in.halo) in.halo->update_ghost_values(x, 6);
    }
    iterations += it;
    if (warm != nullptr) keep_by_id(p, in.owned, x, *warm);
    return lambda;
}

/// Id of the particle where the vector x is largest (over the ranks' owned particles).
std::uint32_t peak_particle(const GuardInputs& in, const std::vector<double>& x) {
    std::size_t best = 0;
    double top = -1.0;
    for (std::size_t i = 0; i < in.owned; ++i) {
        double e = 0.0;
        for (int k = 0; k < 6; ++k) e += x[6 * i + k] * x[6 * i + k];
        if (e > top) top = e, best = i;
    }
    const std::uint32_t id = in.owned > 0 ? in.p.id[best] : 0;
    return in.halo ? in.halo->id_of_max(top, id) : id;
}

} // namespace

Simulation::StabilityEstimate Simulation::stability_estimate() const {
    StabilityEstimate out;
    if (nl_.owners() != p_.size()) return out;
    if (halo_ ? halo_->all_sum(std::uint64_t(p_.size())) == 0 : p_.size() == 0) return out;
    const bool semi = semi_implicit();
    // The stiffness is in the kick's inertia (M-9.1) and damping never bounds the semi-implicit
    // kick: nothing left to estimate.
    if (semi && settings_.implicit_stiffness) return out;
    const GuardInputs in{p_,
                         nl_,
                         box_,
                         ff_,
                         liquid_level_,
                         plate_height_,
                         bonds_,
                         semi,
                         std::size_t(threads_),
                         owned(),
                         halo_ ? &*halo_ : nullptr};
    const GuardOperators op = assemble_operators(in);
    const std::uint64_t step = std::uint64_t(step_);
    const bool warm = settings_.guard_warm_start;
    if (!semi)
        out.damping_rate = largest_rate(in, op.damping, op.blocks, 0.0, step, guard_vector_[0],
                                        warm ? &guard_by_id_[0] : nullptr, out.iterations);
    const double omega2 =
        largest_rate(in, op.stiffness, op.blocks, semi ? settings_.dt : 0.0, step, guard_vector_[1],
                     warm ? &guard_by_id_[1] : nullptr, out.iterations);
    out.stiffness_rate = std::sqrt(std::max(omega2, 0.0));
    const bool damping_limits = !semi && out.damping_rate * 2.0 > out.stiffness_rate;
    out.particle_id = peak_particle(in, damping_limits ? guard_vector_[0] : guard_vector_[1]);
    return out;
}

double stability_indicator(double dt, const Simulation::StabilityEstimate& e) {
    return dt * std::max(e.damping_rate, e.stiffness_rate);
}

double guarded_time_step(double cap, const Simulation::StabilityEstimate& e,
                         double critical_fraction) {
    constexpr double damping_margin = 1.5; // of the bound 2 (as the old guard)
    double dt = cap;
    if (e.damping_rate > 0.0) dt = std::min(dt, damping_margin / e.damping_rate);
    if (e.stiffness_rate > 0.0) dt = std::min(dt, critical_fraction * 2.0 / e.stiffness_rate);
    return dt;
}

} // namespace drydem
