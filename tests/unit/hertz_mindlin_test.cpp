// SPDX-License-Identifier: MIT
// Hertz-Mindlin pair contact (model.md M-2.1-M-2.4) against the V-2 statics and the law's
// properties: Coulomb cap with rescaled history, history rotation (C-4), lever-arm torques,
// rolling friction (C-7 option), Newton's third law and angular momentum.
#include "drydem/forces/hertz_mindlin.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>

namespace {
using namespace drydem;

constexpr double kR = 0.75e-6;   // CB radius
constexpr double kRNcm = 4.3e-6; // NCM radius of V-2
constexpr double kDelta = 10e-9; // overlap of V-2
constexpr double kDt = 1e-11;
constexpr double kPi = std::numbers::pi;
const Vec3 kN = Vec3{1.0, 2.0, -2.0} / 3.0; // oblique unit normal (i -> j)
const Vec3 kT = Vec3{2.0, 1.0, 2.0} / 3.0;  // unit tangent, kT ⊥ kN
const Vec3 kB = cross(kN, kT);              // second unit tangent

void expect_rel(double actual, double expected, double rel) {
    EXPECT_NEAR(actual, expected, rel * std::abs(expected)) << "expected " << expected;
}

double sphere_mass(double r, double rho = 1187.5) { return 4.0 / 3.0 * kPi * r * r * r * rho; }

// E = 142 GPa, ν = 0.3 for both (M-2.7), e = 0.5, μ_s = 0.8.
HertzMindlinParams material(double e = 0.5, double mu = 0.8, double mu_r = 0.0) {
    return mix_hertz_mindlin(142e9, 0.3, 142e9, 0.3, e, mu, mu_r);
}

/// Pair (i, j) with overlap δ along n; velocities and spins as given.
PairGeometry pair(double r_i, double r_j, double overlap, const Vec3& v_i = {},
                  const Vec3& v_j = {}, const Vec3& w_i = {}, const Vec3& w_j = {},
                  const Vec3& n = kN) {
    const double d = r_i + r_j - overlap;
    return make_pair_geometry(d * n, d, r_i, r_j, sphere_mass(r_i), sphere_mass(r_j), v_i, v_j, w_i,
                              w_j);
}

// M-2.1 / M-10 header: E* = 7.8022e10 Pa, G* = 1.6063e10 Pa; β(e = 0.5).
TEST(HertzMindlin, EffectiveConstants) {
    const HertzMindlinParams p = material();
    expect_rel(p.e_star, 7.8022e10, 1e-5);
    expect_rel(p.g_star, 1.6063e10, 1e-4);
    // Closed forms (1e-12): E/(2(1-ν²)), E/(4(2-ν)(1+ν)).
    expect_rel(p.e_star, 142e9 / (2 * (1 - 0.09)), 1e-12);
    expect_rel(p.g_star, 142e9 / (4 * 1.7 * 1.3), 1e-12);
    // β = -ln e / sqrt(ln²e + π²): 0.2154538 for e = 0.5, 0 for e = 1, → 1 for e → 0.
    expect_rel(damping_ratio(0.5), 0.21545376, 1e-7);
    EXPECT_EQ(damping_ratio(1.0), 0.0);
    EXPECT_GT(damping_ratio(1e-9), 0.98);
}

// V-2: static normal force and normal stiffness at δ = 10 nm.
TEST(HertzMindlin, StaticNormalForceV2) {
    Vec3 xi;
    const PairForce cb = hertz_mindlin(pair(kR, kR, kDelta), material(), xi, kDt);
    // Repulsive: the force on i points away from j (along -n).
    expect_rel(dot(cb.force_i, kN), -6.3705e-5, 1e-5);
    EXPECT_NEAR(norm(perp(cb.force_i, kN)), 0.0, 1e-12 * norm(cb.force_i));
    EXPECT_EQ(norm(cb.torque_i) + norm(cb.torque_j), 0.0);
    // S_n = dF/dδ = 9.556e3 N/m (central difference, ±0.1 nm).
    auto fn = [&](double r_i, double r_j, double d) {
        Vec3 h;
        return -dot(hertz_mindlin(pair(r_i, r_j, d), material(), h, kDt).force_i, kN);
    };
    const double s_n = (fn(kR, kR, kDelta + 1e-10) - fn(kR, kR, kDelta - 1e-10)) / 2e-10;
    expect_rel(s_n, 9.556e3, 1e-4);
    // NCM-NCM, r = 4.3 µm.
    expect_rel(fn(kRNcm, kRNcm, kDelta), 1.5254e-4, 1e-4);
    // Closed form (4/3) E* sqrt(R*) δ^{3/2} for an unequal pair, 1e-12.
    const double r_star = kR * kRNcm / (kR + kRNcm);
    expect_rel(fn(kR, kRNcm, kDelta),
               4.0 / 3.0 * material().e_star * std::sqrt(r_star) * std::pow(kDelta, 1.5), 1e-12);
}

// M-2.2: damping γ_n = 2 sqrt(5/6) β sqrt(S_n m*) on the approach velocity, not clipped.
TEST(HertzMindlin, NormalDampingNotClipped) {
    const HertzMindlinParams p = material();
    const double s_n = 2 * p.e_star * std::sqrt(0.5 * kR * kDelta);
    const double m_star = 0.5 * sphere_mass(kR);
    const double gamma_n = 2 * std::sqrt(5.0 / 6.0) * p.beta * std::sqrt(s_n * m_star);
    // Separating fast (v_n = -100 m/s): damping exceeds the elastic force, the force is tensile.
    Vec3 xi;
    const PairForce f = hertz_mindlin(pair(kR, kR, kDelta, -50.0 * kN, 50.0 * kN), p, xi, kDt);
    const double elastic = 2.0 / 3.0 * s_n * kDelta; // (4/3) E* sqrt(R*) δ^{3/2}
    expect_rel(dot(f.force_i, kN), -(elastic - gamma_n * 100.0), 1e-12);
    EXPECT_GT(dot(f.force_i, kN), 0.0); // tensile: i pulled toward j
}

// V-2: S_t = 7.869e3 N/m from the tangential force of a tiny tangential displacement.
TEST(HertzMindlin, TangentialStiffnessV2) {
    const double dx = 1e-12;
    Vec3 xi = dx * kT; // spring stretched by 1 pm, no motion
    const PairForce f = hertz_mindlin(pair(kR, kR, kDelta), material(), xi, kDt);
    expect_rel(-dot(f.force_i, kT) / dx, 7.869e3, 1e-4);
    EXPECT_NEAR(dot(f.force_i, kB), 0.0, 1e-12 * norm(f.force_i));
    // The same spring built by sliding: one step of v_t Δt, plus damping γ_t v_t.
    const HertzMindlinParams p = material();
    const double s_t = 8 * p.g_star * std::sqrt(0.5 * kR * kDelta);
    const double gamma_t =
        2 * std::sqrt(5.0 / 6.0) * p.beta * std::sqrt(s_t * 0.5 * sphere_mass(kR));
    const double u = 1e-3; // v_t [m/s]: S_t u Δt + γ_t u well below μ F_n
    Vec3 xi2;
    const PairForce g = hertz_mindlin(pair(kR, kR, kDelta, u * kT), p, xi2, kDt);
    expect_rel(norm(xi2), u * kDt, 1e-10);
    expect_rel(-dot(g.force_i, kT), s_t * u * kDt + gamma_t * u, 1e-10);
}

// M-2.3: Coulomb cap |F_t| = μ_s |F_n|, history cut back to μ_s |F_n| / S_t along its direction,
// no damping while sliding.
TEST(HertzMindlin, CoulombCapRescalesHistory) {
    const HertzMindlinParams p = material();
    const double s_t = 8 * p.g_star * std::sqrt(0.5 * kR * kDelta);
    const Vec3 dir = (3.0 * kT + 4.0 * kB) / 5.0;
    Vec3 xi = 1e-6 * dir; // far beyond the elastic limit
    const Vec3 v_t = 0.7 * kT;
    const PairForce f = hertz_mindlin(pair(kR, kR, kDelta, v_t), p, xi, kDt);
    const double f_n = -dot(f.force_i, kN);
    const Vec3 f_t = perp(f.force_i, kN);
    expect_rel(norm(f_t), 0.8 * f_n, 1e-12);
    expect_rel(norm(xi), 0.8 * f_n / s_t, 1e-12);
    // Direction: the spring after the step (old + v_t Δt, rescaled); the force is -S_t ξ.
    const Vec3 expect_dir = (1e-6 * dir + kDt * v_t) / norm(1e-6 * dir + kDt * v_t);
    EXPECT_NEAR(norm(xi / norm(xi) - expect_dir), 0.0, 1e-12);
    EXPECT_NEAR(norm(f_t + s_t * xi), 0.0, 1e-12 * norm(f_t));
    // C-5 with normal damping: the bound uses |F_n| including its damping term.
    Vec3 xi2 = 1e-6 * dir;
    const PairForce g = hertz_mindlin(pair(kR, kR, kDelta, 0.5 * kN, -0.5 * kN), p, xi2, kDt);
    expect_rel(norm(perp(g.force_i, kN)), 0.8 * std::abs(dot(g.force_i, kN)), 1e-12);
}

// C-4: the history is rotated onto the current tangent plane and keeps its length.
TEST(HertzMindlin, HistoryRotationKeepsLength) {
    // History in the tangent plane of an older normal, tilted by 10° toward the new one.
    const double a = 10.0 * kPi / 180.0;
    const Vec3 n_old = std::cos(a) * kN + std::sin(a) * kT;
    const Vec3 t_old = std::cos(a) * kT - std::sin(a) * kN; // ⊥ n_old
    const double len = 1e-10;                               // elastic (S_t len ≪ μ F_n)
    Vec3 xi = len * (0.6 * t_old + 0.8 * kB);
    ASSERT_NEAR(dot(xi, n_old), 0.0, 1e-24);
    const PairForce f = hertz_mindlin(pair(kR, kR, kDelta), material(), xi, kDt);
    EXPECT_NEAR(dot(xi, kN), 0.0, 1e-12 * len);
    expect_rel(norm(xi), len, 1e-12);
    const double s_t = 8 * material().g_star * std::sqrt(0.5 * kR * kDelta);
    EXPECT_NEAR(norm(perp(f.force_i, kN) + s_t * xi), 0.0, 1e-12 * s_t * len);
}

// M-2.3: torques T_i = c_i n × F_t, T_j = c_j n × F_t with c = r - δ/2; angular momentum about
// the origin is conserved (the lever arms add up to the centre distance).
TEST(HertzMindlin, TorquesFromLeverArms) {
    const double r_j = 2.0 * kR;
    const Vec3 w_i{1e5, -2e5, 3e5}, w_j{-4e5, 1e5, 2e5};
    Vec3 xi = 2e-11 * kB;
    const PairGeometry g = pair(kR, r_j, kDelta, 0.01 * kT, {}, w_i, w_j);
    const PairForce f = hertz_mindlin(g, material(), xi, kDt);
    const Vec3 f_t = perp(f.force_i, kN);
    ASSERT_GT(norm(f_t), 0.0);
    const double c_i = kR - 0.5 * kDelta, c_j = r_j - 0.5 * kDelta;
    EXPECT_NEAR(norm(f.torque_i - c_i * cross(kN, f_t)), 0.0, 1e-12 * c_i * norm(f_t));
    EXPECT_NEAR(norm(f.torque_j - c_j * cross(kN, f_t)), 0.0, 1e-12 * c_j * norm(f_t));
    // Angular momentum: x_i × F_i + x_j × (-F_i) + T_i + T_j = 0 (x_i = 0, x_j = D n).
    const Vec3 l_dot = cross(g.distance * kN, -f.force_i) + f.torque_i + f.torque_j;
    EXPECT_NEAR(norm(l_dot), 0.0, 1e-12 * kR * norm(f.force_i));
    // The contact-point velocity uses the same lever arms: rolling without slip, v_c = 0, gives
    // no tangential increment: v_i - v_j = -(c_i ω_i + c_j ω_j) × n.
    const Vec3 w{0.0, 0.0, 0.0}, w2 = 1e5 * kT;
    const Vec3 v_roll = -cross(c_i * w2 + c_j * w2, kN);
    Vec3 xi0;
    hertz_mindlin(pair(kR, r_j, kDelta, v_roll, w, w2, w2), material(), xi0, kDt);
    EXPECT_NEAR(norm(xi0), 0.0, 1e-12 * norm(v_roll) * kDt);
}

// M-2.4 (C-7 option): T_roll,i = -μ_r |F_n| R* ω̂_rel with ω_rel = (ω_i - ω_j)_⊥, T_roll,j = -T_roll,i.
TEST(HertzMindlin, RollingFrictionTorque) {
    const double mu_r = 0.05;
    const Vec3 w_i = 2e5 * kT + 7e5 * kN, w_j = -1e5 * kT; // the twist part (along n) is ignored
    auto eval = [&](double mu) {
        Vec3 xi;
        return hertz_mindlin(pair(kR, kRNcm, kDelta, {}, {}, w_i, w_j), material(0.5, 0.8, mu), xi,
                             kDt);
    };
    const PairForce with = eval(mu_r), without = eval(0.0);
    EXPECT_NEAR(norm(with.force_i - without.force_i), 0.0, 1e-12 * norm(without.force_i));
    const double f_n = -dot(with.force_i, kN);
    const double r_star = kR * kRNcm / (kR + kRNcm);
    const Vec3 expect = -mu_r * f_n * r_star * kT; // ω̂_rel = +kT
    EXPECT_NEAR(norm(with.torque_i - without.torque_i - expect), 0.0, 1e-12 * norm(expect));
    EXPECT_NEAR(norm(with.torque_j - without.torque_j + expect), 0.0, 1e-12 * norm(expect));
    expect_rel(norm(expect),
               mu_r * 4.0 / 3.0 * material().e_star * std::sqrt(r_star) * std::pow(kDelta, 1.5) *
                   r_star,
               1e-12);
    // No relative rotation: no rolling torque.
    Vec3 xi;
    const PairForce same =
        hertz_mindlin(pair(kR, kR, kDelta, {}, {}, w_j, w_j), material(0.5, 0.8, mu_r), xi, kDt);
    Vec3 xi2;
    const PairForce ref =
        hertz_mindlin(pair(kR, kR, kDelta, {}, {}, w_j, w_j), material(), xi2, kDt);
    EXPECT_NEAR(norm(same.torque_i - ref.torque_i), 0.0, 1e-12 * norm(ref.torque_i) + 1e-28);
}

// M-0: Newton's third law. Swapping the roles of i and j (n -> -n, v_rel -> -v_rel, history ->
// -history) returns exactly the opposite force and swaps the torques.
TEST(HertzMindlin, NewtonsThirdLawUnderSwap) {
    const double r_j = 3.0 * kR;
    const Vec3 v_i{0.3, -0.1, 0.2}, v_j{-0.2, 0.4, 0.1}, w_i{1e5, 2e5, -1e5}, w_j{-3e5, 0, 1e5};
    for (double hist : {0.0, 3e-11, 1e-6}) { // fresh, elastic, sliding
        Vec3 xi_ij = hist * kB, xi_ji = -hist * kB;
        const PairForce a =
            hertz_mindlin(pair(kR, r_j, kDelta, v_i, v_j, w_i, w_j, kN), material(), xi_ij, kDt);
        const PairForce b =
            hertz_mindlin(pair(r_j, kR, kDelta, v_j, v_i, w_j, w_i, -kN), material(), xi_ji, kDt);
        const double scale = norm(a.force_i);
        EXPECT_NEAR(norm(a.force_i + b.force_i), 0.0, 1e-12 * scale) << hist;
        EXPECT_NEAR(norm(a.torque_i - b.torque_j), 0.0, 1e-12 * scale * r_j) << hist;
        EXPECT_NEAR(norm(a.torque_j - b.torque_i), 0.0, 1e-12 * scale * r_j) << hist;
        EXPECT_NEAR(norm(xi_ij + xi_ji), 0.0, 1e-12 * norm(xi_ij) + 1e-30) << hist;
    }
}

} // namespace

