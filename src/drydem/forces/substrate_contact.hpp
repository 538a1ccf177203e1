// SPDX-License-Identifier: MIT
// Particle-substrate contact with the rigid current collector, the plane z = 0: model.md M-2.6,
// the contact law of M-2 against a wall below the particles (wall_contact.hpp):
//   δ = r - z,  n = -ẑ (from the particle toward the wall),  R* = r,  m* = m,
//   lever c_i = r - δ (the contact point lies on the plane),  c_j = 0,  ω_j = 0.
// Aluminium substrate (C-8, C-6); no van der Waals with the wall (C-14).
#pragma once
#include "drydem/forces/body_law.hpp"
#include "drydem/forces/hertz_mindlin.hpp"
#include "drydem/forces/law_limits.hpp"
#include "drydem/forces/wall_contact.hpp"
#include <string_view>

namespace drydem {

/// The contact as a body law (body_law.hpp). Its state is the history of the (particle,
/// substrate) contact, erased when the contact opens (M-2.3, M-2.5); E* = 0: off.
struct SubstrateContactLaw {
    using Params = HertzMindlinParams; ///< the species' material mixed with the substrate's
    using State = ContactHistory;
    static constexpr std::string_view name = "substrate_contact";
    static constexpr auto limits = HertzMindlinLaw::limits;
    static constexpr Wall wall{0.0, -1.0};

    [[gnu::always_inline]] static inline void add_force(const BodyGeometry& g, const Params& p,
                                                        State& s, double dt, BodyForce& f,
                                                        BodyResistance* damping) {
        wall_contact_force(g, p, s, dt, f, damping, wall);
    }
    /// γ_n, γ_t at the deepest overlap within g.reach (the sticking contact's: an upper bound).
    static BodyResistance resistance(const BodyGeometry& g, const Params& p) {
        return wall_contact_bound(g, p, wall, false);
    }
    /// S_n, S_t at the deepest overlap within g.reach (the springs stiffen as it grows).
    static BodyResistance stiffness(const BodyGeometry& g, const Params& p) {
        return wall_contact_bound(g, p, wall, true);
    }
    /// The quasi-static step's resistance: γ_n, and γ_t unless the contact slides.
    static BodyResistance resistance(const BodyGeometry& g, const Params& p, const State& s) {
        return wall_contact_kept(g, p, s, wall, false);
    }
    /// The quasi-static step's stiffness: dF_n/dδ, and S_t unless the contact slides.
    static BodyResistance tangent(const BodyGeometry& g, const Params& p, const State& s) {
        return wall_contact_kept(g, p, s, wall, true);
    }
    static bool keeps(const State& s) { return s.kept(); }
};

} // namespace drydem
