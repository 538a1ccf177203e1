// SPDX-License-Identifier: MIT
// The descending liquid level (model.md M-8.1): z_L(0) = H_wet, then piecewise linear with the
// scaled shrinkage rate of each dryer zone; the last zone's rate continues (C-21). The level stops
// at the substrate.
#pragma once
#include <algorithm>
#include <vector>

namespace drydem {

struct LiquidLevelSchedule {
    double initial_level = 0.0; ///< H_wet [m]
    std::vector<double> speeds; ///< scaled level speed per zone [m/s], > 0 = downward
    double zone_duration = 0.0; ///< scaled duration of one zone [s]

    /// Zone index at simulated time t (the last zone continues).
    [[nodiscard]] int zone(double t) const {
        const int z = int(t / zone_duration);
        return std::min(z, int(speeds.size()) - 1);
    }
    /// z_L(t) [m].
    [[nodiscard]] double level(double t) const {
        double z = initial_level, t0 = 0.0;
        for (std::size_t k = 0; k < speeds.size(); ++k) {
            const bool last = k + 1 == speeds.size();
            const double t1 = last ? t : std::min(t, t0 + zone_duration);
            if (t1 <= t0) break;
            z -= speeds[k] * (t1 - t0);
            t0 = t1;
        }
        return std::max(0.0, z);
    }
    /// Simulated time at which the level reaches height z [s] (the inverse of level()).
    [[nodiscard]] double time_at_level(double z) const {
        double level_now = initial_level, t0 = 0.0;
        for (std::size_t k = 0; k < speeds.size(); ++k) {
            const bool last = k + 1 == speeds.size();
            const double drop = speeds[k] * zone_duration;
            if (last || level_now - drop <= z) return t0 + std::max(0.0, level_now - z) / speeds[k];
            level_now -= drop;
            t0 += zone_duration;
        }
        return t0;
    }
};

} // namespace drydem
