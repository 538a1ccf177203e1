// SPDX-License-Identifier: MIT
// The stability guard's policy (docs/model.md "Stability guard") as a pure function: what each
// numerics.stability_guard setting does with an estimate of the explicit rates.
#include "drydem/drying/stability_guard.hpp"
#include <gtest/gtest.h>

using namespace drydem;
using Action = GuardDecision::Action;

namespace {
Simulation::StabilityEstimate estimate(double damping, double stiffness) {
    Simulation::StabilityEstimate e;
    e.damping_rate = damping;
    e.stiffness_rate = stiffness;
    return e;
}
} // namespace

TEST(GuardDecision, AdaptSetsTheGuardedStepNeverAboveTheCap) {
    const auto e = estimate(1e10, 5e9);
    const GuardDecision d = guard_decision(GuardPolicy::adapt, 1e-9, {1e-9, 0.5}, e, 0.0);
    EXPECT_DOUBLE_EQ(d.time_step, guarded_time_step(1e-9, e, 0.5));
    EXPECT_LE(d.time_step, 1e-9);
    EXPECT_DOUBLE_EQ(d.indicator, stability_indicator(d.time_step, e));
    EXPECT_LT(d.indicator, 2.0);
    EXPECT_EQ(d.action, Action::none);
    // Slow rates: the cap holds.
    EXPECT_DOUBLE_EQ(
        guard_decision(GuardPolicy::adapt, 1e-12, {1e-9, 0.5}, estimate(1.0, 1.0), 0.0).time_step,
        1e-9);
}

TEST(GuardDecision, RefuseAndWarnKeepTheStepAndFlagTheBound) {
    const auto e = estimate(1e10, 0.0); // dt * lambda = 3 at 3e-10 s
    for (GuardPolicy p : {GuardPolicy::refuse, GuardPolicy::warn}) {
        const GuardDecision d = guard_decision(p, 3e-10, {1e-9, 0.5}, e, 0.0);
        EXPECT_DOUBLE_EQ(d.time_step, 3e-10);
        EXPECT_DOUBLE_EQ(d.indicator, 3.0);
        EXPECT_EQ(d.action, Action::beyond_bound);
    }
}

TEST(GuardDecision, CloseToTheBoundWarnsOnlyWhenRising) {
    const auto e = estimate(1e10, 0.0);
    EXPECT_EQ(guard_decision(GuardPolicy::warn, 1.4e-10, {1e-9, 0.5}, e, 0.0).action, Action::none);
    EXPECT_EQ(guard_decision(GuardPolicy::warn, 1.7e-10, {1e-9, 0.5}, e, 0.0).action,
              Action::warn_close);
    // Warned at 1.68 already: 1.7 is not kGuardWarnRise above it.
    EXPECT_EQ(guard_decision(GuardPolicy::warn, 1.7e-10, {1e-9, 0.5}, e, 1.68).action,
              Action::none);
    EXPECT_EQ(guard_decision(GuardPolicy::warn, 1.8e-10, {1e-9, 0.5}, e, 1.68).action,
              Action::warn_close);
}

TEST(GuardDecision, CriticalStepFractionScalesTheStiffnessLimitOnly) {
    // Stiffness-limited: dt = f * 2 / omega, so f = 0.5 gives dt omega = 1 and f = 0.65 gives 1.3.
    const auto e = estimate(1e9, 1e10);
    EXPECT_DOUBLE_EQ(guarded_time_step(1e-9, e, 0.5), 1e-10);
    EXPECT_DOUBLE_EQ(guarded_time_step(1e-9, e, 0.65), 1.3e-10);
    EXPECT_DOUBLE_EQ(guarded_time_step(1e-9, e, 0.25), 0.5e-10);
    EXPECT_DOUBLE_EQ(guard_decision(GuardPolicy::adapt, 1e-12, {1e-9, 0.65}, e, 0.0).indicator,
                     1.3);
    // Damping-limited (explicit integrator): the fraction does not touch the damping margin 1.5.
    const auto d = estimate(1e10, 1e9);
    EXPECT_DOUBLE_EQ(guarded_time_step(1e-9, d, 0.5), 1.5e-10);
    EXPECT_DOUBLE_EQ(guarded_time_step(1e-9, d, 0.65), 1.5e-10);
    // Never above the cap.
    EXPECT_DOUBLE_EQ(guarded_time_step(1e-11, e, 0.65), 1e-11);
}

TEST(GuardDecision, SemiImplicitBoundIsSqrtTwo) {
    // Stiffness indicator 1.5 at 1.5e-10 s: inside the explicit bound 2, beyond the semi-implicit
    // kick's sqrt(2) (an overdamped mode; tests/integration/stability_test.cpp).
    const auto e = estimate(0.0, 1e10);
    const GuardLimits semi{1e-9, 0.5, stability_bound_for("semi_implicit")};
    EXPECT_EQ(guard_decision(GuardPolicy::refuse, 1.5e-10, semi, e, 0.0).action,
              Action::beyond_bound);
    EXPECT_EQ(guard_decision(GuardPolicy::refuse, 1.5e-10,
                             {1e-9, 0.5, stability_bound_for("explicit")}, e, 0.0)
                  .action,
              Action::none); // 1.5 is not above the explicit warning level 1.5
    // warn at 3/4 of the bound: 1.1 > 0.75 sqrt(2) = 1.06.
    EXPECT_EQ(guard_decision(GuardPolicy::warn, 1.1e-10, semi, e, 0.0).action, Action::warn_close);
    EXPECT_EQ(guard_decision(GuardPolicy::warn, 1.0e-10, semi, e, 0.0).action, Action::none);
}

TEST(GuardDecision, PolicyNames) {
    EXPECT_EQ(guard_policy_of("adapt"), GuardPolicy::adapt);
    EXPECT_EQ(guard_policy_of("refuse"), GuardPolicy::refuse);
    EXPECT_EQ(guard_policy_of("warn"), GuardPolicy::warn);
    EXPECT_ANY_THROW((void)guard_policy_of("sometimes"));
}
