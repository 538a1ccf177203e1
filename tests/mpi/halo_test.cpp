// SPDX-License-Identifier: MIT
// The halo exchanges of the domain decomposition (parallel/halo.hpp), run by ctest under
// `mpirun -np 1..4` (and alone). Every rank generates the same particles from one seed, so each
// can check its own share against the whole: ownership after migration, the ghost set against a
// brute-force search, and the ghosts' motion after an update. Each test runs on a thin film (cut
// in x and y) and on a thick one (cut in z: an open axis, layers with one or two neighbours).
#include "drydem/parallel/halo.hpp"
#include "drydem/parallel/mpi_world.hpp"
#include <gtest/gtest.h>
#include <mpi.h>
#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>

using namespace drydem;
using namespace drydem::parallel;

namespace {

const Box kBox{75e-6, 75e-6};

/// The same film on every rank: CB-sized and NCM-sized spheres in a layer `thickness` thick.
ParticleStore film(std::size_t n, std::uint64_t seed, double thickness) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> ux(0.0, kBox.lx), uy(0.0, kBox.ly), uz(0.0, thickness),
        u01(0.0, 1.0);
    ParticleStore p;
    for (std::size_t i = 0; i < n; ++i) {
        const bool cb = u01(rng) < 0.8;
        const double r = cb ? 0.75e-6 : 2e-6 + 6e-6 * u01(rng);
        p.add(std::uint32_t(i), cb ? 1 : 0, r, cb ? 1900.0 : 4700.0, {ux(rng), uy(rng), uz(rng)});
        p.velocity.back() = {1e-3 * i, -2e-3 * i, 0.5};
        p.force.back() = {3e-9 * i, 0.0, -1e-9};
    }
    return p;
}

/// A deterministic motion of particle `id` at `step` (every rank computes the same).
Vec3 moved(const Vec3& x0, std::uint32_t id, int step) {
    const double a = 0.37 * id + step;
    return {x0.x + 4e-6 * std::sin(a), x0.y + 4e-6 * std::cos(1.3 * a),
            x0.z + 4e-6 * std::sin(0.7 * a)};
}

/// What an extra per-particle array carries: something the engine keeps beside the store.
struct Kept {
    std::uint32_t id;
    double value;
};

std::vector<std::uint32_t> all_ids(const ParticleStore& p, std::size_t owned) {
    const int n = int(owned);
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    std::vector<int> counts(size), offsets(size);
    MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    int total = 0;
    for (int r = 0; r < size; ++r) {
        offsets[r] = total;
        total += counts[r];
    }
    std::vector<std::uint32_t> ids(std::size_t(total), 0);
    MPI_Allgatherv(p.id.data(), n, MPI_UINT32_T, ids.data(), counts.data(), offsets.data(),
                   MPI_UINT32_T, MPI_COMM_WORLD);
    return ids;
}

parallel::Halo make_halo(double reach, double thickness) {
    const World w = world();
    return parallel::Halo(decompose(kBox, w.size, reach, thickness), MPI_COMM_WORLD);
}

/// The film's thickness: 30 um is cut in x and y, 150 um in z (on 2 to 4 ranks).
class HaloExchange : public ::testing::TestWithParam<double> {};
INSTANTIATE_TEST_SUITE_P(Films, HaloExchange, ::testing::Values(30e-6, 150e-6));

} // namespace

TEST_P(HaloExchange, MigrationKeepsEveryParticleOnceWithWhatTravelsWithIt) {
    constexpr std::size_t n = 4000;
    const ParticleStore whole = film(n, 17, GetParam());
    ParticleStore p = whole;
    std::vector<Kept> kept(n);
    std::vector<double> tag(n);
    for (std::size_t i = 0; i < n; ++i) {
        kept[i] = {whole.id[i], 0.25 * i};
        tag[i] = -double(i);
    }
    parallel::Halo halo = make_halo(17e-6, GetParam());
    halo.keep_owned(p, kept, tag);
    for (int step = 1; step <= 4; ++step) {
        for (std::size_t i = 0; i < p.size(); ++i) {
            p.position[i] = moved(whole.position[p.id[i]], p.id[i], step);
            kept[i].value = 0.25 * p.id[i] + step;
        }
        halo.migrate(p, kept, tag);
        ASSERT_EQ(p.size(), halo.owned());
        ASSERT_EQ(kept.size(), p.size());
        ASSERT_EQ(tag.size(), p.size());
        for (std::size_t i = 0; i < p.size(); ++i) {
            const std::uint32_t id = p.id[i];
            EXPECT_EQ(halo.decomposition().owner(p.position[i]), halo.rank());
            EXPECT_EQ(kept[i].id, id);
            EXPECT_EQ(kept[i].value, 0.25 * id + step);
            EXPECT_EQ(tag[i], -double(id));
            EXPECT_EQ(p.radius[i], whole.radius[id]);
            EXPECT_EQ(p.mass[i], whole.mass[id]);
            EXPECT_EQ(p.velocity[i].x, whole.velocity[id].x);
            EXPECT_EQ(p.force[i].x, whole.force[id].x);
        }
        std::vector<std::uint32_t> ids = all_ids(p, p.size());
        std::sort(ids.begin(), ids.end());
        ASSERT_EQ(ids.size(), n);
        for (std::size_t k = 0; k < n; ++k) ASSERT_EQ(ids[k], k);
    }
    if (world().size > 1) {
        EXPECT_GT(halo.counters().migrated, 0u);
    }
    // Gathered, the film is whole again on every rank, ordered by id, as last moved.
    const ParticleStore all = halo.gather(p);
    ASSERT_EQ(all.size(), n);
    for (std::size_t k = 0; k < n; ++k) {
        EXPECT_EQ(all.id[k], k);
        EXPECT_EQ(all.position[k].z, moved(whole.position[k], std::uint32_t(k), 4).z);
        EXPECT_EQ(all.radius[k], whole.radius[k]);
    }
}

