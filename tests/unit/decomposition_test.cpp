// SPDX-License-Identifier: MIT
// The domain decomposition's geometry (parallel/decomposition.hpp): the grid it picks, ownership,
// neighbours and the periodic distance to a subdomain, and the refusal of too many ranks.
#include "drydem/core/error.hpp"
#include "drydem/parallel/decomposition.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace drydem;
using namespace drydem::parallel;

namespace {
const Box kBox{75e-6, 75e-6};
constexpr double kReach = 12e-6;
constexpr double kThin = 20e-6;   ///< a film thinner than two reaches: never cut in z
constexpr double kThick = 130e-6; ///< the paper's wet film: 1.7 cells tall
} // namespace

TEST(Decomposition, PicksTheGridWithTheLeastGhostArea) {
    EXPECT_EQ(decompose(kBox, 1, kReach, kThin).px, 1);
    const auto d2 = decompose(kBox, 2, kReach, kThin);
    EXPECT_EQ(d2.px * d2.py, 2);
    EXPECT_EQ(d2.px, 2); // ties go to x
    // 4 ranks, reach 12 um: 4 x 1 holds 2 x 12 x 75 = 1800 um2 of ghosts per rank, 2 x 2
    // (37.5 + 24)^2 - 37.5^2 = 2376 um2 (its corners too).
    const auto d4 = decompose(kBox, 4, kReach, kThin);
    EXPECT_EQ(d4.px, 4);
    EXPECT_EQ(d4.py, 1);
    // With a reach of 20 um, 18.75 um wide strips are too narrow: 2 x 2.
    const auto d4_wide = decompose(kBox, 4, 20e-6, kThin);
    EXPECT_EQ(d4_wide.px, 2);
    EXPECT_EQ(d4_wide.py, 2);
    // 16 ranks: only 4 x 4 leaves subdomains 12 um wide.
    const auto d16 = decompose(kBox, 16, kReach, kThin);
    EXPECT_EQ(d16.px, 4);
    EXPECT_EQ(d16.py, 4);
    // A long cell is cut across its length.
    const auto long_cell = decompose(Box{300e-6, 75e-6}, 4, kReach, kThin);
    EXPECT_EQ(long_cell.px, 4);
    EXPECT_EQ(long_cell.py, 1);
    // 6 ranks: 6 x 1 (12.5 um strips: 1800 um2) before 3 x 2 (49 x 61.5 - 25 x 37.5 = 2076).
    const auto d6 = decompose(kBox, 6, kReach, kThin);
    EXPECT_EQ(d6.px, 6);
    EXPECT_EQ(d6.py, 1);
}

TEST(Decomposition, RefusesSubdomainsNarrowerThanTheReachNamingTheNumbers) {
    // 75 um / 12 um: at most 6 per direction. 7 ranks is a prime > 6: 7 x 1 leaves 10.7 um.
    try {
        (void)decompose(kBox, 7, kReach, kThin);
        FAIL() << "7 ranks accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("7 ranks"), std::string::npos) << what;
        EXPECT_NE(what.find("12 um"), std::string::npos) << what;
        EXPECT_NE(what.find("at most 36 ranks"), std::string::npos) << what;
    }
    EXPECT_NO_THROW((void)decompose(kBox, 36, kReach, kThin));
    EXPECT_THROW((void)decompose(kBox, 49, kReach, kThin), InputError);
    EXPECT_THROW((void)decompose(kBox, 0, kReach, kThin), InputError);
    EXPECT_THROW((void)decompose(kBox, 2, NAN, kThin), InputError);
    EXPECT_THROW((void)decompose(kBox, 2, -1.0, kThin), InputError);
    EXPECT_THROW((void)decompose(kBox, 2, kReach, NAN), InputError);
    EXPECT_THROW((void)decompose(kBox, 2, kReach, -1e-6), InputError);
}

