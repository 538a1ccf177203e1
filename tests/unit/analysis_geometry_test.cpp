// SPDX-License-Identifier: MIT
// Structure analysis against closed forms (issue 5): sphere-slab volumes, profiles and porosity of
// single spheres and of SC / FCC lattices, masses and density, coordination numbers, voxelization.
#include "drydem/drying/analysis_inputs.hpp"
#include "drydem/analysis/bulk.hpp"
#include "drydem/analysis/coordination.hpp"
#include "drydem/analysis/profiles.hpp"
#include "drydem/analysis/voxel_grid.hpp"
#include "drydem/core/error.hpp"
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace drydem;
using namespace drydem::analysis;

namespace {

/// An empty structure with the embedded default's formulation (the paper's 20.1 mg/cm2 recipe).
Structure paper_structure() {
    Structure s;
    s.formulation = analysis_formulation(Config{});
    return s;
}

constexpr double pi = std::numbers::pi;

/// Simple cubic lattice of touching spheres (radius r, spacing 2r): n x n per layer, `layers`
/// layers, the first on the substrate; the box is exactly n cells wide.
Structure simple_cubic(int n, int layers, double r) {
    Structure s = paper_structure();
    s.box.lx = s.box.ly = 2.0 * r * n;
    for (int k = 0; k < layers; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                s.add({(2 * i + 1) * r, (2 * j + 1) * r, (2 * k + 1) * r}, r, Phase::ncm, 4740.0);
    return s;
}

/// FCC lattice (cubic cell a = 2 sqrt(2) r, touching along the face diagonals), n x n x m cells;
/// the lowest spheres sit at z = r.
Structure fcc(int n, int m, double r) {
    Structure s = paper_structure();
    const double a = 2.0 * std::sqrt(2.0) * r;
    s.box.lx = s.box.ly = a * n;
    const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
    for (int k = 0; k < m; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                for (const auto& b : basis)
                    s.add({(i + b[0]) * a, (j + b[1]) * a, r + (k + b[2]) * a}, r, Phase::cb);
    return s;
}

} // namespace

TEST(SphereSlab, WholeHalfAndCapVolumes) {
    const double r = 2.0e-6, zc = 5.0e-6;
    EXPECT_NEAR(sphere_slab_volume(zc, r, 0.0, 10e-6), 4.0 / 3.0 * pi * r * r * r,
                1e-12 * r * r * r);
    EXPECT_NEAR(sphere_slab_volume(zc, r, 0.0, zc), 2.0 / 3.0 * pi * r * r * r, 1e-12 * r * r * r);
    // Cap of height h: π h² (3r - h) / 3.
    const double h = 0.7e-6;
    EXPECT_NEAR(sphere_slab_volume(zc, r, zc + r - h, 20e-6), pi * h * h * (3 * r - h) / 3.0,
                1e-12 * r * r * r);
    EXPECT_EQ(sphere_slab_volume(zc, r, 8e-6, 9e-6), 0.0);
}

TEST(Profiles, SingleSphereSlabsAddUpExactly) {
    Structure s = paper_structure();
    s.box.lx = s.box.ly = 10e-6;
    const double r = 3.3e-6, zc = 3.7e-6;
    s.add({5e-6, 5e-6, zc}, r, Phase::ncm, 4740.0);
    const double dz = 0.37e-6;
    const Profiles p = volume_fraction_profiles(s, dz, zc + r);
    double v = 0.0;
    for (std::size_t k = 0; k < p.size(); ++k) {
        const double a = double(k) * dz, b = std::min(zc + r, double(k + 1) * dz);
        v += p.ncm[k] * s.box.area() * (b - a);
        // Each slab: the analytic integral π ∫ (r² - (z - zc)²) dz.
        auto F = [&](double z) {
            const double u = std::clamp(z - zc, -r, r);
            return pi * (r * r * u - u * u * u / 3.0);
        };
        EXPECT_NEAR(p.ncm[k], (F(b) - F(a)) / (s.box.area() * (b - a)), 1e-12);
        EXPECT_NEAR(p.pore[k], 1.0 - p.ncm[k], 1e-15);
    }
    EXPECT_NEAR(v, 4.0 / 3.0 * pi * r * r * r, 1e-9 * r * r * r);
}

TEST(Profiles, SimpleCubicLayersArePiOverSix) {
    const double r = 1.0e-6;
    const Structure s = simple_cubic(4, 5, r);
    // Slabs of one lattice spacing, aligned with the layers: each holds whole spheres.
    const Profiles p = volume_fraction_profiles(s, 2.0 * r, highest_top(s));
    ASSERT_EQ(p.size(), 5u);
    for (std::size_t k = 0; k < p.size(); ++k) {
        EXPECT_NEAR(p.ncm[k], pi / 6.0, 1e-12);
        EXPECT_NEAR(p.pore[k], 1.0 - pi / 6.0, 1e-12);
    }
    // Slabs cutting the spheres in halves: the mean over a period is still π/6.
    const Profiles q = volume_fraction_profiles(s, r, highest_top(s));
    for (std::size_t k = 0; k + 1 < q.size(); k += 2)
        EXPECT_NEAR(0.5 * (q.ncm[k] + q.ncm[k + 1]), pi / 6.0, 1e-12);
}

TEST(Profiles, FccInteriorIsClosePacked) {
    const double r = 0.75e-6, a = 2.0 * std::sqrt(2.0) * r;
    const Structure s = fcc(3, 6, r);
    // An interior slab one cell high: every sphere it cuts is balanced by its periodic partner.
    const Profiles p = volume_fraction_profiles(s, a, highest_top(s));
    for (std::size_t k = 1; k + 2 < p.size(); ++k)
        EXPECT_NEAR(p.cb_envelope[k], pi / (3.0 * std::sqrt(2.0)), 1e-12);
    // Carbon only: (1 - ε_CB) of the envelope.
    EXPECT_NEAR(p.cb_carbon[2], 0.25 * p.cb_envelope[2], 1e-15);
}

TEST(Bulk, NoFormulationGivesNoMassesNotInventedOnes) {
    // The formulation's defaults are the configuration's (io/config_keys.def), never the
    // analysis's own: a structure built without one reports NaN, not the paper's numbers.
    Structure s = simple_cubic(2, 2, 1.0e-6);
    s.formulation = Formulation{};
    EXPECT_TRUE(std::isnan(s.formulation.solids_density()));
    const Profiles p = volume_fraction_profiles(s, 0.25e-6, highest_top(s));
    EXPECT_TRUE(std::isnan(bulk_properties(s, p.solid(), 0.25e-6).porosity));
}

TEST(Bulk, ThicknessDensityAndPorosityFromTheMasses) {
    const double r = 1.0e-6;
    const Structure s = simple_cubic(4, 5, r);
    const Profiles p = volume_fraction_profiles(s, 0.25e-6, highest_top(s));
    const Bulk b = bulk_properties(s, p.solid(), 0.25e-6);
    EXPECT_NEAR(b.thickness, 10.0e-6, 1e-18);
    const double v = 4.0 / 3.0 * pi * r * r * r;
    const double m_ncm = 80 * 4740.0 * v;
    EXPECT_NEAR(b.mass.ncm, m_ncm, 1e-12 * m_ncm);
    // Binder by the recipe's ratio: 0.03 / (0.94 + 0.03) of the resolved solids.
    EXPECT_NEAR(b.mass.pvdf, 0.03 / 0.97 * m_ncm, 1e-12 * m_ncm);
    const double L = (m_ncm + b.mass.pvdf) / s.box.area();
    EXPECT_NEAR(b.density, L / 10e-6, 1e-9 * b.density);
    EXPECT_NEAR(b.porosity, 1.0 - b.density / s.formulation.solids_density(), 1e-12);
    EXPECT_NEAR(b.solids_density, 4287.5, 0.1); // Eq. 4, model.md M-1.7
    EXPECT_NEAR(b.bulk_solid_fraction, pi / 6.0, 0.02);
    // The top layer is whole, so the solid fraction halves only inside the top layer's upper half.
    EXPECT_GT(b.thickness_half_solid, 9.0e-6);
    EXPECT_LE(b.thickness_half_solid, 10.0e-6);
}

TEST(Bulk, CbBinderPorosityEq2IsIndependentOfTheThickness) {
    // model.md M-8.4: Eq. 2 with ε_C = 1 - ρ/ρ_s, C_v = V_NCM/V, ε_C,NMC = 1 - (V_NCM + V_env)/V
    // reduces to (V_NCM + V_env - m/ρ_s) / V_env: the coating volume V cancels.
    Structure s = fcc(3, 4, 0.75e-6);
    for (int i = 0; i < 6; ++i) s.add({1e-6 + i * 1.1e-6, 2e-6, 12e-6}, 0.5e-6, Phase::ncm, 4740.0);
    const Profiles p = volume_fraction_profiles(s, 0.5e-6, highest_top(s));
    const Bulk b = bulk_properties(s, p.solid(), 0.5e-6);
    const double expected =
        (b.mass.ncm_volume + b.mass.cb_envelope_volume - b.mass.dry() / b.solids_density) /
        b.mass.cb_envelope_volume;
    EXPECT_NEAR(b.cb_binder_porosity, expected, 1e-9);
    // Same structure 5 um higher up: a thicker coating, the same ε_CB.
    Structure lifted = s;
    for (auto& x : lifted.position) x.z += 5e-6;
    const Bulk b2 = bulk_properties(
        lifted, volume_fraction_profiles(lifted, 0.5e-6, highest_top(lifted)).solid(), 0.5e-6);
    EXPECT_NEAR(b2.cb_binder_porosity, b.cb_binder_porosity, 1e-9);
    EXPECT_GT(b2.porosity, b.porosity);
}

TEST(Coordination, SimpleCubicHasSixNeighbours) {
    const Structure s = simple_cubic(4, 4, 1.0e-6);
    const Coordination c = coordination(s, 1e-12);
    // Periodic in x, y: every sphere has 4 in its layer, 1 or 2 between layers.
    EXPECT_EQ(c.ncm_ncm,
              16u * 2u * 4u + 16u * 3u); // in-layer bonds (2 per sphere) + bonds between 4 layers
    EXPECT_EQ(c.ncm_substrate, 16u);
    EXPECT_NEAR(c.ncm_with_ncm(), (16 * 2 * 4 + 16 * 3) * 2.0 / 64.0, 1e-12);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const bool surface = s.position[i].z < 1.5e-6 || s.position[i].z > 6.5e-6;
        EXPECT_EQ(c.per_particle[i], surface ? 5u : 6u);
    }
    // With a gap below the lattice's, nothing touches: spheres 1 nm apart.
    Structure apart = simple_cubic(4, 4, 1.0e-6);
    for (double& r : apart.radius) r -= 0.5e-9;
    EXPECT_EQ(coordination(apart, 0.0).ncm_ncm, 0u);
    EXPECT_EQ(coordination(apart, 2e-9).ncm_ncm, 16u * 2u * 4u + 16u * 3u);
}

TEST(Coordination, FccHasTwelveAndPairTypesAreCounted) {
    Structure s = fcc(3, 3, 0.75e-6);
    const Coordination c = coordination(s, 1e-12);
    std::size_t interior = 0;
    const double a = 2.0 * std::sqrt(2.0) * 0.75e-6;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s.position[i].z > 0.75e-6 + 0.6 * a && s.position[i].z < 0.75e-6 + 1.9 * a) {
            EXPECT_EQ(c.per_particle[i], 12u);
            ++interior;
        }
    EXPECT_GT(interior, 0u);
    EXPECT_EQ(c.ncm_ncm + c.ncm_cb, 0u);
    // An NCM sphere resting on top of the lattice touching one CB sphere: one NCM-CB contact.
    const double rn = 3.0e-6;
    s.add({s.position.back().x, s.position.back().y, s.position.back().z + 0.75e-6 + rn}, rn,
          Phase::ncm, 4740.0);
    const Coordination c2 = coordination(s, 1e-12);
    EXPECT_GE(c2.ncm_cb, 1u);
    EXPECT_NEAR(c2.cb_with_ncm() * double(c2.n_cb), double(c2.ncm_cb), 1e-9);
}

