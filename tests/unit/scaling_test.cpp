// SPDX-License-Identifier: MIT
// The time-scaling scheme (model.md M-7 table) and the drying force field built from it (species
// pair table M-3, M-4.1 / C-13 / C-15; substrate V-2; capillary M-6).
#include "drydem/drying/law_parameters.hpp"
#include "drydem/drying/scaling.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>

namespace {
using namespace drydem;

void expect_rel(double actual, double expected, double rel = 1e-9) {
    EXPECT_NEAR(actual, expected, rel * std::abs(expected));
}

// M-7 table for the default (20.1 mg/cm2) configuration.
TEST(Scaling, M7Table) {
    const ScaledParameters s = scale_parameters(Config{});
    expect_rel(s.gravity_scaled, 9.81e6); // g k / b
    expect_rel(s.gravity_physical, 9.81);
    expect_rel(s.drag_viscosity_scaled, 0.1801); // η / b
    expect_rel(s.drag_viscosity_physical, 1.801);
    expect_rel(s.lubrication_viscosity, 1.801); // C-17: unreduced
    expect_rel(s.hamaker_cb_cb[0], 4.64e-20);
    expect_rel(s.hamaker_cb_cb[1], 4.64e-13); // × k
    expect_rel(s.hamaker_ncm_cb[1], 9.5e-13); // C-12 default
    expect_rel(s.hamaker_ncm_ncm[1], 2.11e-12);
    expect_rel(s.surface_tension_scaled, 369.0); // σ s_cap
    expect_rel(s.zone_duration_physical, 60.0);  // 2 m at 2 m/min
    expect_rel(s.zone_duration_scaled, 6e-6);
    ASSERT_EQ(s.level_speeds_scaled.size(), 2u);
    expect_rel(s.level_speeds_scaled[0], 6.70); // 0.670 um/s × k
    expect_rel(s.level_speeds_scaled[1], 11.93);
    expect_rel(s.process_time(6e-6), 60.0);
    expect_rel(s.sim_time(75.0), 7.5e-6);

    Config reduced;
    reduced.lubrication_uses_reduced_viscosity = true; // C-17 switch
    expect_rel(scale_parameters(reduced).lubrication_viscosity, 0.1801);
    Config printed;
    printed.hamaker_ncm_cb = 9.5e-19; // C-12 sensitivity case
    expect_rel(scale_parameters(printed).hamaker_ncm_cb[1], 9.5e-12);
}

TEST(Scaling, DryingForceFieldPairTable) {
    const Config c;
    const FilmRecipe r = make_recipe(c);
    const ForceField ff = make_drying_force_field(c, r, scale_parameters(c));
    ASSERT_EQ(ff.species_count, 6);
    const int cb = r.cb_species();
    // CB-CB (M-3, C-13: cut-off = r_L = 0.75 um).
    const PairParams& cc = ff.pair_params(cb, cb);
    expect_rel(law<VanDerWaalsLaw>(cc).hamaker, 4.64e-13);
    expect_rel(law<VanDerWaalsLaw>(cc).min_gap, 5e-9);
    expect_rel(law<VanDerWaalsLaw>(cc).cutoff_gap, 0.75e-6);
    expect_rel(law<LubricationLaw>(cc).viscosity, 1.801);
    expect_rel(law<LubricationLaw>(cc).kappa_c, 0.1);
    // NCM-CB: 10 nm, cut-off 2R* per class (C-15): 1.219 / 1.252 / 1.277 / 1.301 / 1.325 um.
    const double r_l[5] = {1.219e-6, 1.252e-6, 1.277e-6, 1.301e-6, 1.325e-6};
    for (int k = 0; k < 5; ++k) {
        for (const PairParams* p : {&ff.pair_params(k, cb), &ff.pair_params(cb, k)}) {
            expect_rel(law<VanDerWaalsLaw>(*p).hamaker, 9.5e-13);
            expect_rel(law<VanDerWaalsLaw>(*p).min_gap, 10e-9);
            EXPECT_NEAR(law<VanDerWaalsLaw>(*p).cutoff_gap, r_l[k], 0.0005e-6) << "class " << k;
        }
    }
    expect_rel(law<VanDerWaalsLaw>(ff.pair_params(0, cb)).cutoff_gap,
               2 * 3.25 * 0.75 / 4.0 * 1e-6); // exact
    // NCM-NCM: 2.11e-12 J, 50 nm; NCM(6.50)-NCM(11.35) r_L = 4.133 um.
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) {
            expect_rel(law<VanDerWaalsLaw>(ff.pair_params(i, j)).hamaker, 2.11e-12);
            expect_rel(law<VanDerWaalsLaw>(ff.pair_params(i, j)).min_gap, 50e-9);
        }
    EXPECT_NEAR(law<VanDerWaalsLaw>(ff.pair_params(0, 4)).cutoff_gap, 4.133e-6, 0.0005e-6);
    // Particle pairs: E* = 7.8022e10 Pa, G* = 1.6063e10 Pa, μ = 0.8 (M-10).
    expect_rel(law<HertzMindlinLaw>(cc).e_star, 7.8022e10, 1e-4);
    expect_rel(law<HertzMindlinLaw>(cc).g_star, 1.6063e10, 1e-4);
    EXPECT_DOUBLE_EQ(law<HertzMindlinLaw>(cc).friction, 0.8);
}

