// SPDX-License-Identifier: MIT
// Making the dry film's bonds (calendering/bonding.hpp): the share of candidate pairs that bond
// follows p(z) = min(1, p₀ b(z)) of the binder profile, NCM-NCM pairs never bond, pairs beyond the
// gap never bond, the same film gets the same bonds whatever its storage order, and the binder
// profile is read (or its absence said) as the drying run wrote it.
#include "drydem/calendering/bonding.hpp"
#include "drydem/core/error.hpp"
#include "drydem/forces/hertz_mindlin.hpp"
#include "test_dirs.hpp"
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <utility>

using namespace drydem;
namespace fs = std::filesystem;

namespace {
constexpr double kR = 0.5e-6, kRho = 1900, kL = 20e-6, kSpacing = 2 * kR + 10e-9;
constexpr int kSide = 20, kLayers = 10;

/// A simple cubic lattice of CB spheres 10 nm apart (species 1; species 0 an NCM class that is
/// not in it), added in the given order of lattice sites.
Simulation lattice(bool reversed) {
    ParticleStore p;
    const int n = kSide * kSide * kLayers;
    for (int m = 0; m < n; ++m) {
        const int k = reversed ? n - 1 - m : m;
        const int a = k % kSide, b = k / kSide % kSide, c = k / (kSide * kSide);
        p.add(std::uint32_t(k + 1), 1, kR, kRho,
              {(a + 0.5) * kSpacing, (b + 0.5) * kSpacing, kR + 0.5e-6 + c * kSpacing});
    }
    ForceField ff = uniform_contact_force_field(2, 2e9, 0.3, 0.5, 0.5);
    ff.remove_substrate();
    return Simulation(std::move(p), Box{kSide * kSpacing, kSide * kSpacing}, ff,
                      {1e-10, 0.1e-6, 1});
}

BondNetwork cb_bonds() {
    BondNetwork net;
    net.species_count = 2;
    const SolidBondParams bond{2e9, 0.77e9, 0.5, 20e6, 20e6, 0.4};
    net.params = {SolidBondParams{}, bond, bond, bond}; // NCM-NCM never
    return net;
}

BinderDistribution two_levels() { // b = 0.4 below 5 µm, 1.6 above (a step over 10 nm)
    return {{5.0e-6, 5.01e-6}, {0.4, 1.6}, "test"};
}

TEST(Bonding, ShareOfBondsFollowsTheBinderProfile) {
    Simulation sim = lattice(false);
    const BondingReport r = form_bonds(sim, cb_bonds(), two_levels(), 50e-9, 0.5, 12345);
    // Lattice edges: 3 per site minus the open top layer's vertical ones (x and y periodic).
    EXPECT_EQ(r.candidates, std::size_t(3 * kSide * kSide * kLayers - kSide * kSide));
    EXPECT_EQ(r.cb_ncm, 0u);
    EXPECT_EQ(r.saturated, 0u);
    std::size_t low = 0, low_bonded = 0, high = 0, high_bonded = 0;
    std::set<std::pair<std::uint32_t, std::uint32_t>> bonded;
    const ParticleStore& p = sim.particles();
    for (const Bond& b : sim.bonds().bonds) bonded.insert(std::minmax(b.i, b.j));
    // Every candidate, by its mid-height.
    for (std::uint32_t i = 0; i < p.size(); ++i)
        for (std::uint32_t j = i + 1; j < p.size(); ++j) {
            const Vec3 d = sim.box().minimum_image(p.position[i], p.position[j]);
            if (norm(d) > 2 * kR + 50e-9) continue;
            const bool below = p.position[i].z + 0.5 * d.z < 5e-6;
            const bool is_bonded = bonded.count({i, j}) > 0;
            (below ? low : high)++;
            (below ? low_bonded : high_bonded) += is_bonded ? 1 : 0;
        }
    EXPECT_EQ(low + high, r.candidates);
    EXPECT_EQ(low_bonded + high_bonded, r.bonds());
    EXPECT_NEAR(double(low_bonded) / double(low), 0.2, 0.04);   // p₀ b = 0.5 × 0.4
    EXPECT_NEAR(double(high_bonded) / double(high), 0.8, 0.04); // 0.5 × 1.6
    for (const Bond& b : sim.bonds().bonds) {
        const Vec3 d = sim.box().minimum_image(p.position[b.i], p.position[b.j]);
        EXPECT_DOUBLE_EQ(b.state.rest_length, norm(d)); // formed at rest
    }
}

TEST(Bonding, ProfileAboveOneBondsEveryCandidateAndSaysSo) {
    Simulation sim = lattice(false);
    const BondingReport r =
        form_bonds(sim, cb_bonds(), {{0.0, 1.0}, {3.0, 3.0}, "test"}, 50e-9, 0.5, 1);
    EXPECT_EQ(r.bonds(), r.candidates);
    EXPECT_EQ(r.saturated, r.candidates);
}

TEST(Bonding, NoPairBeyondTheGapAndNoNcmPairBonds) {
    Simulation sim = lattice(false);
    EXPECT_EQ(form_bonds(sim, cb_bonds(), {}, 5e-9, 1.0, 1).candidates, 0u); // 10 nm apart
    BondNetwork ncm_only = cb_bonds();
    ncm_only.params = {SolidBondParams{}, SolidBondParams{}, SolidBondParams{}, SolidBondParams{}};
    Simulation again = lattice(false);
    EXPECT_EQ(form_bonds(again, ncm_only, {}, 50e-9, 1.0, 1).candidates, 0u);
}

TEST(Bonding, SameFilmSameBondsWhateverTheStorageOrder) {
    auto id_pairs = [](bool reversed) {
        Simulation sim = lattice(reversed);
        form_bonds(sim, cb_bonds(), two_levels(), 50e-9, 0.5, 777);
        std::set<std::pair<std::uint32_t, std::uint32_t>> ids;
        for (const Bond& b : sim.bonds().bonds)
            ids.insert(std::minmax(sim.particles().id[b.i], sim.particles().id[b.j]));
        return ids;
    };
    const auto a = id_pairs(false), b = id_pairs(true);
    EXPECT_GT(a.size(), 1000u);
    EXPECT_EQ(a, b);
}

TEST(Bonding, ReadsTheBinderProfileOrSaysWhyItIsUniform) {
    const fs::path dir = drydem::testing_support::temp_dir();
    const BinderDistribution none = read_binder_distribution(dir);
    EXPECT_TRUE(none.z.empty());
    EXPECT_NE(none.source.find("uniform"), std::string::npos);
    EXPECT_DOUBLE_EQ(none.at(3e-6), 1.0);
    fs::create_directories(dir / "analysis");
    std::ofstream(dir / "analysis" / "binder_profile.csv")
        << "z_um,binder_over_mean,binder_over_mean_rate_x0.5\n1,0.5,9\n3,1.5,9\n";
    const BinderDistribution d = read_binder_distribution(dir);
    EXPECT_DOUBLE_EQ(d.at(0.0), 0.5);
    EXPECT_DOUBLE_EQ(d.at(2e-6), 1.0);
    EXPECT_DOUBLE_EQ(d.at(9e-6), 1.5);
    std::ofstream(dir / "analysis" / "binder_profile.csv") << "z,b\n1,2\n";
    EXPECT_THROW(read_binder_distribution(dir), InputError);
    std::ofstream(dir / "analysis" / "binder_profile.csv") << "z_um,binder_over_mean\n1,nan\n";
    EXPECT_THROW(read_binder_distribution(dir), InputError);
}

} // namespace
