// SPDX-License-Identifier: MIT
// Estimated time to the end of a run from the recent pace: simulated seconds per wall second over
// a sliding window of progress samples. The pace of a drying run changes by several times (the
// guard's step follows the packing, contacts multiply as the film consolidates), so the pace since
// the start would keep the ETA too optimistic late in the run.
#pragma once
#include <algorithm>
#include <deque>

namespace drydem {

class RecentPace {
public:
    /// window: wall seconds over which the pace is measured.
    explicit RecentPace(double window = 120.0) : window_(window) {}

    /// Records a sample: wall-clock seconds since some origin and the simulated time reached.
    void add(double wall, double sim_time) {
        samples_.push_back({wall, sim_time});
        // Keep one sample older than the window so that the window is always spanned.
        while (samples_.size() > 2 && samples_[1].wall <= wall - window_) samples_.pop_front();
    }

    /// Simulated seconds per wall second over the window; 0 before two samples.
    [[nodiscard]] double pace() const {
        if (samples_.size() < 2) return 0.0;
        const Sample& a = samples_.front();
        const Sample& b = samples_.back();
        return b.wall > a.wall ? (b.sim_time - a.sim_time) / (b.wall - a.wall) : 0.0;
    }

    /// Wall seconds to cover `remaining` simulated seconds at the recent pace (infinite if none).
    [[nodiscard]] double eta(double remaining) const {
        const double p = pace();
        return p > 0.0 ? std::max(remaining, 0.0) / p : 1.0 / 0.0;
    }

private:
    struct Sample {
        double wall, sim_time;
    };
    double window_;
    std::deque<Sample> samples_;
};

} // namespace drydem
