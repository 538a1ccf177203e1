// SPDX-License-Identifier: MIT
// Particles taking leave of the packing (Simulation::remove_particles, the calendering's extruded
// agglomerates, model.md M-2.13): the others keep their order, their contact histories and their
// bonds, and move on exactly as if the particle had been carried far away; its own bonds and pair
// states go with it.
#include "drydem/core/error.hpp"
#include "drydem/engine/simulation.hpp"
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>

using namespace drydem;

namespace {
constexpr double kR = 0.5e-6, kRho = 1900, kL = 20e-6, kSpacing = 0.99e-6;
constexpr std::uint32_t kLeaving = 14; // the lattice's centre: contacts all round

std::size_t index_of(const Simulation& sim, std::uint32_t id) {
    const auto& ids = sim.particles().id;
    return std::size_t(std::find(ids.begin(), ids.end(), id) - ids.begin());
}

/// A 3 × 3 × 3 lattice of spheres pressed 1 % into each other, jiggling; the edges bonded except
/// those of the centre particle, which only touches its neighbours. 300 steps build up the
/// contacts' tangential springs.
Simulation lattice() {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    ParticleStore p;
    for (int k = 0; k < 27; ++k) {
        const Vec3 x{5e-6 + (k % 3) * kSpacing, 5e-6 + (k / 3 % 3) * kSpacing,
                     5e-6 + (k / 9) * kSpacing};
        p.add(std::uint32_t(k + 1), 0, kR, kRho, x);
        p.velocity.back() = 1e-2 * Vec3{u(rng), u(rng), u(rng)};
        p.omega.back() = 1e4 * Vec3{u(rng), u(rng), u(rng)};
    }
    ForceField ff = uniform_contact_force_field(1, 2e9, 0.3, 0.5, 0.5);
    ff.remove_substrate();
    Simulation sim(std::move(p), Box{kL, kL}, ff, {2e-10, 0.1e-6, 1});
    BondNetwork net;
    net.species_count = 1;
    net.params = {SolidBondParams{2e9, 0.8e9, 0.5, 1e9, 1e9, 0.2}};
    const ParticleStore& q = sim.particles();
    for (std::uint32_t a = 0; a < q.size(); ++a)
        for (std::uint32_t b = a + 1; b < q.size(); ++b)
            if (q.id[a] != kLeaving && q.id[b] != kLeaving &&
                norm(q.position[a] - q.position[b]) < 1.2 * kSpacing) {
                Bond bond{a, b, {}};
                bond.state.rest_length = kSpacing;
                net.bonds.push_back(bond);
            }
    sim.set_bonds(std::move(net));
    sim.compute_forces();
    sim.run(300);
    return sim;
}

std::map<std::pair<std::uint32_t, std::uint32_t>, Vec3> springs(const Simulation& sim) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, Vec3> out;
    for (NeighborList::Entry e : sim.neighbors().state_entries(sim.particles()))
        out[{e.owner_id, e.partner_id}] = PairLaws::state<HertzMindlinLaw>(e.state).spring;
    return out;
}
} // namespace

TEST(ParticleRemoval, OthersKeepOrderHistoryAndBonds) {
    Simulation sim = lattice();
    const std::vector<std::uint32_t> ids = sim.particles().id;
    const auto before = springs(sim);
    const std::size_t bonds = sim.bonds().bonds.size();
    ASSERT_GT(bonds, 40u);
    ASSERT_GT(before.size(), 50u); // contacts with a tangential spring kept
    std::size_t centre_springs = 0;
    for (const auto& [key, s] : before)
        if (key.first == kLeaving || key.second == kLeaving) ++centre_springs;
    ASSERT_GT(centre_springs, 0u);

    sim.remove_particles({index_of(sim, kLeaving)});
    std::vector<std::uint32_t> expected = ids;
    expected.erase(std::find(expected.begin(), expected.end(), kLeaving));
    EXPECT_EQ(sim.particles().id, expected);
    EXPECT_EQ(sim.particles().size(), 26u);
    EXPECT_EQ(sim.bonds().bonds.size(), bonds); // none of them held the centre
    const auto after = springs(sim);
    EXPECT_EQ(after.size(), before.size() - centre_springs);
    for (const auto& [key, s] : after) EXPECT_EQ(norm(s - before.at(key)), 0.0);
    sim.run(100); // and it steps on
}

TEST(ParticleRemoval, TheRestMovesAsIfItHadBeenCarriedAway) {
    // Removed against carried 100 um off (its pairs leave the list at the next rebuild): the
    // others see the same forces, step after step.
    Simulation gone = lattice(), away = lattice();
    gone.remove_particles({index_of(gone, kLeaving)});
    away.particles_mut().position[index_of(away, kLeaving)].z += 100e-6;
    away.invalidate_neighbors();
    gone.compute_forces();
    away.compute_forces();
    for (int step = 0; step < 200; ++step) {
        for (std::uint32_t id = 1; id <= 27; ++id) {
            if (id == kLeaving) continue;
            const std::size_t a = index_of(gone, id), b = index_of(away, id);
            const double scale = 1e-12 * (norm(away.particles().force[b]) + 1e-9);
            ASSERT_NEAR(norm(gone.particles().force[a] - away.particles().force[b]), 0.0, scale)
                << "particle " << id << " at step " << step;
        }
        gone.step();
        away.step();
    }
}

TEST(ParticleRemoval, ItsBondsGoWithIt) {
    Simulation sim = lattice();
    const std::uint32_t corner = 1;
    std::size_t held = 0;
    for (const Bond& b : sim.bonds().bonds)
        if (sim.particles().id[b.i] == corner || sim.particles().id[b.j] == corner) ++held;
    ASSERT_EQ(held, 3u);
    // Each surviving bond joins the same two ids as before.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (const Bond& b : sim.bonds().bonds)
        if (sim.particles().id[b.i] != corner && sim.particles().id[b.j] != corner)
            pairs.emplace_back(sim.particles().id[b.i], sim.particles().id[b.j]);
    sim.remove_particles({index_of(sim, corner)});
    ASSERT_EQ(sim.bonds().bonds.size(), pairs.size());
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        EXPECT_EQ(sim.particles().id[sim.bonds().bonds[k].i], pairs[k].first);
        EXPECT_EQ(sim.particles().id[sim.bonds().bonds[k].j], pairs[k].second);
    }
    sim.run(50);
    EXPECT_EQ(sim.bonds().intact(), pairs.size());
}

TEST(ParticleRemoval, RefusedOutsideTheExplicitIntegrator) {
    ParticleStore p;
    p.add(1, 0, kR, kRho, {5e-6, 5e-6, 5e-6});
    p.add(2, 0, kR, kRho, {8e-6, 5e-6, 5e-6});
    ForceField ff = uniform_contact_force_field(1, 2e9, 0.3, 0.5, 0.5);
    EngineSettings es{2e-10, 0.1e-6, 1};
    es.integrator = Integrator::semi_implicit;
    Simulation sim(std::move(p), Box{kL, kL}, ff, es);
    EXPECT_THROW(sim.remove_particles({0}), RunError);
}
