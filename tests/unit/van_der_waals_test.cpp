// SPDX-License-Identifier: MIT
// Van der Waals law (model.md M-3) against V-6, plus the pair-law property checks.
#include "drydem/forces/van_der_waals.hpp"
#include <gtest/gtest.h>
#include "expect_rel.hpp"

namespace {
using namespace drydem;

constexpr double kRCb = 0.75e-6, kRNcm = 4.3e-6; // CB 1.5 µm, NCM 8.6 µm
const Vec3 kN{0.6, 0.0, 0.8};                    // pair normal, deliberately oblique

PairGeometry pair(double r_i, double r_j, double gap, const Vec3& n = kN) {
    const double d = r_i + r_j + gap;
    return make_pair_geometry(d * n, d, r_i, r_j, 1e-15, 2e-15, {0.1, -0.2, 0.3}, {}, {}, {});
}

VanDerWaalsParams cb_cb() { return {4.64e-13, 5e-9, 0.75e-6}; }
VanDerWaalsParams ncm_cb(double a = 9.5e-13) { return {a, 10e-9, 1.3e-6}; }
VanDerWaalsParams ncm_ncm() { return {2.11e-12, 50e-9, 4.3e-6}; }

double magnitude(const PairGeometry& g, const VanDerWaalsParams& p) {
    return norm(van_der_waals(g, p).force_i);
}

using testing_support::expect_rel;

TEST(VanDerWaals, CbCbReferenceValuesV6) {
    for (double h : {5e-9, 1e-9, 0.0, -20e-9})
        expect_rel(magnitude(pair(kRCb, kRCb, h), cb_cb()), 1.1600e-3);
    expect_rel(magnitude(pair(kRCb, kRCb, 10e-9), cb_cb()), 2.900e-4);
    expect_rel(magnitude(pair(kRCb, kRCb, 100e-9), cb_cb()), 2.900e-6);
    EXPECT_GT(magnitude(pair(kRCb, kRCb, 0.75e-6), cb_cb()), 0.0);
    EXPECT_EQ(magnitude(pair(kRCb, kRCb, 0.75e-6 * (1 + 1e-12)), cb_cb()), 0.0);
}

TEST(VanDerWaals, NcmReferenceValuesV6) {
    for (double h : {10e-9, 2e-9, -5e-9}) {
        expect_rel(magnitude(pair(kRNcm, kRCb, h), ncm_cb()), 1.0111e-3);
        expect_rel(magnitude(pair(kRNcm, kRCb, h), ncm_cb(9.5e-12)), 1.0111e-2); // printed constant
    }
    expect_rel(magnitude(pair(kRNcm, kRNcm, 50e-9), ncm_ncm()), 3.0243e-4);
    expect_rel(magnitude(pair(kRNcm, kRNcm, 100e-9), ncm_ncm()), 7.561e-5);
}

TEST(VanDerWaals, AttractiveAlongNormalWithoutTorque) {
    const PairGeometry g = pair(kRNcm, kRCb, 30e-9);
    const PairForce f = van_der_waals(g, ncm_cb());
    EXPECT_NEAR(dot(f.force_i, g.n), norm(f.force_i), 1e-15 * norm(f.force_i));
    EXPECT_GT(dot(f.force_i, g.n), 0.0); // i pulled toward j
    EXPECT_EQ(norm(f.torque_i), 0.0);
    EXPECT_EQ(norm(f.torque_j), 0.0);
}

TEST(VanDerWaals, NewtonThirdLaw) {
    for (double h : {-3e-9, 20e-9, 0.4e-6}) {
        const Vec3 v_i{0.3, 0.1, -0.2}, v_j{-0.1, 0.5, 0.2};
        const double d = kRNcm + kRCb + h;
        const PairGeometry ij = make_pair_geometry(d * kN, d, kRNcm, kRCb, 1, 2, v_i, v_j, {}, {});
        const PairGeometry ji = make_pair_geometry(-d * kN, d, kRCb, kRNcm, 2, 1, v_j, v_i, {}, {});
        const PairForce a = van_der_waals(ij, ncm_cb()), b = van_der_waals(ji, ncm_cb());
        EXPECT_GT(norm(a.force_i), 0.0);
        // Round-off only: h = D - r_i - r_j is summed in the other order for (j, i).
        EXPECT_NEAR(norm(a.force_i + b.force_i), 0.0, 1e-12 * norm(a.force_i));
    }
}

TEST(VanDerWaals, ContinuousAtMinimumGap) {
    const double h_min = cb_cb().min_gap;
    const double below = magnitude(pair(kRCb, kRCb, h_min * (1 - 1e-9)), cb_cb());
    const double above = magnitude(pair(kRCb, kRCb, h_min * (1 + 1e-9)), cb_cb());
    EXPECT_NEAR(below, above, 1e-8 * below);
}

TEST(VanDerWaals, DisabledAndRange) {
    EXPECT_EQ(magnitude(pair(kRCb, kRCb, 1e-9), VanDerWaalsParams{}), 0.0);
    EXPECT_EQ(van_der_waals_range(VanDerWaalsParams{}, kRCb, kRCb), 0.0);
    EXPECT_EQ(van_der_waals_range(cb_cb(), kRCb, kRCb), 0.75e-6);
}

} // namespace

// Rigid-body check (issue 3: every pair law): the attraction depends on the geometry only, so a
// pair moving as one rigid body feels exactly the force of the pair at rest, and no torque.
TEST(VanDerWaals, RigidBodyMotionChangesNothing) {
    const drydem::VanDerWaalsParams p{4.64e-13, 5e-9, 0.75e-6};
    const double r = 0.75e-6, d = 2 * r + 40e-9;
    const drydem::Vec3 n{0.0, 0.6, 0.8}, omega{2e5, -3e5, 1e5}, v_j{0.5, 0.1, -0.2};
    const drydem::Vec3 v_i = v_j + drydem::cross(omega, -d * n);
    const auto moving = drydem::van_der_waals(
        drydem::make_pair_geometry(d * n, d, r, r, 2e-15, 2e-15, v_i, v_j, omega, omega), p);
    const auto resting = drydem::van_der_waals(
        drydem::make_pair_geometry(d * n, d, r, r, 2e-15, 2e-15, {}, {}, {}, {}), p);
    EXPECT_EQ(moving.force_i.x, resting.force_i.x);
    EXPECT_EQ(moving.force_i.y, resting.force_i.y);
    EXPECT_EQ(moving.force_i.z, resting.force_i.z);
    EXPECT_EQ(drydem::norm(moving.torque_i) + drydem::norm(moving.torque_j), 0.0);
}
