// SPDX-License-Identifier: MIT
// Pore analysis against closed forms (issue 5): the exact distance transform against brute force,
// chord lengths of a Boolean model (exponential, mean 4R / (3 (-ln ε))), local thickness of a slit
// and a cylinder, intrusion through a throat, and the voxel files' round trip.
#include "drydem/analysis/analyze.hpp"
#include "drydem/drying/analysis_inputs.hpp"
#include "drydem/core/error.hpp"
#include "drydem/analysis/chords.hpp"
#include "drydem/analysis/distance_transform.hpp"
#include "drydem/analysis/pore_size.hpp"
#include "drydem/analysis/voxel_grid.hpp"
#include "drydem/output/voxel_export.hpp"
#include <cmath>
#include <cstdio>
#include <fstream>
#include <gtest/gtest.h>
#include "test_dirs.hpp"
#include <numbers>
#include <random>
#include <sstream>

using namespace drydem;
using namespace drydem::analysis;

namespace {

/// An empty structure with the embedded default's formulation (the paper's 20.1 mg/cm2 recipe).
Structure paper_structure() {
    Structure s;
    s.formulation = analysis_formulation(Config{});
    return s;
}

VoxelGrid solid_grid(int nx, int ny, int nz, std::uint8_t fill = label_ncm) {
    VoxelGrid g;
    g.nx = nx;
    g.ny = ny;
    g.nz = nz;
    g.ax = g.ay = g.az = 0.1e-6;
    g.label.assign(std::size_t(nx) * ny * nz, fill);
    return g;
}

double diameter(std::uint16_t r2) { return 2.0 * std::sqrt(double(r2)); }

/// A Boolean model: spheres of radius R placed uniformly (overlaps allowed), periodic in x and y,
/// centres also below and above [0, H] so the whole film is homogeneous.
Structure boolean_model(double box, double height, double R, double porosity, std::uint64_t seed) {
    Structure s = paper_structure();
    s.box.lx = s.box.ly = box;
    const double n_per_volume = -std::log(porosity) / (4.0 / 3.0 * std::numbers::pi * R * R * R);
    const double volume = box * box * (height + 2 * R);
    std::mt19937_64 rng(seed);
    std::poisson_distribution<long> count(n_per_volume * volume);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const long n = count(rng);
    for (long i = 0; i < n; ++i)
        s.add({u(rng) * box, u(rng) * box, -R + u(rng) * (height + 2 * R)}, R, Phase::cb);
    return s;
}

} // namespace

TEST(DistanceTransform, EqualsBruteForceWithPeriodicSidesAndSubstrate) {
    std::mt19937 rng(7);
    std::bernoulli_distribution solid(0.08);
    VoxelGrid g = solid_grid(13, 11, 9, label_pore);
    for (auto& l : g.label) l = solid(rng) ? label_cb : label_pore;
    const auto d2 = squared_distance_to_solid(g);
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                long best = long(k + 1) * (k + 1); // the substrate plane at k = -1
                for (int kk = 0; kk < g.nz; ++kk)
                    for (int jj = 0; jj < g.ny; ++jj)
                        for (int ii = 0; ii < g.nx; ++ii) {
                            if (g.label[g.index(ii, jj, kk)] == label_pore) continue;
                            const int dx = std::min(std::abs(i - ii), g.nx - std::abs(i - ii));
                            const int dy = std::min(std::abs(j - jj), g.ny - std::abs(j - jj));
                            best = std::min(best, long(dx * dx + dy * dy + (k - kk) * (k - kk)));
                        }
                ASSERT_EQ(long(d2[g.index(i, j, k)]), best) << i << " " << j << " " << k;
            }
}

TEST(DistanceTransform, OneDimensionalEnvelope) {
    // f = 0 at 2 and 7 in a periodic line of 10: the distance wraps around.
    std::vector<std::uint32_t> f(10, 1000), out(10);
    f[2] = f[7] = 0;
    std::vector<double> z;
    std::vector<int> v;
    std::vector<std::uint32_t> fv;
    distance_transform_1d(f.data(), 10, true, false, 1000, 65535, out.data(), z, v, fv);
    const std::uint32_t expect[10] = {4, 1, 0, 1, 4, 4, 1, 0, 1, 4};
    for (int q = 0; q < 10; ++q) EXPECT_EQ(out[std::size_t(q)], expect[q]) << q;
    // No sample: everything at the cap.
    std::vector<std::uint32_t> none(5, 1000), o2(5);
    distance_transform_1d(none.data(), 5, false, false, 1000, 65535, o2.data(), z, v, fv);
    for (auto x : o2) EXPECT_EQ(x, 65535u);
}