TEST(Scaling, DryingForceFieldParticleForces) {
    const Config c;
    const FilmRecipe r = make_recipe(c);
    const ForceField ff = make_drying_force_field(c, r, scale_parameters(c));
    // V-2: 142 GPa / 0.3 particles on the aluminium substrate (C-8).
    EXPECT_TRUE(ff.substrate_on());
    ASSERT_EQ(ff.body.size(), 6u);
    for (const BodyParams& b : ff.body) {
        const HertzMindlinParams& w = law<SubstrateContactLaw>(b);
        expect_rel(w.e_star, 5.2251e10, 1e-4);
        expect_rel(w.g_star, 1.0572e10, 1e-4);
        EXPECT_DOUBLE_EQ(w.friction, 0.8);                            // C-6
        expect_rel(law<SubstrateLubricationLaw>(b).viscosity, 1.801); // M-4.4, C-17
        expect_rel(law<StokesDragLaw>(b).viscosity, 0.1801);          // M-5
        EXPECT_TRUE(law<StokesDragLaw>(b).rotational);                // C-18
        expect_rel(law<GravityBuoyancyLaw>(b).gravity, 9.81e6);
        expect_rel(law<GravityBuoyancyLaw>(b).fluid_density, 1030);
    }
    // M-6: the law receives σ s_cap as simulated; stiffness 2πσ s_cap = 2318 N/m.
    const CapillaryParams& cap = law<CapillaryFrontLaw>(ff.body_params(0));
    expect_rel(cap.surface_tension, 369.0);
    expect_rel(cap.contact_angle, 40.0 * std::numbers::pi / 180.0);
    EXPECT_NEAR(capillary_stiffness(cap), 2318.0, 0.5);
    // Largest push on a CB: 2πσ s_cap r cos²(θ/2) = 2318.5 × 0.75e-6 × 0.88302 N.
    expect_rel(capillary_max_force(0.75e-6, cap), 2318.495 * 0.75e-6 * 0.8830222, 1e-5);

    Config no_lub = c;
    no_lub.lubrication = false;
    no_lub.substrate_lubrication = false;
    const ForceField off = make_drying_force_field(no_lub, r, scale_parameters(no_lub));
    EXPECT_EQ(law<LubricationLaw>(off.pair_params(5, 5)).viscosity, 0.0);
    EXPECT_EQ(law<SubstrateLubricationLaw>(off.body_params(0)).viscosity, 0.0);
}

