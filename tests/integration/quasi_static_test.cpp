// SPDX-License-Identifier: MIT
// The overdamped, linearly implicit step (engine/quasi_static.hpp) against the exact quasi-static
// solutions: a sphere pressed on the substrate by its weight sits at the Hertz overlap
// δ = (3W / (4 E* sqrt(r)))^(2/3); a vertical chain of three carries W, 2W and 3W through its
// contacts. The step is then limited by the displacement, not by the contact stiffness: at
// equilibrium it takes max_step (1 s), nine orders of magnitude above the contact time.
#include "drydem/engine/quasi_static.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>

namespace {
using namespace drydem;

constexpr double kR = 5e-6, kRho = 4740.0, kG = 1e7;

ForceField field() {
    ForceField ff = uniform_contact_force_field(1, 1e10, 0.3, 0.5, 0.5);
    ff.set_body_law<StokesDragLaw>({0.18, true});
    ff.set_body_law<GravityBuoyancyLaw>({kG, 0.0});
    return ff;
}

double hertz_overlap_of(double force, double r_eff, double e_star) {
    return std::pow(3.0 * force / (4.0 * e_star * std::sqrt(r_eff)), 2.0 / 3.0);
}

QuasiStaticSettings settings() {
    QuasiStaticSettings s;
    s.max_step = 1.0;
    s.max_displacement = 0.01 * kR;
    s.tolerance = 1e-12;
    return s;
}

TEST(QuasiStatic, SpherePressedOnTheSubstrateSitsAtTheHertzOverlap) {
    const ForceField ff = field();
    ParticleStore p;
    p.add(1, 0, kR, kRho, {20e-6, 20e-6, kR}); // touching the substrate, at rest
    QuasiStaticEngine e(std::move(p), Box{40e-6, 40e-6}, ff, settings());
    const double w = e.particles().mass[0] * kG;
    const double exact = hertz_overlap_of(w, kR, law<SubstrateContactLaw>(ff.body[0]).e_star);
    QuasiStaticReport last;
    for (int k = 0; k < 40; ++k) last = e.step();
    const double overlap = kR - e.particles().position[0].z;
    EXPECT_NEAR(overlap, exact, 1e-9 * exact);
    EXPECT_LT(std::abs(e.net_force(0).z), 1e-9 * w);
    EXPECT_EQ(last.dt, 1.0); // at equilibrium nothing limits the step
    EXPECT_NEAR(e.particles().position[0].x, 20e-6, 1e-18);
}

TEST(QuasiStatic, ChainOfThreeCarriesTheWeightAbove) {
    const ForceField ff = field();
    ParticleStore p;
    for (int k = 0; k < 3; ++k)
        p.add(std::uint32_t(k + 1), 0, kR, kRho, {20e-6, 20e-6, kR + 2 * kR * k});
    QuasiStaticEngine e(std::move(p), Box{40e-6, 40e-6}, ff, settings());
    const double w = e.particles().mass[0] * kG;
    const double e_wall = law<SubstrateContactLaw>(ff.body[0]).e_star;
    const double e_pair = law<HertzMindlinLaw>(ff.pair[0]).e_star;
    // Newton's convergence once the step is free (dt = max_step): K is the laws' exact -dF/dx, so
    // the net force falls quadratically, from a quarter of W to 1e-10 W in a handful of steps (a
    // wrong stiffness converges linearly, in tens).
    auto worst = [&] {
        double f = 0.0;
        for (std::size_t k = 0; k < 3; ++k) f = std::max(f, norm(e.net_force(k)) / w);
        return f;
    };
    int free_steps = 0;
    for (int k = 0; k < 80 && worst() > 1e-10; ++k)
        if (e.step().dt == 1.0) ++free_steps;
    EXPECT_LE(free_steps, 5);
    for (int k = 0; k < 10; ++k) e.step();
    // Storage order is kept (no re-sort), so index k is the k-th sphere from the bottom.
    const auto& x = e.particles().position;
    const double d_wall = hertz_overlap_of(3 * w, kR, e_wall);
    const double d_12 = hertz_overlap_of(2 * w, 0.5 * kR, e_pair);
    const double d_23 = hertz_overlap_of(w, 0.5 * kR, e_pair);
    EXPECT_NEAR(kR - x[0].z, d_wall, 1e-8 * d_wall);
    EXPECT_NEAR(2 * kR - (x[1].z - x[0].z), d_12, 1e-8 * d_12);
    EXPECT_NEAR(2 * kR - (x[2].z - x[1].z), d_23, 1e-8 * d_23);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_LT(norm(e.net_force(k)), 1e-8 * w) << k;
}

} // namespace
