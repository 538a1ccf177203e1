// SPDX-License-Identifier: MIT
// The progress line's ETA follows the recent pace, not the pace since the start.
#include "drydem/drying/eta.hpp"
#include <gtest/gtest.h>
#include <cmath>

using namespace drydem;

TEST(RecentPace, FollowsAPaceThatDrops) {
    RecentPace p(60.0);
    EXPECT_TRUE(std::isinf(p.eta(1.0))); // no pace yet
    p.add(0.0, 0.0);
    // 100 s at 1e-8 sim s per wall s, then 300 s at a quarter of it.
    for (int s = 10; s <= 100; s += 10) p.add(s, 1e-8 * s);
    EXPECT_NEAR(p.pace(), 1e-8, 1e-20);
    for (int s = 110; s <= 400; s += 10) p.add(s, 1e-6 + 0.25e-8 * (s - 100));
    EXPECT_NEAR(p.pace(), 0.25e-8, 1e-20); // the window holds only the slow part
    EXPECT_NEAR(p.eta(1e-6), 400.0, 1e-6); // the average since the start would say ~160 s
}

TEST(RecentPace, KeepsTheWindowSpannedWithSparseSamples) {
    RecentPace p(60.0);
    p.add(0.0, 0.0);
    p.add(500.0, 5e-6); // one sample long after the window: the pace still uses both
    EXPECT_NEAR(p.pace(), 1e-8, 1e-20);
}
