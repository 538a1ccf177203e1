// SPDX-License-Identifier: MIT
// Simulation box: periodic in x and y, rigid substrate plane at z = 0, open top (model.md M-1.6).
#pragma once
#include "drydem/core/vec3.hpp"
#include <cmath>

namespace drydem {

struct Box {
    double lx = 75e-6; ///< periodic length in x [m]
    double ly = 75e-6; ///< periodic length in y [m]

    /// Minimum-image separation vector d = b - a in x and y (M-0); z is not periodic. Both points
    /// must lie within one period of each other's image (true for wrapped positions).
    [[nodiscard]] Vec3 minimum_image(const Vec3& a, const Vec3& b) const {
        Vec3 d = b - a;
        // Branches instead of nearbyint(d/l): no division in the pair loop.
        if (d.x > 0.5 * lx)
            d.x -= lx;
        else if (d.x < -0.5 * lx)
            d.x += lx;
        if (d.y > 0.5 * ly)
            d.y -= ly;
        else if (d.y < -0.5 * ly)
            d.y += ly;
        return d;
    }
    /// Wraps x and y into [0, l). A particle moves far less than a period per step, so one
    /// correction suffices; far-away points (input files) take the floor path.
    void wrap(Vec3& p) const {
        if (p.x < 0.0 || p.x >= lx) {
            p.x -= lx * std::floor(p.x / lx);
            if (p.x >= lx) p.x -= lx; // floor rounding at the upper edge
        }
        if (p.y < 0.0 || p.y >= ly) {
            p.y -= ly * std::floor(p.y / ly);
            if (p.y >= ly) p.y -= ly;
        }
    }
    [[nodiscard]] double area() const { return lx * ly; }
};

} // namespace drydem
