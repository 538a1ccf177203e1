// SPDX-License-Identifier: MIT
// Contact dynamics through the full engine (model.md M-10 V-1, V-3, V-4, V-5, V-13).
#include "drydem/engine/simulation.hpp"
#include <gtest/gtest.h>
#include <cmath>

using namespace drydem;

namespace {
constexpr double r_cb = 0.75e-6, rho_cb = 1187.5;

ParticleStore two_spheres(double gap, double r1 = r_cb, double r2 = r_cb) {
    ParticleStore p;
    p.add(1, 0, r1, rho_cb, {20e-6, 20e-6, 20e-6});
    p.add(2, 0, r2, rho_cb, {20e-6 + r1 + r2 + gap, 20e-6, 20e-6});
    return p;
}

ForceField contact_only(double e, double mu) {
    ForceField ff = uniform_contact_force_field(1, 142e9, 0.3, e, mu);
    ff.remove_substrate();
    return ff;
}

struct Collision {
    double speed_ratio, duration, max_overlap;
};

Collision head_on(double e, double v_rel, double dt = 1e-12) {
    ParticleStore p = two_spheres(1e-9);
    p.velocity[0] = {0.5 * v_rel, 0, 0};
    p.velocity[1] = {-0.5 * v_rel, 0, 0};
    Simulation sim(std::move(p), Box{40e-6, 40e-6}, contact_only(e, 0.0), {dt, 0.1e-6, 1});
    double t_in = -1, t_out = -1, max_overlap = 0;
    for (int s = 0; s < 200000 && t_out < 0; ++s) {
        sim.step();
        const auto& q = sim.particles();
        const double gap = q.position[1].x - q.position[0].x - 2 * r_cb;
        if (gap < 0 && t_in < 0) t_in = sim.time();
        if (gap >= 0 && t_in >= 0) t_out = sim.time();
        max_overlap = std::max(max_overlap, -gap);
    }
    const auto& q = sim.particles();
    return {(q.velocity[1].x - q.velocity[0].x) / v_rel, t_out - t_in, max_overlap};
}
} // namespace

// V-1: the damping of M-2.1 reproduces the restitution coefficient at any e.
TEST(Restitution, SpeedRatioEqualsInputCoefficient) {
    for (double e : {0.1, 0.3, 0.5, 0.7, 0.9}) {
        const Collision c = head_on(e, 1.0);
        EXPECT_NEAR(c.speed_ratio, e, 0.01 * e) << "e = " << e;
    }
}

// V-1: contact duration and maximum overlap against the Hertz values of model.md M-10.
TEST(Restitution, ContactDurationAndOverlapMatchHertz) {
    const Collision elastic = head_on(0.999999, 1.0);
    EXPECT_NEAR(elastic.duration, 2.479e-9, 0.01 * 2.479e-9);
    EXPECT_NEAR(elastic.max_overlap, 8.42e-10, 0.01 * 8.42e-10);
    const Collision damped = head_on(0.5, 1.0);
    EXPECT_NEAR(damped.duration, 2.711e-9, 0.01 * 2.711e-9);
    EXPECT_NEAR(damped.max_overlap, 6.63e-10, 0.01 * 6.63e-10);
    const Collision fast = head_on(0.999999, 6.7);
    EXPECT_NEAR(fast.duration, 1.694e-9, 0.01 * 1.694e-9);
    EXPECT_NEAR(fast.max_overlap, 3.86e-9, 0.01 * 3.86e-9);
}

// V-5: e = 1, μ = 0, no fluid: an oblique collision conserves the total energy.
TEST(EnergyConservation, ObliqueElasticCollision) {
    ParticleStore p = two_spheres(5e-9);
    // Oblique: centres offset 0.6 um in y, 5 nm surface gap.
    p.position[1].y += 0.6e-6;
    p.position[1].x = 20e-6 + std::sqrt(1.505e-6 * 1.505e-6 - 0.6e-6 * 0.6e-6);
    p.velocity[0] = {1.0, 0.2, 0};
    p.velocity[1] = {-1.0, 0, 0.1};
    p.omega[0] = {0, 0, 2e5};
    Simulation sim(std::move(p), Box{40e-6, 40e-6}, contact_only(1.0, 0.0), {1e-12, 0.1e-6, 1});
    const double e0 = sim.kinetic_energy();
    double max_dev = 0;
    bool touched = false;
    for (int s = 0; s < 20000; ++s) {
        sim.step();
        touched = touched || sim.stats().contacts > 0;
        // Elastic energy of the contact: (8/15) E* sqrt(R*) δ^{5/2}.
        const auto& q = sim.particles();
        const double gap = norm(sim.box().minimum_image(q.position[0], q.position[1])) - 2 * r_cb;
        const double e_star = law<HertzMindlinLaw>(sim.forces().pair[0]).e_star;
        const double elastic =
            gap < 0 ? 8.0 / 15.0 * e_star * std::sqrt(0.5 * r_cb) * std::pow(-gap, 2.5) : 0.0;
        max_dev = std::max(max_dev, std::abs(sim.kinetic_energy() + elastic - e0) / e0);
    }
    EXPECT_TRUE(touched);
    EXPECT_LT(max_dev, 1e-4);
}

// V-13: in a closed periodic box without substrate and fields, pair forces sum to zero and the
// momentum is conserved.
TEST(MomentumConservation, DenseFrictionalPeriodicBox) {
    ParticleStore p;
    std::uint32_t id = 1;
    const double spacing = 1.45e-6; // slight overlaps: contacts from the start
    for (int i = 0; i < 26; ++i)
        for (int j = 0; j < 26; ++j)
            for (int k = 0; k < 4; ++k) {
                const double jitter = 0.02e-6 * std::sin(1.7 * id);
                p.add(id, std::uint8_t(id % 2), (id % 2 ? 0.75e-6 : 0.7e-6), rho_cb,
                      {i * spacing + jitter, j * spacing - jitter, 10e-6 + k * spacing + jitter});
                p.velocity.back() = {std::sin(id * 0.37), std::cos(id * 0.11), std::sin(id * 0.73)};
                ++id;
            }
    ForceField ff = uniform_contact_force_field(2, 142e9, 0.3, 0.5, 0.8);
    ff.remove_substrate();
    Simulation sim(std::move(p), Box{26 * spacing, 26 * spacing}, ff, {1e-11, 0.1e-6, 2});
    const Vec3 m0 = sim.momentum();
    double scale = 0;
    for (std::size_t i = 0; i < sim.particles().size(); ++i)
        scale += sim.particles().mass[i] * norm(sim.particles().velocity[i]);
    for (int s = 0; s < 500; ++s) {
        sim.step();
        Vec3 total{};
        double magnitude = 0;
        for (const Vec3& f : sim.particles().force) {
            total += f;
            magnitude += norm(f);
        }
        ASSERT_LT(norm(total), 1e-12 * magnitude) << "step " << s;
    }
    EXPECT_GT(sim.stats().contacts, 100u);
    EXPECT_LT(norm(sim.momentum() - m0), 1e-12 * scale);
}
