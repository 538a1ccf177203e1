// SPDX-License-Identifier: MIT
// Simulation box: periodic in x and y, rigid substrate plane at z = 0, open top (model.md M-1.6).
#pragma once
#include "drydem/core/vec3.hpp"
#include <cmath>

namespace drydem {

struct Box {
    double lx = 75e-6; ///< periodic length in x [m]
    double ly = 75e-6; ///< periodic length in y [m]

    /// Minimum-image separation vector d = b - a in x and y (M-0); z is not periodic.
    [[nodiscard]] Vec3 minimum_image(const Vec3& a, const Vec3& b) const {
        Vec3 d = b - a;
        d.x -= lx * std::nearbyint(d.x / lx);
        d.y -= ly * std::nearbyint(d.y / ly);
        return d;
    }
    /// Wraps x and y into [0, l).
    void wrap(Vec3& p) const {
        p.x -= lx * std::floor(p.x / lx);
        p.y -= ly * std::floor(p.y / ly);
        if (p.x >= lx) p.x -= lx; // floor rounding at the upper edge
        if (p.y >= ly) p.y -= ly;
    }
    [[nodiscard]] double area() const { return lx * ly; }
};

} // namespace drydem