// A film taller than the cell is wide is cut in layers: one cut in z of the 75 um cell under a
// 130 um film holds 75 x 75 x 12 = 67,500 um3 of ghosts per rank, one cut in x (two faces,
// periodic) 2 x 12 x 75 x 130 / 2 x 2 = 234,000 um3. A wide cell goes back to columns.
TEST(Decomposition, ThickFilmsAreCutInLayers) {
    const auto d2 = decompose(kBox, 2, kReach, kThick);
    EXPECT_EQ(d2.px * d2.py, 1);
    EXPECT_EQ(d2.pz, 2);
    ASSERT_EQ(d2.cut_z.size(), 3u);
    EXPECT_NEAR(d2.cut_z[1], 65e-6, 1e-18);
    EXPECT_EQ(d2.z_lo(0), -INFINITY); // the lowest layer reaches through the substrate
    EXPECT_EQ(d2.z_hi(1), INFINITY);  // the highest up without bound
    // 4 ranks: 4 layers of 32.5 um (75^2 x 18 = 101,250 um3) before 2 x 1 x 2 (172,350) and
    // 4 x 1 x 1 (234,000).
    const auto d4 = decompose(kBox, 4, kReach, kThick);
    EXPECT_EQ(d4.pz, 4);
    // 300 um wide: 4 x 1 x 1 (936,000 um3) before 2 x 2 x 1 (1,010,880) and 1 x 1 x 4.
    const auto wide = decompose(Box{300e-6, 300e-6}, 4, kReach, kThick);
    EXPECT_EQ(wide.px, 4);
    EXPECT_EQ(wide.pz, 1);
    // Layers at least a reach thick: 130 / 12 allows 10.
    EXPECT_NO_THROW((void)decompose(kBox, 10, kReach, kThick, {1, 1, 0}));
    EXPECT_THROW((void)decompose(kBox, 11, kReach, kThick, {1, 1, 0}), InputError);
}

// A grid asked for is kept where it fits, refused with the request named where it does not.
TEST(Decomposition, KeepsTheGridAskedFor) {
    const auto columns = decompose(kBox, 2, kReach, kThick, {0, 0, 1});
    EXPECT_EQ(columns.px, 2);
    EXPECT_EQ(columns.pz, 1);
    const auto rows = decompose(kBox, 2, kReach, kThick, {1, 0, 1});
    EXPECT_EQ(rows.py, 2);
    const auto mixed = decompose(kBox, 4, kReach, kThick, {2, 1, 2});
    EXPECT_EQ(mixed.px, 2);
    EXPECT_EQ(mixed.pz, 2);
    try {
        (void)decompose(kBox, 2, kReach, kThin, {1, 1, 2});
        FAIL() << "two layers of a 20 um film accepted with a 12 um reach";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("1 x 1 x 2"), std::string::npos) << what;
        EXPECT_NE(what.find("20 um thick"), std::string::npos) << what;
    }
}

TEST(Decomposition, EveryPointHasOneOwnerWhoseSubdomainHoldsIt) {
    const Decomposition d{kBox, 3, 2, {}, {}, 2, {0.0, 50e-6, 130e-6}};
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.5 * kBox.lx, 2.5 * kBox.lx), uz(-5e-6, 200e-6);
    for (int k = 0; k < 2000; ++k) {
        const Vec3 x{u(rng), u(rng), uz(rng)};
        const int owner = d.owner(x);
        ASSERT_GE(owner, 0);
        ASSERT_LT(owner, d.ranks());
        EXPECT_EQ(d.distance2(owner, x), 0.0);
        int inside = 0;
        for (int r = 0; r < d.ranks(); ++r) inside += d.distance2(r, x) == 0.0 ? 1 : 0;
        EXPECT_EQ(inside, 1) << "x = " << x.x << ", " << x.y;
    }
    // The upper edge belongs to the first subdomain again (periodic); z is not periodic.
    EXPECT_EQ(d.owner(Vec3{kBox.lx, kBox.ly, 0.0}), 0);
    EXPECT_EQ(d.owner(Vec3{1e-6, 1e-6, 50e-6}), 6); // the upper layer starts at its cut
    EXPECT_EQ(d.owner(Vec3{1e-6, 1e-6, -1e-6}), 0);
    EXPECT_EQ(d.owner(Vec3{1e-6, 1e-6, 1.0}), 6);
}

