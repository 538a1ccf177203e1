// SPDX-License-Identifier: MIT
// Contact with the calendering plate, a rigid plane z = z_p above the film (model.md M-2.9): the
// contact law of M-2 (with Thornton-Ning plasticity when p_y > 0) against a wall above the
// particles (wall_contact.hpp):
//   δ = r - (z_p - z),  n = +ẑ,  R* = r,  m* = m,  lever c_i = r - δ,  c_j = 0,  ω_j = 0.
// The roll's nip is flat on the scale of a particle cell, so the plate spans the periodic cell.
// Its height comes with the particle (BodyGeometry::plate, +inf without a plate).
#pragma once
#include "drydem/forces/body_law.hpp"
#include "drydem/forces/hertz_mindlin.hpp"
#include "drydem/forces/law_limits.hpp"
#include "drydem/forces/wall_contact.hpp"
#include <string_view>

namespace drydem {

/// The contact as a body law (body_law.hpp); E* = 0 (the drying run): off.
struct PlateContactLaw {
    using Params = HertzMindlinParams; ///< the species' material mixed with the plate's
    using State = ContactHistory;
    static constexpr std::string_view name = "plate_contact";
    static constexpr auto limits = HertzMindlinLaw::limits;
    static Wall wall(const BodyGeometry& g) { return {g.plate, 1.0}; }

    [[gnu::always_inline]] static inline void add_force(const BodyGeometry& g, const Params& p,
                                                        State& s, double dt, BodyForce& f,
                                                        BodyResistance* damping) {
        if (p.e_star == 0.0) return; // no plate (the drying run): one compare per particle
        wall_contact_force(g, p, s, dt, f, damping, wall(g));
    }
    static BodyResistance resistance(const BodyGeometry& g, const Params& p) {
        return wall_contact_bound(g, p, wall(g), false);
    }
    static BodyResistance stiffness(const BodyGeometry& g, const Params& p) {
        return wall_contact_bound(g, p, wall(g), true);
    }
    static BodyResistance resistance(const BodyGeometry& g, const Params& p, const State& s) {
        return wall_contact_kept(g, p, s, wall(g), false);
    }
    static BodyResistance tangent(const BodyGeometry& g, const Params& p, const State& s) {
        return wall_contact_kept(g, p, s, wall(g), true);
    }
    static bool keeps(const State& s) { return s.kept(); }
};

} // namespace drydem
