// SPDX-License-Identifier: MIT
// The next pass's peak porosity in unloaded_porosity mode (calendering/passes.hpp).
#include "drydem/calendering/passes.hpp"
#include <gtest/gtest.h>
#include <cmath>

using namespace drydem;

namespace {

/// A pass pressed to `peak` that relaxed to `unloaded`.
CalenderPass pass(double peak, double unloaded) {
    CalenderPass p;
    p.peak_target = p.peak_porosity = peak;
    p.unloaded_porosity = unloaded;
    return p;
}

TEST(CalenderPasses, OnePassShiftsThePeakByTheMiss) {
    // Pressed to 0.30, sprang back to 0.36; for 0.32 the next presses 0.04 deeper.
    EXPECT_NEAR(next_peak_porosity({pass(0.30, 0.36)}, 0.32), 0.26, 1e-15);
}

TEST(CalenderPasses, TwoPassesFollowALinearSpringbackExactly) {
    // A film whose unloaded porosity is a + b ε_peak: the secant of two passes hits the target.
    const double a = 0.05, b = 1.2, target = 0.30;
    auto unloaded = [&](double peak) { return a + b * peak; };
    const double p1 = 0.30, p2 = 0.27;
    const double next =
        next_peak_porosity({pass(p1, unloaded(p1)), pass(p2, unloaded(p2))}, target);
    EXPECT_NEAR(unloaded(next), target, 1e-12);
    EXPECT_LT(next, p2) << "the target lies below the last unloaded porosity: press deeper";
}

TEST(CalenderPasses, SpringbackGrowingWithDepthClosesInFromAbove) {
    // Springback in porosity growing as the peak deepens (0.039 at 0.369, 0.084 at 0.173 on the
    // Sangros film, a line through both): the first rule lands above the target, the secant on.
    auto unloaded = [](double peak) {
        const double s = 0.039 + (0.084 - 0.039) * (0.369 - peak) / (0.369 - 0.173);
        return peak + s;
    };
    const double target = 0.30;
    std::vector<CalenderPass> done{pass(target, unloaded(target))};
    for (int k = 0; k < 5 && std::abs(done.back().unloaded_porosity - target) > 0.005; ++k) {
        const double next = next_peak_porosity(done, target);
        done.push_back(pass(next, unloaded(next)));
        EXPECT_GE(done.back().unloaded_porosity, target - 0.005) << "never pressed past";
    }
    EXPECT_NEAR(done.back().unloaded_porosity, target, 0.005);
    EXPECT_LE(done.size(), 3u);
}

TEST(CalenderPasses, TheSecantNeverPressesDeeperThanTheShift) {
    // The virgin first pass springs back less (0.018) than the re-presses after it (0.030, the
    // end-to-end test's film): the secant's slope 0.37 would aim ~0.02 below the target, the
    // shift (springback unchanged) at it. The shallower wins; a film cannot be un-pressed.
    const std::vector<CalenderPass> done{pass(0.50, 0.5182), pass(0.4818, 0.5115)};
    const double shift = 0.4818 - (0.5115 - 0.50);
    EXPECT_NEAR(next_peak_porosity(done, 0.50), shift, 1e-15);
    auto unloaded = [](double peak) { return peak + 0.030; }; // springback of a re-press
    EXPECT_GE(unloaded(next_peak_porosity(done, 0.50)), 0.50 - 1e-12);
}

TEST(CalenderPasses, ASlopeOutOfRangeFallsBackToTheShift) {
    // The second pass barely moved the film (slope 0.1): no secant, the shift rule.
    const double next = next_peak_porosity({pass(0.30, 0.360), pass(0.28, 0.358)}, 0.32);
    EXPECT_NEAR(next, 0.28 - (0.358 - 0.32), 1e-15);
    // Equal peaks: no slope at all.
    EXPECT_NEAR(next_peak_porosity({pass(0.30, 0.36), pass(0.30, 0.35)}, 0.32), 0.27, 1e-15);
}

TEST(CalenderPasses, DecisionDoneAgainOrTheWayItCannotGoOn) {
    const double target = 0.30, tol = 0.005, densest = 0.15;
    auto decide = [&](std::vector<CalenderPass> done, int max_passes = 5) {
        return decide_next_pass(done, target, tol, max_passes, densest);
    };
    EXPECT_EQ(decide({pass(0.25, 0.304)}).outcome, PassOutcome::done);
    EXPECT_EQ(decide({pass(0.25, 0.296)}).outcome, PassOutcome::done);
    const PassDecision again = decide({pass(0.30, 0.36)});
    EXPECT_EQ(again.outcome, PassOutcome::again);
    EXPECT_NEAR(again.next_peak, 0.24, 1e-15);
    EXPECT_EQ(decide({pass(0.25, 0.29)}).outcome, PassOutcome::pressed_past);
    EXPECT_EQ(decide({pass(0.30, 0.36), pass(0.24, 0.33)}, 2).outcome, PassOutcome::out_of_passes);
    // Springing back by 0.16 from 0.20: the next would have to press to 0.14, below 0.15.
    const PassDecision far = decide({pass(0.20, 0.36)});
    EXPECT_EQ(far.outcome, PassOutcome::out_of_reach);
    EXPECT_NEAR(far.next_peak, 0.14, 1e-15);
}

} // namespace