TEST(Decomposition, DistanceToALayerIsOpenAtTheEnds) {
    const Decomposition d{kBox, 1, 1, {}, {}, 3, {0.0, 40e-6, 80e-6, 130e-6}};
    EXPECT_NEAR(d.distance2(1, Vec3{10e-6, 10e-6, 100e-6}), 400e-12, 1e-24); // 20 um above
    EXPECT_NEAR(d.distance2(1, Vec3{10e-6, 10e-6, 35e-6}), 25e-12, 1e-24);   // 5 um below
    EXPECT_EQ(d.distance2(0, Vec3{10e-6, 10e-6, -5e-6}), 0.0);               // under the substrate
    EXPECT_EQ(d.distance2(2, Vec3{10e-6, 10e-6, 500e-6}), 0.0);              // above the film
    EXPECT_NEAR(d.distance2(2, Vec3{10e-6, 10e-6, 70e-6}), 100e-12, 1e-24);
    EXPECT_NEAR(d.width_z(), 40e-6, 1e-18);
    // Three layers: the middle one has both others as neighbours, the outer ones only it.
    EXPECT_EQ(d.neighbors(0), std::vector<int>{1});
    EXPECT_EQ(d.neighbors(1), (std::vector<int>{0, 2}));
    EXPECT_EQ(d.neighbors(2), std::vector<int>{1});
    // Columns on layers: 2 x 2 x 3, a middle subdomain sees 2 x 2 x 3 - 1 others.
    const Decomposition g{kBox, 2, 2, {}, {}, 3, {0.0, 40e-6, 80e-6, 130e-6}};
    EXPECT_EQ(g.neighbors(4).size(), 11u);
    EXPECT_EQ(g.neighbors(0).size(), 7u);
}

TEST(Decomposition, PeriodicDistanceToASubdomainMatchesTheImages) {
    const Decomposition d{kBox, 2, 2};
    // Rank 0 holds [0, 37.5) x [0, 37.5) um; a point at x = 74 um is 1 um from it through x = 0.
    EXPECT_NEAR(std::sqrt(d.distance2(0, Vec3{74e-6, 10e-6, 0.0})), 1e-6, 1e-15);
    EXPECT_NEAR(std::sqrt(d.distance2(0, Vec3{40e-6, 10e-6, 0.0})), 2.5e-6, 1e-15);
    // Corner: 1 um in x and 2 um in y through both periodic faces.
    EXPECT_NEAR(std::sqrt(d.distance2(0, Vec3{74e-6, 73e-6, 0.0})), std::sqrt(5.0) * 1e-6, 1e-15);
    // Brute force over the nine images of the rectangle.
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(0.0, 75e-6);
    for (int k = 0; k < 500; ++k) {
        const Vec3 x{u(rng), u(rng), 0.0};
        for (int r = 0; r < 4; ++r) {
            const double x0 = (r % 2) * 37.5e-6, y0 = (r / 2) * 37.5e-6;
            double best = INFINITY;
            for (int ix = -1; ix <= 1; ++ix)
                for (int iy = -1; iy <= 1; ++iy) {
                    const double lo_x = x0 + ix * kBox.lx, lo_y = y0 + iy * kBox.ly;
                    const double dx = std::max({lo_x - x.x, 0.0, x.x - (lo_x + 37.5e-6)});
                    const double dy = std::max({lo_y - x.y, 0.0, x.y - (lo_y + 37.5e-6)});
                    best = std::min(best, dx * dx + dy * dy);
                }
            EXPECT_NEAR(d.distance2(r, x), best, 1e-24);
        }
    }
}

