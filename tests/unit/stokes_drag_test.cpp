// SPDX-License-Identifier: MIT
// Stokes drag, translation (paper Eq. 10) and rotation (C-18): model.md M-5, V-9.
#include "drydem/forces/stokes_drag.hpp"
#include <gtest/gtest.h>
#include "expect_rel.hpp"
#include <numbers>

namespace {
using namespace drydem;

constexpr double kR = 0.75e-6; // CB radius
constexpr double kPi = std::numbers::pi;
const StokesDragParams kDrag{0.1801, true}; // η/b

using testing_support::expect_rel;

TEST(StokesDrag, ForceAndTorque) {
    const Vec3 v{0.3, -0.4, 1.2}, w{1e5, 2e5, -3e5};
    const BodyForce f = stokes_drag(kR, v, w, kDrag);
    EXPECT_NEAR(norm(f.force + 6 * kPi * 0.1801 * kR * v), 0.0, 1e-12 * norm(f.force));
    EXPECT_NEAR(norm(f.torque + 8 * kPi * 0.1801 * kR * kR * kR * w), 0.0, 1e-12 * norm(f.torque));
    expect_rel(stokes_drag_coefficient(kR, kDrag), 6 * kPi * 0.1801 * kR, 1e-14);
    EXPECT_EQ(norm(stokes_drag(kR, v, w, {0.1801, false}).torque), 0.0);
    EXPECT_EQ(norm(stokes_drag(kR, v, w, StokesDragParams{}).force), 0.0);
}

TEST(StokesDrag, CbMovingWithTheLevel) {
    // M-6: a CB moving with the level (6.70 m/s) feels 1.706e-5 N.
    expect_rel(norm(stokes_drag(kR, {0, 0, -6.70}, {}, kDrag).force), 1.706e-5, 2e-4);
}

TEST(StokesDrag, RelaxationTimesV9) {
    // τ = m / (6π(η/b) r) (M-5, printed to 3 digits) and τ_r = I / (8π(η/b) r³) for CB.
    const double d[] = {6.50e-6, 7.58e-6, 8.60e-6, 9.82e-6, 11.35e-6, 1.5e-6};
    const double rho[] = {4740, 4740, 4740, 4740, 4740, 1187.5};
    const double tau[] = {6.18e-8, 8.40e-8, 1.08e-7, 1.41e-7, 1.88e-7, 8.24e-10};
    for (int c = 0; c < 6; ++c) {
        const double r = d[c] / 2, m = 4.0 / 3.0 * kPi * r * r * r * rho[c];
        expect_rel(m / stokes_drag_coefficient(r, kDrag), tau[c], 2e-3);
    }
    const double m_cb = 4.0 / 3.0 * kPi * kR * kR * kR * 1187.5, inertia = 0.4 * m_cb * kR * kR;
    const double t_per_w = -stokes_drag(kR, {}, {0, 0, 1}, kDrag).torque.z;
    expect_rel(inertia / t_per_w, 2.4726e-10);
}

} // namespace
