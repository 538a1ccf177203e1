// SPDX-License-Identifier: MIT
// The solid bonds of the dry film (model.md M-2.10), made once when the film has dried and
// settled: every CB-CB and CB-NCM pair whose surface gap is at most calendering.bond_gap (or that
// overlaps) is a candidate, and bonds with the probability
//   p(z) = min(1, p₀ b(z))
// p₀ = calendering.bond_probability, b(z) the binder per film volume over its mean at the pair's
// mid-height from the drying run's binder-migration model (analysis/binder_profile.csv): where
// drying carried the binder, the film is bonded more densely, so the dryer reaches the
// calendering's mechanics. The draw per pair is a hash of the two particles' ids and the seed:
// the same film gives the same bonds whatever the thread count or storage order. Rest length:
// the pair's present distance (the bond carries nothing in the settled film).
#pragma once
#include "drydem/engine/simulation.hpp"
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace drydem {

/// Binder per film volume over its mean, over the height of the dried film.
struct BinderDistribution {
    std::vector<double> z;      ///< [m], increasing; empty: uniform (b = 1)
    std::vector<double> binder; ///< b(z), mean 1
    std::string source;         ///< the file it came from, or why it is uniform
    /// b at height z: linear between the rows, the end rows' value beyond them.
    [[nodiscard]] double at(double z) const;
};

/// The binder profile a drying run's analysis wrote (analysis/binder_profile.csv: z_um,
/// binder_over_mean); uniform, saying why, when the run has none. InputError for a file that is
/// there but not a profile.
[[nodiscard]] BinderDistribution read_binder_distribution(const std::filesystem::path& run_dir);

struct BondingReport {
    std::size_t candidates = 0;        ///< CB-CB and CB-NCM pairs within the gap
    std::size_t cb_cb = 0, cb_ncm = 0; ///< bonds made
    std::size_t saturated = 0; ///< candidates where p₀ b(z) ≥ 1 (the profile is cut there)
    [[nodiscard]] std::size_t bonds() const { return cb_cb + cb_ncm; }
};

/// Makes the bonds of the film in sim (present storage order) with the parameters of `network`
/// (calendering_bond_parameters), hands them to the engine and says what it made.
BondingReport form_bonds(Simulation& sim, BondNetwork network, const BinderDistribution& binder,
                         double gap, double probability, std::uint64_t seed);

/// Per particle in storage order: its intact and its broken bonds.
struct BondCounts {
    std::vector<std::uint32_t> intact, broken;
};
[[nodiscard]] BondCounts bond_counts(const Simulation& sim);

} // namespace drydem
