// SPDX-License-Identifier: MIT
// The end criterion of a drying run (model.md M-8.2) as a state machine: following the level,
// then relaxing for a fixed window, then done; and its part of a resumed run's state.
#include "drydem/drying/end_criterion.hpp"
#include <gtest/gtest.h>
#include <cmath>

using namespace drydem;
using State = EndCriterion::State;
using Event = EndCriterion::Event;

TEST(EndCriterion, FollowsThenRelaxesThenEnds) {
    EndCriterion end(2e-6, 0.5); // final gap 2 um, relaxation 0.5 s
    EXPECT_EQ(end.state(), State::following);
    EXPECT_TRUE(std::isinf(end.time_end()));
    // The top follows the level (within the gap): nothing happens.
    EXPECT_EQ(end.update(0.1, 20e-6, 21e-6), Event::none);
    EXPECT_EQ(end.update(0.2, 18e-6, 19.5e-6), Event::none);
    EXPECT_FALSE(end.final_found());
    // The level leaves the top behind: H_final = the top at that step.
    EXPECT_EQ(end.update(0.3, 15e-6, 17.5e-6), Event::final_reached);
    EXPECT_EQ(end.state(), State::relaxing);
    EXPECT_DOUBLE_EQ(end.final_thickness(), 17.5e-6);
    EXPECT_DOUBLE_EQ(end.time_final(), 0.3);
    EXPECT_DOUBLE_EQ(end.time_end(), 0.3 + 0.5);
    // Later steps do not move H_final, even if the top settles further.
    EXPECT_EQ(end.update(0.5, 10e-6, 16e-6), Event::none);
    EXPECT_DOUBLE_EQ(end.final_thickness(), 17.5e-6);
    EXPECT_FALSE(end.done());
    EXPECT_EQ(end.update(0.8, 5e-6, 16e-6), Event::none);
    EXPECT_TRUE(end.done());
    EXPECT_EQ(end.state(), State::relaxed);
}

TEST(EndCriterion, LevelAtTheSubstrateEndsTheFollowing) {
    EndCriterion end(5e-6, 0.0);
    EXPECT_EQ(end.update(1.0, 0.0, 3e-6), Event::final_at_substrate);
    EXPECT_DOUBLE_EQ(end.final_thickness(), 3e-6);
    // No relaxation window: done in the same step.
    EXPECT_TRUE(end.done());
}

TEST(EndCriterion, ResumeStateRoundTrips) {
    EndCriterion a(2e-6, 0.5);
    (void)a.update(0.3, 15e-6, 17.5e-6);
    StateFields saved;
    a.fields(saved);
    BinaryWriter w;
    saved.write(w);
    BinaryReader r(w.bytes(), "test");
    StateFields loaded(r, "test");
    EndCriterion b(2e-6, 0.5);
    b.fields(loaded);
    loaded.check_all_loaded();
    EXPECT_EQ(b.state(), State::relaxing);
    EXPECT_EQ(b.final_thickness(), a.final_thickness());
    EXPECT_EQ(b.time_end(), a.time_end());
    // The resumed criterion ends where the uninterrupted one would.
    EXPECT_EQ(b.update(0.8, 5e-6, 16e-6), Event::none);
    EXPECT_TRUE(b.done());
}
