// SPDX-License-Identifier: MIT
// What the outputs of a drying run read of the whole film (docs/parallel.md "The drying run on
// several ranks"). On one rank it is the engine's own store. On several, rank 0 (the root) runs
// every output and the others answer its requests: each request is a collective gather of the
// decomposed film, announced by a broadcast, so the outputs keep their own triggers (simulated or
// wall time) and no rank has to know them.
#pragma once
#include "drydem/engine/simulation.hpp"
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace drydem {

/// One rank's share of a decomposed film and its time waiting on the others (its imbalance).
struct RankLoad {
    std::uint64_t owned = 0, ghosts = 0;
    double waited_s =
        0.0; ///< wall seconds inside MPI calls since the launch (parallel::waited_seconds)
};

class WholeFilm {
public:
    explicit WholeFilm(const Simulation& sim);

    /// This rank runs the outputs (always on one rank).
    [[nodiscard]] bool root() const { return root_; }
    /// The film is spread over several ranks.
    [[nodiscard]] bool decomposed() const { return decomposed_; }

    // Root only. Each gathers at most once per step.
    [[nodiscard]] const ParticleStore& particles() const;
    /// Contacts per particle in particles() order, the substrate counted (Simulation::coordination).
    [[nodiscard]] const std::vector<std::int32_t>& coordination() const;
    /// The film's kinetic energy [J] (a sum over the ranks).
    [[nodiscard]] double kinetic_energy() const;
    /// Several ranks: the 99th percentile of the relative overlaps (Simulation::relative_overlaps)
    /// of the whole film, gathered, not searched.
    [[nodiscard]] double overlap_p99() const;
    /// The engine state for a checkpoint (Simulation::state).
    [[nodiscard]] EngineState state() const;
    /// Every rank's load, in rank order (one entry on one rank).
    [[nodiscard]] std::vector<RankLoad> rank_loads() const;
    /// The film's particle count.
    [[nodiscard]] std::size_t size() const { return size_; }

    /// Root: this round of outputs is over; the other ranks go on stepping.
    void release() const;
    /// Root: an output failed with `why`; the other ranks stop with the same words.
    void fail(const std::string& why) const;
    /// The other ranks: answer the root's requests until it releases them. Throws RunError with
    /// the root's diagnosis when an output failed there.
    void serve() const;

private:
    enum Request : int {
        kRelease = 0,
        kParticles = 1,
        kCoordination = 2,
        kState = 3,
        kFail = 4,
        kKineticEnergy = 5,
        kOverlaps = 6,
        kRankLoads = 7
    };
    [[nodiscard]] RankLoad own_load() const;
    void ask(Request r) const;

    const Simulation& sim_;
    bool root_ = true, decomposed_ = false;
    std::size_t size_ = 0;
    mutable std::int64_t particles_step_ = -1, coordination_step_ = -1;
    mutable ParticleStore particles_;
    mutable std::vector<std::int32_t> coordination_;
};

} // namespace drydem
