// SPDX-License-Identifier: MIT
// The descending liquid level: model.md M-8.1, V-12 (20.1 mg/cm2), C-21 (last zone continues).
#include "drydem/drying/liquid_level.hpp"
#include "drydem/drying/scaling.hpp"
#include "drydem/setup/formulation.hpp"
#include <gtest/gtest.h>

namespace {
using namespace drydem;

LiquidLevelSchedule paper_20p1() {
    const Config c; // the paper's 20.1 mg/cm2 case
    const ScaledParameters s = scale_parameters(c);
    return {make_recipe(c).wet_film_height, s.level_speeds_scaled, s.zone_duration_scaled};
}

TEST(LiquidLevel, ScheduleV12) {
    const LiquidLevelSchedule l = paper_20p1();
    EXPECT_NEAR(l.level(0.0) * 1e6, 130.51, 0.005); // z_L(0) = H_wet
    EXPECT_NEAR(l.level(6e-6) * 1e6, 90.31, 0.005); // after zone 1 at 6.70 m/s
    EXPECT_NEAR((l.level(3e-6) - l.level(0.0)) / 3e-6, -6.70, 1e-6);
    EXPECT_NEAR((l.level(9e-6) - l.level(7e-6)) / 2e-6, -11.93, 1e-6);
    // Continuous at the zone change.
    EXPECT_NEAR(l.level(6e-6 - 1e-12), l.level(6e-6 + 1e-12), 2e-11 * 11.93);
    EXPECT_EQ(l.zone(1e-6), 0);
    EXPECT_EQ(l.zone(7e-6), 1);
}

TEST(LiquidLevel, LastZoneContinuesC21) {
    const LiquidLevelSchedule l = paper_20p1();
    // Beyond the two zones (12 us scaled = 120 s physical) s_2 is kept.
    EXPECT_EQ(l.zone(13e-6), 1);
    EXPECT_NEAR((l.level(13e-6) - l.level(12.5e-6)) / 0.5e-6, -11.93, 1e-6);
    EXPECT_NEAR(l.level(13e-6) * 1e6, 90.31 - 11.93 * 7.0, 0.01);
}

TEST(LiquidLevel, ClampsAtSubstrate) {
    const LiquidLevelSchedule l = paper_20p1();
    EXPECT_EQ(l.level(20e-6), 0.0);
    EXPECT_EQ(l.level(1.0), 0.0);
    const LiquidLevelSchedule one{10e-6, {5.0}, 1e-6};
    EXPECT_NEAR(one.level(1.5e-6), 2.5e-6, 1e-18); // single zone: continues past its duration
    EXPECT_EQ(one.level(3e-6), 0.0);
}

} // namespace

// The inverse of the schedule (used for the ETA): time at which the level reaches a height.
TEST(LiquidLevel, TimeAtLevelInvertsTheSchedule) {
    const drydem::LiquidLevelSchedule s{130.51e-6, {6.70, 11.93}, 6e-6};
    for (double t : {0.0, 1e-6, 5.99e-6, 6e-6, 7.5e-6, 9e-6})
        EXPECT_NEAR(s.time_at_level(s.level(t)), t, 1e-15) << t;
    EXPECT_NEAR(s.time_at_level(90.31e-6), 6e-6, 1e-12);
}
