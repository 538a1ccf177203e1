// SPDX-License-Identifier: MIT
// The overlap census (analysis/overlap_census.hpp) on constructed spheres: overlaps as a fraction
// of the smaller radius, per pair type and on the substrate, lens volumes against their closed forms,
// pairs across the periodic side.
#include "drydem/analysis/overlap_census.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>

namespace {
using namespace drydem;
using namespace drydem::analysis;
constexpr double pi = std::numbers::pi;

Structure box_of(double side) {
    Structure s;
    s.box = Box{side, side};
    return s;
}

TEST(OverlapCensus, EqualSpheresLensIsTwoCaps) {
    // Two CB spheres r = 1 um, 0.1 um apart in overlap: the lens is two caps of height 0.05 um.
    Structure s = box_of(20e-6);
    s.add({5e-6, 5e-6, 5e-6}, 1e-6, Phase::cb);
    s.add({6.9e-6, 5e-6, 5e-6}, 1e-6, Phase::cb);
    const OverlapCensus c = overlap_census(s);
    EXPECT_EQ(c.cb_cb.pairs, 1u);
    EXPECT_NEAR(c.cb_cb.mean, 0.1, 1e-9);
    EXPECT_NEAR(c.cb_cb.max, 0.1, 1e-9);
    const double h = 0.05e-6, cap = pi * h * h * (3 * 1e-6 - h) / 3;
    EXPECT_NEAR(c.cb_cb.lens_volume, 2 * cap, 1e-12 * 2 * cap);
    EXPECT_EQ(c.ncm_cb.pairs + c.ncm_ncm.pairs + c.cb_substrate.pairs + c.ncm_substrate.pairs, 0u);
    EXPECT_NEAR(c.solid_volume, 2 * 4.0 / 3.0 * pi * 1e-18, 1e-30);
    EXPECT_NEAR(c.lens_fraction(), 2 * cap / c.solid_volume, 1e-12);
}

TEST(OverlapCensus, UnequalPairAcrossThePeriodicSideAndTheSubstrate) {
    // NCM r = 5 um at x = 1 um and CB r = 1 um at x = 15.1 um in a 20 um box: d = 5.9 um through
    // the periodic side, overlap 0.1 um = 10 % of the CB radius.
    Structure s = box_of(20e-6);
    s.add({1e-6, 10e-6, 4.8e-6}, 5e-6, Phase::ncm);   // 0.2 um into the substrate
    s.add({15.1e-6, 10e-6, 4.8e-6}, 1e-6, Phase::cb); // d = 5.9 um through the side
    s.add({10e-6, 10e-6, 20e-6}, 1e-6, Phase::cb);    // touches nothing
    const OverlapCensus c = overlap_census(s);
    ASSERT_EQ(c.ncm_cb.pairs, 1u);
    EXPECT_NEAR(c.ncm_cb.max, 0.1, 1e-9); // (5 + 1 - 5.9) / 1
    const double a = 5e-6, b = 1e-6, d = 5.9e-6;
    const double lens = pi * (a + b - d) * (a + b - d) *
                        (d * d + 2 * d * (a + b) - 3 * (a - b) * (a - b)) / (12 * d);
    EXPECT_NEAR(c.ncm_cb.lens_volume, lens, 1e-9 * lens);
    EXPECT_NEAR(sphere_lens_volume(a, b, d), lens, 1e-9 * lens);
    ASSERT_EQ(c.ncm_substrate.pairs, 1u);
    EXPECT_NEAR(c.ncm_substrate.max, 0.04, 1e-9); // 0.2 / 5
    EXPECT_NEAR(c.ncm_substrate.lens_volume, pi * 0.04e-12 * (15e-6 - 0.2e-6) / 3, 1e-27);
    EXPECT_EQ(c.all.pairs, 2u);
    EXPECT_NEAR(c.all.max, 0.1, 1e-9);
}

TEST(OverlapCensus, QuantilesOverManyPairs) {
    // 100 separate CB pairs with overlaps 0.001 ... 0.100 of r: mean 0.0505, median 0.0505,
    // p99 (nearest rank) 0.099, max 0.1. A pair within reach but apart is no overlap.
    Structure s = box_of(100e-6);
    for (int k = 1; k <= 100; ++k) {
        const double x = 10e-6 * ((k - 1) % 10) + 3e-6, y = 10e-6 * ((k - 1) / 10) + 5e-6;
        s.add({x, y, 5e-6}, 1e-6, Phase::cb);
        s.add({x + 2e-6 - 1e-9 * k, y, 5e-6}, 1e-6, Phase::cb);
    }
    s.add({20e-6, 50e-6, 20e-6}, 1e-6, Phase::cb);
    s.add({22.001e-6, 50e-6, 20e-6}, 1e-6, Phase::cb); // 1 nm apart
    const OverlapCensus c = overlap_census(s);
    ASSERT_EQ(c.cb_cb.pairs, 100u);
    EXPECT_NEAR(c.cb_cb.mean, 0.0505, 1e-9);
    EXPECT_NEAR(c.cb_cb.median, 0.0505, 1e-9);
    EXPECT_NEAR(c.cb_cb.p99, 0.099, 1e-9);
    EXPECT_NEAR(c.cb_cb.max, 0.100, 1e-9);
}

TEST(OverlapCensus, NoOverlapsGivesZeros) {
    Structure s = box_of(20e-6);
    s.add({5e-6, 5e-6, 5e-6}, 1e-6, Phase::cb);
    const OverlapCensus c = overlap_census(s);
    EXPECT_EQ(c.all.pairs, 0u);
    EXPECT_EQ(c.all.p99, 0.0);
    EXPECT_EQ(c.lens_fraction(), 0.0);
}

} // namespace
