// SPDX-License-Identifier: MIT
// Steady conduction on voxel images against closed forms (issue 15): straight pores (τ = 1), layered
// media (series 1/σ = Σ f_i/σ_i and parallel σ = Σ f_i σ_i, exact in the finite volumes), a cubic
// array of insulating spheres (Maxwell 1873 / Rayleigh 1892: σ/σ₀ = 2(1 − φ)/(2 + φ), τ = 1 + φ/2),
// percolation (blocked, dead ends, isolated pockets) and the film-level numbers on sphere packings.
#include "drydem/analysis/conduction.hpp"
#include "drydem/analysis/transport.hpp"
#include "drydem/core/error.hpp"
#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <random>

using namespace drydem;
using namespace drydem::analysis;

namespace {

ConductionProblem uniform(int nx, int ny, int nz, float sigma, double a = 1e-6) {
    ConductionProblem p;
    p.nx = nx;
    p.ny = ny;
    p.nz = nz;
    p.ax = p.ay = p.az = a;
    p.sigma.assign(std::size_t(nx) * ny * nz, sigma);
    p.tolerance = 1e-10;
    return p;
}

float& at(ConductionProblem& p, int i, int j, int k) {
    return p.sigma[(std::size_t(k) * p.ny + j) * p.nx + i];
}

double fraction(const ConductionProblem& p) {
    double n = 0;
    for (float s : p.sigma) n += s > 0.0f;
    return n / double(p.sigma.size());
}

} // namespace

TEST(Conduction, HomogeneousBlockHasItsOwnConductivityOnEveryAxis) {
    for (int axis = 0; axis < 3; ++axis) {
        ConductionProblem p = uniform(7, 5, 9, 3.0f);
        p.ax = 0.5e-6; // anisotropic voxels: the face geometry must not matter
        p.az = 2e-6;
        p.axis = axis;
        const ConductionResult r = solve_conduction(p);
        EXPECT_NEAR(r.sigma_eff, 3.0, 1e-8) << axis;
        EXPECT_TRUE(r.percolates);
        EXPECT_TRUE(r.converged);
        EXPECT_LT(r.flux_balance, 1e-8);
    }
}

TEST(Conduction, StraightCylindricalPoresHaveTortuosityOne) {
    // Cylinders of radius 4 voxels along z through solid, periodic in x, y: D_eff = ε D₀, τ = 1.
    ConductionProblem p = uniform(24, 24, 30, 0.0f);
    for (int k = 0; k < p.nz; ++k)
        for (int j = 0; j < p.ny; ++j)
            for (int i = 0; i < p.nx; ++i) {
                const double dx = std::fmod(i + 0.5, 12.0) - 6.0,
                             dy = std::fmod(j + 0.5, 12.0) - 6.0;
                if (dx * dx + dy * dy < 16.0) at(p, i, j, k) = 1.0f;
            }
    const double eps = fraction(p);
    ASSERT_GT(eps, 0.2);
    const ConductionResult r = solve_conduction(p);
    EXPECT_NEAR(tortuosity_factor(eps, r.sigma_eff), 1.0, 1e-8);
    // Across the cylinders (x) the pores do not connect: no path, τ undefined (0).
    p.axis = 0;
    const ConductionResult across = solve_conduction(p);
    EXPECT_FALSE(across.percolates);
    EXPECT_EQ(across.sigma_eff, 0.0);
    EXPECT_EQ(tortuosity_factor(eps, across.sigma_eff), 0.0);
}

TEST(Conduction, LayeredMediumIsSeriesAcrossAndParallelAlongTheLayers) {
    // Layers normal to z: 6 of σ = 1, 4 of σ = 0.1, 5 of σ = 2.5.
    ConductionProblem p = uniform(6, 5, 15, 1.0f);
    const float sig[3] = {1.0f, 0.1f, 2.5f};
    const int thick[3] = {6, 4, 5};
    for (int k = 0, layer = 0, used = 0; k < p.nz; ++k, ++used) {
        if (used == thick[layer]) {
            ++layer;
            used = 0;
        }
        for (int j = 0; j < p.ny; ++j)
            for (int i = 0; i < p.nx; ++i) at(p, i, j, k) = sig[layer];
    }
    double series = 0.0, parallel = 0.0;
    for (int l = 0; l < 3; ++l) {
        series += thick[l] / 15.0 / sig[l];
        parallel += thick[l] / 15.0 * sig[l];
    }
    p.axis = 2;
    const ConductionResult z = solve_conduction(p);
    EXPECT_NEAR(z.sigma_eff, 1.0 / series, 1e-8);
    for (int axis : {0, 1}) {
        p.axis = axis; // along the layers, the substrate-like z sides closed
        const ConductionResult x = solve_conduction(p);
        EXPECT_NEAR(x.sigma_eff, parallel, 1e-8) << axis;
    }
}

