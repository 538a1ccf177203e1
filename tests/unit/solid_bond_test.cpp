// SPDX-License-Identifier: MIT
// The solid bond (forces/solid_bond.hpp, model.md M-2.10) against its closed forms: each mode's
// stiffness (normal, shear, bending, twist), the damping, the stresses at the rim and the combined
// breakage criterion; a broken bond stays broken and carries nothing.
#include "drydem/forces/solid_bond.hpp"
#include "drydem/forces/pair_law.hpp"
#include "expect_rel.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>

using namespace drydem;
using drydem::testing_support::expect_rel;

namespace {
constexpr double kRi = 2e-6, kRj = 0.5e-6, kE = 2e9, kG = 0.8e9, kLambda = 0.5;
constexpr double kMi = 1e-13, kMj = 1e-15;

SolidBondParams params(double sigma_c = 1e9, double tau_c = 1e9, double beta = 0.0) {
    return {kE, kG, kLambda, sigma_c, tau_c, beta};
}

/// The pair along x at distance d, with relative velocity v (of i) and spins.
PairGeometry along_x(double d, Vec3 v_i = {}, Vec3 w_i = {}, Vec3 w_j = {}) {
    return make_pair_geometry({d, 0, 0}, d, kRi, kRj, kMi, kMj, v_i, {}, w_i, w_j);
}

SolidBondState formed(double length) {
    SolidBondState s;
    s.rest_length = length;
    return s;
}

constexpr double kL0 = kRi + kRj; // formed touching
double area() { return std::numbers::pi * std::pow(kLambda * kRj, 2); }
double inertia() { return 0.25 * std::numbers::pi * std::pow(kLambda * kRj, 4); }

static_assert(PairLaw<SolidBondLaw>);

TEST(SolidBond, SectionOfTheSmallerSphere) {
    const BondSection b = bond_section(params(), kRi, kRj);
    EXPECT_DOUBLE_EQ(b.radius, kLambda * kRj);
    EXPECT_DOUBLE_EQ(b.area, area());
    EXPECT_DOUBLE_EQ(b.inertia, inertia());
    EXPECT_DOUBLE_EQ(b.polar, 2.0 * inertia());
}

TEST(SolidBond, NormalForceIsStiffnessPerAreaTimesAreaTimesStretch) {
    const double stretch = 1e-9;
    SolidBondState s = formed(kL0);
    const PairForce f = solid_bond(along_x(kL0 + stretch), params(), s, 1e-9);
    expect_rel(f.force_i.x, kE / kL0 * area() * stretch, 1e-12); // pulls i toward j (+x)
    EXPECT_EQ(f.force_i.y, 0.0);
    EXPECT_EQ(norm(f.torque_i), 0.0);
    SolidBondState c = formed(kL0);
    expect_rel(solid_bond(along_x(kL0 - stretch), params(), c, 1e-9).force_i.x,
               -kE / kL0 * area() * stretch, 1e-12); // pushes apart in compression
}

TEST(SolidBond, ShearDisplacementGivesShearForceAndLeverTorques) {
    SolidBondState s = formed(kL0);
    const double v = 1e-3, dt = 1e-9;
    PairForce f;
    for (int k = 0; k < 10; ++k) f = solid_bond(along_x(kL0, {0, v, 0}), params(), s, dt);
    const double u = 10 * v * dt;
    expect_rel(s.shear.y, u, 1e-12);
    const double fs = -kG / kL0 * area() * u;
    expect_rel(f.force_i.y, fs, 1e-12);
    // T_i = c_i n × F_s with n = x̂: x̂ × (fs ŷ) = fs ẑ; c_i = r_i (gap 0).
    expect_rel(f.torque_i.z, kRi * fs, 1e-12);
    expect_rel(f.torque_j.z, kRj * fs, 1e-12);
}

TEST(SolidBond, BendingAndTwistGiveTheirMoments) {
    const double w = 2e3, dt = 1e-9;
    SolidBondState bend = formed(kL0), twist = formed(kL0);
    PairForce fb, ft;
    for (int k = 0; k < 5; ++k) {
        // Rolling ω_i = -ω_j about z: no slip at the mid-plane needs c_i ω_i + c_j ω_j = 0.
        fb = solid_bond(
            along_x(kL0, {}, {0, 0, w * kRj / (kRi + kRj)}, {0, 0, -w * kRi / (kRi + kRj)}),
            params(), bend, dt);
        ft = solid_bond(along_x(kL0, {}, {w, 0, 0}), params(), twist, dt);
    }
    const double theta = 5 * w * dt;
    expect_rel(bend.bending.z, theta, 1e-12);
    EXPECT_NEAR(norm(bend.shear), 0.0, 1e-25);
    expect_rel(fb.torque_i.z, -kE / kL0 * inertia() * theta, 1e-9);
    expect_rel(fb.torque_j.z, kE / kL0 * inertia() * theta, 1e-9);
    expect_rel(twist.twist, theta, 1e-12);
    expect_rel(ft.torque_i.x, -kG / kL0 * 2 * inertia() * theta, 1e-12);
    expect_rel(ft.torque_j.x, kG / kL0 * 2 * inertia() * theta, 1e-12);
}

TEST(SolidBond, ShearTurnsWithTheNormalKeepingItsLength) {
    SolidBondState s = formed(kL0);
    s.shear = {0, 3e-10, 0};
    const double a = 0.1; // the pair turned by 0.1 rad about z
    const Vec3 d{kL0 * std::cos(a), kL0 * std::sin(a), 0};
    const PairGeometry g = make_pair_geometry(d, kL0, kRi, kRj, kMi, kMj, {}, {}, {}, {});
    solid_bond(g, params(), s, 1e-9);
    EXPECT_NEAR(dot(s.shear, g.n), 0.0, 1e-22);
    expect_rel(norm(s.shear), 3e-10, 1e-12);
}

TEST(SolidBond, DampingIsTwoBetaSqrtMassStiffness) {
    const double beta = 0.3, v = 1e-3;
    SolidBondState s = formed(kL0);
    PairResistance r;
    const PairForce f = solid_bond(along_x(kL0, {v, 0, 0}), params(1e9, 1e9, beta), s, 0.0, &r);
    const double m_eff = kMi * kMj / (kMi + kMj);
    const double a_n = 2 * beta * std::sqrt(m_eff * kE / kL0 * area());
    expect_rel(r.normal, a_n, 1e-12);
    expect_rel(f.force_i.x, -a_n * v, 1e-12); // no stretch: all of it is damping
}

TEST(SolidBond, BreaksInTensionAtTheTensileStrength) {
    const double sigma_c = 10e6;
    const double stretch_c = sigma_c / (kE / kL0); // σ = k̄_n (D - L0)
    SolidBondState below = formed(kL0), above = formed(kL0);
    EXPECT_GT(
        norm(solid_bond(along_x(kL0 + 0.999 * stretch_c), params(sigma_c), below, 0.0).force_i),
        0.0);
    EXPECT_TRUE(below.intact());
    const PairForce f = solid_bond(along_x(kL0 + 1.001 * stretch_c), params(sigma_c), above, 0.0);
    EXPECT_TRUE(above.broken);
    EXPECT_EQ(norm(f.force_i), 0.0);
    // Broken for good: back at rest length it carries nothing.
    EXPECT_EQ(norm(solid_bond(along_x(kL0), params(sigma_c), above, 0.0).force_i), 0.0);
    EXPECT_FALSE(SolidBondLaw::keeps(above));
}

TEST(SolidBond, CompressionAloneNeverBreaksItInTension) {
    SolidBondState s = formed(kL0);
    solid_bond(along_x(0.9 * kL0), params(1e3, 1e9), s, 0.0); // σ_c tiny, but σ < 0
    EXPECT_TRUE(s.intact());
}

TEST(SolidBond, CombinedCriterionBreaksSoonerUnderShearAndTension) {
    const double sigma_c = 10e6, tau_c = 20e6;
    SolidBondState s = formed(kL0);
    s.shear = {0, 0.5 * tau_c / (kG / kL0), 0}; // τ = τ_c / 2
    const double stretch_half = 0.5 * sigma_c / (kE / kL0);
    SolidBondState t = s;
    solid_bond(along_x(kL0 + 0.99 * stretch_half), params(sigma_c, tau_c), s, 0.0);
    EXPECT_TRUE(s.intact());
    solid_bond(along_x(kL0 + 1.01 * stretch_half), params(sigma_c, tau_c), t, 0.0);
    EXPECT_TRUE(t.broken);
    const BondStress st = solid_bond_stress(along_x(kL0 + stretch_half), params(), s);
    expect_rel(st.tensile, 0.5 * sigma_c, 1e-12);
    expect_rel(st.shear, 0.5 * tau_c, 1e-12);
}

TEST(SolidBond, BendingStressAtTheRim) {
    SolidBondState s = formed(kL0);
    s.bending = {0, 0, 1e-3};
    const BondStress st = solid_bond_stress(along_x(kL0), params(), s);
    // σ = |M_b| r_b / I with M_b = k̄_n I θ: k̄_n r_b θ.
    expect_rel(st.tensile, kE / kL0 * kLambda * kRj * 1e-3, 1e-12);
}

TEST(SolidBond, LimitsRefuseAZeroStrength) {
    EXPECT_TRUE(limit_violations<SolidBondLaw>(params()).empty());
    EXPECT_FALSE(limit_violations<SolidBondLaw>(params(0.0)).empty());
    SolidBondParams p = params();
    p.radius_ratio = 1.5;
    EXPECT_FALSE(limit_violations<SolidBondLaw>(p).empty());
}

} // namespace