TEST(Decomposition, NeighboursAreSymmetricUniqueAndNeverSelf) {
    for (auto [px, py] : {std::pair{1, 1}, {2, 1}, {1, 2}, {2, 2}, {3, 2}, {4, 4}}) {
        const Decomposition d{kBox, px, py};
        for (int r = 0; r < d.ranks(); ++r) {
            const auto nb = d.neighbors(r);
            for (std::size_t k = 0; k < nb.size(); ++k) {
                EXPECT_NE(nb[k], r);
                if (k > 0) {
                    EXPECT_LT(nb[k - 1], nb[k]);
                }
                const auto back = d.neighbors(nb[k]);
                EXPECT_NE(std::find(back.begin(), back.end(), r), back.end());
            }
        }
        const std::size_t expect = std::size_t(std::min(px, 3) * std::min(py, 3) - 1);
        EXPECT_EQ(d.neighbors(0).size(), expect) << px << " x " << py;
    }
}

// Moved cuts (the balancing): ownership and the distance to a subdomain follow them.
TEST(Decomposition, OwnershipFollowsMovedCuts) {
    Decomposition d = decompose(kBox, 2, kReach, kThin);
    d.cut_x = {0.0, 50e-6, 75e-6};
    EXPECT_EQ(d.owner({45e-6, 10e-6, 1e-6}), 0);
    EXPECT_EQ(d.owner({55e-6, 10e-6, 1e-6}), 1);
    EXPECT_EQ(d.owner({-1e-6, 10e-6, 1e-6}), 1); // wraps to 74 um
    EXPECT_DOUBLE_EQ(d.width_x(), 25e-6);
    EXPECT_DOUBLE_EQ(d.distance2(1, {45e-6, 0.0, 0.0}), 25e-12);    // 5 um left of rank 1
    EXPECT_NEAR(d.distance2(0, {60e-6, 0.0, 0.0}), 100e-12, 1e-24); // 10 um right of rank 0
    EXPECT_NEAR(d.distance2(0, {72e-6, 0.0, 0.0}), 9e-12, 1e-24);   // 3 um across the edge
}

// The cuts split a work histogram into equal shares, move at most max_shift, and keep every
// part at least min_width wide.
TEST(Decomposition, BalancedCutsSplitTheWork) {
    const double l = 75e-6;
    std::vector<double> work(300, 1.0);
    for (std::size_t b = 0; b < 100; ++b) work[b] = 3.0; // the first third weighs 3x
    const std::vector<double> uniform{0.0, 37.5e-6, 75e-6};
    // Total 300 + 200 = 500; half (250) is reached at bin 83.3 (83.3 x 3): x = 20.8 um.
    const auto free = balanced_cuts(work, l, uniform, 10e-6, 1.0);
    EXPECT_NEAR(free[1], 250.0 / 3.0 / 300.0 * l, 1e-12);
    EXPECT_DOUBLE_EQ(free[0], 0.0);
    EXPECT_DOUBLE_EQ(free[2], l);
    // At most 5 um per call.
    const auto slow = balanced_cuts(work, l, uniform, 10e-6, 5e-6);
    EXPECT_NEAR(slow[1], 32.5e-6, 1e-12);
    // Never narrower than 25 um.
    const auto wide = balanced_cuts(work, l, uniform, 25e-6, 1.0);
    EXPECT_NEAR(wide[1], 25e-6, 1e-12);
    // Four parts of uniform work stay uniform; no work at all keeps the cuts.
    const std::vector<double> four{0.0, 18.75e-6, 37.5e-6, 56.25e-6, 75e-6};
    const auto same = balanced_cuts(std::vector<double>(300, 2.0), l, four, 10e-6, 1.0);
    for (std::size_t k = 0; k < four.size(); ++k) EXPECT_NEAR(same[k], four[k], 1e-12);
    EXPECT_EQ(balanced_cuts(std::vector<double>(300, 0.0), l, four, 10e-6, 1.0), four);
}
