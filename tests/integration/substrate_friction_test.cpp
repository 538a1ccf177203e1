// SPDX-License-Identifier: MIT
// Coulomb friction against the substrate (model.md M-2.3, M-2.6; V-3): a sphere pressed on the
// aluminium substrate by a fixed normal load and pulled tangentially sticks below μ_s F_n (elastic
// displacement F/S_t) and slides with |F_t| = μ_s F_n above it. The engine check launches a sphere
// sliding on the substrate under gravity: it decelerates at μ_s g until it rolls at 5/7 v_0.
#include "drydem/engine/simulation.hpp"
#include "drydem/forces/substrate_contact.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>

using namespace drydem;

namespace {
constexpr double kR = 0.75e-6, kRho = 1187.5; // CB sphere
constexpr double kMu = 0.8;
const double kMass = 4.0 / 3.0 * std::numbers::pi * kR * kR * kR * kRho;

// Aluminium substrate against E = 142 GPa, ν = 0.3 particles (C-8, C-6), e = 0.5.
HertzMindlinParams aluminium() { return mix_hertz_mindlin(142e9, 0.3, 70e9, 0.33, 0.5, kMu, 0.0); }

/// Hertz overlap that carries the normal load w against the plane (R* = r).
double hertz_overlap(double w, double e_star) {
    return std::cbrt(std::pow(3.0 * w / (4.0 * e_star * std::sqrt(kR)), 2.0));
}

struct PullResult {
    double displacement;   ///< x - x_0 at the end [m]
    double velocity;       ///< v_x at the end [m/s]
    double velocity_mid;   ///< v_x half-way [m/s]
    double history;        ///< ξ_x at the end [m]
    double max_slip_error; ///< max | |F_t| / (μ F_n) - 1 | over the sliding steps
    int sliding_steps;
};

/// V-3 rig: a sphere held against the substrate by the load w (rotation clamped, as in a pin
/// on a flat) and pulled along +x by p from t = 0, integrated with the engine's velocity-Verlet
/// scheme (M-9.1: forces from the half-step velocity).
PullResult pull(double w, double p, int steps, double dt) {
    const HertzMindlinParams hm = aluminium();
    const double z0 = kR - hertz_overlap(w, hm.e_star);
    Vec3 x{0.0, 0.0, z0}, v{}, xi{};
    auto force = [&](const Vec3& pos, const Vec3& vel) { // through the law's own add_force
        SubstrateContactLaw::State state{xi};
        BodyForce f{};
        SubstrateContactLaw::add_force({pos, vel, {}, kR, kMass, 0.0, 0.0, 0.0}, hm, state, dt, f,
                                       nullptr);
        xi = state.spring;
        return f.force;
    };
    const Vec3 load{p, 0.0, -w};
    Vec3 f = force(x, v) + load;
    PullResult out{};
    for (int s = 0; s < steps; ++s) {
        if (s == steps / 2) out.velocity_mid = v.x;
        v += (0.5 * dt / kMass) * f;
        x += dt * v;
        const Vec3 contact = force(x, v);
        f = contact + load;
        v += (0.5 * dt / kMass) * f;
        // Sliding = the spring was cut back to the Coulomb limit (S_t |ξ| = μ F_n).
        const double s_t = 8.0 * hm.g_star * std::sqrt(kR * (kR - x.z));
        const double f_t = std::hypot(contact.x, contact.y);
        if (s_t * norm(xi) > (1.0 - 1e-9) * kMu * contact.z) {
            ++out.sliding_steps;
            out.max_slip_error =
                std::max(out.max_slip_error, std::abs(f_t / (kMu * contact.z) - 1));
        }
    }
    out.displacement = x.x;
    out.velocity = v.x;
    out.history = xi.x;
    return out;
}
} // namespace

// V-3, stick: a pull of 0.5 μ_s F_n is carried by the tangential spring; the sphere comes to rest
// displaced by F/S_t, S_t = 8 G* sqrt(r δ) at the load's Hertz overlap.
TEST(SubstrateFriction, StickBelowCoulombLimitV3) {
    const double w = 1e-5, p = 0.5 * kMu * w, dt = 1e-11;
    const PullResult r = pull(w, p, 30000, dt);
    const double s_t =
        8.0 * aluminium().g_star * std::sqrt(kR * hertz_overlap(w, aluminium().e_star));
    EXPECT_EQ(r.sliding_steps, 0);
    EXPECT_NEAR(r.displacement, p / s_t, 0.02 * p / s_t);
    EXPECT_NEAR(r.history, r.displacement, 1e-9 * r.displacement); // ξ = elastic displacement
    EXPECT_LT(std::abs(r.velocity), 1e-6 * std::sqrt(s_t / kMass) * p / s_t); // at rest
}

