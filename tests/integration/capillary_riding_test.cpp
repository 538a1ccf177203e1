// SPDX-License-Identifier: MIT
// Capillary riding through the full engine (model.md M-10 V-11): a single particle caught by the
// descending liquid level (M-6) is carried down with it, sitting slightly deeper than the static
// floating equilibrium u = cos θ = 0.766 so that the capillary pull balances Stokes drag (M-5)
// and weight minus buoyancy at the level speed (M-7: 6.70 m/s for 20.1 mg/cm2, zone 1).
#include "drydem/engine/simulation.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>

using namespace drydem;

namespace {
constexpr double kLevelSpeed = 6.70; // scaled level speed [m/s]

struct Riding {
    double u;       ///< h_s / r = (z_L - z) / r at the end of the run
    double v_z;     ///< particle velocity [m/s]
    double u_drift; ///< change of u over the last quarter of the run
};

/// A single sphere at rest with its centre u0 r below the level (u0 slightly below cos θ), the
/// level descending at 6.70 m/s; runs `duration` (several relaxation times 2m/(6π(η/b)r), M-5).
Riding ride(double r, double rho, double u0, double dt, double duration) {
    ForceField ff = uniform_contact_force_field(1, 142e9, 0.3, 0.5, 0.8); // no pair laws needed
    ff.remove_substrate();                               // free particle, far from any wall
    ff.set_body_law<GravityBuoyancyLaw>({9.81e6, 1030}); // g k / b, NMP buoyancy (M-5, M-7)
    ff.set_body_law<StokesDragLaw>({0.1801, true});      // η / b with rotation (M-5, C-18)
    ff.set_body_law<CapillaryFrontLaw>(
        {0.041 * 9e3, 40.0 * std::numbers::pi / 180.0}); // σ s_cap, θ (M-6)
    const double z0 = 60e-6, level0 = z0 + u0 * r;
    ParticleStore p;
    p.add(1, 0, r, rho, {20e-6, 20e-6, z0});
    Simulation sim(std::move(p), Box{40e-6, 40e-6}, ff, {dt, 0.1e-6, 1});
    sim.set_liquid_level(level0);
    sim.set_liquid_level_schedule([level0](double t) { return level0 - kLevelSpeed * t; });
    sim.compute_forces(); // with the level in place
    auto u_now = [&] { return (sim.liquid_level() - sim.particles().position[0].z) / r; };
    const auto steps = std::int64_t(std::llround(duration / dt));
    sim.run(steps * 3 / 4);
    const double u_early = u_now();
    sim.run(steps - steps * 3 / 4);
    return {u_now(), sim.particles().velocity[0].z, u_now() - u_early};
}
} // namespace

// V-11, CB (r = 0.75 um, ρ_CB,eff = 1187.5 kg/m3): u = 0.75632, h_s = 0.56724 um. Relaxation
// 2m/(6π(η/b)r) = 1.65e-9 s; 3e-8 s is 18 of them (3000 steps at Δt = 1e-11 s, C-23).
TEST(CapillaryRiding, CarbonBlackMovesWithTheLevelV11) {
    constexpr double r = 0.75e-6;
    const Riding s = ride(r, 1187.5, 0.74, 1e-11, 3e-8);
    EXPECT_NEAR(s.u, 0.75632, 1e-4);
    EXPECT_NEAR(s.u * r, 0.56724e-6, 1e-4 * r);
    EXPECT_NEAR(s.v_z, -kLevelSpeed, 1e-4 * kLevelSpeed);
    EXPECT_NEAR(s.u_drift, 0.0, 1e-5); // steady: rides with the level
    // 7.3 nm below the static equilibrium h_s = r cos θ.
    EXPECT_NEAR(r * std::cos(40.0 * std::numbers::pi / 180.0) - s.u * r, 7.3e-9, 0.1e-9);
}

// V-11, largest NCM (d = 11.35 um, 4740 kg/m3): u = 0.75841. Relaxation 3.77e-7 s; the
// capillary spring (period 2.5e-7 s) allows Δt = 1e-10 s; 4e-6 s is 10 relaxation times.
TEST(CapillaryRiding, LargestNcmMovesWithTheLevelV11) {
    constexpr double r = 11.35e-6 / 2;
    const Riding s = ride(r, 4740, 0.74, 1e-10, 4e-6);
    EXPECT_NEAR(s.u, 0.75841, 1e-4);
    EXPECT_NEAR(s.v_z, -kLevelSpeed, 1e-3 * kLevelSpeed);
    EXPECT_NEAR(s.u_drift, 0.0, 1e-4);
}
