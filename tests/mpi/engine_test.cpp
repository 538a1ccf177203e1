// SPDX-License-Identifier: MIT
// The engine on a domain decomposition (docs/parallel.md) against the same film on one rank:
// every rank runs the one-rank reference itself (same seed, same particles), then the decomposed
// engine, and compares the particles it owns by id. Every drying law is on (contact histories,
// lubrication, capillary front, van der Waals, substrate), the skin is small so that lists are
// rebuilt and particles change rank every few steps. The two runs sum forces in different orders,
// so they agree to round-off growth, not bit for bit.
#include "drydem/analysis/overlap_census.hpp"
#include "drydem/drying/derived_checks.hpp"
#include "drydem/drying/film_measures.hpp"
#include "drydem/drying/law_parameters.hpp"
#include "drydem/drying/liquid_level.hpp"
#include "drydem/drying/scaling.hpp"
#include "drydem/engine/simulation.hpp"
#include "drydem/parallel/mpi_world.hpp"
#include "drydem/setup/formulation.hpp"
#include "drydem/setup/insertion.hpp"
#include <gtest/gtest.h>
#include "thin_film_case.hpp"
#include <algorithm>
#include <cmath>
#include <array>
#include <random>
#include <string>
#include <unordered_map>

using namespace drydem;

namespace {

using test::Case;
using test::thin_film;

/// The decompositions the tests run: cut in x and y only, and in layers along z only.
constexpr std::array<int, 3> kColumns{0, 0, 1}, kLayers{1, 1, 0};

EngineSettings film_settings(const Case& k, Integrator integrator, int ranks,
                             std::array<int, 3> grid = {0, 0, 0}) {
    EngineSettings es;
    es.grid = grid;
    es.integrator = integrator;
    es.dt = 8e-12;
    es.skin = 0.01e-6; // a rebuild (and migration) every few steps
    es.threads = 1;
    es.ranks = ranks;
    es.initial_liquid_level = k.schedule.level(0.0);
    return es;
}

void sweep_level(const Case& k, Simulation& sim) {
    // The level sweeps ~100x faster than the case's, so it reaches particles within the run.
    const LiquidLevelSchedule level = k.schedule;
    sim.set_liquid_level_schedule([level](double t) { return level.level(1e2 * t); });
}

Simulation make(const Case& k, Integrator integrator, int ranks,
                std::array<int, 3> grid = {0, 0, 0}) {
    ParticleStore p =
        insert_particles(k.recipe, Box{k.c.box_x, k.c.box_y}, k.recipe.wet_film_height, 5);
    Simulation sim(std::move(p), Box{k.c.box_x, k.c.box_y},
                   make_drying_force_field(k.c, k.recipe, k.scaled),
                   film_settings(k, integrator, ranks, grid));
    sweep_level(k, sim);
    return sim;
}

/// The film continued from a state.
Simulation resume(const Case& k, const EngineState& st, Integrator integrator, int ranks) {
    Simulation sim(st, Box{k.c.box_x, k.c.box_y}, make_drying_force_field(k.c, k.recipe, k.scaled),
                   film_settings(k, integrator, ranks));
    sweep_level(k, sim);
    return sim;
}

/// A frictional granular gas in the same cell: Hertz-Mindlin contacts with tangential springs,
/// gravity, no drag; spheres of 1.5 and 0.75 um on a jittered lattice at ~4 m/s, so that many
/// collide and many cross subdomain faces within the run.
ForceField gas_forces() {
    ForceField ff = uniform_contact_force_field(2, 1e10, 0.3, 0.5, 0.8);
    ff.set_body_law<GravityBuoyancyLaw>({9.81e6, 0.0});
    return ff;
}

EngineSettings gas_settings(Integrator integrator, int ranks, std::array<int, 3> grid) {
    EngineSettings es;
    es.grid = grid;
    es.integrator = integrator;
    es.dt = 2e-10;
    es.skin = 0.1e-6;
    es.threads = 1;
    es.ranks = ranks;
    return es;
}

const Box gas_box{36e-6, 36e-6};

Simulation gas(Integrator integrator, int ranks, std::array<int, 3> grid = {0, 0, 0}) {
    ParticleStore p;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uint32_t id = 0;
    for (int iz = 0; iz < 8; ++iz)
        for (int iy = 0; iy < 6; ++iy)
            for (int ix = 0; ix < 6; ++ix) {
                const bool large = (ix + iy + iz) % 2 == 0;
                const Vec3 x{(ix + 0.25) * 6e-6 + 0.5e-6 * u(rng),
                             (iy + 0.25) * 6e-6 + 0.5e-6 * u(rng), 2e-6 + iz * 3.75e-6};
                p.add(id++, large ? 0 : 1, large ? 1.5e-6 : 0.75e-6, 2000.0, x);
                p.velocity.back() = {4.0 * u(rng), 4.0 * u(rng), 4.0 * u(rng)};
            }
    return Simulation(std::move(p), gas_box, gas_forces(), gas_settings(integrator, ranks, grid));
}

/// Runs both for `steps` and compares what this rank owns with the one-rank run.
void compare(Simulation& one, Simulation& many, int steps, bool expect_migration) {
    for (int s = 0; s < steps; ++s) {
        one.step();
        many.step();
        // Global after the reductions, the same on every rank: an ASSERT leaves all together.
        ASSERT_EQ(many.stats().contacts, one.stats().contacts) << "step " << s;
        ASSERT_EQ(many.stats().wall_contacts, one.stats().wall_contacts) << "step " << s;
    }
    const ParticleStore& a = one.particles();
    const ParticleStore& b = many.particles();
    const Box box = one.box();
    std::unordered_map<std::uint32_t, std::size_t> at;
    for (std::size_t i = 0; i < a.size(); ++i) at[a.id[i]] = i;
    double worst = 0.0, worst_v = 0.0, v_scale = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) v_scale = std::max(v_scale, norm(a.velocity[i]));
    for (std::size_t i = 0; i < many.owned(); ++i) {
        const auto it = at.find(b.id[i]);
        ASSERT_NE(it, at.end());
        const std::size_t j = it->second;
        worst =
            std::max(worst, norm(box.minimum_image(a.position[j], b.position[i])) / a.radius[j]);
        worst_v = std::max(worst_v, norm(a.velocity[j] - b.velocity[i]));
    }
    EXPECT_LT(worst, 1e-9) << "largest position difference / radius";
    EXPECT_LE(worst_v, 1e-6 * v_scale) << "largest velocity difference";
    // Every particle is owned by exactly one rank, and the reductions see them all.
    const std::uint64_t total =
        many.halo() ? many.halo()->all_sum(std::uint64_t(many.owned())) : many.owned();
    EXPECT_EQ(total, a.size());
    EXPECT_NEAR(many.kinetic_energy(), one.kinetic_energy(), 1e-6 * one.kinetic_energy());
    EXPECT_NEAR(many.stats().layer_top, one.stats().layer_top, 1e-9 * one.stats().layer_top);
    EXPECT_GT(one.neighbors().builds(), 5u);
    if (many.halo() && expect_migration) {
        EXPECT_GT(many.halo()->all_sum(many.halo()->counters().migrated), 0u)
            << "no particle changed rank";
    }
    // The guard's estimate sees the same film (a power iteration from another start vector).
    const auto e1 = one.stability_estimate(), e2 = many.stability_estimate();
    EXPECT_NEAR(e2.stiffness_rate, e1.stiffness_rate, 0.05 * e1.stiffness_rate);
    EXPECT_NEAR(e2.damping_rate, e1.damping_rate, 0.05 * e1.damping_rate);
}

