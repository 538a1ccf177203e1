// SPDX-License-Identifier: MIT
// The dimensionless groups (docs/model.md "Dimensionless groups") against values worked by hand
// from the paper's parameters (20.1 mg/cm2, η = 1.801 Pa s, σ = 0.041 N/m, θ = 40°, r_CB = 0.75 um,
// largest NCM r = 5.675 um, E* = 78.02 GPa), and how each scheme scales them.
#include "drydem/drying/dimensionless_groups.hpp"
#include <gtest/gtest.h>
#include "expect_rel.hpp"
#include <cmath>

namespace {
using namespace drydem;

using testing_support::expect_rel;

TEST(DimensionlessGroups, PhysicalAgainstHandValues) {
    const DimensionlessGroups d = dimensionless_groups(Config{});
    ASSERT_EQ(d.physical.size(), 2u);
    const Groups &z1 = d.physical[0], &z2 = d.physical[1];
    // 3 η U / (σ cos²20°) at 0.670 / 1.193 um/s.
    expect_rel(z1.capillary_drag, 9.998947e-5);
    expect_rel(z2.capillary_drag, 1.780410e-4);
    // 6π η r_L X(0.1) f*(0.1) U / (2π σ r cos²20°), X = 3.02424, f* = 0.423410.
    expect_rel(z1.capillary_lubrication, 1.280361e-4);
    // (ρ - ρ_f) g (4/3)π r³ / (2π σ r cos²20°), r = 5.675 um.
    expect_rel(z1.bond_ncm, 2.158380e-5);
    // m / (6π η r) U / r, zone 2; CB density (1 - 0.75) 1660 + 0.75 1030 = 1187.5 kg/m3.
    expect_rel(z2.stokes_ncm, 3.959665e-9);
    expect_rel(z2.stokes_cb, 1.311019e-10);
    // A R* / (6 h_min²) over 2π σ r_CB cos²20°: 4.64e-20 J, R* = 0.375 um, 5 nm.
    expect_rel(z1.vdw_capillary_cb_cb, 6.799256e-4);
    // (3F / (4 E* sqrt R*))^(2/3) / r: NCM on CB and on aluminium under its capillary push, CB-CB
    // under van der Waals.
    expect_rel(z1.overlap_ncm_cb, 8.198186e-4);
    expect_rel(z1.overlap_ncm_substrate, 6.917646e-5);
    expect_rel(z1.overlap_cb_cb, 1.988214e-6);
    // The push number is Ca H / l*.
    expect_rel(z2.push, z2.capillary_drag * d.film_thickness / d.push_length, 1e-12);
}

TEST(DimensionlessGroups, PushLengthOfOneSpecies) {
    FilmRecipe r;
    r.species = {SizeClass{2e-6, 1000, 10, 10, true}};
    expect_rel(push_length(r), 2e-6, 1e-12); // 2 r² / r = d
}

// The paper's scheme (k = 1e7, b = 10, capillary × 9e3, Hamaker × 1e7) distorts the capillary
// number by k/b / 9e3 = 111, van der Waals over capillarity by 1e7 / 9e3 = 1111, the Stokes number
// by k b = 1e8 (docs/model.md "Dimensionless groups").
TEST(DimensionlessGroups, PaperSchemeDistortions) {
    const DimensionlessGroups d = dimensionless_groups(Config{});
    const Groups &p = d.physical[1], &s = d.simulated[1];
    expect_rel(s.capillary_drag / p.capillary_drag, 1e6 / 9e3, 1e-9);
    expect_rel(s.push / p.push, 1e6 / 9e3, 1e-9);
    expect_rel(s.capillary_lubrication / p.capillary_lubrication, 1e7 / 9e3, 1e-9);
    expect_rel(s.vdw_capillary_cb_cb / p.vdw_capillary_cb_cb, 1e7 / 9e3, 1e-9);
    expect_rel(s.bond_ncm / p.bond_ncm, 1e6 / 9e3, 1e-9);
    expect_rel(s.stokes_ncm / p.stokes_ncm, 1e8, 1e-9);
    expect_rel(s.overlap_ncm_cb / p.overlap_ncm_cb, std::pow(9e3, 2.0 / 3.0), 1e-9);
}

// force_ratio keeps every ratio of forces; inertia grows by k b, overlaps by (k / (b e))^(2/3).
TEST(DimensionlessGroups, ForceRatioKeepsEveryForceRatio) {
    Config c;
    c.scaling_scheme = "force_ratio";
    c.time_factor = 1e6;
    c.viscosity_reduction = 100;
    c.stiffness_factor = 8;
    const DimensionlessGroups d = dimensionless_groups(c);
    for (std::size_t z = 0; z < 2; ++z) {
        const Groups &p = d.physical[z], &s = d.simulated[z];
        expect_rel(s.capillary_drag, p.capillary_drag, 1e-12);
        expect_rel(s.capillary_lubrication, p.capillary_lubrication, 1e-12);
        expect_rel(s.push, p.push, 1e-12);
        expect_rel(s.vdw_capillary_cb_cb, p.vdw_capillary_cb_cb, 1e-12);
        expect_rel(s.vdw_capillary_ncm_cb, p.vdw_capillary_ncm_cb, 1e-12);
        expect_rel(s.bond_ncm, p.bond_ncm, 1e-12);
        expect_rel(s.stokes_ncm / p.stokes_ncm, 1e8, 1e-9);
        expect_rel(s.stokes_cb / p.stokes_cb, 1e8, 1e-9);
        expect_rel(s.inertial / p.inertial, 1e6 / std::sqrt(1e4), 1e-9);
        expect_rel(s.overlap_ncm_cb / p.overlap_ncm_cb, std::pow(1e4 / 8, 2.0 / 3.0), 1e-9);
        expect_rel(s.overlap_ncm_substrate / p.overlap_ncm_substrate, std::pow(1e4 / 8, 2.0 / 3.0),
                   1e-9);
    }
}

// Density scaling of the CB raises the CB's Stokes number × S, as simulated only, and nothing else.
TEST(DimensionlessGroups, CbDensityScalingRaisesOnlyTheCbStokesNumber) {
    Config c;
    c.scaling_scheme = "force_ratio";
    c.time_factor = 9e5;
    c.viscosity_reduction = 100;
    const DimensionlessGroups d1 = dimensionless_groups(c);
    c.drying_cb_density_scaling = 16;
    const DimensionlessGroups d16 = dimensionless_groups(c);
    for (std::size_t z = 0; z < 2; ++z) {
        expect_rel(d16.simulated[z].stokes_cb, 16.0 * d1.simulated[z].stokes_cb, 1e-12);
        EXPECT_EQ(d16.physical[z].stokes_cb, d1.physical[z].stokes_cb);
        EXPECT_EQ(d16.simulated[z].stokes_ncm, d1.simulated[z].stokes_ncm);
        EXPECT_EQ(d16.simulated[z].inertial, d1.simulated[z].inertial);
        EXPECT_EQ(d16.simulated[z].bond_ncm, d1.simulated[z].bond_ncm);
        EXPECT_EQ(d16.simulated[z].capillary_drag, d1.simulated[z].capillary_drag);
    }
}

} // namespace
