// SPDX-License-Identifier: MIT
// Pair lubrication (model.md M-4.1-M-4.3) against V-7 and the M-4 reference values, plus the
// pair-law property checks (Newton, rigid-body motion, angular momentum, dissipation, rotation).
#include "drydem/forces/lubrication.hpp"
#include <gtest/gtest.h>
#include "expect_rel.hpp"
#include <cmath>
#include <numbers>

namespace {
using namespace drydem;

constexpr double kR = 0.75e-6;   // CB radius
constexpr double kRBig = 4.3e-6; // NCM radius (unequal pairs)
constexpr double kPi = std::numbers::pi;
const LubricationParams kLub{1.801, 0.1};   // full η (C-17)
const Vec3 kN = Vec3{1.0, 2.0, -2.0} / 3.0; // oblique unit normal

using testing_support::expect_rel;

/// Pair with unit normal n, gap h and given velocities.
PairGeometry pair(double r_i, double r_j, double gap, const Vec3& v_i, const Vec3& v_j,
                  const Vec3& w_i = {}, const Vec3& w_j = {}, const Vec3& n = kN) {
    const double d = r_i + r_j + gap;
    return make_pair_geometry(d * n, d, r_i, r_j, 1e-15, 2e-15, v_i, v_j, w_i, w_j);
}

/// Unit vector perpendicular to kN.
const Vec3 kT = Vec3{2.0, 1.0, 2.0} / 3.0;

TEST(Lubrication, ScalarFunctionsReferenceValues) {
    expect_rel(vinogradova_factor(0.1, 0.1), 0.42341);
    expect_rel(vinogradova_factor(1.0, 0.1), 0.84448);
    expect_rel(lubrication_x(0.1), 3.02425, 1e-5);
    expect_rel(lubrication_x(0.1) * vinogradova_factor(0.1, 0.1), 1.28050, 1e-5);
    expect_rel(lubrication_x(0.2) * vinogradova_factor(0.2, 0.1), 0.91669, 1e-5);
    expect_rel(lubrication_x(0.5) * vinogradova_factor(0.5, 0.1), 0.49395, 1e-5);
    expect_rel(lubrication_x(1.0) * vinogradova_factor(1.0, 0.1), 0.21112, 1e-4);
    // f* against its closed form with log1p, on both sides of the switch to ln((q + 6)/q) at q = 60
    // and far beyond it (κ_c = 1e-6): within a few ulps.
    for (const double q : {1.0 + 1e-9, 1.5, 3.0, 10.0, 59.999, 60.0, 1e3, 1e6}) {
        const double exact = (q / 3.0) * ((1.0 + q / 6.0) * std::log1p(6.0 / q) - 1.0);
        expect_rel(vinogradova_factor(q * 1e-6, 1e-6), exact, 1e-12);
    }
    // r_L of M-4.1 (printed to 4 digits): CB with the five NCM classes, NCM 6.50 with 11.35 µm.
    EXPECT_DOUBLE_EQ(lubrication_radius(kR, kR), kR);
    const double r_ncm[] = {3.25e-6, 3.79e-6, 4.30e-6, 4.91e-6, 5.675e-6};
    const double r_l[] = {1.219e-6, 1.252e-6, 1.277e-6, 1.301e-6, 1.325e-6};
    for (int c = 0; c < 5; ++c) expect_rel(lubrication_radius(kR, r_ncm[c]), r_l[c], 5e-4);
    expect_rel(lubrication_radius(3.25e-6, 5.675e-6), 4.133e-6, 5e-4);
}

TEST(Lubrication, NormalForceV7) {
    const Vec3 v_i = 0.5 * kN, v_j = -0.5 * kN; // v_n = 1 m/s approaching
    auto f_n = [&](double kappa) {
        return norm(lubrication(pair(kR, kR, kappa * kR, v_i, v_j), kLub).force_i);
    };
    expect_rel(f_n(1.0), 5.375e-6);
    expect_rel(f_n(1.0 - 1e-12), 5.375e-6);
    EXPECT_EQ(f_n(1.0 + 1e-12), 0.0);
    expect_rel(f_n(0.5), 1.2577e-5);
    expect_rel(f_n(0.2), 2.3340e-5);
    for (double kappa : {0.1, 0.05, 1e-3, 0.0, -0.01}) expect_rel(f_n(kappa), 3.2603e-5);
    // Direction: opposes approach, and (as a resistance) opposes separation too.
    const PairGeometry g = pair(kR, kR, 0.3 * kR, v_i, v_j);
    EXPECT_LT(dot(lubrication(g, kLub).force_i, g.n), 0.0);
    const PairGeometry s = pair(kR, kR, 0.3 * kR, v_j, v_i);
    EXPECT_GT(dot(lubrication(s, kLub).force_i, s.n), 0.0);
    // Purely normal motion gives no tangential force and no torque.
    const PairForce f = lubrication(g, kLub);
    EXPECT_NEAR(norm(perp(f.force_i, g.n)), 0.0, 1e-12 * norm(f.force_i));
    EXPECT_NEAR(norm(f.torque_i) + norm(f.torque_j), 0.0, 1e-12 * norm(f.force_i) * kR);
}

TEST(Lubrication, SlidingForceV7) {
    auto slide = [&](double kappa) { return lubrication(pair(kR, kR, kappa * kR, kT, {}), kLub); };
    expect_rel(norm(slide(0.5).force_i), 2.9414e-6);
    for (double kappa : {0.1, 0.01, -0.01}) expect_rel(norm(slide(kappa).force_i), 9.7710e-6);
    EXPECT_NEAR(norm(slide(1.0).force_i), 0.0, 1e-12 * 9.7710e-6); // L = ln(1/κ) → 0 smoothly
    EXPECT_EQ(norm(slide(1.5).force_i), 0.0);
    // Opposes the sliding, coefficient (1/6) L = 0.38376 in units of 6πη r at κ_e = κ_c.
    const PairForce f = slide(0.05);
    EXPECT_LT(dot(f.force_i, kT), 0.0);
    expect_rel(norm(f.force_i), 6 * kPi * 1.801 * kR * 0.38376);
    // Equal and parallel lever torques on both spheres (equal radii), along n × F.
    EXPECT_GT(dot(f.torque_i, cross(kN, f.force_i)), 0.0);
    EXPECT_NEAR(norm(f.torque_i - f.torque_j), 0.0, 1e-12 * norm(f.torque_i));
}

TEST(Lubrication, RollingAndTwistingTorquesV7) {
    // Counter-rotation ⊥ n, no sliding: rolling torque, opposite on i and j, no force.
    for (double kappa : {0.1, 0.02, -0.01}) {
        const PairForce f =
            lubrication(pair(kR, kR, kappa * kR, {}, {}, 0.5 * kT, -0.5 * kT), kLub);
        expect_rel(norm(f.torque_i), 3.2977e-18);
        EXPECT_LT(dot(f.torque_i, kT), 0.0);
        EXPECT_NEAR(norm(f.torque_i + f.torque_j), 0.0, 1e-12 * norm(f.torque_i));
        EXPECT_NEAR(norm(f.force_i), 0.0, 1e-6 * norm(f.torque_i) / kR);
    }
    // Twisting about n: 8πη r³ (1/8) κ L |ω_r| with (1/8) κ_e L = 0.02878 at κ_e = κ_c.
    const PairForce t = lubrication(pair(kR, kR, 0.05 * kR, {}, {}, 0.5 * kN, -0.5 * kN), kLub);
    expect_rel(norm(t.torque_i), 8 * kPi * 1.801 * kR * kR * kR * 0.02878, 2e-4);
    EXPECT_LT(dot(t.torque_i, kN), 0.0);
    EXPECT_NEAR(norm(t.force_i), 0.0, 1e-30);
    // Rolling coefficient (3/40) L = 0.17269 at κ_e = κ_c: half the torque difference is -t_r.
    const PairForce one = lubrication(pair(kR, kR, 0.0, {}, {}, kT, {}), kLub);
    expect_rel(norm(one.torque_i - one.torque_j) / 2, 8 * kPi * 1.801 * kR * kR * kR * 0.17269);
}

// A general state: unequal radii, all velocity components.
struct State {
    double r_i, r_j, gap;
    Vec3 v_i, v_j, w_i, w_j;
};
const State kStates[] = {
    {kRBig, kR, 0.7e-6, {0.3, -0.2, 0.5}, {-0.4, 0.1, 0.2}, {2e5, -1e5, 3e5}, {-1e5, 4e5, 1e5}},
    {kR, kRBig, 0.05e-6, {-0.1, 0.6, 0.2}, {0.3, 0.3, -0.4}, {-3e5, 2e5, 1e5}, {1e5, -2e5, 5e5}},
    {kR, kR, -0.01e-6, {0.2, 0.1, -0.3}, {0.1, -0.5, 0.2}, {1e5, 1e5, -2e5}, {-3e5, 1e5, 2e5}},
    {kRBig, 2 * kR, 0.5e-6, {0.0, 0.3, 0.1}, {0.2, 0.0, -0.1}, {0.0, 5e5, 1e5}, {2e5, 0.0, -1e5}},
};

TEST(Lubrication, NewtonThirdLawAndAngularMomentum) {
    for (const State& s : kStates) {
        const PairGeometry ij = pair(s.r_i, s.r_j, s.gap, s.v_i, s.v_j, s.w_i, s.w_j);
        const PairGeometry ji = pair(s.r_j, s.r_i, s.gap, s.v_j, s.v_i, s.w_j, s.w_i, -kN);
        const PairForce a = lubrication(ij, kLub), b = lubrication(ji, kLub);
        const double f = norm(a.force_i), t = norm(a.torque_i) + norm(a.torque_j);
        ASSERT_GT(f, 0.0);
        EXPECT_NEAR(norm(a.force_i + b.force_i), 0.0, 1e-12 * f);
        EXPECT_NEAR(norm(a.torque_i - b.torque_j), 0.0, 1e-12 * t);
        EXPECT_NEAR(norm(a.torque_j - b.torque_i), 0.0, 1e-12 * t);
        // Total torque about any point: (x_i - x_j) × F_i + T_i + T_j = 0.
        const Vec3 l = cross(-ij.distance * ij.n, a.force_i) + a.torque_i + a.torque_j;
        EXPECT_NEAR(norm(l), 0.0, 1e-12 * (f * ij.distance + t));
    }
}

TEST(Lubrication, RigidBodyMotionGivesNothing) {
    const Vec3 big_omega{3e5, -2e5, 4e5}, trans{0.3, -0.7, 0.2}, x_i{1e-6, -2e-6, 5e-6};
    for (const State& s : kStates) {
        const double d = s.r_i + s.r_j + s.gap;
        const Vec3 x_j = x_i + d * kN;
        const Vec3 v_i = trans + cross(big_omega, x_i), v_j = trans + cross(big_omega, x_j);
        const PairForce f =
            lubrication(pair(s.r_i, s.r_j, s.gap, v_i, v_j, big_omega, big_omega), kLub);
        const double f_ref = 6 * kPi * 1.801 * d * norm(big_omega) * d; // 6πη D |Ω| D
        EXPECT_NEAR(norm(f.force_i), 0.0, 1e-13 * f_ref);
        EXPECT_NEAR(norm(f.torque_i), 0.0, 1e-13 * f_ref * s.r_i);
        EXPECT_NEAR(norm(f.torque_j), 0.0, 1e-13 * f_ref * s.r_i);
    }
}

TEST(Lubrication, Dissipative) {
    for (const State& s : kStates) {
        const PairForce f =
            lubrication(pair(s.r_i, s.r_j, s.gap, s.v_i, s.v_j, s.w_i, s.w_j), kLub);
        const double power =
            dot(f.force_i, s.v_i - s.v_j) + dot(f.torque_i, s.w_i) + dot(f.torque_j, s.w_j);
        EXPECT_LT(power, 0.0);
    }
}

Vec3 rotate(const Vec3& a) { // fixed rotation: 0.7 rad about (1, 2, 2)/3 (Rodrigues)
    const Vec3 k = Vec3{1.0, 2.0, 2.0} / 3.0;
    const double c = std::cos(0.7), s = std::sin(0.7);
    return c * a + s * cross(k, a) + (1 - c) * dot(k, a) * k;
}

TEST(Lubrication, RotationInvariance) {
    for (const State& s : kStates) {
        const PairForce a =
            lubrication(pair(s.r_i, s.r_j, s.gap, s.v_i, s.v_j, s.w_i, s.w_j), kLub);
        const PairForce b = lubrication(pair(s.r_i, s.r_j, s.gap, rotate(s.v_i), rotate(s.v_j),
                                             rotate(s.w_i), rotate(s.w_j), rotate(kN)),
                                        kLub);
        EXPECT_NEAR(norm(b.force_i - rotate(a.force_i)), 0.0, 1e-12 * norm(a.force_i));
        EXPECT_NEAR(norm(b.torque_i - rotate(a.torque_i)), 0.0, 1e-12 * norm(a.torque_i));
        EXPECT_NEAR(norm(b.torque_j - rotate(a.torque_j)), 0.0, 1e-12 * norm(a.torque_j));
    }
}

TEST(Lubrication, RangeAndDisabled) {
    EXPECT_DOUBLE_EQ(lubrication_range(kLub, kR, kR), kR);
    expect_rel(lubrication_range(kLub, kR, 3.25e-6), 1.219e-6, 5e-4);
    EXPECT_EQ(lubrication_range(LubricationParams{}, kR, kR), 0.0);
    const State& s = kStates[0];
    const double r_l = lubrication_radius(s.r_i, s.r_j);
    auto f = [&](double gap, const LubricationParams& p) {
        const PairForce out = lubrication(pair(s.r_i, s.r_j, gap, s.v_i, s.v_j, s.w_i, s.w_j), p);
        return norm(out.force_i) + norm(out.torque_i) + norm(out.torque_j);
    };
    EXPECT_GT(f(r_l * (1 - 1e-9), kLub), 0.0);
    EXPECT_EQ(f(r_l * (1 + 1e-9), kLub), 0.0);
    EXPECT_EQ(f(0.5 * r_l, LubricationParams{}), 0.0);
}

} // namespace