TEST(Conduction, RandomTwoPhaseMediumLiesWithinWienerAndHashinShtrikmanBounds) {
    std::mt19937 rng(3);
    std::bernoulli_distribution second(0.35);
    ConductionProblem p = uniform(20, 20, 20, 1.0f);
    for (float& s : p.sigma) s = second(rng) ? 10.0f : 1.0f;
    double f2 = 0;
    for (float s : p.sigma) f2 += s > 5.0f;
    f2 /= double(p.sigma.size());
    const double s1 = 1.0, s2 = 10.0, f1 = 1.0 - f2;
    const double hs_lo = s1 + f2 / (1.0 / (s2 - s1) + f1 / (3.0 * s1));
    const double hs_hi = s2 + f1 / (1.0 / (s1 - s2) + f2 / (3.0 * s2));
    const double wiener_lo = 1.0 / (f1 / s1 + f2 / s2), wiener_hi = f1 * s1 + f2 * s2;
    const ConductionResult r = solve_conduction(p);
    EXPECT_GT(r.sigma_eff, hs_lo);
    EXPECT_LT(r.sigma_eff, hs_hi);
    EXPECT_GT(hs_lo, wiener_lo);
    EXPECT_LT(hs_hi, wiener_hi);
}

TEST(Conduction, MultigridAndJacobiAgreeOnAHighContrastMediumWithInsulatingVoxels) {
    // NCM/CB-like contrast (1e4) with 30 % insulating pores: the two solvers, to a relative
    // residual of 1e-10, give the same σ_eff (the contrast amplifies the residual into the current:
    // both balance their in- and outflow to ~3e-7 here); multigrid needs ~10 iterations whatever
    // the grid size, Jacobi hundreds to thousands (its count grows with the grid).
    for (const int n : {16, 32}) {
        std::mt19937 rng(11);
        std::discrete_distribution<int> phase({0.3, 0.5, 0.2});
        ConductionProblem p = uniform(n, n, n, 1.0f);
        for (float& s : p.sigma)
            s = std::array<float, 3>{0.0f, 1e-2f, 1e2f}[std::size_t(phase(rng))];
        const ConductionResult amg = solve_conduction(p);
        p.preconditioner = Preconditioner::jacobi;
        const ConductionResult jacobi = solve_conduction(p);
        ASSERT_TRUE(amg.converged && jacobi.converged) << n;
        EXPECT_STREQ(amg.preconditioner, "BoomerAMG");
        EXPECT_NEAR(amg.sigma_eff / jacobi.sigma_eff, 1.0, 2e-6) << n;
        EXPECT_LT(amg.flux_balance, 2e-6) << n;
        EXPECT_LE(amg.iterations, 20) << n;
        EXPECT_GT(jacobi.iterations, 20 * amg.iterations) << n;
    }
}

TEST(Conduction, DiluteCubicArrayOfSpheresFollowsMaxwell) {
    // One insulating sphere of radius R voxels centred in a (4R)³ cell, periodic in x, y: the fixed
    // faces lie midway between spheres of the cubic array, where the potential is uniform by
    // symmetry, so this is the array. Maxwell: σ/σ₀ = 2(1 − φ)/(2 + φ) (Rayleigh's correction at
    // φ = 0.065 is ~1e-4); τ of the pore phase = (1 − φ)/(σ/σ₀) = 1 + φ/2. The staircase surface
    // of a voxel sphere adds resistance of order one voxel / R: measured 0.75 % at R = 10, and it
    // must shrink as R grows.
    auto relative_error = [](int R) {
        const int n = 4 * R;
        ConductionProblem p = uniform(n, n, n, 1.0f);
        const double c = 2.0 * R;
        for (int k = 0; k < n; ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const double dx = i + 0.5 - c, dy = j + 0.5 - c, dz = k + 0.5 - c;
                    if (dx * dx + dy * dy + dz * dz < double(R) * R) at(p, i, j, k) = 0.0f;
                }
        const double phi = 1.0 - fraction(p); // the voxelized sphere's volume
        EXPECT_NEAR(phi, std::numbers::pi / 48.0, 5e-3);
        const ConductionResult r = solve_conduction(p);
        const double maxwell = 2.0 * (1.0 - phi) / (2.0 + phi);
        const double tau = tortuosity_factor(1.0 - phi, r.sigma_eff);
        EXPECT_NEAR(tau, 1.0 + phi / 2.0, 0.02) << R;
        return std::abs(r.sigma_eff / maxwell - 1.0);
    };
    const double e5 = relative_error(5), e10 = relative_error(10);
    EXPECT_LT(e10, 0.01);
    EXPECT_LT(e10, 0.75 * e5);
}