/// The grid a decomposed engine runs, as "px x py x pz".
std::string grid_of(const Simulation& sim) {
    if (!sim.halo()) return "1 x 1 x 1";
    const parallel::Decomposition& d = sim.halo()->decomposition();
    return std::to_string(d.px) + " x " + std::to_string(d.py) + " x " + std::to_string(d.pz);
}

/// On one rank both grids are the undivided cell; on several, columns cut x or y and never z,
/// layers cut z only.
void expect_grid(const Simulation& sim, std::array<int, 3> grid) {
    if (!sim.halo()) return;
    const parallel::Decomposition& d = sim.halo()->decomposition();
    if (grid == kColumns) {
        EXPECT_EQ(d.pz, 1) << grid_of(sim);
    } else {
        EXPECT_EQ(d.px * d.py, 1) << grid_of(sim);
    }
}

void compare_film(Integrator integrator, int steps) {
    const Case k = thin_film();
    for (const auto grid : {kColumns, kLayers}) {
        Simulation one = make(k, integrator, 1);
        Simulation many = make(k, integrator, parallel::world().size, grid);
        expect_grid(many, grid);
        SCOPED_TRACE(grid_of(many));
        compare(one, many, steps, false);
    }
}

void compare_gas(Integrator integrator, int steps) {
    for (const auto grid : {kColumns, kLayers}) {
        Simulation one = gas(integrator, 1);
        Simulation many = gas(integrator, parallel::world().size, grid);
        ASSERT_EQ(one.particles().size(), 288u);
        expect_grid(many, grid);
        SCOPED_TRACE(grid_of(many));
        compare(one, many, steps, true);
    }
}

} // namespace

