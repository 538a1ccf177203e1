// SPDX-License-Identifier: MIT
// The double-layer repulsion (forces/double_layer.hpp), the law added through the pair-law
// contract (forces/pair_law.hpp): its force against the derivative of its HHF energy, its limits,
// its stiffness, its config mapping, and energy conservation of a head-on approach through the
// full engine.
#include "drydem/drying/law_parameters.hpp"
#include "drydem/drying/scaling.hpp"
#include "drydem/engine/simulation.hpp"
#include "drydem/forces/force_field.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>

using namespace drydem;

static_assert(PairLaw<DoubleLayerLaw> && PairLaw<HertzMindlinLaw> && PairLaw<VanDerWaalsLaw> &&
              PairLaw<LubricationLaw>);
// Laws that keep nothing take no space beside the contact's history in every list slot.
static_assert(sizeof(PairState) == sizeof(ContactHistory));

namespace {
constexpr double kR = 0.75e-6, kRho = 1187.5;
constexpr double kLambda = 50e-9;

/// V(h) = amplitude R* ln(1 + e^{-h/λ}) (Hogg, Healy & Fuerstenau 1966, equal potentials).
double energy(double h, double r_eff, const DoubleLayerParams& p) {
    return p.amplitude * r_eff * std::log1p(std::exp(-h / p.debye_length));
}

PairGeometry pair_at(double gap, double r_i = kR, double r_j = kR) {
    const double d = r_i + r_j + gap;
    return make_pair_geometry({d, 0, 0}, d, r_i, r_j, 1e-15, 1e-15, {}, {}, {}, {});
}

DoubleLayerParams params(double amplitude = 4e-7) { return {amplitude, kLambda, 10 * kLambda}; }
} // namespace

TEST(DoubleLayer, ForceIsMinusTheDerivativeOfTheHhfEnergy) {
    const DoubleLayerParams p = params();
    for (double h : {0.0005e-6, 0.01e-6, 0.05e-6, 0.2e-6, 0.45e-6}) {
        const PairGeometry g = pair_at(h);
        const double dh = 1e-4 * kLambda;
        const double expected =
            -(energy(h + dh, g.r_eff, p) - energy(h - dh, g.r_eff, p)) / (2 * dh);
        const PairForce f = double_layer(g, p);
        // Repulsive: i (at the origin, n = +x toward j) is pushed along -n.
        EXPECT_NEAR(-f.force_i.x, expected, 1e-7 * expected) << "h = " << h;
        EXPECT_EQ(f.force_i.y, 0.0);
        EXPECT_EQ(norm(f.torque_i) + norm(f.torque_j), 0.0); // central: no torque
    }
}

TEST(DoubleLayer, LimitsAtContactFarAwayAndBeyondTheCutoff) {
    const DoubleLayerParams p = params();
    const double r_eff = 0.5 * kR;
    // Contact: F(0) = amplitude R* / (2 λ); in overlap it stays there (Hertz takes over).
    const double f0 = p.amplitude * r_eff / (2 * kLambda);
    EXPECT_NEAR(double_layer_magnitude(0.0, r_eff, p), f0, 1e-12 * f0);
    EXPECT_NEAR(-double_layer(pair_at(-5e-9), p).force_i.x, f0, 1e-12 * f0);
    // h ≫ λ: the exponential tail amplitude R*/λ e^{-h/λ} (the linear-superposition form).
    const double h = 8 * kLambda;
    const double tail = p.amplitude * r_eff / kLambda * std::exp(-h / kLambda);
    EXPECT_NEAR(double_layer_magnitude(h, r_eff, p), tail, 1e-3 * tail);
    // Beyond the cut-off and when off: nothing, and no range.
    EXPECT_EQ(norm(double_layer(pair_at(p.cutoff_gap * 1.01), p).force_i), 0.0);
    EXPECT_EQ(norm(double_layer(pair_at(0.1e-6), DoubleLayerParams{}).force_i), 0.0);
    EXPECT_EQ(DoubleLayerLaw::range(DoubleLayerParams{}, kR, kR), 0.0);
    EXPECT_EQ(DoubleLayerLaw::range(p, kR, kR), p.cutoff_gap);
}

