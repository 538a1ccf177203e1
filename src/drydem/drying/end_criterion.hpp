// SPDX-License-Identifier: MIT
// When a drying run ends (model.md M-8.2): the film follows the descending liquid level until its
// top stands `final_gap` above the level (or the level reaches the substrate); that top is the
// final thickness H_final at t*. The run then relaxes for a fixed window of simulated time and
// ends. A small state machine: following -> relaxing -> relaxed; it never goes back.
#pragma once
#include "drydem/drying/run_state.hpp"
#include <cstdint>
#include <limits>

namespace drydem {

class EndCriterion {
public:
    enum class State : std::uint8_t { following, relaxing, relaxed };
    /// What one update found (at most one event per step; relaxed may follow in the same step).
    enum class Event : std::uint8_t {
        none,
        final_reached,      ///< the top rose final_gap above the level
        final_at_substrate, ///< the level reached the substrate first; H_final taken there
    };

    /// final_gap [m]: top - level that marks the final thickness; relaxation [s, simulated].
    EndCriterion(double final_gap, double relaxation)
        : final_gap_(final_gap), relaxation_(relaxation) {}

    /// After each step: simulated time t, liquid level and layer top [m].
    Event update(double t, double level, double top) {
        Event event = Event::none;
        if (state_ == State::following && (top - level > final_gap_ || level <= 0.0)) {
            state_ = State::relaxing;
            final_thickness_ = top;
            time_final_ = t;
            time_end_ = t + relaxation_;
            event = level <= 0.0 ? Event::final_at_substrate : Event::final_reached;
        }
        if (state_ == State::relaxing && t >= time_end_) state_ = State::relaxed;
        return event;
    }

    [[nodiscard]] State state() const { return state_; }
    [[nodiscard]] bool final_found() const { return state_ != State::following; }
    [[nodiscard]] bool done() const { return state_ == State::relaxed; }
    [[nodiscard]] double final_gap() const { return final_gap_; }
    [[nodiscard]] double relaxation() const { return relaxation_; }
    /// H_final [m] (0 before it is found).
    [[nodiscard]] double final_thickness() const { return final_thickness_; }
    /// t* [s, simulated] (0 before the final thickness is found).
    [[nodiscard]] double time_final() const { return time_final_; }
    /// End of the relaxation window [s, simulated] (infinite before the final thickness is found).
    [[nodiscard]] double time_end() const { return time_end_; }

    /// Its part of a resumed run's state.
    void fields(StateFields& f) {
        f("end.state", state_);
        f("end.final_thickness", final_thickness_);
        f("end.time_final", time_final_);
        f("end.time_end", time_end_);
    }

private:
    double final_gap_, relaxation_;
    State state_ = State::following;
    double final_thickness_ = 0.0, time_final_ = 0.0;
    double time_end_ = std::numeric_limits<double>::infinity();
};

} // namespace drydem
