// SPDX-License-Identifier: MIT
// The semi-implicit kick with each particle's own stiffness (numerics.implicit_stiffness,
// docs/model.md M-9.1): v += Δt (M + Δt D + Δt² K_ii)⁻¹ F. At a step far beyond the contact's
// explicit bound it stays stable and comes to the exact quasi-static state: a vertical chain of
// three spheres on the substrate carries W, 2W and 3W through its Hertz contacts, δ = (3F / (4 E*
// sqrt(R*)))^(2/3). Without the self-stiffness the same step blows up.
#include "drydem/core/error.hpp"
#include "drydem/engine/simulation.hpp"
#include "settling_column.hpp"
#include <gtest/gtest.h>
#include <array>
#include <cmath>

namespace {
using namespace drydem;
using namespace drydem::testing_support;

ForceField field() { return settling_field(); }

/// The exact overlaps of the chain: substrate, lower pair, upper pair.
std::array<double, 3> chain_overlaps() {
    const ForceField ff = field();
    const double w = kRho * 4.0 / 3.0 * M_PI * kR * kR * kR * kG;
    const double e_wall = law<SubstrateContactLaw>(ff.body[0]).e_star;
    const double e_pair = law<HertzMindlinLaw>(ff.pair[0]).e_star;
    return {hertz_overlap_of(3 * w, kR, e_wall), hertz_overlap_of(2 * w, 0.5 * kR, e_pair),
            hertz_overlap_of(w, 0.5 * kR, e_pair)};
}

/// The chain at half its exact overlaps, at rest: the step has to bring it the rest of the way
/// (a free fall at the step's length would cross the overlaps many times over in one step).
Simulation chain_of_three(double dt, bool implicit_stiffness) {
    const std::array<double, 3> d = chain_overlaps();
    ParticleStore p;
    double z = kR - 0.5 * d[0];
    for (int k = 0; k < 3; ++k) {
        p.add(std::uint32_t(k + 1), 0, kR, kRho, {20e-6, 20e-6, z});
        if (k < 2) z += 2 * kR - 0.5 * d[std::size_t(k) + 1];
    }
    EngineSettings s;
    s.integrator = Integrator::semi_implicit;
    s.implicit_stiffness = implicit_stiffness;
    s.dt = dt;
    s.threads = 1;
    s.sort_every = 0; // index k stays the k-th sphere from the bottom
    return Simulation(std::move(p), Box{40e-6, 40e-6}, field(), s);
}

/// The explicit bound of the stiffest contact at rest, 2 / sqrt(S_n / m): the substrate contact
/// carrying 3W (S_n = 2 E* sqrt(R δ)).
double contact_step_bound() {
    const ForceField ff = field();
    const double m = kRho * 4.0 / 3.0 * M_PI * kR * kR * kR;
    const double e_wall = law<SubstrateContactLaw>(ff.body[0]).e_star;
    const double s_n = 2.0 * e_wall * std::sqrt(kR * hertz_overlap_of(3 * m * kG, kR, e_wall));
    return 2.0 / std::sqrt(s_n / m);
}

TEST(ImplicitStiffness, ChainSettlesAtTheHertzOverlapsFiftyTimesBeyondTheContactStep) {
    const double dt = 50.0 * contact_step_bound();
    Simulation e = chain_of_three(dt, true);
    // The self-stiffness is inertia: the chain relaxes over ~Δt K / D steps (~600 here), so it
    // needs a few thousand to come to rest.
    for (int k = 0; k < 20000; ++k) e.step();
    const auto& x = e.particles().position;
    const auto [d_wall, d_12, d_23] = chain_overlaps();
    EXPECT_NEAR(kR - x[0].z, d_wall, 1e-6 * d_wall);
    EXPECT_NEAR(2 * kR - (x[1].z - x[0].z), d_12, 1e-6 * d_12);
    EXPECT_NEAR(2 * kR - (x[2].z - x[1].z), d_23, 1e-6 * d_23);
    // The stiffness is in the kick's inertia: the guard has nothing to bound.
    const Simulation::StabilityEstimate est = e.stability_estimate();
    EXPECT_EQ(est.stiffness_rate, 0.0);
    EXPECT_EQ(est.damping_rate, 0.0);
}

TEST(ImplicitStiffness, WithoutItTheSameStepBlowsUp) {
    const double dt = 50.0 * contact_step_bound();
    Simulation e = chain_of_three(dt, false);
    EXPECT_GT(e.stability_estimate().stiffness_rate * dt, 2.0);
    bool failed = false;
    try {
        for (int k = 0; k < 4000 && !failed; ++k) {
            e.step();
            for (const Vec3& x : e.particles().position)
                failed |= !std::isfinite(x.z) || x.z > 1e-3;
        }
    } catch (const RunError&) {
        failed = true; // the runaway-overlap diagnosis
    }
    EXPECT_TRUE(failed);
}

} // namespace
