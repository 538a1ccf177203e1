// SPDX-License-Identifier: MIT
#include "drydem/calendering/bonding.hpp"
#include "drydem/analysis/pair_search.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace drydem {
namespace {

/// A uniform number in [0, 1) from the pair's ids and the seed (splitmix64 finaliser): the same
/// pair draws the same number whatever the storage order or the thread count.
double pair_draw(std::uint32_t id_a, std::uint32_t id_b, std::uint64_t seed) {
    const std::uint64_t lo = std::min(id_a, id_b), hi = std::max(id_a, id_b);
    std::uint64_t x = seed ^ (hi << 32 | lo);
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    x ^= x >> 31;
    return double(x >> 11) * 0x1.0p-53;
}

} // namespace

double BinderDistribution::at(double height) const {
    if (z.empty()) return 1.0;
    if (height <= z.front()) return binder.front();
    if (height >= z.back()) return binder.back();
    const std::size_t k = std::size_t(std::upper_bound(z.begin(), z.end(), height) - z.begin());
    const double w = (height - z[k - 1]) / (z[k] - z[k - 1]);
    return (1.0 - w) * binder[k - 1] + w * binder[k];
}

BinderDistribution read_binder_distribution(const std::filesystem::path& run_dir) {
    const std::filesystem::path file = run_dir / "analysis" / "binder_profile.csv";
    BinderDistribution d;
    std::ifstream in(file);
    if (!in) {
        d.source = fmt::format("uniform: the drying run has no {} (its analysis did not run "
                               "the binder-migration model)",
                               file.string());
        return d;
    }
    std::string line;
    std::getline(in, line);
    if (line.rfind("z_um,binder_over_mean", 0) != 0)
        throw InputError(fmt::format("{}: not a binder profile (its header is '{}', expected "
                                     "z_um,binder_over_mean,...)",
                                     file.string(), line));
    while (std::getline(in, line)) {
        std::stringstream ss(line);
        std::string z_cell, b_cell;
        std::getline(ss, z_cell, ',');
        std::getline(ss, b_cell, ',');
        double z = NAN, b = NAN;
        try {
            z = std::stod(z_cell) * 1e-6;
            b = std::stod(b_cell);
        } catch (const std::exception&) {
        }
        if (!std::isfinite(z) || !std::isfinite(b) || b < 0.0 || (!d.z.empty() && z <= d.z.back()))
            throw InputError(fmt::format("{}: bad row '{}' (heights must increase, the binder "
                                         "be a finite number ≥ 0)",
                                         file.string(), line));
        d.z.push_back(z);
        d.binder.push_back(b);
    }
    if (d.z.empty())
        throw InputError(fmt::format("{}: a binder profile without rows", file.string()));
    d.source = file.string();
    return d;
}

BondingReport form_bonds(Simulation& sim, BondNetwork network, const BinderDistribution& binder,
                         double gap, double probability, std::uint64_t seed) {
    const ParticleStore& p = sim.particles();
    analysis::Structure s;
    s.box = sim.box();
    for (std::size_t i = 0; i < p.size(); ++i) {
        const bool cb_like = network.pair(p.species[i], p.species[i]).youngs_modulus > 0.0;
        s.add(p.position[i], p.radius[i], cb_like ? analysis::Phase::cb : analysis::Phase::ncm);
    }
    BondingReport report;
    analysis::for_each_close_pair(s, gap, [&](std::size_t i, std::size_t j, const Vec3& d) {
        const SolidBondParams& bp = network.pair(p.species[i], p.species[j]);
        if (bp.youngs_modulus == 0.0) return; // NCM-NCM: no binder bridge
        ++report.candidates;
        const double chance = probability * binder.at(p.position[i].z + 0.5 * d.z);
        if (chance >= 1.0) ++report.saturated;
        if (pair_draw(p.id[i], p.id[j], seed) >= chance) return;
        Bond b{std::uint32_t(i), std::uint32_t(j), {}};
        b.state.rest_length = norm(d);
        network.bonds.push_back(b);
        (s.phase[i] == analysis::Phase::cb && s.phase[j] == analysis::Phase::cb ? report.cb_cb
                                                                                : report.cb_ncm)++;
    });
    sim.set_bonds(std::move(network));
    return report;
}

BondCounts bond_counts(const Simulation& sim) {
    BondCounts c{std::vector<std::uint32_t>(sim.particles().size(), 0),
                 std::vector<std::uint32_t>(sim.particles().size(), 0)};
    for (const Bond& b : sim.bonds().bonds) {
        auto& count = b.state.broken ? c.broken : c.intact;
        ++count[b.i];
        ++count[b.j];
    }
    return c;
}

} // namespace drydem