TEST(Voxelize, SphereVolumeAndPeriodicWrap) {
    Structure s = paper_structure();
    s.box.lx = s.box.ly = 8e-6;
    const double r = 2.0e-6;
    s.add({0.3e-6, 7.9e-6, 3e-6}, r, Phase::ncm, 4740.0); // cut by both periodic edges
    const VoxelGrid g = voxelize(s, 0.1e-6, 6e-6);
    EXPECT_EQ(g.nx, 80);
    EXPECT_EQ(g.nz, 60);
    std::size_t n = 0;
    for (auto l : g.label) n += l == label_ncm;
    const double v = double(n) * g.ax * g.ay * g.az;
    EXPECT_NEAR(v / (4.0 / 3.0 * pi * r * r * r), 1.0, 0.005);
    // The voxel at the sphere's centre across the wrap is solid; a far one is pore.
    EXPECT_EQ(g.label[g.index(2, 78, 30)], label_ncm);
    EXPECT_EQ(g.label[g.index(40, 40, 30)], label_pore);
}

TEST(Voxelize, NcmWinsOverCbAndLatticePorosity) {
    Structure s = simple_cubic(3, 3, 1.0e-6);
    s.add(s.position[0], 0.5e-6, Phase::cb); // a CB sphere inside an NCM sphere
    const VoxelGrid g = voxelize(s, 0.05e-6, highest_top(s));
    std::size_t pore = 0, cb = 0;
    for (auto l : g.label) {
        pore += l == label_pore;
        cb += l == label_cb;
    }
    EXPECT_EQ(cb, 0u);
    EXPECT_NEAR(double(pore) / double(g.size()), 1.0 - pi / 6.0, 0.003);
    EXPECT_THROW((void)voxelize(s, -1.0, 1e-6), InputError);
}