TEST(Chords, BooleanModelIsExponentialWithTheClosedFormMean) {
    // Pore chords of a Boolean model are exponential with mean 1 / (λ π R²) = 4R / (3 (-ln ε)),
    // λ the sphere number density, ε the porosity (both of this realisation: the sphere count is
    // Poisson, ±3 % here).
    const double R = 1.0e-6, box = 24e-6, H = 12e-6, a = 0.1e-6;
    const Structure s = boolean_model(box, H, R, 0.5, 11);
    const VoxelGrid g = voxelize(s, a, H);
    std::size_t pore = 0;
    for (auto l : g.label) pore += l == label_pore;
    const double eps = double(pore) / double(g.size());
    EXPECT_NEAR(eps, 0.5, 0.03);
    const double lambda = double(s.size()) / (box * box * (H + 2 * R));
    const double mean_lambda = 1.0 / (lambda * std::numbers::pi * R * R);
    const double mean_eps = 4.0 * R / (3.0 * -std::log(eps));
    const auto h = chord_lengths(g, g.nz);
    for (int axis = 0; axis < 2; ++axis) {
        const auto& c = h[std::size_t(axis)];
        const double mean = c.mean_voxels() * a;
        std::printf("axis %d: %llu chords, mean %.4f um; 1/(lambda pi R^2) %.4f um, 4R/(3(-ln "
                    "eps)) %.4f um\n",
                    axis, (unsigned long long)c.chords(), mean * 1e6, mean_lambda * 1e6,
                    mean_eps * 1e6);
        EXPECT_NEAR(mean / mean_eps, 1.0, 0.03) << "axis " << axis;
        EXPECT_NEAR(mean / mean_lambda, 1.0, 0.03) << "axis " << axis;
        // Exponential shape: the share of chords longer than one and two means.
        double longer1 = 0, longer2 = 0;
        for (std::size_t n = 1; n < c.count.size(); ++n) {
            if (double(n) * a > mean_eps) longer1 += double(c.count[n]);
            if (double(n) * a > 2 * mean_eps) longer2 += double(c.count[n]);
        }
        EXPECT_NEAR(longer1 / double(c.chords()), std::exp(-1.0), 0.03);
        EXPECT_NEAR(longer2 / double(c.chords()), std::exp(-2.0), 0.02);
    }
}

TEST(Chords, PeriodicRunsWrapAndZRunsAtTheTopAreCut) {
    VoxelGrid g = solid_grid(10, 1, 6, label_ncm);
    // x: one run of 4 across the periodic edge (i = 8, 9, 0, 1) in layer 0.
    for (int i : {8, 9, 0, 1}) g.label[g.index(i, 0, 0)] = label_pore;
    // z: column i = 5 pore in layers 0..1 (chord of 2 from the substrate) and 4..5 (cut at the top).
    for (int k : {0, 1, 4, 5}) g.label[g.index(5, 0, k)] = label_pore;
    const auto h = chord_lengths(g, g.nz);
    ASSERT_GE(h[0].count.size(), 5u);
    EXPECT_EQ(h[0].count[4], 1u);
    EXPECT_EQ(h[2].count[2], 1u);
    EXPECT_EQ(h[2].open_lines, 1u);
}

TEST(LocalThickness, SlitWidthWithinOneVoxel) {
    for (int w : {10, 11}) {
        VoxelGrid g = solid_grid(40, 6, 30);
        for (int k = 0; k < g.nz; ++k)
            for (int j = 0; j < g.ny; ++j)
                for (int i = 15; i < 15 + w; ++i) g.label[g.index(i, j, k)] = label_pore;
        const auto lt = local_thickness(g, squared_distance_to_solid(g));
        // Away from the substrate: its corners with the walls are narrower than the slit.
        for (std::size_t idx = g.index(0, 0, w); idx < g.size(); ++idx) {
            if (g.label[idx] != label_pore) {
                ASSERT_EQ(lt[idx], 0u);
                continue;
            }
            ASSERT_LE(std::abs(diameter(lt[idx]) - w), 1.0) << "w " << w << " voxel " << idx;
        }
    }
}

TEST(LocalThickness, CylinderDiameterWithinOneVoxel) {
    const int n = 40;
    const double D = 16.0, c = 20.0;
    VoxelGrid g = solid_grid(n, n, 24);
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double dx = i + 0.5 - c, dy = j + 0.5 - c;
                if (dx * dx + dy * dy < 0.25 * D * D) g.label[g.index(i, j, k)] = label_pore;
            }
    const auto lt = local_thickness(g, squared_distance_to_solid(g));
    for (std::size_t idx = g.index(0, 0, 10); idx < g.size(); ++idx)
        if (g.label[idx] == label_pore) {
            ASSERT_LE(std::abs(diameter(lt[idx]) - D), 1.0) << idx;
        }
}

