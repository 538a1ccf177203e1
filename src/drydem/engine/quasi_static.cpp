// SPDX-License-Identifier: MIT
#include "drydem/engine/quasi_static.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
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
double dot6(const std::vector<double>& a, const std::vector<double>& b) {
    double s = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) s += a[k] * b[k];
    return s;
}
PairResistance combined(const PairResistance& r, const PairResistance& k, double dt) {
    PairResistance c = r;
    c.normal += dt * k.normal;
    c.sliding += dt * k.sliding;
    c.rolling += dt * k.rolling;
    c.twisting += dt * k.twisting;
    return c;
}
BodyResistance combined(const BodyResistance& r, const BodyResistance& k, double dt) {
    BodyResistance c = k;
    c.normal *= dt, c.tangential *= dt, c.coupling *= dt, c.rotation_t *= dt, c.rotation_n *= dt;
    c += r;
    return c;
}

} // namespace

QuasiStaticEngine::QuasiStaticEngine(ParticleStore particles, Box box, ForceField forces,
                                     QuasiStaticSettings s)
    : p_(std::move(particles)), body_state_(p_.size()), box_(box), ff_(std::move(forces)), s_(s),
      nl_(s.skin, 1) {
    if (!(s_.max_step > 0.0) || !(s_.max_displacement > 0.0))
        throw InputError("quasi-static step: max_step and max_displacement must be positive");
}

void QuasiStaticEngine::assemble() {
    auto range = [&](std::size_t i, std::size_t j) {
        return interaction_range(ff_.pair_params(p_.species[i], p_.species[j]), p_.radius[i],
                                 p_.radius[j]);
    };
    auto owner_range = [&](std::size_t i) {
        double r = 0.0;
        for (int sj = 0; sj < ff_.species_count; ++sj)
            r = std::max(r, interaction_range(ff_.pair_params(p_.species[i], sj), p_.radius[i],
                                              p_.radius[i]));
        return r;
    };
    nl_.build(p_, box_, range, owner_range, false); // storage order kept: body states index it
    const std::size_t n = p_.size();
    pairs_.clear();
    bodies_.assign(n, {});
    force_.assign(6 * n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const BodyParams& bp = ff_.body_params(p_.species[i]);
        const BodyGeometry at_rest{p_.position[i],  {}, {}, p_.radius[i], p_.mass[i], p_.density[i],
                                   s_.liquid_level, 0.0};
        BodyState kept = body_state_[i];
        const BodyForce f = BodyLaws::force(at_rest, bp, kept, 0.0);
        add_part(force_, i, 0, f.force);
        add_part(force_, i, 1, f.torque);
        bodies_[i] = {BodyLaws::resistance(at_rest, bp), BodyLaws::stiffness(at_rest, bp)};
        for (std::uint32_t s = nl_.begin(i); s < nl_.end(i); ++s) {
            const std::uint32_t j = nl_.partner(s);
            const Vec3 d = box_.minimum_image(p_.position[i], p_.position[j]);
            const double dist2 = norm2(d);
            if (dist2 >= nl_.reach2(s)) continue;
            const PairParams& pp = ff_.pair_params(p_.species[i], p_.species[j]);
            const PairGeometry g =
                make_pair_geometry(d, std::sqrt(dist2), p_.radius[i], p_.radius[j], p_.mass[i],
                                   p_.mass[j], {}, {}, {}, {});
            PairState pair_kept = nl_.state(s);
            const PairForce pf = PairLaws::force(g, pp, pair_kept, 0.0);
            add_part(force_, i, 0, pf.force_i);
            add_part(force_, i, 1, pf.torque_i);
            add_part(force_, j, 0, -1.0 * pf.force_i);
            add_part(force_, j, 1, pf.torque_j);
            pairs_.push_back({std::uint32_t(i), j, s, g, PairLaws::resistance(g, pp),
                              PairLaws::stiffness(g, g, pp)});
        }
    }
}

void QuasiStaticEngine::apply(double dt, const std::vector<double>& u,
                              std::vector<double>& y) const {
    std::fill(y.begin(), y.end(), 0.0);
    for (const PairEntry& e : pairs_) {
        const PairForce f =
            resistance_force(combined(e.r, e.k, dt), e.g.n, part(u, e.i, 0) - part(u, e.j, 0),
                             part(u, e.i, 1), part(u, e.j, 1));
        add_part(y, e.i, 0, -1.0 * f.force_i); // A u = -(the force of u)
        add_part(y, e.i, 1, -1.0 * f.torque_i);
        add_part(y, e.j, 0, f.force_i);
        add_part(y, e.j, 1, -1.0 * f.torque_j);
    }
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        const BodyForce f = resistance_force(combined(bodies_[i].r, bodies_[i].k, dt),
                                             part(u, i, 0), part(u, i, 1));
        add_part(y, i, 0, -1.0 * f.force);
        add_part(y, i, 1, -1.0 * f.torque);
    }
}