TEST_P(HaloExchange, GhostsAreExactlyTheNeighboursParticlesWithinReach) {
    constexpr std::size_t n = 3000;
    const ParticleStore whole = film(n, 23, GetParam());
    // Reach of particle j: its radius, the largest radius, a range and the skin (the engine's
    // bound on how far a partner on another rank can be).
    auto reach_of = [&](std::size_t id) { return whole.radius[id] + 8e-6 + 1.1e-6; };
    ParticleStore p = whole;
    parallel::Halo halo = make_halo(8e-6 + 8e-6 + 1.1e-6, GetParam());
    halo.keep_owned(p);
    std::vector<double> reach(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) reach[i] = reach_of(p.id[i]);
    halo.make_ghosts(p, reach);
    const std::size_t owned = halo.owned();
    std::set<std::uint32_t> ghosts;
    for (std::size_t g = owned; g < p.size(); ++g) {
        EXPECT_TRUE(ghosts.insert(p.id[g]).second) << "ghost " << p.id[g] << " twice";
        const std::uint32_t id = p.id[g];
        EXPECT_EQ(p.position[g].x, whole.position[id].x);
        EXPECT_EQ(p.velocity[g].y, whole.velocity[id].y);
        EXPECT_EQ(p.radius[g], whole.radius[id]);
        EXPECT_EQ(p.inv_inertia[g], whole.inv_inertia[id]);
        EXPECT_EQ(p.force[g].x, 0.0); // a ghost's force is its owner's
    }
    std::set<std::uint32_t> expected;
    const Decomposition& d = halo.decomposition();
    for (std::size_t j = 0; j < n; ++j) {
        if (d.owner(whole.position[j]) == halo.rank()) continue;
        const double r = reach_of(j);
        if (d.distance2(halo.rank(), whole.position[j]) < r * r) expected.insert(std::uint32_t(j));
    }
    EXPECT_EQ(ghosts, expected);
    if (world().size > 1) {
        EXPECT_FALSE(ghosts.empty());
    }
    // Every pair closer than the owner's reach, one of them owned here, is here whole.
    std::set<std::uint32_t> here(p.id.begin(), p.id.end());
    for (std::size_t i = 0; i < owned; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            const Vec3 dx = kBox.minimum_image(p.position[i], whole.position[j]);
            const double r = reach_of(j);
            if (norm2(dx) < r * r) {
                EXPECT_TRUE(here.count(std::uint32_t(j))) << j;
            }
        }
}

TEST_P(HaloExchange, UpdateGhostsCopiesTheOwnersMotion) {
    constexpr std::size_t n = 3000;
    const ParticleStore whole = film(n, 31, GetParam());
    ParticleStore p = whole;
    parallel::Halo halo = make_halo(17e-6, GetParam());
    halo.keep_owned(p);
    std::vector<double> reach(p.size(), 12e-6);
    halo.make_ghosts(p, reach);
    const std::size_t owned = halo.owned();
    for (int step = 1; step <= 3; ++step) {
        for (std::size_t i = 0; i < owned; ++i) {
            const std::uint32_t id = p.id[i];
            p.position[i] = {whole.position[id].x, whole.position[id].y,
                             whole.position[id].z + 1e-7 * step};
            p.velocity[i] = {double(id), double(step), 0.0};
            p.omega[i] = {0.0, 0.0, id + 0.5 * step};
        }
        halo.update_ghosts(p);
        for (std::size_t g = owned; g < p.size(); ++g) {
            const std::uint32_t id = p.id[g];
            EXPECT_EQ(p.position[g].z, whole.position[id].z + 1e-7 * step);
            EXPECT_EQ(p.velocity[g].x, double(id));
            EXPECT_EQ(p.velocity[g].y, double(step));
            EXPECT_EQ(p.omega[g].z, id + 0.5 * step);
        }
    }
    // Dropping the ghosts leaves the owned particles as they were.
    halo.drop_ghosts(p);
    EXPECT_EQ(p.size(), owned);
    if (world().size > 1) {
        EXPECT_GT(halo.counters().bytes, 0u);
        EXPECT_EQ(halo.counters().exchanges, 4u); // make_ghosts + 3 updates
    }
}

