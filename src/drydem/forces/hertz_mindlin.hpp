// SPDX-License-Identifier: MIT
// Hertz-Mindlin (no slip) contact with tangential history, Coulomb limit and optional rolling
// friction: model.md M-2 (EDEM "Hertz-Mindlin (no slip)", LIGGGHTS hertz + tangential history).
//   S_n = 2 E* sqrt(R* δ),  S_t = 8 G* sqrt(R* δ)
//   γ_n = 2 sqrt(5/6) β sqrt(S_n m*),  γ_t = 2 sqrt(5/6) β sqrt(S_t m*),  β = -ln e / sqrt(ln²e + π²)
//   F_n,i = -[(4/3) E* sqrt(R*) δ^{3/2} + γ_n v_n] n            (M-2.2, not clipped)
//   F_t = -S_t ξ - γ_t v_t, |F_t| ≤ μ_s |F_n|                  (M-2.3)
// With a limiting contact pressure p_y > 0 the elastic normal force is Thornton-Ning's
// elastic-plastic one instead (thornton_ning.hpp, M-2.8), for compaction; with a CB agglomerate
// in the contact p_y may harden as the contact's lens compacts it (agglomerate_hardening.hpp,
// M-2.12).
#pragma once
#include "drydem/forces/agglomerate_hardening.hpp"
#include "drydem/forces/pair_geometry.hpp"
#include "drydem/forces/thornton_ning.hpp"
#include "drydem/forces/resistance.hpp"
#include "drydem/forces/law_limits.hpp"
#include <array>
#include <cmath>
#include <numbers>
#include <string_view>

