// SPDX-License-Identifier: MIT
// ParticleStore::scale_inertia: density scaling of one species (docs/calendering.md).
#include "drydem/core/particles.hpp"
#include <gtest/gtest.h>

namespace drydem {
namespace {

TEST(ParticleStore, ScaleInertiaScalesMassAndInertiaOfOneSpeciesOnly) {
    ParticleStore p;
    p.add(0, 0, 5e-6, 4740.0, {});
    p.add(1, 1, 0.75e-6, 1187.5, {});
    p.add(2, 1, 0.75e-6, 1187.5, {});
    const ParticleStore before = p;
    p.scale_inertia(1, 16.0);
    EXPECT_EQ(p.mass[0], before.mass[0]);
    EXPECT_EQ(p.inv_inertia[0], before.inv_inertia[0]);
    for (std::size_t i : {1u, 2u}) {
        EXPECT_DOUBLE_EQ(p.mass[i], 16.0 * before.mass[i]);
        EXPECT_DOUBLE_EQ(p.inv_mass[i] * p.mass[i], 1.0);
        // I = (2/5) m r^2 with the scaled mass: the sphere stays a uniform sphere.
        EXPECT_DOUBLE_EQ(1.0 / p.inv_inertia[i], 0.4 * p.mass[i] * p.radius[i] * p.radius[i]);
        EXPECT_EQ(p.density[i], before.density[i]) << "gravity reads the physical density";
    }
    p.scale_inertia(1, 1.0 / 16.0);
    EXPECT_DOUBLE_EQ(p.mass[1], before.mass[1]);
}

} // namespace
} // namespace drydem
