// SPDX-License-Identifier: MIT
// Contact of a particle with a rigid plane z = z_w, shared by the substrate below the film
// (M-2.6) and the calendering plate above it (M-2.9): the contact law of M-2 (hertz_mindlin.hpp,
// with Thornton-Ning plasticity when p_y > 0) with
//   δ = r - s (z_w - z),  n = s ẑ (from the particle to the wall; s = -1 below, +1 above),
//   R* = r,  m* = m,  lever c_i = r - δ (the contact point lies on the plane),  c_j = 0,  ω_j = 0.
#pragma once
#include "drydem/forces/body_law.hpp"
#include "drydem/forces/hertz_mindlin.hpp"
#include <string_view>

namespace drydem {

/// A rigid plane: its height and on which side of the particles it lies.
struct Wall {
    double height = 0.0; ///< z_w [m]
    double side = -1.0;  ///< -1: below the particles (substrate), +1: above them (plate)
};

/// δ = r - s (z_w - z) of a particle centred at z, moved by `reach` toward the wall [m].
inline double wall_overlap(const BodyGeometry& g, const Wall& w, double reach = 0.0) {
    return g.r - w.side * (w.height - g.x.z) + reach;
}

/// The body form (resistance.hpp) of the contact's coefficients a_n, a_t at lever c; the
/// rotation-translation coupling changes sign with the side the contact point lies on.
inline BodyResistance wall_resistance(double a_n, double a_t, double lever, const Wall& w) {
    return wall_pair_resistance(a_n, a_t, -w.side * lever);
}

/// Adds the contact's force and torque; advances (or erases, out of contact) its history.
/// E* = 0 (a wall that is not there, e.g. the plate while the film dries): one compare.
[[gnu::always_inline]] inline void wall_contact_force(const BodyGeometry& g,
                                                      const HertzMindlinParams& p,
                                                      ContactHistory& s, double dt, BodyForce& f,
                                                      BodyResistance* damping, const Wall& w) {
    if (p.e_star == 0.0) return;
    const double overlap = wall_overlap(g, w);
    if (overlap <= 0.0) {
        s = {};
        return;
    }
    const ContactKinematics k{Vec3{0.0, 0.0, w.side}, overlap, {g.r, 0.0}, g.r,     g.mass,
                              g.r - overlap,          0.0,     g.v,        g.omega, {}};
    const ContactForce c = hertz_mindlin_contact(k, p, s, dt);
    if (damping) *damping += wall_resistance(c.damping_n, c.damping_t, k.lever_i, w);
    f += BodyForce{c.force_i, c.torque_i};
}

/// γ_n, γ_t (or S_n, S_t with `springs`) at the deepest overlap within g.reach: the sticking
/// contact's, an upper bound, as the coefficients grow with the overlap.
inline BodyResistance wall_contact_bound(const BodyGeometry& g, const HertzMindlinParams& p,
                                         const Wall& w, bool springs) {
    const double overlap = wall_overlap(g, w, g.reach);
    if (overlap <= 0.0 || p.e_star == 0.0) return {};
    const HertzMindlinCoefficients co = hertz_mindlin_coefficients(g.r, overlap, g.mass, p);
    return springs ? wall_resistance(contact_stiffness_bound(co, {g.r, 0.0}, g.r, overlap, p),
                                     co.s_t, g.r - overlap, w)
                   : wall_resistance(co.gamma_n, co.gamma_t, g.r - overlap, w);
}

/// The quasi-static step's linearisation given the history: the resistance (γ_n, and γ_t unless
/// the contact slides) or, with `springs`, the stiffness (dF_n/dδ, and S_t unless it slides).
inline BodyResistance wall_contact_kept(const BodyGeometry& g, const HertzMindlinParams& p,
                                        const ContactHistory& s, const Wall& w, bool springs) {
    const double overlap = wall_overlap(g, w);
    if (overlap <= 0.0 || p.e_star == 0.0) return {};
    const HertzMindlinCoefficients co = hertz_mindlin_coefficients(g.r, overlap, g.mass, p);
    if (springs) {
        const PairResistance k = hertz_mindlin_tangent(co, {g.r, 0.0}, g.r, overlap, p, s);
        return wall_resistance(k.normal, k.sliding, g.r - overlap, w);
    }
    const bool slides = hertz_mindlin_sliding(co, {g.r, 0.0}, g.r, overlap, p, s);
    return wall_resistance(co.gamma_n, slides ? 0.0 : co.gamma_t, g.r - overlap, w);
}

/// The contact with one wall as a body law (body_law.hpp), for a `Side` that names it and places
/// its plane (substrate_contact.hpp, plate_contact.hpp). Its state is the contact's history,
/// erased when the contact opens (M-2.3, M-2.5).
template <class Side>
struct WallContactLaw {
    using Params = HertzMindlinParams; ///< the species' material mixed with the wall's
    using State = ContactHistory;
    static constexpr std::string_view name = Side::name;
    static constexpr auto limits = HertzMindlinLaw::limits;

    [[gnu::always_inline]] static inline void add_force(const BodyGeometry& g, const Params& p,
                                                        State& s, double dt, BodyForce& f,
                                                        BodyResistance* damping) {
        wall_contact_force(g, p, s, dt, f, damping, Side::wall(g));
    }
    /// γ_n, γ_t at the deepest overlap within g.reach (the sticking contact's: an upper bound).
    static BodyResistance resistance(const BodyGeometry& g, const Params& p) {
        return wall_contact_bound(g, p, Side::wall(g), false);
    }
    /// S_n, S_t at the deepest overlap within g.reach (the springs stiffen as it grows).
    static BodyResistance stiffness(const BodyGeometry& g, const Params& p) {
        return wall_contact_bound(g, p, Side::wall(g), true);
    }
    /// The quasi-static step's resistance: γ_n, and γ_t unless the contact slides.
    static BodyResistance resistance(const BodyGeometry& g, const Params& p, const State& s) {
        return wall_contact_kept(g, p, s, Side::wall(g), false);
    }
    /// The quasi-static step's stiffness: dF_n/dδ, and S_t unless the contact slides.
    static BodyResistance tangent(const BodyGeometry& g, const Params& p, const State& s) {
        return wall_contact_kept(g, p, s, Side::wall(g), true);
    }
    static bool keeps(const State& s) { return s.kept(); }
};

} // namespace drydem
