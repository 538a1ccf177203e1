// SPDX-License-Identifier: MIT
// Particle-substrate contact with the rigid current collector, the plane z = 0: model.md M-2.6,
// the Hertz-Mindlin law of M-2 (hertz_mindlin.hpp) with
//   δ = r - z,  n = -ẑ (from the particle toward the wall),  R* = r,  m* = m,
//   lever c_i = r - δ (the contact point lies on the plane),  c_j = 0,  ω_j = 0.
// Aluminium substrate (C-8, C-6); no van der Waals with the wall (C-14).
#pragma once
#include "drydem/forces/body_law.hpp"
#include "drydem/forces/hertz_mindlin.hpp"
#include "drydem/forces/law_limits.hpp"
#include <array>
#include <string_view>

namespace drydem {

/// The contact as a body law (body_law.hpp). Its state is the tangential spring ξ of the
/// (particle, substrate) contact, erased when the contact opens (M-2.3, M-2.5); E* = 0: off.
struct SubstrateContactLaw {
    using Params = HertzMindlinParams; ///< the species' material mixed with the substrate's
    struct State {
        Vec3 spring; ///< ξ [m]
    };
    static constexpr std::string_view name = "substrate_contact";
    static constexpr auto limits = HertzMindlinLaw::limits;

    [[gnu::always_inline]] static inline void add_force(const BodyGeometry& g, const Params& p,
                                                        State& s, double dt, BodyForce& f,
                                                        BodyResistance* damping) {
        const double overlap = g.r - g.x.z;
        if (overlap <= 0.0 || p.e_star == 0.0) {
            s.spring = {};
            return;
        }
        const ContactKinematics k{
            Vec3{0.0, 0.0, -1.0}, overlap, g.r, g.mass, g.r - overlap, 0.0, g.v, g.omega, {}};
        const ContactForce c = hertz_mindlin_contact(k, p, s.spring, dt);
        if (damping) *damping += wall_pair_resistance(c.damping_n, c.damping_t, k.lever_i);
        f += BodyForce{c.force_i, c.torque_i};
    }
    /// γ_n, γ_t at the deepest overlap within g.reach (the sticking contact's: an upper bound).
    static BodyResistance resistance(const BodyGeometry& g, const Params& p) {
        const double overlap = g.r - (g.x.z - g.reach);
        if (overlap <= 0.0 || p.e_star == 0.0) return {};
        const HertzMindlinCoefficients co = hertz_mindlin_coefficients(g.r, overlap, g.mass, p);
        return wall_pair_resistance(co.gamma_n, co.gamma_t, g.r - overlap);
    }
    /// S_n, S_t at the deepest overlap within g.reach (the springs stiffen as it grows).
    static BodyResistance stiffness(const BodyGeometry& g, const Params& p) {
        const double overlap = g.r - (g.x.z - g.reach);
        if (overlap <= 0.0 || p.e_star == 0.0) return {};
        const HertzMindlinCoefficients co = hertz_mindlin_coefficients(g.r, overlap, g.mass, p);
        return wall_pair_resistance(co.s_n, co.s_t, g.r - overlap);
    }
    /// The quasi-static step's resistance: γ_n, and γ_t unless the contact slides.
    static BodyResistance resistance(const BodyGeometry& g, const Params& p, const State& s) {
        const double overlap = g.r - g.x.z;
        if (overlap <= 0.0 || p.e_star == 0.0) return {};
        const HertzMindlinCoefficients co = hertz_mindlin_coefficients(g.r, overlap, g.mass, p);
        const bool slides = hertz_mindlin_sliding(co, overlap, p, s.spring);
        return wall_pair_resistance(co.gamma_n, slides ? 0.0 : co.gamma_t, g.r - overlap);
    }
    /// The quasi-static step's stiffness: S_n, and S_t unless the contact slides.
    static BodyResistance tangent(const BodyGeometry& g, const Params& p, const State& s) {
        const double overlap = g.r - g.x.z;
        if (overlap <= 0.0 || p.e_star == 0.0) return {};
        const HertzMindlinCoefficients co = hertz_mindlin_coefficients(g.r, overlap, g.mass, p);
        const PairResistance k = hertz_mindlin_tangent(co, overlap, p, s.spring);
        return wall_pair_resistance(k.normal, k.sliding, g.r - overlap);
    }
    static bool keeps(const State& s) {
        return s.spring.x != 0.0 || s.spring.y != 0.0 || s.spring.z != 0.0;
    }
};

} // namespace drydem
