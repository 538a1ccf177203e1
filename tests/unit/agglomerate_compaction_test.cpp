// SPDX-License-Identifier: MIT
// The carbon-binder agglomerate's compaction (forces/agglomerate_compaction.hpp, model.md
// M-2.11) against its equation: the exponential in the mean stress, plastic (the pores never
// reopen), the solid kept as the envelope shrinks, and the inner porosity read back from the
// density of a sphere resized with its mass kept.
#include "drydem/core/particles.hpp"
#include "drydem/forces/agglomerate_compaction.hpp"
#include "drydem/io/config.hpp"
#include "drydem/setup/formulation.hpp"
#include "drydem/setup/solids.hpp"
#include <gtest/gtest.h>
#include <cmath>

namespace drydem {
namespace {

constexpr AgglomerateCompactionParams kLaw{0.75, 0.35, 10e6};

TEST(AgglomerateCompaction, FollowsTheExponentialInTheMeanStress) {
    EXPECT_DOUBLE_EQ(compacted_porosity(kLaw, 0.75, 10e6), 0.35 + 0.40 / std::exp(1.0));
    EXPECT_DOUBLE_EQ(compacted_porosity(kLaw, 0.75, 30e6), 0.35 + 0.40 * std::exp(-3.0));
    EXPECT_NEAR(compacted_porosity(kLaw, 0.75, 1e12), 0.35, 1e-15) << "ε_min is the floor";
}

TEST(AgglomerateCompaction, NoCompressionOrNoLawLeavesThePoresAlone) {
    EXPECT_EQ(compacted_porosity(kLaw, 0.75, 0.0), 0.75);
    EXPECT_EQ(compacted_porosity(kLaw, 0.6, -5e6), 0.6) << "tension does not reopen pores";
    EXPECT_EQ(compacted_porosity(kLaw, 0.75, std::nan("")), 0.75);
    AgglomerateCompactionParams rigid = kLaw;
    rigid.pressure = 0.0;
    EXPECT_FALSE(rigid.compacts());
    EXPECT_EQ(compacted_porosity(rigid, 0.75, 1e9), 0.75);
}

TEST(AgglomerateCompaction, IsPlasticThePoresNeverReopen) {
    const double pressed = compacted_porosity(kLaw, 0.75, 40e6);
    EXPECT_EQ(compacted_porosity(kLaw, pressed, 5e6), pressed);
    EXPECT_LT(compacted_porosity(kLaw, pressed, 80e6), pressed);
}

TEST(AgglomerateCompaction, TheEnvelopeShrinksWithItsSolidKept) {
    const double r = 0.75e-6, e = 0.75, e2 = 0.5;
    const double r2 = compacted_radius(r, e, e2);
    EXPECT_LT(r2, r);
    EXPECT_NEAR((1 - e2) * sphere_volume(r2), (1 - e) * sphere_volume(r), 1e-12 * sphere_volume(r));
    EXPECT_EQ(compacted_radius(r, e, e), r);
}

TEST(AgglomerateCompaction, InnerPorosityIsReadBackFromTheResizedSpheresDensity) {
    const double rho0 = 0.25 * 1800.0 + 0.75 * 1028.0;
    ParticleStore p;
    p.add(0, 1, 0.75e-6, rho0, {});
    const double m = p.mass[0];
    EXPECT_DOUBLE_EQ(agglomerate_porosity(0.75, p.density[0], rho0), 0.75);
    const double e2 = compacted_porosity(kLaw, 0.75, 25e6);
    p.resize_sphere(0, compacted_radius(p.radius[0], 0.75, e2));
    EXPECT_EQ(p.mass[0], m) << "the mass is kept";
    EXPECT_NEAR(p.density[0] * sphere_volume(p.radius[0]), m, 1e-12 * m);
    EXPECT_DOUBLE_EQ(1.0 / p.inv_inertia[0], 0.4 * m * p.radius[0] * p.radius[0]);
    EXPECT_NEAR(agglomerate_porosity(0.75, p.density[0], rho0), e2, 1e-12);
}

TEST(AgglomerateCompaction, BinderFilledPorosityLeavesRoomForTheBinderOnly) {
    // Equal volumes of binder and carbon: half of the envelope is binder.
    EXPECT_DOUBLE_EQ(binder_filled_porosity(1.0), 0.5);
    EXPECT_DOUBLE_EQ(binder_filled_porosity(0.0), 0.0);
    // The Sangros Gimenez film: 4 % PVDF (1.78 g/cm³) on 6 % carbon (1.66 g/cm³).
    const double b = binder_volume_per_carbon(0.04, 1780.0, 0.06, 1660.0);
    EXPECT_NEAR(binder_filled_porosity(b), (0.04 / 1780.0) / (0.04 / 1780.0 + 0.06 / 1660.0),
                1e-15);
}

TEST(AgglomerateCompaction, TheSpheresOwnHeightFallsWithTheAgglomeratesPores) {
    const FilmRecipe r = make_recipe(Config{});
    EXPECT_DOUBLE_EQ(r.sphere_height(r.cb_porosity), r.sphere_height());
    // The CB envelopes' share scales as (1 - ε_0) / (1 - ε): from 0.75 to 0.5 it halves.
    FilmRecipe no_cb = r;
    no_cb.species.back().count = 0;
    const double cb_share = r.sphere_height() - no_cb.sphere_height();
    EXPECT_NEAR(r.sphere_height(0.5), no_cb.sphere_height() + 0.5 * cb_share,
                1e-12 * r.sphere_height());
}

} // namespace
} // namespace drydem