TEST(MercuryIntrusion, BodyBehindAThroatFillsAtTheThroatSize) {
    // A wide cylinder (D 16) at the bottom, reached from the top only through a narrow one (D 6);
    // a second wide cylinder with no way out is never intruded.
    const int n = 40;
    VoxelGrid g = solid_grid(n, n, 40);
    auto carve = [&](double cx, double cy, double D, int k0, int k1) {
        for (int k = k0; k < k1; ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const double dx = i + 0.5 - cx, dy = j + 0.5 - cy;
                    if (dx * dx + dy * dy < 0.25 * D * D) g.label[g.index(i, j, k)] = label_pore;
                }
    };
    carve(12, 20, 16, 0, 20); // body
    carve(12, 20, 6, 20, 40); // throat to the top
    carve(31, 20, 12, 3, 19); // closed pore
    const auto d2 = squared_distance_to_solid(g);
    const auto lt = local_thickness(g, d2);
    const auto mip = intrusion_map(g, invasion_levels(g, d2));
    for (int k = 2; k < 16; ++k) {
        const std::size_t body = g.index(12, 20, k), closed = g.index(31, 20, k);
        EXPECT_LE(std::abs(diameter(lt[body]) - 16.0), 1.0);
        EXPECT_LE(std::abs(diameter(mip[body]) - 6.0), 1.0) << k;
        if (k >= 8 && k < 14) {
            // Its axis lies on voxel faces: the digitised circle is 1.2 voxels narrower diagonally.
            EXPECT_LE(std::abs(diameter(lt[closed]) - 12.0), 1.5);
            EXPECT_EQ(mip[closed], 0u);
        }
    }
    // The whole throat and body are intruded (nothing of them left at 0).
    for (std::size_t idx = 0; idx < g.size(); ++idx)
        if (g.label[idx] == label_pore && idx % std::size_t(n) < 22) {
            ASSERT_GT(mip[idx], 0u);
        }
}

TEST(VoxelFiles, RawJsonMhdAndTiffRoundTrip) {
    const auto dir = testing_support::temp_dir();
    Structure s = paper_structure();
    s.box.lx = 3e-6;
    s.box.ly = 2e-6;
    s.add({1e-6, 1e-6, 1.2e-6}, 0.8e-6, Phase::ncm, 4740.0);
    s.add({2.4e-6, 0.5e-6, 0.6e-6}, 0.5e-6, Phase::cb);
    const VoxelGrid g = voxelize(s, 0.1e-6, 2.0e-6);
    const VoxelExport e = write_voxel_image(dir, g, "test", true);
    const VoxelGrid back = read_voxel_image(e.json);
    EXPECT_EQ(back.nx, 30);
    EXPECT_EQ(back.ny, 20);
    EXPECT_EQ(back.nz, 20);
    EXPECT_EQ(back.label, g.label);
    const VoxelGrid tif = read_voxel_tiff(e.tiff);
    EXPECT_EQ(tif.nx, 30);
    EXPECT_EQ(tif.nz, 20);
    EXPECT_EQ(tif.label, g.label);
    std::ifstream mhd(e.mhd);
    std::stringstream text;
    text << mhd.rdbuf();
    EXPECT_NE(text.str().find("DimSize = 30 20 20"), std::string::npos);
    EXPECT_NE(text.str().find("ElementType = MET_UCHAR"), std::string::npos);
    EXPECT_NE(text.str().find("ElementDataFile = structure.raw"), std::string::npos);
}

TEST(Analyze, PipelineOnABooleanFilm) {
    const Structure s = boolean_model(12e-6, 8e-6, 1.0e-6, 0.5, 3);
    AnalysisOptions o;
    o.voxel = 0.1e-6;
    o.pore_top = "highest";
    const AnalysisResult r = analyze_structure(s, o);
    ASSERT_TRUE(r.voxelized);
    EXPECT_NEAR(r.voxel_porosity, 0.5, 0.05);
    // Local thickness of a Boolean model's pores: between a few voxels and the box.
    EXPECT_GT(r.psd.peak, 0.3e-6);
    EXPECT_LT(r.psd.peak, 6e-6);
    double total = 0.0, intruded = 0.0;
    for (double v : r.psd.volume) total += v;
    for (double v : r.psd.intruded) intruded += v;
    EXPECT_NEAR(total, 1.0, 1e-9);
    EXPECT_NEAR(intruded + r.psd.not_intruded, 1.0, 1e-9);
    // Intrusion is limited by throats: never coarser than the local thickness, median not above it.
    EXPECT_LE(r.psd.mip_median, r.psd.median + 1e-12);
    // A voxel image beyond the machine (here 1 nm voxels: ~1e12) is refused before any allocation.
    AnalysisOptions tiny = o;
    tiny.voxel = 1e-9;
    try {
        (void)analyze_structure(s, tiny);
        ADD_FAILURE() << "no error for a 1e12-voxel image";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("choose a coarser voxel size"), std::string::npos)
            << e.what();
    }
}

