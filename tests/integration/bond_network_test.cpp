// SPDX-License-Identifier: MIT
// Solid bonds in the engine (engine/bond_network.hpp, Simulation::set_bonds): a bonded dimer
// oscillates with the bond's period, a pair thrown apart breaks its bond and leaves with the
// energy the bond did not store, a bonded cluster conserves momentum, re-sorting the particles
// keeps each bond on its pair, the bond enters the contact stress, and an integrator that cannot
// carry bonds is refused.
#include "drydem/core/error.hpp"
#include "drydem/engine/simulation.hpp"
#include "drydem/forces/hertz_mindlin.hpp"
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

using namespace drydem;

namespace {
constexpr double kR = 0.5e-6, kRho = 1900, kL = 20e-6, kE = 2e9, kG = 0.8e9, kLambda = 0.5;
constexpr double kGap = 0.1e-6; // the dimer is made 100 nm apart: no contact

double mass() { return kRho * 4.0 / 3.0 * std::numbers::pi * kR * kR * kR; }

BondNetwork network(double sigma_c = 1e9, double beta = 0.0) {
    BondNetwork b;
    b.species_count = 1;
    b.params = {SolidBondParams{kE, kG, kLambda, sigma_c, 1e9, beta}};
    return b;
}

/// The storage index of the particle with this id (the engine sorts the particles at its start).
std::uint32_t index_of(const Simulation& sim, std::uint32_t id) {
    const auto& ids = sim.particles().id;
    return std::uint32_t(std::find(ids.begin(), ids.end(), id) - ids.begin());
}

ForceField no_walls() {
    ForceField ff = uniform_contact_force_field(1, 142e9, 0.3, 1.0, 0.5);
    ff.remove_substrate();
    return ff;
}

/// Two spheres along x, centres L0 + stretch apart, velocities ±v along x, bonded at L0.
Simulation dimer(double stretch, double v, BondNetwork net,
                 EngineSettings es = {1e-10, 0.1e-6, 1}) {
    const double l0 = 2 * kR + kGap;
    ParticleStore p;
    p.add(1, 0, kR, kRho, {5e-6, 10e-6, 10e-6});
    p.add(2, 0, kR, kRho, {5e-6 + l0 + stretch, 10e-6, 10e-6});
    p.velocity[0] = {-v, 0, 0};
    p.velocity[1] = {v, 0, 0};
    Simulation sim(std::move(p), Box{kL, kL}, no_walls(), es);
    Bond bond{index_of(sim, 1), index_of(sim, 2), {}};
    bond.state.rest_length = l0;
    net.bonds.push_back(bond);
    sim.set_bonds(std::move(net));
    sim.compute_forces();
    return sim;
}

double stiffness() {
    const double area = std::numbers::pi * kLambda * kLambda * kR * kR;
    return kE / (2 * kR + kGap) * area;
}

TEST(BondNetwork, DimerOscillatesWithTheBondPeriod) {
    const double stretch = 1e-10;
    Simulation sim = dimer(stretch, 0.0, network());
    const double period = 2 * std::numbers::pi * std::sqrt(0.5 * mass() / stiffness());
    const double dt = period / 400;
    sim.set_time_step(dt);
    auto gap = [&] { return sim.particles().position[1].x - sim.particles().position[0].x; };
    const double l0 = 2 * kR + kGap;
    sim.run(200); // half a period: compressed by the same stretch
    EXPECT_NEAR(gap() - l0, -stretch, 1e-3 * stretch);
    sim.run(200); // a full period: back where it started
    EXPECT_NEAR(gap() - l0, stretch, 1e-3 * stretch);
    EXPECT_EQ(sim.bonds().intact(), 1u);
}

TEST(BondNetwork, PairThrownApartBreaksAndKeepsWhatTheBondDidNotStore) {
    const double sigma_c = 1e6;
    const double stretch_c = sigma_c * (2 * kR + kGap) / kE; // σ = k̄_n s
    const double m_eff = 0.5 * mass();
    const double stored = 0.5 * stiffness() * stretch_c * stretch_c;
    const double v0 =
        2.0 * std::sqrt(stored / m_eff); // relative speed 2 v0 ... ½ m* (2v)² ≥ 4 stored
    Simulation sim = dimer(0.0, 0.5 * v0, network(sigma_c));
    sim.set_time_step(2 * std::numbers::pi * std::sqrt(m_eff / stiffness()) / 2000);
    for (int k = 0; k < 20000 && sim.bonds().broken() == 0; ++k) sim.step();
    ASSERT_EQ(sim.bonds().broken(), 1u);
    sim.run(10);
    const double v_rel = sim.particles().velocity[1].x - sim.particles().velocity[0].x;
    // ½ m* v_rel² = ½ m* v0² - stored, to the step's resolution of the break.
    const double expected = std::sqrt(v0 * v0 - 2 * stored / m_eff);
    EXPECT_NEAR(v_rel, expected, 2e-3 * expected);
}

TEST(BondNetwork, BondedClusterConservesMomentum) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    ParticleStore p;
    const int n = 27;
    for (int k = 0; k < n; ++k) {
        const Vec3 x{5e-6 + (k % 3) * 1.05e-6, 5e-6 + (k / 3 % 3) * 1.05e-6,
                     5e-6 + (k / 9) * 1.05e-6};
        p.add(std::uint32_t(k + 1), 0, kR, kRho, x + 1e-9 * Vec3{u(rng), u(rng), u(rng)});
        p.velocity.back() = 1e-3 * Vec3{u(rng), u(rng), u(rng)};
        p.omega.back() = 1e3 * Vec3{u(rng), u(rng), u(rng)};
    }
    Simulation sim(std::move(p), Box{kL, kL}, no_walls(), {2e-10, 0.1e-6, 2});
    BondNetwork net = network(1e9, 0.2);
    const auto& x = sim.particles().position;
    for (std::uint32_t a = 0; a < n; ++a)
        for (std::uint32_t b = a + 1; b < n; ++b)
            if (norm(x[a] - x[b]) < 1.2e-6) {
                Bond bond{a, b, {}};
                bond.state.rest_length = 1.05e-6;
                net.bonds.push_back(bond);
            }
    ASSERT_EQ(net.bonds.size(), 54u); // the 3x3x3 lattice's edges
    sim.set_bonds(std::move(net));
    sim.compute_forces();
    const Vec3 p0 = sim.momentum();
    sim.run(2000);
    const Vec3 p1 = sim.momentum();
    EXPECT_NEAR(norm(p1 - p0), 0.0, 1e-12 * mass() * 1e-3 * n);
    EXPECT_EQ(sim.bonds().intact(), 54u);
}

