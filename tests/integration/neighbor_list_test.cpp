// SPDX-License-Identifier: MIT
// Neighbor search (model.md M-9.4, M-2.5) against an O(N²) minimum-image brute force, for the
// paper's 1:7.6 size ratio (CB r = 0.75 µm, NCM r = 3.25 ... 5.675 µm) in a 40 × 40 µm periodic
// box with the drying force field's ranges (lubrication r_L, van der Waals cut-off r_L), and the
// determinism of the engine (M-9.1: fixed summation order for a fixed thread count).
#include "drydem/drying/law_parameters.hpp"
#include "drydem/drying/scaling.hpp"
#include "drydem/core/rng.hpp"
#include "drydem/engine/simulation.hpp"
#include "drydem/engine/peer_bed.hpp"
#include "drydem/setup/insertion.hpp"
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <utility>

using namespace drydem;

namespace {
constexpr double kL = 40e-6;

Config small_box_config() {
    Config c;
    c.box_x = c.box_y = kL;
    return c;
}

/// The drying force field (all models; species 0-4 = NCM classes, 5 = CB) for a 40 µm box.
ForceField drying_field() {
    const Config c = small_box_config();
    return make_drying_force_field(c, make_recipe(c), scale_parameters(c));
}

/// Random sequential addition (C-2): 12 NCM of all five classes and 1200 CB in 40 × 40 × 30 µm.
ParticleStore polydisperse_gas(std::uint64_t seed) {
    FilmRecipe recipe = make_recipe(small_box_config());
    const int ncm_counts[5] = {3, 3, 2, 2, 2};
    for (int c = 0; c < 5; ++c) recipe.species[c].count = ncm_counts[c];
    recipe.species[5].count = 1200;
    return insert_particles(recipe, Box{kL, kL}, 30e-6, seed);
}

using IdPair = std::pair<std::uint32_t, std::uint32_t>; // (owner id, partner id)

/// Every pair with centre distance below r_i + r_j + range_ij + extra, by brute force.
std::set<IdPair> brute_force_pairs(const Simulation& sim, double extra, int* across_boundary) {
    const ParticleStore& p = sim.particles();
    std::set<IdPair> out;
    *across_boundary = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = i + 1; j < p.size(); ++j) {
            const PairParams& pp = sim.forces().pair_params(p.species[i], p.species[j]);
            const double cut =
                p.radius[i] + p.radius[j] + interaction_range(pp, p.radius[i], p.radius[j]) + extra;
            const Vec3 d = sim.box().minimum_image(p.position[i], p.position[j]);
            if (norm2(d) >= cut * cut) continue;
            const bool i_owns = NeighborList::owns(p.radius[i], p.id[i], p.radius[j], p.id[j]);
            out.insert(i_owns ? IdPair{p.id[i], p.id[j]} : IdPair{p.id[j], p.id[i]});
            if (norm2(d - (p.position[j] - p.position[i])) > 0) ++*across_boundary;
        }
    return out;
}

/// The list's pairs as (owner id, partner id); fails on duplicates and on wrong ownership.
std::set<IdPair> listed_pairs(const Simulation& sim) {
    const ParticleStore& p = sim.particles();
    const NeighborList& nl = sim.neighbors();
    std::set<IdPair> out;
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::uint32_t s = nl.begin(i); s < nl.end(i); ++s) {
            const std::uint32_t j = nl.partner(s);
            EXPECT_TRUE(NeighborList::owns(p.radius[i], p.id[i], p.radius[j], p.id[j]));
            EXPECT_TRUE(out.insert({p.id[i], p.id[j]}).second)
                << "duplicate " << p.id[i] << "-" << p.id[j];
            // Never both orientations (each pair exactly once).
            EXPECT_EQ(out.count({p.id[j], p.id[i]}), 0u);
        }
    return out;
}
} // namespace

// M-9.4: the list holds exactly the pairs within r_i + r_j + range_ij + skin, each once, owned by
// the larger particle, including pairs across the periodic edges and the wide NCM stencils; after
// a run it still covers every pair within range (skin criterion), and a forced rebuild after
// re-sorting is exact again.
TEST(NeighborList, MatchesBruteForcePolydispersePeriodic) {
    Simulation sim(polydisperse_gas(2024), Box{kL, kL}, drying_field(), {1e-11, 0.1e-6, 1, 1});
    ASSERT_EQ(sim.particles().size(), 1212u);
    int across = 0;
    const std::set<IdPair> expected = brute_force_pairs(sim, sim.neighbors().skin(), &across);
    EXPECT_GT(across, 50); // many pairs straddle the periodic edges
    int ncm_pairs = 0;
    for (const IdPair& q : expected) ncm_pairs += (q.first <= 12) + (q.second <= 12);
    EXPECT_GT(ncm_pairs, 100); // NCM ids are 1..12 (inserted first): wide stencils exercised
    EXPECT_EQ(listed_pairs(sim), expected);
    EXPECT_EQ(sim.neighbors().pairs(), expected.size());

    sim.run(300);
    int unused = 0;
    const std::set<IdPair> in_range = brute_force_pairs(sim, 0.0, &unused);
    const std::set<IdPair> listed = listed_pairs(sim);
    EXPECT_TRUE(std::includes(listed.begin(), listed.end(), in_range.begin(), in_range.end()));
    sim.invalidate_neighbors();
    sim.compute_forces(); // rebuild (and re-sort) now
    EXPECT_EQ(listed_pairs(sim), brute_force_pairs(sim, sim.neighbors().skin(), &unused));
}

