// SPDX-License-Identifier: MIT
// Binder migration (paper Eq. 1) against closed forms (issue 15): mass conservation; fast diffusion
// leaves the binder uniform; pure convection during pore emptying keeps c uniform in the film and
// piles the binder of the evaporated solvent into the top cell (M_top = c₀ ε H (1 − S_end)); faster
// drying (higher Pe) puts more binder at the top and less at the substrate.
#include "drydem/analysis/binder_migration.hpp"
#include <cmath>
#include <gtest/gtest.h>

using namespace drydem::analysis;

namespace {
/// Level descending at `rate` from h0 to 0 in rows of 0.1 s; uniform final porosity ε over H_f.
DryingHistory linear_history(double h0, double Hf, double rate, double eps) {
    DryingHistory h;
    for (double t = 0.0, lv = h0; lv > 0.2 * Hf; t += 0.1, lv -= rate * 0.1) {
        h.time.push_back(t);
        h.liquid_level.push_back(lv);
    }
    h.final_height = Hf;
    h.dz = Hf / 20;
    h.porosity.assign(20, eps);
    return h;
}
} // namespace

TEST(BinderMigration, ConservesMassAndFastDiffusionStaysUniform) {
    const DryingHistory h = linear_history(40e-6, 20e-6, 1e-6, 0.45);
    BinderParams p;
    p.cells = 50;
    p.diffusivity = 1e-8; // Pe = E H₀/D = 0.004
    // Stop at half saturation: below it the pore diffusion D₀ θ^(α−1) fades while the capillary
    // flow u = F/θ grows, and no diffusivity keeps the binder uniform to the end.
    p.residual_saturation = 0.5;
    const BinderProfile b = binder_migration(h, p);
    EXPECT_LT(b.mass_balance, 1e-10);
    EXPECT_NEAR(b.peclet, 1e-6 * 40e-6 / 1e-8, 1e-6);
    for (double v : b.binder) EXPECT_NEAR(v, 1.0, 0.01);
    EXPECT_NEAR(b.consolidation_time, 20.0, 0.011);
}

TEST(BinderMigration, PureConvectionWhileThePoresEmptyPilesTheBinderOnTop) {
    // Start at consolidation (h₀ = H_f): no shrinkage, only capillary flow to the top, D = 0.
    const double eps = 0.4, Sres = 0.05;
    const DryingHistory h = linear_history(20e-6, 20e-6, 1e-6, eps);
    BinderParams p;
    p.cells = 40;
    p.diffusivity = 0.0;
    p.residual_saturation = Sres;
    const BinderProfile b = binder_migration(h, p);
    EXPECT_LT(b.mass_balance, 1e-10);
    // In the film c stays c₀ (upwind of a uniform field), so every cell but the top one keeps the
    // share ε S_end c₀ of its ε c₀: binder/mean = S_end; the top cell holds the rest,
    // 1 + (N − 1)(1 − S_end). S_end lies within one step below S_res.
    const int n = p.cells;
    const double S_end = b.binder[0];
    EXPECT_LE(S_end, Sres + 1e-12);
    EXPECT_GT(S_end, Sres - 0.01);
    for (int i = 0; i + 1 < n; ++i) EXPECT_NEAR(b.binder[std::size_t(i)], S_end, 1e-9) << i;
    EXPECT_NEAR(b.binder[std::size_t(n) - 1], 1.0 + (n - 1) * (1.0 - S_end), 1e-9);
}

TEST(BinderMigration, FasterDryingPutsMoreBinderOnTopAndLessAtTheSubstrate) {
    BinderParams p;
    p.cells = 60;
    p.diffusivity = 5e-12;
    double last_bottom = 2.0, last_top = 0.0;
    for (double rate : {0.2e-6, 0.7e-6, 2.0e-6}) {
        const BinderProfile b = binder_migration(linear_history(60e-6, 30e-6, rate, 0.45), p);
        EXPECT_LT(b.mass_balance, 1e-10);
        EXPECT_LT(b.bottom10, last_bottom) << rate;
        EXPECT_GT(b.top10, last_top) << rate;
        EXPECT_LT(b.bottom10, 1.0);
        EXPECT_GT(b.top10, 1.0);
        last_bottom = b.bottom10;
        last_top = b.top10;
    }
}

namespace {
/// Frames of the shrinkage at the given times: the solid fraction `solid(ξ)` (ξ = z/level) of a
/// film holding the final film's solids, on slabs of h.dz up to the level.
template <class Solid>
std::vector<PorosityFrame> frames_of(const DryingHistory& h, std::initializer_list<double> times,
                                     Solid&& solid) {
    std::vector<PorosityFrame> out;
    for (double t : times) {
        const std::size_t k = std::size_t(std::lround(t / 0.1));
        PorosityFrame f{h.time[k], h.liquid_level[k], {}};
        const std::size_t slabs = std::size_t(std::ceil(f.height / h.dz - 1e-9));
        for (std::size_t s = 0; s < slabs; ++s)
            f.porosity.push_back(1.0 - solid((s + 0.5) * h.dz / f.height, f.height));
        out.push_back(std::move(f));
    }
    return out;
}
} // namespace

// The run's own frames replace the affine compression of the final film while it shrinks: frames
// that are that compression give the same binder profile (the model reads them, scaled to the final
// solid volume, and interpolates in time); frames with the solids piled under the level (a skin)
// give another one, with the binder mass conserved either way.
TEST(BinderMigration, ShrinkageFollowsTheRunsFrames) {
    const double eps = 0.45, Hf = 20e-6;
    const DryingHistory affine = linear_history(40e-6, Hf, 1e-6, eps);
    BinderParams p;
    p.cells = 40;
    p.diffusivity = 2e-11;
    const BinderProfile a = binder_migration(affine, p);
    EXPECT_EQ(a.porosity_frames, 0);

    DryingHistory same = affine;
    same.frames = frames_of(affine, {0.0, 5.0, 10.0, 15.0},
                            [&](double, double level) { return (1.0 - eps) * Hf / level; });
    const BinderProfile b = binder_migration(same, p);
    EXPECT_EQ(b.porosity_frames, 4);
    EXPECT_LT(b.mass_balance, 1e-10);
    ASSERT_EQ(b.binder.size(), a.binder.size());
    for (std::size_t i = 0; i < a.binder.size(); ++i)
        EXPECT_NEAR(b.binder[i], a.binder[i], 1e-9) << i;

    DryingHistory skin = affine;
    // Solids twice as dense in the upper half of the wet film as in the lower (same volume).
    skin.frames = frames_of(affine, {0.0, 5.0, 10.0, 15.0}, [&](double xi, double level) {
        return (1.0 - eps) * Hf / level * (xi > 0.5 ? 4.0 / 3.0 : 2.0 / 3.0);
    });
    const BinderProfile c = binder_migration(skin, p);
    EXPECT_EQ(c.porosity_frames, 4);
    EXPECT_LT(c.mass_balance, 1e-10);
    double diff = 0.0;
    for (std::size_t i = 0; i < a.binder.size(); ++i)
        diff = std::max(diff, std::abs(c.binder[i] - a.binder[i]));
    EXPECT_GT(diff, 1e-3);
    // Frames after the level reached H_f (or at it) do not count: the pore emptying uses ε_f.
    DryingHistory late = affine;
    late.frames = frames_of(affine, {25.0}, [&](double, double) { return 1.0 - eps; });
    EXPECT_EQ(binder_migration(late, p).porosity_frames, 0);
}