namespace {
using namespace drydem;

// Rigid-body check (issue 3: every pair law): a touching pair that translates and rotates as one
// rigid body (v_i - v_j = Ω × (x_i - x_j), ω_i = ω_j = Ω) feels only the elastic normal force —
// no damping, no tangential spring, no torque — for unequal radii too (lever arms r - δ/2).
TEST(HertzMindlin, RigidBodyMotionGivesOnlyTheElasticForce) {
    const HertzMindlinParams p = mix_hertz_mindlin(142e9, 0.3, 142e9, 0.3, 0.5, 0.8, 0.1);
    const double r_i = 4.3e-6, r_j = 0.75e-6, overlap = 10e-9, d = r_i + r_j - overlap;
    const Vec3 n = Vec3{1.0, 2.0, -2.0} / 3.0;
    const Vec3 omega{3e5, -1e5, 2e5}, v_j{0.3, -0.2, 0.1};
    const Vec3 v_i = v_j + cross(omega, -d * n); // x_i - x_j = -d n
    const double m_i = 4.0 / 3.0 * std::numbers::pi * std::pow(r_i, 3) * 4740;
    const double m_j = 4.0 / 3.0 * std::numbers::pi * std::pow(r_j, 3) * 1187.5;
    const PairGeometry g = make_pair_geometry(d * n, d, r_i, r_j, m_i, m_j, v_i, v_j, omega, omega);
    Vec3 xi{};
    const PairForce f = hertz_mindlin(g, p, xi, 1e-11);
    const double elastic = 4.0 / 3.0 * p.e_star * std::sqrt(g.r_eff) * std::pow(overlap, 1.5);
    EXPECT_NEAR(norm(f.force_i + elastic * n), 0.0, 1e-9 * elastic);
    EXPECT_LT(norm(xi), 1e-12 * overlap);
    EXPECT_LT(norm(f.torque_i), 1e-9 * elastic * r_i);
    EXPECT_LT(norm(f.torque_j), 1e-9 * elastic * r_i);
}

} // namespace