/// Kinetic plus the bonds' elastic energy ½ k̄_n A s² + ½ k̄_s A |u_s|² + ½ k̄_n I |θ_b|² +
/// ½ k̄_s J θ_t² (header of solid_bond.hpp).
double total_energy(const Simulation& sim) {
    double e = sim.kinetic_energy();
    const ParticleStore& p = sim.particles();
    for (const Bond& b : sim.bonds().bonds) {
        const Vec3 d = sim.box().minimum_image(p.position[b.i], p.position[b.j]);
        const PairGeometry g = make_pair_geometry(d, norm(d), p.radius[b.i], p.radius[b.j],
                                                  p.mass[b.i], p.mass[b.j], {}, {}, {}, {});
        const PairResistance k = solid_bond_stiffness(
            g, sim.bonds().pair(p.species[b.i], p.species[b.j]), b.state.rest_length);
        const double s = norm(d) - b.state.rest_length;
        e +=
            0.5 * (k.normal * s * s + k.sliding * norm2(b.state.shear) +
                   k.rolling * norm2(b.state.bending) + k.twisting * b.state.twist * b.state.twist);
    }
    return e;
}

TEST(BondNetwork, UndampedBondedChainConservesEnergy) {
    // A bent chain of unequal spheres, spinning and moving: every mode of the bonds loaded.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    ParticleStore p;
    const double radii[] = {kR, 4 * kR, kR, 2 * kR, kR};
    Vec3 x{5e-6, 8e-6, 8e-6};
    for (int k = 0; k < 5; ++k) {
        if (k > 0) x += (radii[k - 1] + radii[k] + 20e-9) * Vec3{0.8, 0.6 * (k % 2 ? 1 : -1), 0};
        p.add(std::uint32_t(k + 1), 0, radii[k], kRho, x);
        p.velocity.back() = 2e-3 * Vec3{u(rng), u(rng), u(rng)};
        p.omega.back() = 2e3 * Vec3{u(rng), u(rng), u(rng)};
    }
    Simulation sim(std::move(p), Box{kL, kL}, no_walls(), {1e-11, 0.1e-6, 1});
    BondNetwork net = network();
    for (std::uint32_t id = 1; id < 5; ++id) {
        Bond b{index_of(sim, id), index_of(sim, id + 1), {}};
        b.state.rest_length = norm(sim.particles().position[b.i] - sim.particles().position[b.j]);
        net.bonds.push_back(b);
    }
    sim.set_bonds(std::move(net));
    sim.compute_forces();
    const double e0 = total_energy(sim);
    double drift = 0.0;
    for (int k = 0; k < 50; ++k) {
        sim.run(200);
        drift = std::max(drift, std::abs(total_energy(sim) - e0));
    }
    EXPECT_EQ(sim.bonds().intact(), 4u);
    EXPECT_LT(drift, 1e-3 * e0);
}

