// SPDX-License-Identifier: MIT
// Particle-substrate contact (model.md M-2.6, V-2) and lubrication (M-4.4, V-8).
#include "drydem/forces/substrate_contact.hpp"
#include "drydem/forces/substrate_lubrication.hpp"
#include <gtest/gtest.h>
#include "expect_rel.hpp"
#include <cmath>
#include <numbers>

namespace {
using namespace drydem;

constexpr double kR = 0.75e-6;                                                 // CB radius
constexpr double kMass = 4.0 / 3.0 * std::numbers::pi * kR * kR * kR * 1187.5; // CB mass
constexpr double kDt = 1e-11;
constexpr double kPi = std::numbers::pi;
const SubstrateLubricationParams kLub{1.801, 0.1};

using testing_support::expect_rel;

// Aluminium (C-8) against NCM/CB (E = 142 GPa, ν = 0.3), e = 0.5, μ_s = 0.8 (C-6).
HertzMindlinParams wall() { return mix_hertz_mindlin(70e9, 0.33, 142e9, 0.3, 0.5, 0.8, 0.0); }

/// The contact through the law's own add_force (body_law.hpp), its spring ξ in `xi`.
BodyForce substrate_contact(double z, double r, double m, const Vec3& v, const Vec3& omega,
                            const HertzMindlinParams& p, Vec3& xi, double dt,
                            BodyResistance* damping = nullptr) {
    SubstrateContactLaw::State s{xi};
    BodyForce f{};
    SubstrateContactLaw::add_force({{0.0, 0.0, z}, v, omega, r, m, 0.0, 0.0, 0.0}, p, s, dt, f,
                                   damping);
    xi = s.spring;
    return f;
}

TEST(SubstrateContact, EffectiveModuliV2) {
    expect_rel(wall().e_star, 5.2251e10);
    expect_rel(wall().g_star, 1.0572e10);
}

TEST(SubstrateContact, StaticNormalForce) {
    const double delta = 10e-9;
    Vec3 xi;
    const BodyForce f = substrate_contact(kR - delta, kR, kMass, {}, {}, wall(), xi, kDt);
    // Hertz with R* = r: (4/3) E* sqrt(r) δ^{3/2}, pushing the particle up.
    expect_rel(f.force.z, 4.0 / 3.0 * 5.2251e10 * std::sqrt(kR) * std::pow(delta, 1.5));
    EXPECT_EQ(f.force.x, 0.0);
    EXPECT_EQ(f.force.y, 0.0);
    EXPECT_EQ(norm(f.torque), 0.0);
    // Approaching the wall adds damping (more repulsion).
    Vec3 xi2;
    EXPECT_GT(substrate_contact(kR - delta, kR, kMass, {0, 0, -1}, {}, wall(), xi2, kDt).force.z,
              f.force.z);
}

TEST(SubstrateContact, NoContactClearsHistory) {
    Vec3 xi{1e-9, 2e-9, 0.0};
    const BodyForce f =
        substrate_contact(kR * (1 + 1e-12), kR, kMass, {1, 0, 0}, {}, wall(), xi, kDt);
    EXPECT_EQ(norm(f.force) + norm(f.torque), 0.0);
    EXPECT_EQ(norm(xi), 0.0);
}

TEST(SubstrateContact, SlidingFrictionAndLeverArm) {
    const double delta = 10e-9;
    Vec3 xi;
    const BodyForce f = substrate_contact(kR - delta, kR, kMass, {1, 0, 0}, {}, wall(), xi, kDt);
    EXPECT_LT(f.force.x, 0.0); // opposes the sliding
    EXPECT_NEAR(xi.x, kDt, 1e-25);
    // Torque (r - δ) |F_t| about +y: it spins the sphere up toward rolling.
    expect_rel(f.torque.y, (kR - delta) * -f.force.x, 1e-12);
    EXPECT_NEAR(f.torque.x, 0.0, 1e-30);
    // Coulomb limit with a long spring: |F_t| = μ_s F_n.
    Vec3 xi_big{1e-6, 0, 0};
    const BodyForce s = substrate_contact(kR - delta, kR, kMass, {}, {}, wall(), xi_big, kDt);
    expect_rel(-s.force.x, 0.8 * s.force.z, 1e-12);
}

TEST(SubstrateContact, RollingWithoutSlipHasNoTangentialForce) {
    const double delta = 10e-9, omega = 1e6;
    Vec3 xi;
    // Contact point at -(r - δ) ẑ; v = (r - δ) ω × ẑ makes its velocity zero.
    const Vec3 w{0.0, omega, 0.0};
    const Vec3 v = (kR - delta) * cross(w, Vec3{0, 0, 1});
    const BodyForce f = substrate_contact(kR - delta, kR, kMass, v, w, wall(), xi, kDt);
    EXPECT_NEAR(f.force.x, 0.0, 1e-12 * f.force.z);
    EXPECT_NEAR(norm(xi), 0.0, 1e-24);
}

TEST(SubstrateLubrication, ScalarReferenceValues) {
    expect_rel(substrate_lubrication_x(0.1), 10.4715, 1e-5);
    expect_rel(substrate_lubrication_x(0.1) * vinogradova_factor(0.1, 0.1), 4.4337, 1e-4);
}

TEST(SubstrateLubrication, NormalForceV8) {
    auto f = [&](double kappa) {
        return substrate_lubrication(kR * (1 + kappa), kR, {0, 0, -1}, {}, kLub);
    };
    for (double kappa : {0.1, 0.05, 0.0, -0.01}) expect_rel(f(kappa).force.z, 1.1289e-4);
    expect_rel(f(0.5).force.z, 4.0743e-5);
    expect_rel(f(1.0).force.z, 2.1501e-5);
    EXPECT_EQ(norm(f(1.0 + 1e-12).force), 0.0);
    EXPECT_GT(f(0.3).force.z, 0.0); // repels an approaching particle
    EXPECT_EQ(norm(f(0.3).torque), 0.0);
    EXPECT_LT(substrate_lubrication(kR * 1.3, kR, {0, 0, 1}, {}, kLub).force.z, 0.0);
}

TEST(SubstrateLubrication, SlidingAndRotation) {
    const double z = kR * 1.05, l = std::log(10.0), k = 0.1; // frozen at κ_c
    const BodyForce slide = substrate_lubrication(z, kR, {1, 0, 0}, {}, kLub);
    const double a_w = (8.0 / 15.0) * l + (64.0 / 375.0) * k * l;
    const double b_w = (2.0 / 15.0) * l + (86.0 / 375.0) * k * l;
    expect_rel(slide.force.x, -6 * kPi * 1.801 * kR * a_w, 1e-12);
    // Symmetric coupling: force per unit ω_y equals torque per unit v_x (both 6πη r² B_w).
    const BodyForce spin = substrate_lubrication(z, kR, {}, {0, 1, 0}, kLub);
    expect_rel(spin.force.x, slide.torque.y, 1e-12);
    expect_rel(spin.force.x, 6 * kPi * 1.801 * kR * kR * b_w, 1e-12);
    EXPECT_LT(spin.torque.y, 0.0); // rotation is resisted
    const BodyForce twist = substrate_lubrication(z, kR, {}, {0, 0, 1}, kLub);
    expect_rel(twist.torque.z, -8 * kPi * 1.801 * kR * kR * kR * 0.5 * k * l, 1e-12);
    EXPECT_EQ(norm(twist.force), 0.0);
}

TEST(SubstrateLubrication, DissipativeAndRange) {
    const Vec3 vs[] = {{0.3, -0.2, -0.5}, {-1.0, 0.4, 0.2}, {0.1, 0.9, 0.0}};
    const Vec3 ws[] = {{4e5, 1e5, -2e5}, {-2e6, 1e6, 3e5}, {1e6, -1e6, 0.0}};
    for (double kappa : {0.05, 0.4, 0.9})
        for (int c = 0; c < 3; ++c) {
            const BodyForce f = substrate_lubrication(kR * (1 + kappa), kR, vs[c], ws[c], kLub);
            EXPECT_LT(dot(f.force, vs[c]) + dot(f.torque, ws[c]), 0.0);
        }
    EXPECT_EQ(
        norm(substrate_lubrication(kR * 1.5, kR, vs[0], ws[0], SubstrateLubricationParams{}).force),
        0.0);
    EXPECT_EQ(substrate_lubrication_range(kLub, kR), kR);
    EXPECT_EQ(substrate_lubrication_range(SubstrateLubricationParams{}, kR), 0.0);
}

} // namespace
