// SPDX-License-Identifier: MIT
// The near list: the slots of the neighbour list (neighbor_list.hpp) whose pair lies within its
// interaction reach plus a thin skin s_near, rebuilt from the neighbour list whenever some
// particle moved more than s_near/2 since its last build (model.md M-9.4, a two-level Verlet
// list). The pair loop walks it instead of the whole neighbour list.
//
// Why: the neighbour list's skin is sized so that the cell search (the expensive build) runs
// rarely; a settled bed has ~2.4 listed pairs per touching one at the peers' 0.3 µm skin, and
// every step paid a distance test, a state check and the partner's loads for each of them
// (docs/performance.md, "The near list"). The near list pays that once per build, from the
// neighbour list's rows in their order, so the pair loop sees the same pairs in the same order
// and adds the same forces: results do not change by a bit, whatever s_near is (test).
//
// A pair left out is beyond its reach by more than s_near and cannot come within it before the
// next build; what its laws kept is cleared at the build, as the pair loop would have done at
// that step.
//
// When it pays: a build costs about one step's walk of the whole list, so the list must outlive
// several steps. s_near = f s is chosen from how long lists live: at each rebuild of the
// neighbour list, f = 32 / (steps the last one lived), as a power of two in [1/32, 1/4]; above
// 1/4 (a list rebuilt every < 128 steps: a drying film on the move) the near list is off and the
// pair loop walks the neighbour list itself. While on, f halves when a near list lives over 128
// steps and doubles when it lives under 8 (off above 1/4).
#pragma once
#include "drydem/core/box.hpp"
#include "drydem/core/particles.hpp"
#include "drydem/core/vec3.hpp"
#include "drydem/neighbor/neighbor_list.hpp"
#include <cstdint>
#include <vector>

namespace drydem {

class NearList {
public:
    /// outer_skin: the neighbour list's skin s [m]; enabled = false: never on (the pair loop
    /// always walks the neighbour list; tests and A/B timings).
    explicit NearList(double outer_skin = 0.0, bool enabled = true)
        : outer_skin_(outer_skin), enabled_(enabled), on_(enabled) {}

    /// Whether the pair loop walks this list (else the neighbour list itself).
    [[nodiscard]] bool on() const { return on_; }
    /// On and built since the last change of the particles: usable as it is.
    [[nodiscard]] bool valid() const { return on_ && !stale_; }
    /// s_near [m].
    [[nodiscard]] double skin() const { return fraction_ * outer_skin_; }
    [[nodiscard]] std::size_t pairs() const { return slot_.size(); }
    [[nodiscard]] std::uint64_t builds() const { return builds_; }
    [[nodiscard]] std::uint32_t begin(std::size_t i) const { return offset_[i]; }
    [[nodiscard]] std::uint32_t end(std::size_t i) const { return offset_[i + 1]; }
    /// The neighbour-list slot of near entry k (its state and reach live there).
    [[nodiscard]] std::uint32_t slot(std::uint32_t k) const { return slot_[k]; }
    [[nodiscard]] std::uint32_t partner(std::uint32_t k) const { return partner_[k]; }
    [[nodiscard]] const std::vector<Vec3>& positions_at_build() const { return x_build_; }

    /// The neighbour list was rebuilt at this step: choose s_near from how long the last one
    /// lived, build before the next use.
    void neighbors_rebuilt(std::int64_t step);
    /// After a step: max_displacement2 is the largest squared displacement since
    /// positions_at_build(); beyond (s_near/2)² the list is built again before the next use.
    void moved(double max_displacement2, std::int64_t step);
    /// The particles were moved outside the steps: build before the next use.
    void invalidate() { stale_ = true; }

    /// Builds from the neighbour list at the present positions; clears the states of the slots
    /// left out (they are beyond reach now).
    void build(NeighborList& nl, const ParticleStore& p, const Box& box, int threads,
               std::int64_t step);

private:
    static constexpr double finest = 1.0 / 32, coarsest = 0.25;
    double outer_skin_;
    bool enabled_;
    double fraction_ = 1.0 / 32; ///< f = s_near / s
    bool on_, stale_ = true;
    std::int64_t outer_step_ = -1, near_step_ = 0; ///< steps of the last builds (-1: none yet)
    std::uint64_t builds_ = 0;
    std::vector<std::uint32_t> offset_, slot_, partner_;
    std::vector<std::uint8_t> near_; ///< per neighbour-list slot, scratch of build()
    std::vector<Vec3> x_build_;
};

} // namespace drydem