TEST(DecomposedEngine, DryingFilmExplicitMatchesOneRank) {
    compare_film(Integrator::explicit_verlet, 600);
}

TEST(DecomposedEngine, DryingFilmSemiImplicitMatchesOneRank) {
    compare_film(Integrator::semi_implicit, 600);
}

TEST(DecomposedEngine, GranularGasExplicitMatchesOneRank) {
    compare_gas(Integrator::explicit_verlet, 3000);
}

TEST(DecomposedEngine, GranularGasSemiImplicitMatchesOneRank) {
    compare_gas(Integrator::semi_implicit, 3000);
}

TEST(DecomposedEngine, RefusesWhatDoesNotRunOnSeveralRanksYet) {
    if (parallel::world().size < 2) GTEST_SKIP() << "one rank";
    const Case k = thin_film();
    EXPECT_THROW((void)make(k, Integrator::quasi_static, parallel::world().size), InputError);
}

/// Largest position difference (over the radius) of what `sim` owns against `whole` (by id).
double worst_position(const Simulation& sim, const ParticleStore& whole) {
    std::unordered_map<std::uint32_t, std::size_t> at;
    for (std::size_t i = 0; i < whole.size(); ++i) at[whole.id[i]] = i;
    double worst = 0.0;
    const ParticleStore& p = sim.particles();
    for (std::size_t i = 0; i < sim.owned(); ++i) {
        const std::size_t j = at.at(p.id[i]);
        worst = std::max(worst, norm(sim.box().minimum_image(whole.position[j], p.position[i])) /
                                    whole.radius[j]);
    }
    return worst;
}

// A checkpoint of a decomposed engine (its gathered state) continues on the same rank count and
// on one rank where the uninterrupted run goes: positions to round-off (the resumed ranks hold
// their particles in another order). The drying film's contacts last and keep tangential springs
// and the substrate's in their states: a continuation that lost them drifts by far more.
TEST(DecomposedEngine, GatheredStateResumesOnAnyRankCount) {
    const int ranks = parallel::world().size;
    const Case k = thin_film();
    for (const Integrator integrator : {Integrator::explicit_verlet, Integrator::semi_implicit}) {
        Simulation many = make(k, integrator, ranks);
        many.run(300);
        const EngineState st = many.state();
        const std::size_t n = st.particles.size();
        ASSERT_GT(n, 100u);
        if (ranks > 1) { // gathered in id order (one rank: its own storage order)
            for (std::size_t i = 1; i < n; ++i)
                ASSERT_LT(st.particles.id[i - 1], st.particles.id[i]);
        }
        ASSERT_EQ(st.neighbors.offset.size(), n + 1);
        EXPECT_EQ(st.neighbors.partner.size(), st.neighbors.pair_state.size());
        EXPECT_EQ(st.step, 300);
        EXPECT_EQ(st.accel.size(), integrator == Integrator::semi_implicit ? n : 0u);
        Simulation again = resume(k, st, integrator, ranks);
        Simulation alone = resume(k, st, integrator, 1);
        for (int s = 0; s < 300; ++s) {
            many.step();
            again.step();
            alone.step();
            ASSERT_EQ(again.stats().contacts, many.stats().contacts) << "step " << s;
        }
        const ParticleStore whole = many.whole_particles();
        EXPECT_LT(worst_position(again, whole), 1e-9) << "resumed on " << ranks << " ranks";
        EXPECT_LT(worst_position(alone, whole), 1e-9) << "resumed on one rank";
        EXPECT_EQ(again.step_count(), 600);
    }
}

// The time series' overlap percentile on several ranks (each rank's own pairs, gathered) is the
// census's of the whole film (a pair search over the gathered particles), the same pairs counted
// once.
TEST(DecomposedEngine, GatheredOverlapsAreTheCensus) {
    const Case k = thin_film();
    Simulation many = make(k, Integrator::semi_implicit, parallel::world().size);
    many.run(600);
    std::vector<double> rel = many.halo() ? many.halo()->gather_items(many.relative_overlaps())
                                          : many.relative_overlaps();
    const ParticleStore whole = many.whole_particles();
    const analysis::OverlapCensus census =
        analysis::overlap_census(as_structure(whole, many.box(), k.recipe.cb_species()));
    ASSERT_GT(census.all.pairs, 50u);
    EXPECT_EQ(rel.size(), census.all.pairs);
    const analysis::OverlapStats gathered = analysis::summarise(rel);
    EXPECT_NEAR(gathered.p99, census.all.p99, 1e-12);
    EXPECT_NEAR(gathered.max, census.all.max, 1e-12);
}
