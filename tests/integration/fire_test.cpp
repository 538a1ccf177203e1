// SPDX-License-Identifier: MIT
// FIRE relaxation (engine/fire.hpp) brings undamped contacts to their static equilibrium, which
// plain velocity Verlet never reaches (with restitution 1 it oscillates forever): a sphere resting
// on the substrate under weight at the Hertz overlap, and a column of three.
#include "drydem/engine/fire.hpp"
#include "drydem/forces/hertz_mindlin.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>

using namespace drydem;

namespace {
constexpr double kR = 2e-6, kRho = 4700, kE = 142e9, kNu = 0.3, kG = 1e7;

/// n spheres stacked on the substrate at rest, the first `lift` above its equilibrium, no
/// damping (restitution 1), weight kG.
Simulation column(int n, double lift) {
    ForceField ff = uniform_contact_force_field(1, kE, kNu, 1.0, 0.5);
    ff.set_body_law<GravityBuoyancyLaw>({kG, 0.0, 0.0});
    ParticleStore p;
    for (int k = 0; k < n; ++k)
        p.add(std::uint32_t(k + 1), 0, kR, kRho, {5e-6, 5e-6, kR * (1 + 2 * k) + lift});
    return Simulation(std::move(p), Box{40e-6, 40e-6}, ff, {2e-10, 0.1e-6, 1});
}

double mass() { return kRho * 4.0 / 3.0 * std::numbers::pi * kR * kR * kR; }

TEST(Fire, SphereOnTheSubstrateSettlesAtTheHertzOverlap) {
    Simulation sim = column(1, -5e-9); // pressed 5 nm too deep
    const double e_star = mix_hertz_mindlin(kE, kNu, kE, kNu, 1.0, 0.5, 0.0).e_star;
    const double delta = hertz_overlap(mass() * kG, kR, e_star);
    FireRelaxation fire(2e-10);
    int steps = 0;
    while (fire.rms_force() > 1e-6 * mass() * kG && steps < 20000) {
        sim.step();
        fire.after_step(sim);
        ++steps;
    }
    EXPECT_LT(steps, 20000);
    EXPECT_NEAR(kR - sim.particles().position[0].z, delta, 1e-4 * delta);
    EXPECT_GT(fire.stops(), 0); // it overshot at least once and stopped
}

TEST(Fire, PlainDynamicsWithoutDampingDoesNotSettle) {
    Simulation sim = column(1, -5e-9);
    const double f0 = std::abs(sim.particles().force[0].z); // the net force at the start
    double late = 0.0;
    for (int k = 0; k < 20000; ++k) {
        sim.step();
        if (k >= 19000) late = std::max(late, std::abs(sim.particles().force[0].z));
    }
    EXPECT_GT(late, 0.5 * f0); // still oscillating with most of its first swing
}

TEST(Fire, ColumnOfThreeCarriesTheWeightAbove) {
    Simulation sim = column(3, 2e-9);
    FireRelaxation fire(2e-10);
    for (int k = 0; k < 40000 && fire.rms_force() > 1e-6 * mass() * kG; ++k) {
        sim.step();
        fire.after_step(sim);
    }
    const double e_star = mix_hertz_mindlin(kE, kNu, kE, kNu, 1.0, 0.5, 0.0).e_star;
    const auto& x = sim.particles().position;
    // Overlaps: substrate carries 3 weights (R* = r), the first pair 2 and the second 1 (R* = r/2).
    EXPECT_NEAR(kR - x[0].z, hertz_overlap(3 * mass() * kG, kR, e_star), 1e-3 * (kR - x[0].z));
    EXPECT_NEAR(2 * kR - (x[1].z - x[0].z), hertz_overlap(2 * mass() * kG, kR / 2, e_star),
                1e-3 * (2 * kR - (x[1].z - x[0].z)));
    EXPECT_NEAR(2 * kR - (x[2].z - x[1].z), hertz_overlap(mass() * kG, kR / 2, e_star),
                1e-3 * (2 * kR - (x[2].z - x[1].z)));
}

} // namespace
