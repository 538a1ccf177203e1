// SPDX-License-Identifier: MIT
// Particle-substrate contact with the rigid current collector, the plane z = 0: model.md M-2.6,
// the contact law of M-2 against a wall below the particles (wall_contact.hpp):
//   δ = r - z,  n = -ẑ (from the particle toward the wall),  R* = r,  m* = m,
//   lever c_i = r - δ (the contact point lies on the plane),  c_j = 0,  ω_j = 0.
// Aluminium substrate (C-8, C-6); no van der Waals with the wall (C-14). E* = 0: off.
#pragma once
#include "drydem/forces/wall_contact.hpp"
#include <string_view>

namespace drydem {

/// The substrate: the plane z = 0 below the film.
struct SubstrateSide {
    static constexpr std::string_view name = "substrate_contact";
    static constexpr Wall wall(const BodyGeometry&) { return {0.0, -1.0}; }
};
using SubstrateContactLaw = WallContactLaw<SubstrateSide>;

} // namespace drydem
