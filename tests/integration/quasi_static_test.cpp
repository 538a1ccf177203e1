// SPDX-License-Identifier: MIT
// The quasi-static step (engine/quasi_static.hpp) against the exact quasi-static
// solutions: a sphere pressed on the substrate by its weight sits at the Hertz overlap
// δ = (3W / (4 E* sqrt(r)))^(2/3); a vertical chain of three carries W, 2W and 3W through its
// contacts. The step is then limited by the displacement, not by the contact stiffness: at
// equilibrium it takes max_step (1 s), nine orders of magnitude above the contact time. A sphere on
// an incline rolls without slipping below the angle where the friction it needs reaches μN, and
// rolls and slides above it: both steady motions are known exactly.
#include "drydem/engine/simulation.hpp"
#include "settling_column.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>

namespace {
using namespace drydem;
using namespace drydem::testing_support;

ForceField field() { return settling_field(); }

EngineSettings settings() {
    EngineSettings s;
    s.integrator = Integrator::quasi_static;
    s.dt = 0.0; // the first trial step is max_step
    s.threads = 1;
    s.sort_every = 0; // storage order kept: index k is the k-th sphere from the bottom
    s.quasi_static.max_step = 1.0;
    s.quasi_static.max_displacement = 0.01 * kR;
    s.quasi_static.tolerance = 1e-12;
    return s;
}

/// Every force on particle k at rest at the present positions (the residual of equilibrium).
Vec3 net_force(Simulation& e, std::size_t k) {
    e.compute_forces();
    return e.particles().force[k];
}

TEST(QuasiStatic, SpherePressedOnTheSubstrateSitsAtTheHertzOverlap) {
    const ForceField ff = field();
    ParticleStore p;
    p.add(1, 0, kR, kRho, {20e-6, 20e-6, kR}); // touching the substrate, at rest
    Simulation e(std::move(p), Box{40e-6, 40e-6}, ff, settings());
    const double w = e.particles().mass[0] * kG;
    const double exact = hertz_overlap_of(w, kR, law<SubstrateContactLaw>(ff.body[0]).e_star);
    for (int k = 0; k < 40; ++k) e.step();
    const QuasiStaticReport last = e.quasi_static_report();
    const double overlap = kR - e.particles().position[0].z;
    EXPECT_NEAR(overlap, exact, 1e-9 * exact);
    EXPECT_LT(std::abs(net_force(e, 0).z), 1e-9 * w);
    EXPECT_EQ(last.dt, 1.0); // at equilibrium nothing limits the step
    EXPECT_NEAR(e.particles().position[0].x, 20e-6, 1e-18);
}

TEST(QuasiStatic, ChainOfThreeCarriesTheWeightAbove) {
    const ForceField ff = field();
    ParticleStore p;
    for (int k = 0; k < 3; ++k)
        p.add(std::uint32_t(k + 1), 0, kR, kRho, {20e-6, 20e-6, kR + 2 * kR * k});
    Simulation e(std::move(p), Box{40e-6, 40e-6}, ff, settings());
    const double w = e.particles().mass[0] * kG;
    const double e_wall = law<SubstrateContactLaw>(ff.body[0]).e_star;
    const double e_pair = law<HertzMindlinLaw>(ff.pair[0]).e_star;
    // Newton's convergence once the step is free (dt = max_step): K is the laws' exact -dF/dx, so
    // the net force falls quadratically, from a quarter of W to 1e-10 W in a handful of steps (a
    // wrong stiffness converges linearly, in tens).
    auto worst = [&] {
        double f = 0.0;
        for (std::size_t k = 0; k < 3; ++k) f = std::max(f, norm(net_force(e, k)) / w);
        return f;
    };
    int free_steps = 0;
    for (int k = 0; k < 80 && worst() > 1e-10; ++k)
        if (e.step(); e.quasi_static_report().dt == 1.0) ++free_steps;
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
    for (std::size_t k = 0; k < 3; ++k) EXPECT_LT(norm(net_force(e, k)), 1e-8 * w) << k;
}

/// A sphere on the substrate tilted by θ (weight W along (sin θ, 0, -cos θ)), in a liquid of
/// viscosity η: Stokes drag 6πηr v and 8πηr³ ω, Coulomb friction μ = 0.5 at the contact point,
/// lever c = r - δ. Rolling without slipping (v = c ω_y) needs the friction F = 8πηr³ v / c²
/// (torque balance), so v = W sin θ / (6πηr + 8πηr³/c²), and holds while F ≤ μ W cos θ, up to
/// tan θ_c ≈ 1.75 μ. Beyond, the contact slides at F = μ W cos θ: v = (W sin θ - F) / (6πηr),
/// ω_y = F c / (8πηr³).
struct InclineMotion {
    double v, omega;
    bool slides;
};
InclineMotion incline_exact(double w, double theta, double eta, double r, double c, double mu) {
    const double pi = std::numbers::pi, n = w * std::cos(theta);
    const double v_roll =
        w * std::sin(theta) / (6 * pi * eta * r + 8 * pi * eta * r * r * r / (c * c));
    const double f_roll = 8 * pi * eta * r * r * r * v_roll / (c * c);
    if (f_roll <= mu * n) return {v_roll, v_roll / c, false};
    const double f = mu * n;
    return {(w * std::sin(theta) - f) / (6 * pi * eta * r), f * c / (8 * pi * eta * r * r * r),
            true};
}

/// The steady motion the quasi-static step reaches on an incline of angle theta.
InclineMotion incline_steady(double theta, double& exact_v, double& exact_omega, bool& slides) {
    ForceField ff = field();
    law<GravityBuoyancyLaw>(ff.body[0]).inclination = theta;
    const double mu = law<SubstrateContactLaw>(ff.body[0]).friction;
    const double eta = law<StokesDragLaw>(ff.body[0]).viscosity;
    ParticleStore p;
    p.add(1, 0, kR, kRho, {20e-6, 20e-6, kR});
    Simulation e(std::move(p), Box{40e-6, 40e-6}, ff, settings());
    const double w = e.particles().mass[0] * kG;
    const double n = w * std::cos(theta);
    const double overlap = hertz_overlap_of(n, kR, law<SubstrateContactLaw>(ff.body[0]).e_star);
    const InclineMotion exact = incline_exact(w, theta, eta, kR, kR - overlap, mu);
    exact_v = exact.v, exact_omega = exact.omega, slides = exact.slides;
    for (int k = 0; k < 400; ++k) e.step();
    return {e.particles().velocity[0].x, e.particles().omega[0].y, false};
}

TEST(QuasiStatic, SphereOnAnInclineRollsBelowAndSlidesAboveTheFrictionAngle) {
    const double mu = 0.5, pi = std::numbers::pi;
    const double theta_c = std::atan(1.75 * mu); // c ≈ r: 8/14 W sin θ = μ W cos θ
    struct Case {
        double theta;
        bool slides;
    };
    for (const Case& k : {Case{pi / 6, false}, Case{theta_c - 0.01, false},
                          Case{theta_c + 0.01, true}, Case{50 * pi / 180, true}}) {
        double v = 0.0, omega = 0.0;
        bool slides = false;
        const InclineMotion got = incline_steady(k.theta, v, omega, slides);
        EXPECT_EQ(slides, k.slides) << k.theta;
        EXPECT_NEAR(got.v, v, 1e-3 * v) << "theta " << k.theta;
        EXPECT_NEAR(got.omega, omega, 1e-3 * omega) << "theta " << k.theta;
    }
}

} // namespace