// V-3, slide: a pull of 1.5 μ_s F_n slides the sphere with |F_t| = μ_s F_n (1e-6) and the net
// force 0.5 μ_s F_n accelerates it (measured over the second half, after the spring loaded up).
TEST(SubstrateFriction, SlideAboveCoulombLimitV3) {
    const double w = 1e-5, p = 1.5 * kMu * w, dt = 1e-11;
    const int steps = 2000;
    const PullResult r = pull(w, p, steps, dt);
    EXPECT_GT(r.sliding_steps, steps - 100); // slides after a few steps of spring loading
    EXPECT_LT(r.max_slip_error, 1e-6);
    const double dv = r.velocity - r.velocity_mid, a = (p - kMu * w) / kMass;
    EXPECT_NEAR(dv, a * 0.5 * steps * dt, 0.01 * a * 0.5 * steps * dt);
    // The spring is cut back to the Coulomb limit: ξ = μ F_n / S_t.
    const double s_t =
        8.0 * aluminium().g_star * std::sqrt(kR * hertz_overlap(w, aluminium().e_star));
    EXPECT_NEAR(r.history, kMu * w / s_t, 1e-3 * kMu * w / s_t);
}

// Through the engine: a sphere launched at v_0 on the substrate under gravity slides with
// |F_t| = μ_s F_n (deceleration μ_s g, spin-up μ_s m g c / I) until the contact point sticks, then
// rolls at v_0 k/(1 + k), k = m c²/I = 2.5 (c/r)² (5/7 v_0 for c → r); wall history carried in
// the particle store.
TEST(SubstrateFriction, SlidingSphereStartsRollingAtFiveSevenths) {
    ForceField ff = uniform_contact_force_field(1, 142e9, 0.3, 0.5, kMu);
    law<SubstrateContactLaw>(ff.body[0]) = aluminium();
    ff.set_body_law<GravityBuoyancyLaw>(
        {9.81e6, 0.0}); // scaled gravity, no buoyancy: normal load W = m g
    const double g = 9.81e6, w = kMass * g, v0 = 1.0, dt = 1e-11;
    const double delta = hertz_overlap(w, aluminium().e_star), c = kR - delta;
    ParticleStore p;
    p.add(1, 0, kR, kRho, {10e-6, 10e-6, kR - delta});
    p.velocity[0] = {v0, 0.0, 0.0};
    Simulation sim(std::move(p), Box{40e-6, 40e-6}, ff, {dt, 0.1e-6, 1});
    const double k = 2.5 * (c / kR) * (c / kR);
    const double t_roll = v0 / (kMu * g * (1.0 + k));
    // The first steps load the spring (M-2.3 caps the spring, not the damping term: |F_t| may
    // exceed μ F_n there); from then on the contact slides on the Coulomb cone.
    sim.run(10);
    const double t1 = sim.time(), v1 = sim.particles().velocity[0].x,
                 w1 = sim.particles().omega[0].y;
    double max_slip_error = 0.0;
    while (sim.time() < 0.5 * t_roll) {
        sim.step();
        const Vec3 f = sim.particles().force[0];
        const double f_n = f.z + w; // contact normal force (the weight is in f.z)
        max_slip_error = std::max(max_slip_error, std::abs(std::hypot(f.x, f.y) / (kMu * f_n) - 1));
    }
    EXPECT_LT(max_slip_error, 1e-6);
    const double dt_slide = sim.time() - t1;
    const double spin_up = kMu * w * c / (0.4 * kMass * kR * kR); // μ F_n c / I
    EXPECT_NEAR(sim.particles().velocity[0].x - v1, -kMu * g * dt_slide, 0.01 * kMu * g * dt_slide);
    EXPECT_NEAR(sim.particles().omega[0].y - w1, spin_up * dt_slide, 0.01 * spin_up * dt_slide);
    EXPECT_GT(norm(BodyLaws::state<SubstrateContactLaw>(sim.body_states()[0]).spring), 0.0);
    while (sim.time() < 3.0 * t_roll) sim.step();
    const double v_roll = v0 * k / (1.0 + k);
    EXPECT_NEAR(sim.particles().velocity[0].x, v_roll, 0.01 * v_roll);
    EXPECT_NEAR(sim.particles().omega[0].y * c, v_roll, 0.01 * v_roll); // rolling: v = c ω
    EXPECT_EQ(sim.stats().wall_contacts, 1u);
}
