// SPDX-License-Identifier: MIT
// Capillary force at the liquid level (paper Eq. 11-12 with I-1, C-20): model.md M-6, V-10.
#include "drydem/forces/capillary_front.hpp"
#include <gtest/gtest.h>
#include "expect_rel.hpp"
#include <cmath>
#include <numbers>

namespace {
using namespace drydem;

constexpr double kR = 0.75e-6; // CB radius
constexpr double kRNcm = 11.35e-6 / 2;
constexpr double kLevel = 0.0; // z_L (the law depends on z_L - z only; 0 keeps u = ±1 exact)
const CapillaryParams kCap{0.041 * 9e3, 40.0 * std::numbers::pi / 180.0};

/// Force on a particle of radius r at u = h_s / r = (z_L - z) / r.
double force_at(double u, double r = kR) {
    return capillary_front(kLevel - u * r, r, kLevel, kCap).z;
}

using testing_support::expect_rel;

TEST(CapillaryFront, ReferenceValuesV10) {
    expect_rel(force_at(0.9397), 2.0341e-4);
    expect_rel(force_at(0.5), -5.1505e-4);
    expect_rel(force_at(0.0), -1.33205e-3, 1e-5);
    expect_rel(force_at(-0.342), -1.53546e-3, 1e-5);
    expect_rel(force_at(-0.5), -1.48303e-3, 1e-5);
    expect_rel(force_at(0.0, kRNcm), -1.00792e-2, 1e-5);
    const double scale = capillary_stiffness(kCap) * kR; // 2πσ s r = 1.7389e-3 N for CB
    expect_rel(scale, 1.7389e-3);
    EXPECT_NEAR(force_at(0.766044), 0.0, 1e-6 * scale);
}

TEST(CapillaryFront, ZeroOutsideAndAtTheEdges) {
    for (double u : {1.0, -1.0, 1.5, -3.0}) EXPECT_EQ(force_at(u), 0.0);
    const double scale = capillary_stiffness(kCap) * kR;
    EXPECT_NEAR(force_at(1.0 - 1e-12), 0.0, 1e-5 * scale); // continuous at both edges
    EXPECT_NEAR(force_at(-1.0 + 1e-12), 0.0, 1e-5 * scale);
    const Vec3 f = capillary_front(kLevel, kR, kLevel, kCap);
    EXPECT_EQ(f.x, 0.0);
    EXPECT_EQ(f.y, 0.0);
    EXPECT_EQ(capillary_front(kLevel, kR, kLevel, CapillaryParams{}).z, 0.0);
}

TEST(CapillaryFront, EquilibriumAndStiffness) {
    EXPECT_NEAR(capillary_stiffness(kCap), 2318.0, 0.5); // N/m, printed to 4 digits
    const double u0 = std::cos(kCap.contact_angle);      // h_s = 0.766 r
    const double z0 = kLevel - u0 * kR;
    EXPECT_NEAR(capillary_front(z0, kR, kLevel, kCap).z, 0.0, 1e-15);
    // Restoring: pushed up when below, pulled down when above; slope -2πσ s_cap.
    const double dz = 1e-12;
    const double slope = (capillary_front(z0 + dz, kR, kLevel, kCap).z -
                          capillary_front(z0 - dz, kR, kLevel, kCap).z) /
                         (2 * dz);
    expect_rel(slope, -capillary_stiffness(kCap), 1e-5);
    // Extremes of M-6: +0.117 and -0.883 × 2πσ s r at u = 0.9397 and -0.342.
    const double scale = capillary_stiffness(kCap) * kR;
    EXPECT_NEAR(force_at(0.9397) / scale, std::pow(std::sin(kCap.contact_angle / 2), 2), 1e-6);
    EXPECT_NEAR(force_at(-0.342) / scale, -std::pow(std::cos(kCap.contact_angle / 2), 2), 1e-6);
}

} // namespace