// M-9.1: identical input and thread count give bitwise identical trajectories; 1 and 2 threads
// differ only by the summation order (round-off).
TEST(NeighborList, DeterministicTrajectories) {
    const ParticleStore gas = polydisperse_gas(7);
    Simulation a(gas, Box{kL, kL}, drying_field(), {1e-11, 0.1e-6, 2, 1});
    Simulation b(gas, Box{kL, kL}, drying_field(), {1e-11, 0.1e-6, 2, 1});
    Simulation one(gas, Box{kL, kL}, drying_field(), {1e-11, 0.1e-6, 1, 1});
    ASSERT_EQ(a.threads(), 2);
    for (int s = 0; s < 300; ++s) {
        if (s % 100 == 50) // rebuilds (with re-sorting) inside the compared window
            for (Simulation* sim : {&a, &b, &one}) sim->invalidate_neighbors();
        a.step();
        b.step();
        one.step();
    }
    const ParticleStore &pa = a.particles(), &pb = b.particles(), &p1 = one.particles();
    ASSERT_EQ(pa.id, pb.id);
    ASSERT_EQ(pa.id, p1.id);
    double v_max = 0, dv = 0, dx = 0;
    std::size_t bit_diffs = 0;
    for (std::size_t i = 0; i < pa.size(); ++i) {
        bit_diffs += pa.position[i].x != pb.position[i].x || pa.position[i].y != pb.position[i].y ||
                     pa.position[i].z != pb.position[i].z || pa.velocity[i].x != pb.velocity[i].x ||
                     pa.velocity[i].y != pb.velocity[i].y || pa.velocity[i].z != pb.velocity[i].z;
        v_max = std::max(v_max, norm(pa.velocity[i]));
        dv = std::max(dv, norm(pa.velocity[i] - p1.velocity[i]));
        dx = std::max(dx, norm(a.box().minimum_image(pa.position[i], p1.position[i])));
    }
    EXPECT_EQ(bit_diffs, 0u);
    EXPECT_GT(v_max, 1e-3); // the particles did move (van der Waals, gravity)
    EXPECT_LT(dv, 1e-9 * v_max);
    const double travel = v_max * 300 * 1e-11;
    EXPECT_LT(dx, 1e-9 * travel);
}

namespace {
/// The peers' settled bed in the 30 µm box (tests/data/peers), as `drydem bench` sets it up:
/// Hertz-Mindlin with history, gravity, Stokes drag, particles and substrate.
Simulation settled_bed(Integrator integrator, bool near_list) {
    PeerBed bed = read_peer_bed(std::filesystem::path(DRYDEM_SOURCE_DIR) / "tests" / "data" /
                                "peers" / "settled_30um.data");
    EngineSettings es;
    es.dt = 2e-10;
    es.skin = 0.3e-6;
    es.threads = 2;
    es.integrator = integrator;
    es.near_list = near_list;
    return Simulation(std::move(bed.particles), bed.box, bed.forces, es);
}
} // namespace

// M-9.4, near_list.hpp: walking the near list adds the same forces in the same order as walking
// the whole neighbour list, so the trajectories agree to the bit, while the near list is built
// again as the particles move, switched off when they move fast (random kicks of 20 m/s) and on
// again when they have settled; explicit and semi-implicit (self-blocks) pair loops.
TEST(NearList, SameTrajectoryAsTheWholeList) {
    for (const Integrator integrator : {Integrator::explicit_verlet, Integrator::semi_implicit}) {
        Simulation near = settled_bed(integrator, true), whole = settled_bed(integrator, false);
        Rng rng(11);
        bool seen_on = false, seen_off = false;
        for (int s = 0; s < 1000; ++s) {
            if (s % 300 == 150) {
                for (std::size_t i = 0; i < near.particles().size(); ++i) {
                    const Vec3 kick{rng.uniform(-20, 20), rng.uniform(-20, 20),
                                    rng.uniform(-20, 20)};
                    near.particles_mut().velocity[i] += kick;
                    whole.particles_mut().velocity[i] += kick;
                }
            }
            near.step();
            whole.step();
            seen_on = seen_on || near.near_pairs().on();
            seen_off = seen_off || !near.near_pairs().on();
            EXPECT_FALSE(whole.near_pairs().on());
        }
        EXPECT_TRUE(seen_on);
        EXPECT_TRUE(seen_off);
        EXPECT_GE(near.near_pairs().builds(), 5u);
        EXPECT_LT(near.near_pairs().pairs(), near.neighbors().pairs());
        const ParticleStore &a = near.particles(), &b = whole.particles();
        ASSERT_EQ(a.id, b.id);
        std::size_t bit_diffs = 0;
        for (std::size_t i = 0; i < a.size(); ++i)
            bit_diffs += a.position[i].x != b.position[i].x || a.position[i].y != b.position[i].y ||
                         a.position[i].z != b.position[i].z || a.velocity[i].x != b.velocity[i].x ||
                         a.velocity[i].y != b.velocity[i].y || a.velocity[i].z != b.velocity[i].z ||
                         a.omega[i].x != b.omega[i].x || a.omega[i].z != b.omega[i].z;
        EXPECT_EQ(bit_diffs, 0u) << "integrator " << int(integrator);
        EXPECT_GT(near.stats().contacts, 1000u);
    }
}