TEST(Lubrication, FrozenRangeUsesTheLogarithmOfItsOwnKappaC) {
    // In contact and within h_c every coefficient is that of κ_c, whose logarithm the parameters
    // store: for any κ_c it must be the resistance of the formulas evaluated at κ_c.
    const State& s = kStates[0];
    const double r_l = lubrication_radius(s.r_i, s.r_j);
    for (const double kappa_c : {0.02, 0.1, 0.3}) {
        const LubricationParams p{1.801, kappa_c};
        EXPECT_EQ(p.log_kappa_c, std::log(kappa_c));
        const double l = -std::log(kappa_c), pi_eta = std::numbers::pi * 1.801;
        for (const double gap : {-0.05 * kR, 0.0, 0.5 * kappa_c * r_l}) {
            const PairResistance r =
                lubrication_resistance(pair(s.r_i, s.r_j, gap, s.v_i, s.v_j, s.w_i, s.w_j), p);
            expect_rel(r.normal,
                       6.0 * pi_eta * r_l * lubrication_x(kappa_c) *
                           vinogradova_factor(kappa_c, kappa_c),
                       1e-14);
            expect_rel(r.sliding, pi_eta * r_l * l, 1e-14);
            expect_rel(r.rolling, (3.0 / 40.0) * 8.0 * pi_eta * r_l * r_l * r_l * l, 1e-14);
        }
    }
}
