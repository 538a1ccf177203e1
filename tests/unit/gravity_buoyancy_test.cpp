// SPDX-License-Identifier: MIT
// Weight minus buoyancy (paper Eq. 8-9, model.md M-5) and the settling speeds it gives against
// Stokes drag (M-5 table, V-9).
#include "drydem/forces/gravity_buoyancy.hpp"
#include "drydem/forces/stokes_drag.hpp"
#include <gtest/gtest.h>
#include "expect_rel.hpp"
#include <numbers>

namespace {
using namespace drydem;

constexpr double kPi = std::numbers::pi;
const GravityBuoyancyParams kGravity{9.81e6, 1030.0}; // scaled g_s, NMP

using testing_support::expect_rel;

TEST(GravityBuoyancy, ForceAlongMinusZ) {
    const double r = 0.75e-6;
    const Vec3 f = gravity_buoyancy(r, 1187.5, kGravity);
    EXPECT_EQ(f.x, 0.0);
    EXPECT_EQ(f.y, 0.0);
    expect_rel(f.z, -4.0 / 3.0 * kPi * r * r * r * (1187.5 - 1030.0) * 9.81e6, 1e-14);
    EXPECT_GT(gravity_buoyancy(r, 900.0, kGravity).z, 0.0); // lighter than the liquid: rises
    EXPECT_EQ(gravity_buoyancy(r, 1187.5, GravityBuoyancyParams{}).z, 0.0);
}

TEST(GravityBuoyancy, TerminalVelocitiesM5) {
    // Drag 6π(η/b) r v_t balances weight minus buoyancy; the M-5 table (scaled, m/s).
    const StokesDragParams drag{0.1801, true};
    const double d[] = {6.50e-6, 7.58e-6, 8.60e-6, 9.82e-6, 11.35e-6, 1.5e-6};
    const double rho[] = {4740, 4740, 4740, 4740, 4740, 1187.5};
    const double v_t[] = {0.4743, 0.6451, 0.8303, 1.0826, 1.4463, 1.072e-3};
    for (int c = 0; c < 6; ++c) {
        const double r = d[c] / 2;
        const double v =
            -gravity_buoyancy(r, rho[c], kGravity).z / stokes_drag_coefficient(r, drag);
        expect_rel(v, v_t[c], c == 5 ? 5e-4 : 1e-4); // CB value printed to 4 digits
        // At v = -v_t ẑ the particle is force-free.
        const Vec3 total =
            gravity_buoyancy(r, rho[c], kGravity) + stokes_drag(r, {0, 0, -v}, {}, drag).force;
        EXPECT_NEAR(norm(total), 0.0, 1e-12 * v * stokes_drag_coefficient(r, drag));
    }
}

} // namespace