TEST(Conduction, DeadEndsAndIsolatedPocketsCarryNoCurrentButCountInThePorosity) {
    // One straight channel (1 x 1 voxels) along z, a dead-end branch off it and an isolated pocket.
    ConductionProblem p = uniform(9, 9, 10, 0.0f);
    for (int k = 0; k < 10; ++k) at(p, 2, 2, k) = 1.0f;
    for (int i = 3; i < 7; ++i) at(p, i, 2, 5) = 1.0f; // dead end
    at(p, 7, 7, 3) = at(p, 7, 7, 4) = 1.0f;            // isolated
    const ConductionResult r = solve_conduction(p);
    const double cell = 81.0;
    EXPECT_NEAR(r.sigma_eff, 1.0 / cell, 1e-10); // the channel alone
    EXPECT_NEAR(r.percolating_fraction, (10.0 + 4.0) / 810.0, 1e-12);
    EXPECT_NEAR(r.conducting_fraction, 16.0 / 810.0, 1e-12);
    EXPECT_NEAR(tortuosity_factor(r.conducting_fraction, r.sigma_eff), 16.0 / 10.0, 1e-8);
}

TEST(Conduction, BlockedByOneInsulatingLayer) {
    ConductionProblem p = uniform(5, 5, 8, 1.0f);
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) at(p, i, j, 4) = 0.0f;
    const ConductionResult r = solve_conduction(p);
    EXPECT_FALSE(r.percolates);
    EXPECT_EQ(r.sigma_eff, 0.0);
    EXPECT_EQ(r.unknowns, 0u);
}

TEST(Conduction, TwoVoxelPeriodicSideCountsBothFaces) {
    // nx = 2 periodic: each voxel meets the other through two faces; a uniform block stays uniform.
    ConductionProblem p = uniform(2, 1, 6, 1.0f);
    p.axis = 2;
    EXPECT_NEAR(solve_conduction(p).sigma_eff, 1.0, 1e-10);
    // Alternating columns of 1 and 4 along z: parallel, 2.5.
    for (int k = 0; k < 6; ++k) at(p, 1, 0, k) = 4.0f;
    EXPECT_NEAR(solve_conduction(p).sigma_eff, 2.5, 1e-10);
}

TEST(Conduction, RefusesNegativeConductivity) {
    ConductionProblem p = uniform(2, 2, 2, 1.0f);
    p.sigma[3] = -1.0f;
    EXPECT_THROW((void)solve_conduction(p), InputError);
}

TEST(Transport, BruggemanExponentInvertsTheLaw) {
    EXPECT_NEAR(bruggeman_exponent(0.4, std::pow(0.4, -0.5)), 1.5, 1e-12);
    EXPECT_NEAR(bruggeman_exponent(0.3, 1.0), 1.0, 1e-12);
    EXPECT_TRUE(std::isnan(bruggeman_exponent(1.0, 1.0)));
    EXPECT_TRUE(std::isnan(bruggeman_exponent(0.4, 0.0)));
}

/// A 4 x 4 um box: one column of overlapping CB spheres (r = 0.75 um, spacing 1.2 um, necks of
/// radius 0.45 um; the lowest cut by the substrate) at (1, 1) um up to above 6 um, and one NCM
/// sphere (r = 1 um) at (3, 3, 2) um beside it.
Structure cb_column_beside_ncm() {
    Structure s;
    s.box.lx = s.box.ly = 4e-6;
    for (int m = 0; m < 6; ++m) s.add({1e-6, 1e-6, 0.3e-6 + 1.2e-6 * m}, 0.75e-6, Phase::cb);
    s.add({3e-6, 3e-6, 2e-6}, 1.0e-6, Phase::ncm, 4740.0);
    return s;
}