// The analysis reads any snapshot: the same particles as our CSV and as a LAMMPS dump (with its box)
// give the same structure and numbers; a type the config does not know is an InputError.
#include "drydem/core/particles.hpp"
#include "drydem/io/particle_io.hpp"
#include "drydem/io/snapshot_writers.hpp"
#include "test_dirs.hpp"
#include <fstream>

TEST(AnalysisInput, CsvAndLammpsDumpGiveTheSameStructure) {
    const auto dir = testing_support::temp_dir();
    Config c;
    c.box_x = c.box_y = 20e-6;
    ParticleStore p;
    p.add(1, 0, 3.25e-6, 4740.0, {5e-6, 5e-6, 3.3e-6});
    p.add(2, 4, 5.675e-6, 4740.0, {14e-6, 12e-6, 5.7e-6});
    for (int i = 0; i < 20; ++i)
        p.add(std::uint32_t(3 + i), 5, 0.75e-6, 1190.0, {1e-6 * i, 19.5e-6, 0.8e-6 + 0.1e-6 * i});
    write_particles_csv(dir / "final.csv", p);
    {
        std::ofstream dump(dir / "dump.lammpstrj");
        Box box;
        box.lx = box.ly = 20e-6;
        append_lammps_dump(dump, p, box, 100, 12e-6);
    }
    const Structure a = structure_from_file(read_particles(dir / "final.csv"), file_defaults(c));
    const Structure b =
        structure_from_file(read_particles(dir / "dump.lammpstrj"), file_defaults(c));
    ASSERT_EQ(a.size(), 22u);
    ASSERT_EQ(b.size(), 22u);
    EXPECT_DOUBLE_EQ(b.box.lx, 20e-6);
    std::size_t cb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a.phase[i], b.phase[i]);
        EXPECT_NEAR(a.radius[i], b.radius[i], 1e-15);
        EXPECT_NEAR(a.position[i].z, b.position[i].z, 1e-15);
        cb += a.phase[i] == Phase::cb;
    }
    EXPECT_EQ(cb, 20u);
    const Masses ma = masses(a), mb = masses(b);
    EXPECT_NEAR(ma.dry(), mb.dry(), 1e-9 * ma.dry());
    // CB carbon: (1 - ε_CB) ρ_CB of the envelope, not the file's effective density.
    EXPECT_NEAR(ma.cb_carbon, 20 * 0.25 * 1660.0 * 4.0 / 3.0 * pi * std::pow(0.75e-6, 3),
                1e-9 * ma.cb_carbon);
    // Type 7 is not in a 5-class config; --cb-type makes it CB and every other type NCM.
    p.add(99, 6, 1e-6, 1000.0, {1e-6, 1e-6, 1e-6});
    write_particles_csv(dir / "bad.csv", p);
    EXPECT_THROW((void)structure_from_file(read_particles(dir / "bad.csv"), file_defaults(c)),
                 InputError);
    PhaseRule rule;
    rule.cb_type = 7;
    const Structure d =
        structure_from_file(read_particles(dir / "bad.csv"), file_defaults(c), rule);
    std::size_t cb7 = 0;
    for (auto ph : d.phase) cb7 += ph == Phase::cb;
    EXPECT_EQ(cb7, 1u);
}