TEST(LocalThickness, PaintedBallsEqualBruteForceAcrossSeamsAndLayers) {
    // Every voxel gets the largest r² of the balls {|p − c|² < r²(c)} that cover it, x and y
    // periodic: the pruned centres, the unwrapped interior test and the seams' wrapped test must
    // all agree with painting every centre. Boolean pores on a grid small enough for brute force.
    for (const std::uint64_t seed : {11u, 12u, 13u, 14u}) {
        const Structure s = boolean_model(2.0e-6, 1.6e-6, 0.3e-6, 0.7, seed);
        const VoxelGrid g = voxelize(s, 0.1e-6, 1.6e-6);
        ASSERT_EQ(g.nx, 20);
        const auto d2 = squared_distance_to_solid(g);
        const auto lt = local_thickness(g, d2);
        std::size_t mismatches = 0, painted = 0;
        for (int k = 0; k < g.nz; ++k)
            for (int j = 0; j < g.ny; ++j)
                for (int i = 0; i < g.nx; ++i) {
                    std::uint16_t best = 0;
                    for (int kc = 0; kc < g.nz; ++kc)
                        for (int jc = 0; jc < g.ny; ++jc)
                            for (int ic = 0; ic < g.nx; ++ic) {
                                const std::uint16_t v = d2[g.index(ic, jc, kc)];
                                if (v <= best) continue;
                                int di = std::abs(i - ic), dj = std::abs(j - jc);
                                di = std::min(di, g.nx - di);
                                dj = std::min(dj, g.ny - dj);
                                if (di * di + dj * dj + (k - kc) * (k - kc) < int(v)) best = v;
                            }
                    painted += best > 0;
                    mismatches += lt[g.index(i, j, k)] != best;
                }
        EXPECT_EQ(mismatches, 0u) << "seed " << seed;
        EXPECT_GT(painted, g.size() / 2); // the test paints a real pore space
    }
}

TEST(Analyze, TransportAlongsidePoreSizesGivesTheSequentialResults) {
    // With both parts on, the transport solves run in a thread of their own beside the pore-size
    // pipeline; every number must equal those of each part run alone (sequentially).
    const Structure s = boolean_model(4e-6, 3e-6, 0.5e-6, 0.5, 5);
    AnalysisOptions both;
    both.voxel = 0.1e-6;
    both.transport.voxels = {0.4e-6, 0.2e-6};
    both.transport.walkers = 200;
    both.transport.walk_steps = 200;
    AnalysisOptions transport_only = both, pores_only = both;
    transport_only.voxel = 0.0;
    pores_only.transport.voxels.clear();
    const AnalysisResult r = analyze_structure(s, both);
    const AnalysisResult t = analyze_structure(s, transport_only);
    const AnalysisResult p = analyze_structure(s, pores_only);
    ASSERT_TRUE(r.transport && t.transport && r.voxelized && p.voxelized);
    EXPECT_TRUE(r.transport->alongside_pore_sizes);
    EXPECT_FALSE(t.transport->alongside_pore_sizes);
    ASSERT_EQ(r.transport->levels.size(), t.transport->levels.size());
    for (std::size_t m = 0; m < r.transport->levels.size(); ++m) {
        const TransportLevel &a = r.transport->levels[m], &b = t.transport->levels[m];
        EXPECT_EQ(a.pore_z.sigma_eff, b.pore_z.sigma_eff);
        EXPECT_EQ(a.pore_x.sigma_eff, b.pore_x.sigma_eff);
        EXPECT_EQ(a.electronic_z.sigma_eff, b.electronic_z.sigma_eff);
        EXPECT_EQ(a.cb_z.sigma_eff, b.cb_z.sigma_eff);
        EXPECT_EQ(a.walk.diffusivity[0], b.walk.diffusivity[0]);
    }
    EXPECT_GT(r.transport->reported().pore_z.sigma_eff, 0.0);
    EXPECT_EQ(r.psd.volume, p.psd.volume);
    EXPECT_EQ(r.psd.intruded, p.psd.intruded);
    EXPECT_EQ(r.voxel_porosity, p.voxel_porosity);
}