// The force_ratio scheme (M-7): every conservative force × k/b, every viscosity / b, moduli × e.
TEST(Scaling, ForceRatioScheme) {
    Config c;
    c.scaling_scheme = "force_ratio";
    c.time_factor = 1e6;
    c.viscosity_reduction = 100;
    c.stiffness_factor = 20;
    const ScaledParameters s = scale_parameters(c);
    expect_rel(s.capillary_factor, 1e4);
    expect_rel(s.hamaker_factor, 1e4);
    expect_rel(s.gravity_scaled, 9.81e4);
    expect_rel(s.drag_viscosity_scaled, 0.01801);
    expect_rel(s.lubrication_viscosity, 0.01801);
    expect_rel(s.hamaker_cb_cb[1], 4.64e-16);
    expect_rel(s.surface_tension_scaled, 410.0);
    expect_rel(s.youngs_cb[1], 142e9 * 20);
    expect_rel(s.youngs_substrate[1], 70e9 * 20);
    expect_rel(s.level_speeds_scaled[0], 0.67);
    // Every force of the field is the one the scaling lists: the laws apply no factor of their own.
    const FilmRecipe r = make_recipe(c);
    const ForceField ff = make_drying_force_field(c, r, s);
    const int cb = r.cb_species();
    expect_rel(law<VanDerWaalsLaw>(ff.pair_params(cb, cb)).hamaker, 4.64e-16);
    expect_rel(law<LubricationLaw>(ff.pair_params(cb, 0)).viscosity, 0.01801);
    expect_rel(law<SubstrateLubricationLaw>(ff.body_params(0)).viscosity, 0.01801);
    expect_rel(law<CapillaryFrontLaw>(ff.body_params(0)).surface_tension, 410.0);
    expect_rel(law<HertzMindlinLaw>(ff.pair_params(cb, cb)).e_star, 142e9 * 20 / (2 * (1 - 0.09)));
}

// Density scaling of the CB (scaling.cb_density_scaling): the CB spheres' mass and moment of
// inertia × S, their density (what gravity and buoyancy read) and every NCM sphere untouched.
TEST(Scaling, CbDensityScalingScalesOnlyTheCbInertia) {
    Config c;
    c.drying_cb_density_scaling = 16;
    const ScaledParameters s = scale_parameters(c);
    expect_rel(s.cb_density_scaling, 16.0);
    EXPECT_EQ(scale_parameters(Config{}).cb_density_scaling, 1.0);
    const FilmRecipe r = make_recipe(c);
    const auto cb = std::uint8_t(r.cb_species());
    ParticleStore p;
    p.add(1, 0, 3e-6, 4740.0, {0, 0, 5e-6});
    p.add(2, cb, 0.75e-6, 1187.5, {0, 0, 1e-5});
    const ParticleStore before = p;
    scale_cb_inertia(p, r, s);
    expect_rel(p.mass[1], 16.0 * before.mass[1]);
    expect_rel(p.inv_mass[1], before.inv_mass[1] / 16.0);
    expect_rel(p.inv_inertia[1], before.inv_inertia[1] / 16.0);
    EXPECT_EQ(p.density[1], before.density[1]);
    EXPECT_EQ(p.mass[0], before.mass[0]);
    EXPECT_EQ(p.inv_inertia[0], before.inv_inertia[0]);
}

// The paper scheme's zeros mean its own factors: capillary 9e3, Hamaker = k (Sec. 4.1).
TEST(Scaling, PaperSchemeDefaultFactors) {
    Config c;
    c.time_factor = 3e6;
    const ScaledParameters s = scale_parameters(c);
    expect_rel(s.capillary_factor, 9e3);
    expect_rel(s.hamaker_factor, 3e6);
    c.hamaker_factor = 1e7;
    c.capillary_factor = 4.5e3;
    expect_rel(scale_parameters(c).hamaker_factor, 1e7);
    expect_rel(scale_parameters(c).capillary_factor, 4.5e3);
    expect_rel(scale_parameters(c).stiffness_factor, 1.0);
}

} // namespace