TEST(DoubleLayer, StiffnessIsMinusTheForceDerivativeAtTheClosestApproach) {
    const DoubleLayerParams p = params();
    for (double h : {0.002e-6, 0.03e-6, 0.3e-6}) {
        const double dh = 1e-4 * kLambda, r_eff = 0.5 * kR;
        const double expected =
            -(double_layer_magnitude(h + dh, r_eff, p) - double_layer_magnitude(h - dh, r_eff, p)) /
            (2 * dh);
        const PairGeometry g = pair_at(h);
        EXPECT_NEAR(double_layer_stiffness(g, p), expected, 1e-6 * expected);
        // The guard's estimate: at the skin-reduced gap, clamped at contact.
        const PairGeometry closer = pair_at(h - 0.1e-6);
        const double at = double_layer_stiffness(pair_at(std::max(h - 0.1e-6, 0.0)), p);
        EXPECT_DOUBLE_EQ(DoubleLayerLaw::stiffness(closer, g, p).normal, at);
        EXPECT_EQ(DoubleLayerLaw::resistance(g, p).normal, 0.0); // conservative
    }
}

TEST(DoubleLayer, ConfigMappingScalesLikeVanDerWaalsAndDefaultsToTheLubricationRange) {
    Config c;
    const FilmRecipe r = make_recipe(c);
    const int cb = r.cb_species(), ncm = cb - 1;
    const double r_cb = 0.5 * r.species[std::size_t(cb)].diameter,
                 r_ncm = 0.5 * r.species[std::size_t(ncm)].diameter;
    EXPECT_EQ(
        law<DoubleLayerLaw>(make_drying_force_field(c, r, scale_parameters(c)).pair_params(cb, ncm))
            .amplitude,
        0.0); // off by default
    c.double_layer = true;
    // The law receives the simulated values (law_parameters.cpp after scaling.cpp): the strength
    // × the Hamaker factor.
    const ForceField ff = make_drying_force_field(c, r, scale_parameters(c));
    const DoubleLayerParams& p = law<DoubleLayerLaw>(ff.pair_params(cb, ncm));
    const double expected = 4 * std::numbers::pi * 32.2 * 8.8541878128e-12 * 0.025 * 0.025 * 1e7;
    EXPECT_NEAR(p.amplitude, expected, 1e-12 * expected);
    EXPECT_DOUBLE_EQ(p.debye_length, 100e-9);
    EXPECT_NEAR(p.cutoff_gap, 2 * r_cb * r_ncm / (r_cb + r_ncm), 1e-18); // r_L = 2R*
    // The neighbour range does not grow: the lubrication range r_L bounds the pair's reach.
    EXPECT_DOUBLE_EQ(interaction_range(ff.pair_params(cb, ncm), r_cb, r_ncm), p.cutoff_gap);
}

// Two CB spheres approach head-on with only the repulsion acting (no contact damping, no
// fluid): they turn before touching and leave with their initial speed; kinetic plus HHF
// energy stays constant along the way.
TEST(DoubleLayer, HeadOnApproachConservesEnergyThroughTheEngine) {
    ForceField ff = uniform_contact_force_field(1, 142e9, 0.3, 1.0, 0.0);
    ff.remove_substrate();
    const DoubleLayerParams p = params();
    law<DoubleLayerLaw>(ff.pair[0]) = p;
    ParticleStore s;
    s.add(1, 0, kR, kRho, {20e-6, 20e-6, 20e-6});
    s.add(2, 0, kR, kRho, {20e-6 + 2 * kR + 0.6e-6, 20e-6, 20e-6});
    const double v = 5.0;
    s.velocity[0] = {v, 0, 0};
    s.velocity[1] = {-v, 0, 0};
    Simulation sim(std::move(s), Box{40e-6, 40e-6}, ff, {1e-11, 0.1e-6, 1});
    const double r_eff = 0.5 * kR;
    auto gap = [&] {
        const auto& q = sim.particles();
        return q.position[1].x - q.position[0].x - 2 * kR;
    };
    auto total = [&] {
        const double h = gap();
        return sim.kinetic_energy() + (h <= p.cutoff_gap ? energy(h, r_eff, p) : 0.0);
    };
    const double e0 = total();
    double min_gap = 1.0, max_dev = 0.0;
    for (int k = 0; k < 40000; ++k) {
        sim.step();
        min_gap = std::min(min_gap, gap());
        max_dev = std::max(max_dev, std::abs(total() - e0));
    }
    EXPECT_GT(min_gap, 0.0) << "the repulsion should turn the spheres before contact";
    EXPECT_LT(min_gap, 2 * kLambda) << "the approach should reach into the double layer";
    // The cut-off jump amplitude R* ln(1 + e^{-10}) is 4.5e-5 of V(0); the integration error is smaller.
    EXPECT_LT(max_dev, 2e-4 * e0);
    const auto& q = sim.particles();
    EXPECT_NEAR(q.velocity[1].x - q.velocity[0].x, 2 * v, 1e-3 * 2 * v); // elastic rebound
}