int QuasiStaticEngine::solve(double dt, std::vector<double>& u, double& residual) const {
    const std::size_t n = p_.size();
    // Block-Jacobi preconditioner: each particle's 6×6 block of R + dt K.
    std::vector<SelfBlock> block(n);
    for (const PairEntry& e : pairs_) {
        const PairResistance c = combined(e.r, e.k, dt);
        add_self_block(block[e.i], c, e.g.n, c.lever_i, 1.0);
        add_self_block(block[e.j], c, e.g.n, c.lever_j, -1.0);
    }
    for (std::size_t i = 0; i < n; ++i)
        add_self_block(block[i], combined(bodies_[i].r, bodies_[i].k, dt));
    auto precondition = [&](const std::vector<double>& r, std::vector<double>& z) {
        for (std::size_t i = 0; i < n; ++i) {
            Vec3 a, b;
            solve_self_block(block[i], 1.0, 0.0, 0.0, part(r, i, 0), part(r, i, 1), a, b);
            z[6 * i] = a.x, z[6 * i + 1] = a.y, z[6 * i + 2] = a.z;
            z[6 * i + 3] = b.x, z[6 * i + 4] = b.y, z[6 * i + 5] = b.z;
        }
    };
    std::vector<double> r = force_, z(6 * n), q(6 * n), au(6 * n);
    std::fill(u.begin(), u.end(), 0.0);
    const double norm_f = std::sqrt(dot6(force_, force_));
    residual = 0.0;
    if (norm_f == 0.0) return 0;
    precondition(r, z);
    std::vector<double> d = z;
    double rz = dot6(r, z);
    for (int it = 1; it <= s_.max_iterations; ++it) {
        apply(dt, d, q);
        const double alpha = rz / dot6(d, q);
        for (std::size_t k = 0; k < u.size(); ++k) u[k] += alpha * d[k], r[k] -= alpha * q[k];
        residual = std::sqrt(dot6(r, r)) / norm_f;
        if (!std::isfinite(residual))
            throw RunError("quasi-static step: the linear solve diverged (R + dt K not positive "
                           "definite?)",
                           "blow_up");
        if (residual <= s_.tolerance) return it;
        precondition(r, z);
        const double rz_new = dot6(r, z);
        for (std::size_t k = 0; k < d.size(); ++k) d[k] = z[k] + (rz_new / rz) * d[k];
        rz = rz_new;
    }
    return s_.max_iterations;
}

QuasiStaticReport QuasiStaticEngine::step() {
    assemble();
    const std::size_t n = p_.size();
    QuasiStaticReport rep;
    std::vector<double> u(6 * n);
    double dt = s_.max_step;
    for (int attempt = 0; attempt < 8; ++attempt) {
        rep.iterations = solve(dt, u, rep.residual);
        double vmax = 0.0;
        for (std::size_t i = 0; i < n; ++i) vmax = std::max(vmax, norm(part(u, i, 0)));
        rep.max_displacement = dt * vmax;
        if (rep.max_displacement <= s_.max_displacement * (1.0 + 1e-9)) break;
        dt *= 0.9 * s_.max_displacement / rep.max_displacement; // the linearisation's range
    }
    rep.dt = dt;
    // The laws' kept states advance with the solved velocities (springs, Coulomb's cut), then the
    // particles move.
    for (const PairEntry& e : pairs_) {
        PairGeometry g = e.g;
        g.v_rel = part(u, e.i, 0) - part(u, e.j, 0);
        g.v_n = dot(g.v_rel, g.n);
        g.omega_i = part(u, e.i, 1);
        g.omega_j = part(u, e.j, 1);
        (void)PairLaws::force(g, ff_.pair_params(p_.species[e.i], p_.species[e.j]),
                              nl_.state(e.slot), dt);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const BodyGeometry g{p_.position[i], part(u, i, 0), part(u, i, 1),   p_.radius[i],
                             p_.mass[i],     p_.density[i], s_.liquid_level, 0.0};
        (void)BodyLaws::force(g, ff_.body_params(p_.species[i]), body_state_[i], dt);
        p_.position[i] += dt * part(u, i, 0);
        box_.wrap(p_.position[i]);
        p_.velocity[i] = part(u, i, 0);
        p_.omega[i] = part(u, i, 1);
    }
    return rep;
}

Vec3 QuasiStaticEngine::net_force(std::size_t i) const {
    Vec3 f;
    const BodyGeometry at_rest{p_.position[i],  {}, {}, p_.radius[i], p_.mass[i], p_.density[i],
                               s_.liquid_level, 0.0};
    BodyState kept = body_state_[i];
    f += BodyLaws::force(at_rest, ff_.body_params(p_.species[i]), kept, 0.0).force;
    for (std::size_t j = 0; j < p_.size(); ++j) {
        if (j == i) continue;
        const Vec3 d = box_.minimum_image(p_.position[i], p_.position[j]);
        const double dist = norm(d);
        const PairGeometry g = make_pair_geometry(d, dist, p_.radius[i], p_.radius[j], p_.mass[i],
                                                  p_.mass[j], {}, {}, {}, {});
        PairState none{};
        f += PairLaws::force(g, ff_.pair_params(p_.species[i], p_.species[j]), none, 0.0).force_i;
    }
    return f;
}

} // namespace drydem