namespace drydem {

/// Pre-mixed contact parameters of one species pair (or species-substrate pair).
struct HertzMindlinParams {
    double e_star = 0.0;           ///< effective Young's modulus E* [Pa]
    double g_star = 0.0;           ///< effective shear modulus G* [Pa]
    double beta = 0.0;             ///< damping ratio from restitution, ≥ 0 (M-2.1)
    double friction = 0.8;         ///< sliding friction μ_s
    double rolling_friction = 0.0; ///< μ_r (C-7: off by default)
    double yield_pressure = 0.0; ///< Thornton-Ning limiting contact pressure p_y [Pa]; 0 = elastic
    /// M-2.12: p_y hardens toward dense_yield_pressure (0 = it does not) as the contact's lens
    /// compacts its agglomerate side(s) from agglomerate_porosity to dense_porosity.
    double dense_yield_pressure = 0.0;
    double agglomerate_porosity = 0.0, dense_porosity = 0.0;
    AgglomerateSides agglomerates = AgglomerateSides::none;
    double agglomerate_compliance_share = 0.0; ///< each agglomerate's share of 1/E*, in [0, 1]
    /// Derived: 2 sqrt(5/6) β sqrt(2 E*) and 2 sqrt(5/6) β sqrt(8 G*), so that
    /// γ_n = damping_n (R* δ)^{1/4} sqrt(m*) and γ_t = damping_t (R* δ)^{1/4} sqrt(m*) (M-2.1)
    /// cost one square root per contact. Set by mix_hertz_mindlin.
    double damping_n = 0.0, damping_t = 0.0;
};

/// β = -ln e / sqrt(ln² e + π²) (M-2.1).
inline double damping_ratio(double restitution) {
    const double l = std::log(restitution);
    return -l / std::sqrt(l * l + std::numbers::pi * std::numbers::pi);
}

/// Rayleigh wave time π r sqrt(ρ/G) / (0.1631 ν + 0.8766), G = E / (2(1+ν)) [s]: the classic DEM
/// step scale of a contact (model.md M-9.2), printed by `drydem check`.
inline double rayleigh_time(double r, double density, double youngs_modulus, double poisson_ratio) {
    const double g = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
    return std::numbers::pi * r * std::sqrt(density / g) / (0.1631 * poisson_ratio + 0.8766);
}

/// Duration of an elastic Hertz collision 2.868 (m*² / (R* E*² v))^{1/5} [s] (M-9.2).
inline double hertz_contact_time(double m_eff, double r_eff, double e_star, double impact_speed) {
    return 2.868 * std::pow(m_eff * m_eff / (r_eff * e_star * e_star * impact_speed), 0.2);
}

/// The overlap at which the Hertz spring (4/3) E* sqrt(R*) δ^{3/2} carries a force F:
/// δ = (3F / (4 E* sqrt(R*)))^{2/3} [m] (the expected overlap of `drydem check`).
inline double hertz_overlap(double force, double r_eff, double e_star) {
    return std::cbrt(std::pow(3.0 * force / (4.0 * e_star * std::sqrt(r_eff)), 2.0));
}

/// E* and G* of two materials (M-2.1).
inline HertzMindlinParams mix_hertz_mindlin(double e_i, double nu_i, double e_j, double nu_j,
                                            double restitution, double friction,
                                            double rolling_friction) {
    HertzMindlinParams p;
    p.e_star = 1.0 / ((1 - nu_i * nu_i) / e_i + (1 - nu_j * nu_j) / e_j);
    p.g_star = 1.0 / (2 * (2 - nu_i) * (1 + nu_i) / e_i + 2 * (2 - nu_j) * (1 + nu_j) / e_j);
    p.beta = damping_ratio(restitution);
    p.friction = friction;
    p.rolling_friction = rolling_friction;
    constexpr double two_sqrt_5_6 = 1.8257418583505538; // 2 sqrt(5/6)
    p.damping_n = two_sqrt_5_6 * p.beta * std::sqrt(2.0 * p.e_star);
    p.damping_t = two_sqrt_5_6 * p.beta * std::sqrt(8.0 * p.g_star);
    return p;
}

/// The hardening of the pair's limiting pressure (M-2.12).
inline AgglomerateHardening agglomerate_hardening(const HertzMindlinParams& p) {
    return {p.agglomerate_porosity, p.dense_porosity, p.dense_yield_pressure, p.agglomerates,
            p.agglomerate_compliance_share};
}

/// Stiffnesses and damping coefficients of a contact with overlap δ (M-2.1); shared by the law,
/// its resistance (resistance.hpp) and the stability guard's stiffness operator.
struct HertzMindlinCoefficients {
    double s_n, s_t;         ///< S_n = 2 E* sqrt(R* δ), S_t = 8 G* sqrt(R* δ) [N/m]
    double gamma_n, gamma_t; ///< γ_n, γ_t [kg/s]
};
inline HertzMindlinCoefficients hertz_mindlin_coefficients(double r_eff, double overlap,
                                                           double m_eff,
                                                           const HertzMindlinParams& p) {
    const double sqrt_rd = std::sqrt(r_eff * overlap);
    const double root = std::sqrt(sqrt_rd * m_eff); // (R* δ)^{1/4} sqrt(m*)
    return {2.0 * p.e_star * sqrt_rd, 8.0 * p.g_star * sqrt_rd, p.damping_n * root,
            p.damping_t * root};
}
/// The elastic normal force (4/3) E* sqrt(R*) δ^{3/2} = (2/3) S_n δ (M-2.2).
inline double hertz_elastic_force(const HertzMindlinCoefficients& co, double overlap) {
    return (2.0 / 3.0) * co.s_n * overlap;
}
/// The conservative normal force and its slope given the deepest overlap the contact reached:
/// Hertz, or Thornton-Ning's elastic-plastic force when p_y > 0 (M-2.8), with p_y hardened at
/// the deepest overlap (M-2.12).
inline ElasticPlasticNormal contact_normal(const HertzMindlinCoefficients& co,
                                           const ContactSpheres& spheres, double r_eff,
                                           double overlap, const HertzMindlinParams& p,
                                           double max_overlap) {
    if (p.yield_pressure > 0.0) {
        const double deepest = std::max(max_overlap, overlap);
        const HardenedYield y =
            hardened_yield(agglomerate_hardening(p), p.yield_pressure, spheres, deepest);
        return thornton_ning_normal(p.e_star * y.modulus_factor, r_eff, y.pressure, overlap,
                                    deepest, y.slope);
    }
    return {hertz_elastic_force(co, overlap), co.s_n};
}

/// The stability guard's normal stiffness bound at an overlap: the Hertz S_n, or with hardening
/// (M-2.12) the larger of the Hertz S_n at the hardened modulus (the unloading slope) and the
/// plastic line's slope.
inline double contact_stiffness_bound(const HertzMindlinCoefficients& co,
                                      const ContactSpheres& spheres, double r_eff, double overlap,
                                      const HertzMindlinParams& p) {
    if (p.yield_pressure <= 0.0 || !agglomerate_hardening(p).hardens()) return co.s_n;
    const HardenedYield y =
        hardened_yield(agglomerate_hardening(p), p.yield_pressure, spheres, overlap);
    return std::max(co.s_n * y.modulus_factor,
                    contact_normal(co, spheres, r_eff, overlap, p, overlap).stiffness);
}

/// Contact state of the shared law below: overlap δ > 0, lever arms from the centres to the
/// contact point, R*, m*, normal n (from i toward the partner) and the kinematics.
struct ContactKinematics {
    Vec3 n;
    double overlap;          ///< δ [m]
    ContactSpheres spheres;  ///< r_i, r_j (0: a plane)
    double r_eff, m_eff;     ///< R*, m*
    double lever_i, lever_j; ///< c_i, c_j [m] (M-2.3; c_j = 0 for the substrate)
    Vec3 v_rel;              ///< v_i - v_j
    Vec3 omega_i, omega_j;
};

/// Output of the contact law: force on i, torques on i and j, |F_n| (for diagnostics), and the
/// damping it applied (resistance.hpp pair form: γ_n, and γ_t only while the contact sticks).
struct ContactForce {
    Vec3 force_i;
    Vec3 torque_i;
    Vec3 torque_j;
    double normal_force;
    double damping_n, damping_t;
    /// The conservative normal force and its slope dF_n/dδ at the deepest overlap kept, and S_t:
    /// what the contact's tangent (hertz_mindlin_tangent) needs, so the pair loop does not
    /// evaluate the law twice.
    double elastic_force, normal_stiffness, s_t;
};

/// What a contact keeps: the tangential spring ξ and, with plasticity, the deepest overlap
/// δ_max (both erased when the contact opens, M-2.3, M-2.8).
struct ContactHistory {
    Vec3 spring;            ///< ξ [m]
    double max_overlap = 0; ///< δ_max [m]; 0 while p_y = 0
    [[nodiscard]] bool kept() const {
        return spring.x != 0.0 || spring.y != 0.0 || spring.z != 0.0 || max_overlap != 0.0;
    }
};

/// Whether a spring ξ of stiffness S_t sits at the Coulomb limit S_t |ξ| = μ F_n (as the law
/// leaves it after a cut), to rounding: the contact slides.
inline bool spring_at_coulomb_limit(double s_t, const Vec3& spring, double f_coulomb) {
    return s_t * norm(spring) >= (1.0 - 1e-6) * f_coulomb && norm2(spring) > 0.0;
}

/// Whether a contact at this overlap slides: its spring ξ sits at the Coulomb limit
/// S_t |ξ| = μ F_n (F_n elastic, at rest).
inline bool hertz_mindlin_sliding(const HertzMindlinCoefficients& co, const ContactSpheres& spheres,
                                  double r_eff, double overlap, const HertzMindlinParams& p,
                                  const ContactHistory& h) {
    const double f_coulomb =
        p.friction * contact_normal(co, spheres, r_eff, overlap, p, h.max_overlap).force;
    return spring_at_coulomb_limit(co.s_t, h.spring, f_coulomb);
}

/// The stiffness of a contact (pair form) given its normal slope dF_n/dδ, S_t, its elastic
/// normal force and its spring: dF_n/dδ, and S_t while it sticks; a sliding contact resists no
/// further tangential motion (its force stays μ F_n).
inline PairResistance contact_tangent(double s_n, double s_t, double f_elastic, const Vec3& spring,
                                      double friction) {
    return {s_n, spring_at_coulomb_limit(s_t, spring, friction * f_elastic) ? 0.0 : s_t,
            0.0, 0.0,
            0.0, 0.0};
}

/// The quasi-static step's stiffness of a contact (pair form) at an overlap, given what it keeps.
inline PairResistance hertz_mindlin_tangent(const HertzMindlinCoefficients& co,
                                            const ContactSpheres& spheres, double r_eff,
                                            double overlap, const HertzMindlinParams& p,
                                            const ContactHistory& h) {
    const ElasticPlasticNormal n = contact_normal(co, spheres, r_eff, overlap, p, h.max_overlap);
    return contact_tangent(n.stiffness, co.s_t, n.force, h.spring, p.friction);
}

/// Evaluates the Hertz-Mindlin law and advances the contact's history h by one step dt.
inline ContactForce hertz_mindlin_contact(const ContactKinematics& k, const HertzMindlinParams& p,
                                          ContactHistory& h, double dt) {
    Vec3& xi = h.spring;
    const Vec3& n = k.n;
    const HertzMindlinCoefficients co = hertz_mindlin_coefficients(k.r_eff, k.overlap, k.m_eff, p);
    const double s_t = co.s_t;
    const double gamma_n = co.gamma_n; // 2 sqrt(5/6) β sqrt(S_n m*)
    const double gamma_t = co.gamma_t; // 2 sqrt(5/6) β sqrt(S_t m*)

    const double v_n = dot(k.v_rel, n);
    // M-2.2: elastic (4/3) E* sqrt(R*) δ^{3/2} = (2/3) S_n δ (or M-2.8 with yield), plus viscous
    // damping; not clipped.
    double f_elastic, s_n = co.s_n;
    if (p.yield_pressure > 0.0) {
        h.max_overlap = std::max(h.max_overlap, k.overlap);
        const ElasticPlasticNormal ep =
            contact_normal(co, k.spheres, k.r_eff, k.overlap, p, h.max_overlap);
        f_elastic = ep.force;
        s_n = ep.stiffness;
    } else {
        f_elastic = hertz_elastic_force(co, k.overlap);
    }
    const double fn_mag = f_elastic + gamma_n * v_n;
    ContactForce out;
    out.elastic_force = f_elastic;
    out.normal_stiffness = s_n;
    out.s_t = s_t;
    out.normal_force = std::abs(fn_mag);
    out.damping_n = gamma_n;
    out.damping_t = gamma_t;
    out.force_i = -fn_mag * n;

    // M-2.3: contact-point velocity and its tangential part.
    const Vec3 v_c = k.v_rel + cross(k.lever_i * k.omega_i + k.lever_j * k.omega_j, n);
    const Vec3 v_t = perp(v_c, n);

    // C-4: rotate the spring onto the current tangent plane, keep its length.
    xi = onto_plane(xi, n) + v_t * dt;

    Vec3 ft = -s_t * xi - gamma_t * v_t;
    const double f_coulomb = p.friction * out.normal_force; // C-5: contact force only
    const double spring2 = s_t * s_t * norm2(xi);
    if (spring2 > f_coulomb * f_coulomb) {
        // Sliding: cut the spring back to the Coulomb limit; no tangential damping while sliding.
        const double scale = f_coulomb / std::sqrt(spring2);
        xi *= scale;
        ft = -s_t * xi;
        out.damping_t = 0.0;
    }
    out.force_i += ft;
    // Torques from the tangential force at the contact point (M-2.3).
    out.torque_i = k.lever_i * cross(n, ft);
    out.torque_j = k.lever_j * cross(n, ft);

    if (p.rolling_friction > 0.0) {
        // M-2.4 (EDEM/LIGGGHTS CDT rolling resistance).
        const Vec3 w_rel = perp(k.omega_i - k.omega_j, n);
        const double w2 = norm2(w_rel);
        if (w2 > 0.0) {
            const Vec3 t_roll =
                (-p.rolling_friction * out.normal_force * k.r_eff / std::sqrt(w2)) * w_rel;
            out.torque_i += t_roll;
            out.torque_j -= t_roll;
        }
    }
    return out;
}

/// Particle-particle contact (δ = -h > 0), lever arms c = r - δ/2. `damping` receives the
/// viscous part as a resistance (resistance.hpp pair form); `tangent` the contact's stiffness
/// after the step, as hertz_mindlin_tangent gives it from the history the step leaves.
inline PairForce hertz_mindlin(const PairGeometry& g, const HertzMindlinParams& p,
                               ContactHistory& history, double dt,
                               PairResistance* damping = nullptr,
                               PairResistance* tangent = nullptr) {
    const double overlap = -g.gap;
    const ContactKinematics k{g.n,
                              overlap,
                              {g.r_i, g.r_j},
                              g.r_eff,
                              g.m_eff,
                              g.r_i - 0.5 * overlap,
                              g.r_j - 0.5 * overlap,
                              g.v_rel,
                              g.omega_i,
                              g.omega_j};
    const ContactForce c = hertz_mindlin_contact(k, p, history, dt);
    if (damping) {
        damping->normal += c.damping_n;
        damping->sliding += c.damping_t;
    }
    if (tangent)
        *tangent +=
            contact_tangent(c.normal_stiffness, c.s_t, c.elastic_force, history.spring, p.friction);
    return {c.force_i, c.torque_i, c.torque_j};
}

/// The same for a contact whose only history is the spring ξ (no plasticity kept).
inline PairForce hertz_mindlin(const PairGeometry& g, const HertzMindlinParams& p, Vec3& xi,
                               double dt, PairResistance* damping = nullptr) {
    ContactHistory h{xi};
    const PairForce f = hertz_mindlin(g, p, h, dt, damping);
    xi = h.spring;
    return f;
}

/// The contact as a pair law (pair_law.hpp). Its state is the contact's history (the tangential
/// spring ξ, and δ_max with plasticity), erased when the contact opens (M-2.3).
struct HertzMindlinLaw {
    using Params = HertzMindlinParams;
    using State = ContactHistory;
    static constexpr std::string_view name = "hertz_mindlin";
    static constexpr std::array limits{
        ParamLimit<Params>{"e_star", &Params::e_star},
        ParamLimit<Params>{"g_star", &Params::g_star},
        ParamLimit<Params>{"beta", &Params::beta},
        ParamLimit<Params>{"friction", &Params::friction},
        ParamLimit<Params>{"rolling_friction", &Params::rolling_friction},
        ParamLimit<Params>{"yield_pressure", &Params::yield_pressure},
        ParamLimit<Params>{"dense_yield_pressure", &Params::dense_yield_pressure},
        ParamLimit<Params>{"agglomerate_porosity", &Params::agglomerate_porosity, 0.0, 1.0, false,
                           true},
        ParamLimit<Params>{"dense_porosity", &Params::dense_porosity, 0.0, 1.0, false, true},
        ParamLimit<Params>{"agglomerate_compliance_share", &Params::agglomerate_compliance_share,
                           0.0, 1.0},
        ParamLimit<Params>{"damping_n", &Params::damping_n},
        ParamLimit<Params>{"damping_t", &Params::damping_t}};
    static double range(const Params&, double, double) { return 0.0; } // acts in overlap only
    [[gnu::always_inline]] static inline void add_force(const PairGeometry& g, const Params& p,
                                                        State& s, double dt, PairForce& f,
                                                        PairResistance* damping,
                                                        PairResistance* tangent = nullptr) {
        if (g.gap < 0.0)
            f += hertz_mindlin(g, p, s, dt, damping, tangent);
        else
            s = State{};
    }
    /// γ_n and γ_t (the sticking contact's, an upper bound of the damping it applies).
    static PairResistance resistance(const PairGeometry& g, const Params& p) {
        if (g.gap >= 0.0) return {};
        const HertzMindlinCoefficients co = hertz_mindlin_coefficients(g.r_eff, -g.gap, g.m_eff, p);
        return {co.gamma_n, co.gamma_t, 0.0, 0.0, 0.0, 0.0};
    }
    /// S_n, S_t at the overlap the pair can reach before the next rebuild: the springs stiffen
    /// as the overlap grows, so the closest approach bounds their rate.
    static PairResistance stiffness(const PairGeometry& closest, const PairGeometry&,
                                    const Params& p) {
        if (closest.gap >= 0.0) return {};
        const HertzMindlinCoefficients co =
            hertz_mindlin_coefficients(closest.r_eff, -closest.gap, closest.m_eff, p);
        return {
            contact_stiffness_bound(co, {closest.r_i, closest.r_j}, closest.r_eff, -closest.gap, p),
            co.s_t,
            0.0,
            0.0,
            0.0,
            0.0};
    }
    /// The quasi-static step's resistance: γ_n, and γ_t unless the contact slides.
    static PairResistance resistance(const PairGeometry& g, const Params& p, const State& s) {
        if (g.gap >= 0.0) return {};
        const HertzMindlinCoefficients co = hertz_mindlin_coefficients(g.r_eff, -g.gap, g.m_eff, p);
        const bool slides = hertz_mindlin_sliding(co, {g.r_i, g.r_j}, g.r_eff, -g.gap, p, s);
        return {co.gamma_n, slides ? 0.0 : co.gamma_t, 0.0, 0.0, 0.0, 0.0};
    }
    /// The quasi-static step's stiffness: S_n, and S_t unless the contact slides.
    static PairResistance tangent(const PairGeometry& g, const Params& p, const State& s) {
        if (g.gap >= 0.0) return {};
        const HertzMindlinCoefficients co = hertz_mindlin_coefficients(g.r_eff, -g.gap, g.m_eff, p);
        return hertz_mindlin_tangent(co, {g.r_i, g.r_j}, g.r_eff, -g.gap, p, s);
    }
    /// Any component non-zero (four compares: most list slots are pairs out of reach, where the
    /// pair loop asks this every step).
    static bool keeps(const State& s) { return s.kept(); }
};

} // namespace drydem
