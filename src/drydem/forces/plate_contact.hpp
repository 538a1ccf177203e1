// SPDX-License-Identifier: MIT
// Contact with the calendering plate, a rigid plane z = z_p above the film (model.md M-2.9): the
// contact law of M-2 (with Thornton-Ning plasticity when p_y > 0) against a wall above the
// particles (wall_contact.hpp):
//   δ = r - (z_p - z),  n = +ẑ,  R* = r,  m* = m,  lever c_i = r - δ,  c_j = 0,  ω_j = 0.
// The roll's nip is flat on the scale of a particle cell, so the plate spans the periodic cell.
// Its height comes with the particle (BodyGeometry::plate, +inf without a plate); E* = 0 (the
// drying run): off.
#pragma once
#include "drydem/forces/wall_contact.hpp"
#include <string_view>

namespace drydem {

/// The plate: the plane z = z_p above the film.
struct PlateSide {
    static constexpr std::string_view name = "plate_contact";
    static constexpr Wall wall(const BodyGeometry& g) { return {g.plate, 1.0}; }
};
using PlateContactLaw = WallContactLaw<PlateSide>;

} // namespace drydem