TEST_P(HaloExchange, GhostValuesAndItemsReachTheRightRanks) {
    constexpr std::size_t n = 2000;
    const ParticleStore whole = film(n, 41, GetParam());
    ParticleStore p = whole;
    parallel::Halo halo = make_halo(17e-6, GetParam());
    halo.keep_owned(p);
    std::vector<double> reach(p.size(), 10e-6);
    halo.make_ghosts(p, reach);
    // A per-particle vector: owners write theirs, the ghosts' entries arrive from them.
    std::vector<Vec3> v(p.size(), Vec3{-1.0, -1.0, -1.0});
    for (std::size_t i = 0; i < halo.owned(); ++i) v[i] = {double(p.id[i]), 2.0, 3.0};
    halo.update_ghost_values(v);
    for (std::size_t g = halo.owned(); g < p.size(); ++g) EXPECT_EQ(v[g].x, double(p.id[g]));
    // Variable-length items: neighbour k gets k + 1 items naming sender and receiver.
    struct Item {
        int from, to, index;
    };
    const auto& nb = halo.neighbors();
    std::vector<std::vector<Item>> out(nb.size());
    for (std::size_t k = 0; k < nb.size(); ++k)
        for (int m = 0; m < nb[k] + 1; ++m) out[k].push_back({halo.rank(), nb[k], m});
    const auto got = halo.exchange_items(out);
    ASSERT_EQ(got.size(), nb.size());
    for (std::size_t k = 0; k < nb.size(); ++k) {
        ASSERT_EQ(got[k].size(), std::size_t(halo.rank() + 1));
        for (std::size_t m = 0; m < got[k].size(); ++m) {
            EXPECT_EQ(got[k][m].from, nb[k]);
            EXPECT_EQ(got[k][m].to, halo.rank());
            EXPECT_EQ(got[k][m].index, int(m));
        }
    }
}

// The balancing moves the cuts until every rank owns an equal share of a lopsided film: denser
// towards x = 0 (the thin film, cut in x) or towards the substrate (the thick one, cut in z).
// The narrowest subdomain allowed is 5 um here, so that the shares are reachable on 4 ranks.
TEST_P(HaloExchange, RebalancingEqualisesALopsidedFilm) {
    constexpr std::size_t n = 4000;
    ParticleStore p = film(n, 53, GetParam());
    const bool thick = GetParam() > 100e-6;
    for (Vec3& x : p.position) {
        if (thick)
            x.z = x.z * x.z / GetParam(); // half the particles below a quarter of the film
        else
            x.x = kBox.lx * std::pow(x.x / kBox.lx, 1.5);
    }
    parallel::Halo halo = make_halo(17e-6, GetParam());
    halo.keep_owned(p);
    const int ranks = world().size;
    auto most = [&] { return halo.all_max(double(halo.owned())); };
    const double share = double(n) / ranks;
    if (ranks > 1) {
        EXPECT_GT(most(), 1.2 * share) << "the film is not lopsided";
    }
    constexpr double min_width = 5e-6;
    for (int round = 0; round < 12; ++round) {
        halo.rebalance(p, std::vector<double>(halo.owned(), 0.0), min_width, 0.0);
        halo.migrate(p);
    }
    EXPECT_LT(most(), 1.05 * share);
    EXPECT_EQ(halo.all_sum(std::uint64_t(halo.owned())), n);
    const Decomposition& d = halo.decomposition();
    if (thick) {
        for (int k = 1; k + 1 < d.pz; ++k) EXPECT_GE(d.cut_z[k + 1] - d.cut_z[k], min_width);
    } else {
        EXPECT_GE(d.width_x(), min_width);
    }
}

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    start_mpi();
    int failed = RUN_ALL_TESTS();
    // One verdict for all ranks: a failure on any fails the launch.
    int any = 0;
    MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    finish_mpi();
    return any;
}