TEST(Transport, ColumnOfCbSpheresPercolatesAndFilmPoresAreConnected) {
    // A 4 x 4 um box: one column of overlapping CB spheres (r = 0.75 um, spacing 1.2 um, necks of
    // radius 0.45 um; the lowest cut by the substrate) from the substrate to above the top, and one
    // NCM sphere beside it. The CB column percolates; the pores are open.
    const Structure s = cb_column_beside_ncm();
    TransportOptions o;
    o.voxels = {0.4e-6, 0.2e-6};
    o.sigma_cb = 100.0;
    o.sigma_ncm = 0.0;
    o.walkers = 0; // the random walks have their own tests
    const Transport t = film_transport(s, 6e-6, o);
    ASSERT_EQ(t.levels.size(), 2u);
    const TransportLevel& L = t.reported();
    EXPECT_EQ(L.nz, 30);
    EXPECT_TRUE(L.cb_z.percolates);
    EXPECT_TRUE(L.electronic_z.percolates);
    // The CB column alone carries the current: σ_eff = σ_CB × (harmonic mean of the column's
    // cross-section / box area), between the neck's π 0.45² and the widest π 0.75² um².
    EXPECT_GT(L.cb_z.sigma_eff, 100.0 * std::numbers::pi * 0.2025e-12 / 16e-12);
    EXPECT_LT(L.cb_z.sigma_eff, 100.0 * std::numbers::pi * 0.5625e-12 / 16e-12);
    EXPECT_NEAR(L.electronic_z.sigma_eff, L.cb_z.sigma_eff, 1e-9 * L.cb_z.sigma_eff); // σ_NCM = 0
    EXPECT_GT(L.porosity, 0.8);
    EXPECT_GE(L.tau_z, 1.0);
    EXPECT_LT(L.tau_z, 1.25);
    EXPECT_GE(L.tau_x, 1.0);
    EXPECT_LT(L.tau_x, 1.25);
    // One CB sphere on the substrate alone: no CB path to the top.
    Structure lone;
    lone.box = s.box;
    lone.add({1e-6, 1e-6, 0.75e-6}, 0.75e-6, Phase::cb);
    const Transport u = film_transport(lone, 6e-6, o);
    EXPECT_FALSE(u.reported().cb_z.percolates);
    EXPECT_EQ(u.reported().cb_z.sigma_eff, 0.0);
}

TEST(RandomWalk, FreeSpaceDiffusesAtD0AndChannelsOnlyAlongTheirAxis) {
    ConductionProblem free = uniform(16, 16, 16, 1.0f);
    free.periodic = {true, true, true};
    const RandomWalkResult f = random_walk(free, 4000, 4000);
    for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(f.diffusivity[std::size_t(d)], 1.0, 4.0 * f.standard_error[std::size_t(d)]);
    EXPECT_LT(f.standard_error[0], 0.04);
    // Straight channels of radius 4 voxels along z (periodic z): every z step is taken, D_z = D₀;
    // across, the walkers stay in their channel: ⟨Δx²⟩ bounded by the channel, D_x → 0.
    ConductionProblem p = uniform(24, 24, 12, 0.0f);
    p.periodic = {true, true, true};
    for (int k = 0; k < p.nz; ++k)
        for (int j = 0; j < p.ny; ++j)
            for (int i = 0; i < p.nx; ++i) {
                const double dx = std::fmod(i + 0.5, 12.0) - 6.0,
                             dy = std::fmod(j + 0.5, 12.0) - 6.0;
                if (dx * dx + dy * dy < 16.0) at(p, i, j, k) = 1.0f;
            }
    const RandomWalkResult c = random_walk(p, 4000, 6000);
    EXPECT_NEAR(c.diffusivity[2], 1.0, 4.0 * c.standard_error[2]);
    EXPECT_LT(c.diffusivity[0], 0.02); // ⟨Δx²⟩ ≤ (2·4)² = 64 voxels² against 2000 free
}

