// SPDX-License-Identifier: MIT
// Hardening of a CB agglomerate's contact as its lens compacts it (model.md M-2.12): the lens'
// caps against the closed form of two intersecting spheres, the porosity with the solid kept,
// the limiting pressure from p_y0 to p_d and its slope, the contact law's force and stiffness
// with it, and the calendering force field that sets it on the CB contacts only.
#include "drydem/drying/law_parameters.hpp"
#include "drydem/forces/agglomerate_hardening.hpp"
#include "drydem/forces/hertz_mindlin.hpp"
#include "drydem/forces/substrate_contact.hpp"
#include "drydem/core/error.hpp"
#include "drydem/setup/formulation.hpp"
#include <gtest/gtest.h>
#include "expect_rel.hpp"
#include "sphere_lens.hpp"
#include <cmath>
#include <numbers>

namespace {
using namespace drydem;
using testing_support::expect_rel;
using testing_support::lens_volume;

constexpr double kPi = std::numbers::pi;
constexpr double kRcb = 0.75e-6, kRncm = 5e-6;
constexpr double kPy0 = 110e6, kPd = 600e6;

AgglomerateHardening hardening(AgglomerateSides sides) { return {0.75, 0.38, kPd, sides}; }

TEST(AgglomerateHardening, LensCapsAddUpToTheLensAndGrowAtTheirRate) {
    for (double f : {0.01, 0.3, 0.9}) {
        const double overlap = f * kRcb;
        const LensCaps c = lens_caps({kRcb, kRncm}, overlap);
        expect_rel(c.cap_i + c.cap_j, lens_volume(kRcb, kRncm, kRcb + kRncm - overlap), 1e-9);
        EXPECT_GT(c.cap_i, c.cap_j); // the small sphere holds the deeper cap
        const double h = 1e-6 * overlap;
        const LensCaps up = lens_caps({kRcb, kRncm}, overlap + h),
                       down = lens_caps({kRcb, kRncm}, overlap - h);
        expect_rel(c.rate_i, (up.cap_i - down.cap_i) / (2 * h), 1e-5);
        expect_rel(c.rate_j, (up.cap_j - down.cap_j) / (2 * h), 1e-5);
        // Equal spheres: equal caps, each of height δ/2.
        const LensCaps eq = lens_caps({kRcb, kRcb}, overlap);
        expect_rel(eq.cap_i, eq.cap_j, 1e-12);
        expect_rel(eq.cap_i, sphere_cap(kRcb, 0.5 * overlap), 1e-9);
        // On a plane: one cap of height δ.
        const LensCaps wall = lens_caps({kRcb, 0.0}, overlap);
        expect_rel(wall.cap_i, kPi * overlap * overlap * (3 * kRcb - overlap) / 3, 1e-12);
        EXPECT_EQ(wall.cap_j, 0.0);
    }
    EXPECT_EQ(lens_caps({kRcb, kRncm}, -1e-9).cap_i, 0.0);
}

TEST(AgglomerateHardening, PorosityKeepsTheSolidUntilTheDensestState) {
    const AgglomerateHardening h = hardening(AgglomerateSides::i);
    const double v = 4.0 / 3.0 * kPi * kRcb * kRcb * kRcb;
    EXPECT_DOUBLE_EQ(lens_porosity(h, kRcb, 0.0, 0.0).porosity, 0.75);
    for (double share : {0.1, 0.3, 0.5}) {
        const LensPorosity e = lens_porosity(h, kRcb, share * v, 1e-12);
        // (1 − ε)(V − V_l) = (1 − ε_0) V: the agglomerate's solid stays.
        expect_rel((1 - e.porosity) * (v - share * v), 0.25 * v, 1e-12);
        EXPECT_LT(e.rate, 0.0);
    }
    // At V_l = V (1 − (1 − ε_0)/(1 − ε_min)) the densest state, and beyond it no further.
    const double densest = v * (1 - 0.25 / 0.62);
    EXPECT_NEAR(lens_porosity(h, kRcb, 0.999999 * densest, 1e-12).porosity, 0.38, 1e-5);
    EXPECT_EQ(lens_porosity(h, kRcb, 1.5 * densest, 1e-12).porosity, 0.38);
    EXPECT_EQ(lens_porosity(h, kRcb, 1.5 * densest, 1e-12).rate, 0.0);
}

TEST(AgglomerateHardening, PressureRisesFromTheLooseToTheDenseValue) {
    const AgglomerateHardening h = hardening(AgglomerateSides::i);
    const ContactSpheres s{kRcb, 0.0}; // a CB sphere pressed onto a plane
    EXPECT_NEAR(hardened_yield(h, kPy0, s, 1e-12).pressure, kPy0, 1e-3);
    double last = kPy0;
    for (double f : {0.1, 0.4, 0.8, 1.0}) {
        const double d = f * kRcb;
        const HardenedYield y = hardened_yield(h, kPy0, s, d);
        // Linear in the porosity the lens leaves: p_y0 + (p_d − p_y0)(ε_0 − ε)/(ε_0 − ε_min).
        const double eps = lens_porosity(h, kRcb, sphere_cap(kRcb, d), 0.0).porosity;
        expect_rel(y.pressure, kPy0 + (kPd - kPy0) * (0.75 - eps) / 0.37, 1e-12);
        EXPECT_GT(y.pressure, last);
        last = y.pressure;
        const double step = 1e-6 * d;
        expect_rel(y.slope,
                   (hardened_yield(h, kPy0, s, d + step).pressure -
                    hardened_yield(h, kPy0, s, d - step).pressure) /
                       (2 * step),
                   1e-5);
    }
    // Pressed past the densest state (cap 0.6 V at h ≈ 1.13 r): p_d, no further slope.
    const HardenedYield deep = hardened_yield(h, kPy0, s, 1.5 * kRcb);
    EXPECT_DOUBLE_EQ(deep.pressure, kPd);
    EXPECT_EQ(deep.slope, 0.0);
    // No hardening: p_y0 at any depth.
    AgglomerateHardening off = h;
    off.dense_yield_pressure = 0.0;
    EXPECT_EQ(hardened_yield(off, kPy0, s, kRcb).pressure, kPy0);
    off = h;
    off.sides = AgglomerateSides::none;
    EXPECT_EQ(hardened_yield(off, kPy0, s, kRcb).pressure, kPy0);
}

TEST(AgglomerateHardening, TwoAgglomeratesShareTheLensAndTheSofterSetsThePressure) {
    const ContactSpheres equal{kRcb, kRcb};
    const double d = 0.8 * kRcb;
    const HardenedYield both = hardened_yield(hardening(AgglomerateSides::both), kPy0, equal, d);
    const HardenedYield one = hardened_yield(hardening(AgglomerateSides::i), kPy0, equal, d);
    // Each gives up half the lens when both are agglomerates, the whole lens otherwise.
    EXPECT_LT(both.pressure, one.pressure);
    expect_rel(hardened_yield(hardening(AgglomerateSides::j), kPy0, equal, d).pressure,
               one.pressure, 1e-12);
    // Unequal: the larger agglomerate holds the shallower cap, stays looser, and sets p_y.
    const ContactSpheres unequal{kRcb, 2 * kRcb};
    const HardenedYield u = hardened_yield(hardening(AgglomerateSides::both), kPy0, unequal, d);
    const LensCaps c = lens_caps(unequal, d);
    const double eps_j =
        lens_porosity(hardening(AgglomerateSides::both), 2 * kRcb, c.cap_j, 0.0).porosity;
    expect_rel(u.pressure, kPy0 + (kPd - kPy0) * (0.75 - eps_j) / 0.37, 1e-12);
}

/// A CB sphere pressed into a dense NCM sphere through the contact law: the plastic line of
/// Thornton-Ning at the hardened p_y, its slope, and an unloading that starts from it.
TEST(AgglomerateHardening, ContactLawFollowsTheHardenedPlasticLine) {
    HertzMindlinParams p = mix_hertz_mindlin(2e9, 0.3, 142e9, 0.25, 0.5, 0.3, 0.0);
    p.yield_pressure = kPy0;
    p.dense_yield_pressure = kPd;
    p.agglomerate_porosity = 0.75;
    p.dense_porosity = 0.38;
    p.agglomerates = AgglomerateSides::i;
    p.agglomerate_compliance_share = (1 - 0.3 * 0.3) / 2e9 * p.e_star;
    HertzMindlinParams plain = p;
    plain.dense_yield_pressure = 0.0;
    const ContactSpheres s{kRcb, kRncm};
    const double r_eff = kRcb * kRncm / (kRcb + kRncm);
    const double m = 1e-14;
    auto normal = [&](const HertzMindlinParams& q, double overlap, double deepest) {
        return contact_normal(hertz_mindlin_coefficients(r_eff, overlap, m, q), s, r_eff, overlap,
                              q, deepest);
    };
    for (double f : {0.2, 0.6, 1.0}) {
        const double d = f * kRcb;
        const HardenedYield y = hardened_yield(agglomerate_hardening(p), kPy0, s, d);
        const ElasticPlasticNormal n = normal(p, d, d);
        expect_rel(n.force,
                   thornton_ning_normal(p.e_star * y.modulus_factor, r_eff, y.pressure, d, d).force,
                   1e-12);
        EXPECT_GT(n.force, normal(plain, d, d).force);
        const double h = 1e-6 * d;
        // The stiffness leaves out how the hardening modulus moves δ_y (< 1 % here).
        expect_rel(n.stiffness,
                   (normal(p, d + h, d + h).force - normal(p, d - h, d - h).force) / (2 * h), 1e-2);
        // The guard's bound covers the loading slope.
        const HertzMindlinCoefficients co = hertz_mindlin_coefficients(r_eff, d, m, p);
        EXPECT_GE(contact_stiffness_bound(co, s, r_eff, d, p), n.stiffness);
        // Unloading from δ_max: continuous there, softer below, with a permanent set; its slope
        // (the hardened modulus' Hertz slope) within the guard's bound too.
        expect_rel(normal(p, d, 1.0000001 * d).force, n.force, 1e-5);
        EXPECT_GE(contact_stiffness_bound(co, s, r_eff, d, p),
                  (normal(p, d, d).force - normal(p, d - h, d).force) / h * (1 - 1e-3));
        EXPECT_LT(normal(p, 0.9 * d, d).force, n.force);
        EXPECT_EQ(normal(p, 0.05 * d, d).force, 0.0);
    }
}

/// Gibson-Ashby: the agglomerate's modulus grows as its relative density squared, so a dense
/// contact gives back less of its overlap on unloading than one whose modulus stayed loose.
TEST(AgglomerateHardening, ModulusHardensWithTheDensityAndTheSpringbackFalls) {
    AgglomerateHardening h = hardening(AgglomerateSides::i);
    h.compliance_share = 0.9; // the CB's share of 1/E* against a stiff partner
    EXPECT_DOUBLE_EQ(hardened_modulus_factor(h, 0.75, 0.75), 1.0);
    // At ε_min: ρ = 0.62 / 0.25 = 2.48; 1/E* = 1/E*_0 (0.1 + 0.9 / ρ²).
    const double rho = 0.62 / 0.25;
    expect_rel(hardened_modulus_factor(h, 0.38, 0.75), 1.0 / (0.1 + 0.9 / (rho * rho)), 1e-12);
    // Two agglomerates, each half of the compliance.
    h.compliance_share = 0.5;
    expect_rel(hardened_modulus_factor(h, 0.38, 0.38), rho * rho, 1e-12);
    // Deep on a plane the modulus has risen; the unloading's recovered overlap falls.
    h.compliance_share = 0.9;
    const ContactSpheres plane{kRcb, 0.0};
    const HardenedYield deep = hardened_yield(h, kPy0, plane, 1.0 * kRcb);
    EXPECT_GT(deep.modulus_factor, 2.0);
    const double e_star = 2.2e9, d = 1.0 * kRcb;
    const double recovered_hard =
        d - plastic_unloading(e_star * deep.modulus_factor, kRcb, deep.pressure, d).residual;
    const double recovered_loose = d - plastic_unloading(e_star, kRcb, deep.pressure, d).residual;
    EXPECT_LT(recovered_hard, 0.6 * recovered_loose);
}

/// The calendering force field: every contact with a CB sphere hardens, on the CB's side(s);
/// NCM-NCM does not; a dense pressure below the loose one, or without yielding, is refused.
TEST(AgglomerateHardening, CalenderingForceFieldHardensTheCbContactsOnly) {
    Config c;
    c.cb_yield_pressure = kPy0;
    c.cb_dense_yield_pressure = kPd;
    const FilmRecipe rec = make_recipe(c);
    const ForceField ff = make_calendering_force_field(c, rec);
    const int n = ff.species_count, cb = rec.cb_species();
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const HertzMindlinParams& hm = law<HertzMindlinLaw>(ff.pair[std::size_t(i * n + j)]);
            const auto want = AgglomerateSides((i == cb ? 1 : 0) | (j == cb ? 2 : 0));
            EXPECT_EQ(hm.agglomerates, want) << i << "," << j;
            if (want != AgglomerateSides::none) {
                EXPECT_EQ(hm.dense_yield_pressure, kPd);
                EXPECT_EQ(hm.agglomerate_porosity, c.cb_porosity);
                EXPECT_EQ(hm.dense_porosity, agglomerate_binder_porosity(c));
                // Two CB spheres hold half of the contact's compliance each; against NCM almost
                // all of it.
                EXPECT_NEAR(hm.agglomerate_compliance_share,
                            want == AgglomerateSides::both ? 0.5 : 0.98, 0.02);
            }
        }
        const auto side = i == cb ? AgglomerateSides::i : AgglomerateSides::none;
        EXPECT_EQ(law<SubstrateContactLaw>(ff.body[std::size_t(i)]).agglomerates, side);
    }
    Config below = c;
    below.cb_dense_yield_pressure = 0.5 * kPy0;
    EXPECT_THROW(make_calendering_force_field(below, make_recipe(below)), InputError);
    Config elastic = c;
    elastic.cb_yield_pressure = 0.0;
    elastic.calender_yield_displacement = 0.0;
    EXPECT_THROW(make_calendering_force_field(elastic, make_recipe(elastic)), InputError);
    Config off = c;
    off.cb_dense_yield_pressure = 0.0;
    const ForceField plain = make_calendering_force_field(off, make_recipe(off));
    EXPECT_EQ(law<HertzMindlinLaw>(plain.pair[std::size_t(cb * n + cb)]).agglomerates,
              AgglomerateSides::none);
}

} // namespace
