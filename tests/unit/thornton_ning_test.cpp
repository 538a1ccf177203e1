// SPDX-License-Identifier: MIT
// Thornton-Ning elastic-plastic normal contact (model.md M-2.8) against its closed form, through
// the pure function and through the contact law's own history; the calendering plate's contact
// (M-2.9) against Hertz and against the substrate's mirror image.
#include "drydem/forces/hertz_mindlin.hpp"
#include "drydem/forces/plate_contact.hpp"
#include "drydem/forces/substrate_contact.hpp"
#include "drydem/forces/thornton_ning.hpp"
#include <gtest/gtest.h>
#include "expect_rel.hpp"
#include <cmath>
#include <numbers>

namespace {
using namespace drydem;
using testing_support::expect_rel;

constexpr double kPi = std::numbers::pi;
constexpr double kR = 5e-6;        // NCM radius
constexpr double kReff = 0.5 * kR; // two equal NCM spheres
constexpr double kPy = 1.0e9;      // limiting contact pressure [Pa]
const double kEstar = 142e9 / (2 * (1 - 0.25 * 0.25));

// Closed forms written out independently of the header: a² = R δ on loading (TN 1998 Eq. 5),
// p_max = 2 E* a / (π R), F_y = π³ p_y³ R² / (6 E*²), F = π p_y a² - F_y / 2 beyond yield.
double yield_force() { return std::pow(kPi * kPy, 3) * kReff * kReff / (6 * kEstar * kEstar); }

TEST(ThorntonNing, HertzUntilThePressurePeakReachesTheLimit) {
    const double d_y = yield_overlap(kEstar, kReff, kPy);
    // At δ_y the Hertz pressure peak 2 E* sqrt(R δ) / (π R) is p_y.
    expect_rel(2 * kEstar * std::sqrt(kReff * d_y) / (kPi * kReff), kPy, 1e-12);
    expect_rel(yield_pressure_at(kEstar, kReff, d_y), kPy, 1e-12);
    for (double f : {0.1, 0.5, 0.999}) {
        const double d = f * d_y;
        const ElasticPlasticNormal n = thornton_ning_normal(kEstar, kReff, kPy, d, d);
        expect_rel(n.force, 4.0 / 3.0 * kEstar * std::sqrt(kReff) * std::pow(d, 1.5), 1e-12);
        expect_rel(n.stiffness, 2 * kEstar * std::sqrt(kReff * d), 1e-12);
    }
    expect_rel(thornton_ning_normal(kEstar, kReff, kPy, d_y, d_y).force, yield_force(), 1e-12);
}

TEST(ThorntonNing, PlasticLoadingAtConstantPressure) {
    const double d_y = yield_overlap(kEstar, kReff, kPy);
    for (double f : {1.5, 4.0, 30.0}) {
        const double d = f * d_y;
        const ElasticPlasticNormal n = thornton_ning_normal(kEstar, kReff, kPy, d, d);
        expect_rel(n.force, kPi * kPy * kReff * d - 0.5 * yield_force(), 1e-12);
        expect_rel(n.stiffness, kPi * kPy * kReff, 1e-12);
        // Softer than Hertz at the same overlap: yield caps the force.
        EXPECT_LT(n.force, hertz_normal(kEstar, kReff, d).force);
    }
}

TEST(ThorntonNing, UnloadingIsHertzWithTheEnlargedRadiusAndLeavesAPermanentSet) {
    const double d_y = yield_overlap(kEstar, kReff, kPy);
    const double d_max = 10 * d_y;
    const double f_max = kPi * kPy * kReff * d_max - 0.5 * yield_force();
    // R_p = (4 E* / 3 F_max) ((2 F_max + F_y) / (2 π p_y))^{3/2} (TN 1998 Eq. 36).
    const double r_p =
        4 * kEstar / (3 * f_max) * std::pow((2 * f_max + yield_force()) / (2 * kPi * kPy), 1.5);
    const double d_p = d_max - std::pow(3 * f_max / (4 * kEstar * std::sqrt(r_p)), 2.0 / 3.0);
    const PlasticUnloading u = plastic_unloading(kEstar, kReff, kPy, d_max);
    expect_rel(u.radius, r_p, 1e-12);
    expect_rel(u.residual, d_p, 1e-10);
    EXPECT_GT(r_p, kReff); // the contact flattened
    EXPECT_GT(d_p, 0.0);   // ... and keeps a permanent set
    EXPECT_LT(d_p, d_max);
    // Continuous at the turning point, zero at the permanent set, Hertz(R_p) between.
    expect_rel(thornton_ning_normal(kEstar, kReff, kPy, d_max, d_max).force, f_max, 1e-12);
    const double just_below = d_max * (1 - 1e-9);
    expect_rel(thornton_ning_normal(kEstar, kReff, kPy, just_below, d_max).force, f_max, 1e-6);
    EXPECT_EQ(thornton_ning_normal(kEstar, kReff, kPy, 0.99 * d_p, d_max).force, 0.0);
    const double d = 0.5 * (d_p + d_max);
    expect_rel(thornton_ning_normal(kEstar, kReff, kPy, d, d_max).force,
               4.0 / 3.0 * kEstar * std::sqrt(r_p) * std::pow(d - d_p, 1.5), 1e-10);
    // Reloading beyond δ_max continues on the plastic line.
    const double beyond = 1.2 * d_max;
    expect_rel(thornton_ning_normal(kEstar, kReff, kPy, beyond, beyond).force,
               kPi * kPy * kReff * beyond - 0.5 * yield_force(), 1e-12);
}

TEST(ThorntonNing, NoLimitingPressureIsHertz) {
    for (double d : {1e-9, 1e-8, 1e-7})
        EXPECT_EQ(thornton_ning_normal(kEstar, kReff, 0.0, d, 3 * d).force,
                  hertz_normal(kEstar, kReff, d).force);
}

/// Two NCM spheres pressed together along x and pulled apart through the contact law; the law
/// keeps δ_max, so the cycle dissipates the area between the two branches.
TEST(ThorntonNing, ContactLawKeepsTheDeepestOverlapAndDissipates) {
    HertzMindlinParams p = mix_hertz_mindlin(142e9, 0.25, 142e9, 0.25, 1.0, 0.3, 0.0);
    p.yield_pressure = kPy;
    const double mass = 4.0 / 3.0 * kPi * kR * kR * kR * 4700;
    const double d_y = yield_overlap(p.e_star, kReff, kPy);
    auto force_at = [&](double overlap, ContactHistory& h) {
        const double d = 2 * kR - overlap;
        const PairGeometry g = make_pair_geometry({d, 0, 0}, d, kR, kR, mass, mass, {}, {}, {}, {});
        PairForce f{};
        HertzMindlinLaw::add_force(g, p, h, 0.0, f, nullptr);
        return -f.force_i.x; // repulsion on i pushes it along -x
    };
    ContactHistory h;
    const int n = 200;
    const double d_max = 8 * d_y, step = d_max / n;
    double work_in = 0.0, work_out = 0.0;
    for (int k = 1; k <= n; ++k) work_in += step * force_at(k * step, h);
    expect_rel(h.max_overlap, d_max, 1e-12);
    for (int k = n - 1; k >= 0; --k) work_out += step * force_at(k * step, h);
    // Unloading returns less than loading took (the trapezoid errors are O(step), far smaller).
    EXPECT_LT(work_out, 0.5 * work_in);
    EXPECT_GT(work_out, 0.0);
    // The contact opened at δ = 0 above: its history is gone.
    EXPECT_FALSE(HertzMindlinLaw::keeps(h));
    // Without yield, the same cycle is elastic and keeps no δ_max.
    p.yield_pressure = 0.0;
    force_at(d_max, h);
    EXPECT_EQ(h.max_overlap, 0.0);
}

// ---- the calendering plate (M-2.9) ----

BodyGeometry under_plate(double z, double plate, double r, double mass, const Vec3& v = {}) {
    BodyGeometry g{{1e-6, 2e-6, z}, v, {}, r, mass, 4700, 0.0, 0.0};
    g.plate = plate;
    return g;
}

TEST(PlateContact, PushesDownWithTheHertzForceOfTheSphereOnAPlane) {
    const HertzMindlinParams steel = mix_hertz_mindlin(142e9, 0.25, 210e9, 0.3, 1.0, 0.3, 0.0);
    const double mass = 4.0 / 3.0 * kPi * kR * kR * kR * 4700, delta = 20e-9;
    PlateContactLaw::State s;
    BodyForce f{};
    PlateContactLaw::add_force(under_plate(10e-6 - kR + delta, 10e-6, kR, mass), steel, s, 0.0, f,
                               nullptr);
    expect_rel(f.force.z, -4.0 / 3.0 * steel.e_star * std::sqrt(kR) * std::pow(delta, 1.5), 1e-9);
    EXPECT_EQ(f.force.x, 0.0);
    // Out of reach, or without a plate: nothing, and no history kept.
    BodyForce none{};
    PlateContactLaw::add_force(under_plate(10e-6 - kR - delta, 10e-6, kR, mass), steel, s, 0.0,
                               none, nullptr);
    PlateContactLaw::add_force(under_plate(10e-6, INFINITY, kR, mass), steel, s, 0.0, none,
                               nullptr);
    EXPECT_EQ(none.force.z, 0.0);
    EXPECT_FALSE(PlateContactLaw::keeps(s));
}

/// The plate is the substrate seen in a mirror: a particle sliding and spinning against it gets
/// the mirrored force and torque, and the mirrored resistance coupling.
TEST(PlateContact, IsTheSubstrateMirrored) {
    const HertzMindlinParams p = mix_hertz_mindlin(142e9, 0.25, 70e9, 0.33, 0.5, 0.3, 0.0);
    const double mass = 4.0 / 3.0 * kPi * kR * kR * kR * 4700, delta = 15e-9;
    const Vec3 v{1e-3, -2e-3, -5e-4}, w{30.0, 10.0, -4.0};
    SubstrateContactLaw::State s_sub{{2e-9, 1e-9, 0.0}};
    PlateContactLaw::State s_plate{{2e-9, 1e-9, 0.0}};
    BodyForce f_sub{}, f_plate{};
    BodyResistance r_sub, r_plate;
    BodyGeometry below{{0, 0, kR - delta}, v, w, kR, mass, 4700, 0.0, 0.0};
    SubstrateContactLaw::add_force(below, p, s_sub, 1e-9, f_sub, &r_sub);
    // Mirror z -> -z: velocities flip z, angular velocities (axial) flip x and y.
    BodyGeometry above = under_plate(-(kR - delta), 0.0, kR, mass, {v.x, v.y, -v.z});
    above.omega = {-w.x, -w.y, w.z};
    PlateContactLaw::add_force(above, p, s_plate, 1e-9, f_plate, &r_plate);
    expect_rel(f_plate.force.x, f_sub.force.x, 1e-12);
    expect_rel(f_plate.force.y, f_sub.force.y, 1e-12);
    expect_rel(f_plate.force.z, -f_sub.force.z, 1e-12);
    expect_rel(f_plate.torque.x, -f_sub.torque.x, 1e-12);
    expect_rel(f_plate.torque.y, -f_sub.torque.y, 1e-12);
    expect_rel(r_plate.coupling, -r_sub.coupling, 1e-12);
    expect_rel(r_plate.rotation_t, r_sub.rotation_t, 1e-12);
}

} // namespace