TEST(RandomWalk, AgreesWithTheConductionSolveOnARandomPoreSpace) {
    // Site-random pores (p = 0.7, above the percolation threshold 0.31), 32³: τ_x of the solve
    // (fixed faces in x) and of the walks (periodic) agree within the walkers' error and a boundary
    // effect of order one voxel / 32.
    std::mt19937 rng(11);
    std::bernoulli_distribution pore(0.7);
    ConductionProblem p = uniform(32, 32, 32, 0.0f);
    for (float& s : p.sigma) s = pore(rng) ? 1.0f : 0.0f;
    p.periodic = {true, true, true};
    p.axis = 0;
    const double eps = fraction(p);
    const double tau_solve = tortuosity_factor(eps, solve_conduction(p).sigma_eff);
    const RandomWalkResult w = random_walk(p, 8000, 8000);
    const double tau_walk = 1.0 / w.diffusivity[0];
    const double err = w.standard_error[0] / (w.diffusivity[0] * w.diffusivity[0]);
    EXPECT_GT(tau_solve, 1.3); // a real detour, not the trivial case
    EXPECT_NEAR(tau_walk / tau_solve, 1.0, 0.03 + 3.0 * err / tau_solve)
        << tau_walk << " " << tau_solve;
}

TEST(Transport, ExtrapolationToZeroVoxelRecoversAPowerLaw) {
    // v(h) = 1.5 + 0.8 h^p at h = 0.8, 0.4, 0.2: the limit and the order come back.
    for (const double p : {1.0, 2.0}) {
        const std::vector<double> h{0.8, 0.4, 0.2};
        std::vector<double> v;
        for (double x : h) v.push_back(1.5 + 0.8 * std::pow(x, p));
        const Extrapolation e = extrapolate_to_zero_voxel(h, v);
        EXPECT_TRUE(e.order_observed);
        EXPECT_NEAR(e.order, p, 1e-12);
        EXPECT_NEAR(e.value, 1.5, 1e-12);
    }
    // Two levels (the order is unknown), non-monotone changes or unequal ratios give no value.
    EXPECT_TRUE(std::isnan(extrapolate_to_zero_voxel({0.4, 0.2}, {1.9, 1.7}).value));
    EXPECT_TRUE(std::isnan(extrapolate_to_zero_voxel({0.8, 0.4, 0.2}, {1.0, 1.2, 1.1}).value));
    EXPECT_TRUE(std::isnan(extrapolate_to_zero_voxel({0.9, 0.4, 0.2}, {2.0, 1.8, 1.7}).value));
    EXPECT_TRUE(std::isnan(extrapolate_to_zero_voxel({0.4}, {1.0}).value));
}

TEST(Transport, WindowCarriesTheSameCurrentThroughItsSmallerArea) {
    // The CB column of the test above lies inside a 2.4 um window at the origin, the NCM sphere
    // outside it. Insulating NCM: the column's current is the same in the window (closed sides)
    // and in the periodic box, so σ_eff scales with the areas, 16 / 5.76 um².
    const Structure s = cb_column_beside_ncm();
    TransportOptions o;
    o.voxels = {0.3e-6, 0.2e-6}; // the window spans 8 voxels of the coarser
    o.sigma_cb = 100.0;
    o.sigma_ncm = 0.0;
    o.walkers = 1000; // none in a window: its sides are walls
    o.walk_steps = 100;
    o.tolerance = 1e-10;
    const Transport full = film_transport(s, 6e-6, o);
    o.window = 2.4e-6;
    const Transport win = film_transport(s, 6e-6, o);
    EXPECT_EQ(full.window, 0.0);
    EXPECT_NEAR(win.window, 2.4e-6, 1e-15);
    const TransportLevel &F = full.reported(), &W = win.reported();
    EXPECT_EQ(W.nx, 12);
    EXPECT_EQ(W.ny, 12);
    EXPECT_EQ(W.nz, F.nz);
    EXPECT_NEAR(W.cb_z.sigma_eff, F.cb_z.sigma_eff * 16.0 / 5.76, 1e-6 * F.cb_z.sigma_eff);
    EXPECT_EQ(W.walk.diffusivity[0], 0.0);
    EXPECT_GT(F.walk.diffusivity[0], 0.0);
    EXPECT_GT(W.pore_z.sigma_eff, 0.0);
    // A window wider than the box, or narrower than 8 voxels, is refused with the key's name.
    for (const double bad : {4.5e-6, 2.0e-6}) {
        o.window = bad;
        try {
            (void)film_transport(s, 6e-6, o);
            ADD_FAILURE() << "no error for a window of " << bad;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("analysis.transport_window"), std::string::npos)
                << e.what();
        }
    }
}