TEST(BondNetwork, ResortingKeepsEveryBondOnItsPair) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    ParticleStore p;
    const int n = 400;
    for (int k = 0; k < n; ++k)
        p.add(std::uint32_t(k + 1), 0, kR, kRho, {kL * u(rng), kL * u(rng), 2e-6 + 10e-6 * u(rng)});
    EngineSettings es{1e-10, 0.1e-6, 1};
    es.sort_every = 1;
    Simulation sim(std::move(p), Box{kL, kL}, no_walls(), es);
    BondNetwork net = network();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ids;
    const ParticleStore& q = sim.particles();
    for (std::uint32_t k = 0; k + 1 < n; k += 7) {
        Bond bond{k, k + 1, {}};
        bond.state.rest_length = norm(Box{kL, kL}.minimum_image(q.position[k], q.position[k + 1]));
        net.bonds.push_back(bond);
        ids.emplace_back(q.id[k], q.id[k + 1]);
    }
    sim.set_bonds(std::move(net));
    // Shuffle the film so that the next sort changes the storage order.
    ParticleStore& m = sim.particles_mut();
    for (std::size_t k = 0; k < m.size(); ++k)
        m.position[k] = {kL * u(rng), kL * u(rng), 2e-6 + 10e-6 * u(rng)};
    const std::vector<std::uint32_t> before = q.id;
    sim.invalidate_neighbors();
    sim.compute_forces();
    EXPECT_NE(q.id, before);
    for (std::size_t b = 0; b < ids.size(); ++b) {
        EXPECT_EQ(q.id[sim.bonds().bonds[b].i], ids[b].first);
        EXPECT_EQ(q.id[sim.bonds().bonds[b].j], ids[b].second);
    }
}

TEST(BondNetwork, StretchedBondEntersTheContactStressAsTension) {
    const double stretch = 1e-9;
    Simulation sim = dimer(stretch, 0.0, network());
    const double v = 1e-15, d = 2 * kR + kGap + stretch, f = stiffness() * stretch;
    const Sym3 s = sim.contact_stress(v);
    EXPECT_NEAR(s.xx, -f * d / v, 1e-9 * f * d / v); // compression positive: tension negative
}

TEST(BondNetwork, OnlyTheExplicitIntegratorCarriesBonds) {
    EngineSettings es{1e-10, 0.1e-6, 1};
    es.integrator = Integrator::semi_implicit;
    EXPECT_THROW(dimer(0.0, 0.0, network(), es), InputError);
    BondNetwork bad = network(0.0); // no tensile strength
    EXPECT_THROW(dimer(0.0, 0.0, bad), InputError);
}

TEST(BondNetwork, StabilityEstimateSeesTheBond) {
    Simulation sim = dimer(0.0, 0.0, network());
    const double omega = std::sqrt(stiffness() / (0.5 * mass()));
    // The estimate is an upper bound of the dimer's mode (the rolling modes may be stiffer).
    EXPECT_GE(sim.stability_estimate().stiffness_rate, 0.99 * omega);
}

} // namespace
