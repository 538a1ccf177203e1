// SPDX-License-Identifier: MIT
// Resistance of the dissipative laws: the linear map from velocities to viscous forces and
// torques (docs/model.md "Resistance and time integration"). Every dissipative law states its
// coefficients here once; its force, the semi-implicit kick, the stability guard and
// `drydem check` all apply the same coefficients.
//
// Pair form (pair lubrication, Hertz-Mindlin damping), n from i to j, lever arms c_i, c_j:
//   v_s = v_i - v_j + (c_i ω_i + c_j ω_j) × n,   ω_r = ω_i - ω_j
//   F_i = -a_n (v_s·n) n - a_t (v_s)_⊥ = -F_j
//   T_i = c_i n × F_t - a_r (ω_r)_⊥ - a_w (ω_r·n) n,   T_j = c_j n × F_t + a_r (ω_r)_⊥ + a_w (ω_r·n) n
// Body form (Stokes drag, substrate lubrication and contact damping), axis ẑ:
//   F = -a_z v_z ẑ - a_t v_t + b ω × ẑ,   T = b ẑ × v_t - d_t ω_t - d_z ω_z ẑ   (t: part ⊥ ẑ)
// Both are symmetric positive semi-definite for non-negative coefficients (and a_t d_t ≥ b²):
// they only dissipate. The same two forms, with spring constants in place of the resistances,
// describe the linearised stiffness of the conservative laws for the stability guard.
//
// Self-block. The 6×6 block of particle i in the resistance matrix R (rows and columns v_i, ω_i)
//   D_i = [[A, -[k]×], [[k]×, B]]   (A, B symmetric, k a vector: the coupling is skew)
// where a pair adds A += a_n nn + a_t (1 - nn), B += (a_t c_i² + a_r)(1 - nn) + a_w nn,
// k += a_t c_i n (k -= a_t c_j n on j). Every pair's 12×12 block P satisfies P ≤ 2 blockdiag(P)
// (blockdiag(P) - P' with P' = P conjugated by diag(1, -1) is P itself), so R ≤ 2 D with
// D = blockdiag(D_i): the semi-implicit kick v += Δt (M + Δt D)⁻¹ F damps every mode at any Δt.
#pragma once
#include "drydem/forces/pair_geometry.hpp"
#include <cmath>

namespace drydem {

/// Coefficients of the pair form [kg/s for a_n, a_t; kg m²/s for a_r, a_w; m for the levers].
struct PairResistance {
    double normal = 0.0;                 ///< a_n
    double sliding = 0.0;                ///< a_t
    double rolling = 0.0;                ///< a_r
    double twisting = 0.0;               ///< a_w
    double lever_i = 0.0, lever_j = 0.0; ///< c_i, c_j

    /// Sum of two laws acting on the same pair with the same lever arms.
    PairResistance& operator+=(const PairResistance& o) {
        normal += o.normal;
        sliding += o.sliding;
        rolling += o.rolling;
        twisting += o.twisting;
        return *this;
    }
};

/// Viscous force and torques of the pair form for the given velocities.
inline PairForce resistance_force(const PairResistance& r, const Vec3& n, const Vec3& v_rel,
                                  const Vec3& omega_i, const Vec3& omega_j) {
    const Vec3 v_s = v_rel + cross(r.lever_i * omega_i + r.lever_j * omega_j, n);
    const double v_n = dot(v_rel, n);
    const Vec3 f_t = (-r.sliding) * (v_s - v_n * n);
    const Vec3 f = (-r.normal * v_n) * n + f_t;
    const Vec3 w_r = omega_i - omega_j;
    const double w_n = dot(w_r, n);
    const Vec3 t_r = r.rolling * (w_r - w_n * n) + (r.twisting * w_n) * n;
    const Vec3 lever = cross(n, f_t);
    return {f, r.lever_i * lever - t_r, r.lever_j * lever + t_r};
}

/// R + s K of one pair: its resistance and stiffness (same lever arms) as the coefficients of one
/// operator, the stiffness weighted by s (the quasi-static step's Δt: F(x + Δt v) ≈ F(x) - Δt K v).
inline PairResistance plus_scaled(PairResistance r, const PairResistance& k, double s) {
    r.normal += s * k.normal;
    r.sliding += s * k.sliding;
    r.rolling += s * k.rolling;
    r.twisting += s * k.twisting;
    return r;
}

/// Coefficients of the body form [kg/s; kg m/s for b; kg m²/s for d_t, d_z].
struct BodyResistance {
    double normal = 0.0;     ///< a_z
    double tangential = 0.0; ///< a_t
    double coupling = 0.0;   ///< b
    double rotation_t = 0.0; ///< d_t
    double rotation_n = 0.0; ///< d_z
    BodyResistance& operator+=(const BodyResistance& o) {
        normal += o.normal;
        tangential += o.tangential;
        coupling += o.coupling;
        rotation_t += o.rotation_t;
        rotation_n += o.rotation_n;
        return *this;
    }
};

inline BodyForce resistance_force(const BodyResistance& r, const Vec3& v, const Vec3& omega) {
    const Vec3 v_t{v.x, v.y, 0.0};
    const Vec3 z_hat{0.0, 0.0, 1.0};
    return {Vec3{-r.tangential * v.x, -r.tangential * v.y, -r.normal * v.z} +
                r.coupling * cross(omega, z_hat),
            r.coupling * cross(z_hat, v_t) +
                Vec3{-r.rotation_t * omega.x, -r.rotation_t * omega.y, -r.rotation_n * omega.z}};
}

/// R + s K of one particle's body laws (see the pair form's plus_scaled).
inline BodyResistance plus_scaled(BodyResistance r, const BodyResistance& k, double s) {
    r.normal += s * k.normal;
    r.tangential += s * k.tangential;
    r.coupling += s * k.coupling;
    r.rotation_t += s * k.rotation_t;
    r.rotation_n += s * k.rotation_n;
    return r;
}

/// The body form of a contact with the plane z = 0 (normal -ẑ from the particle to the wall)
/// whose damping is a_n normal and a_t tangential at lever arm c (centre to contact point).
inline BodyResistance wall_pair_resistance(double a_n, double a_t, double lever) {
    return {a_n, a_t, a_t * lever, a_t * lever * lever, 0.0};
}

/// Symmetric 3×3 matrix stored as xx, yy, zz, xy, xz, yz.
struct Sym3 {
    double xx = 0, yy = 0, zz = 0, xy = 0, xz = 0, yz = 0;
    /// += s (n n^T) + t (1 - n n^T)
    void add_projected(const Vec3& n, double s, double t) {
        const double d = s - t;
        xx += t + d * n.x * n.x;
        yy += t + d * n.y * n.y;
        zz += t + d * n.z * n.z;
        xy += d * n.x * n.y;
        xz += d * n.x * n.z;
        yz += d * n.y * n.z;
    }
    Sym3& operator+=(const Sym3& o) {
        xx += o.xx, yy += o.yy, zz += o.zz, xy += o.xy, xz += o.xz, yz += o.yz;
        return *this;
    }
};

/// A particle's 6×6 self-block D_i = [[A, -[k]×], [[k]×, B]] (see the header).
struct SelfBlock {
    Sym3 a; ///< translation-translation
    Sym3 b; ///< rotation-rotation
    Vec3 k; ///< coupling: D_ωv = [k]×
    SelfBlock& operator+=(const SelfBlock& o) {
        a += o.a;
        b += o.b;
        k += o.k;
        return *this;
    }
};

/// Adds the pair's self-blocks to particle i (`sign` = +1, lever c_i) or j (`sign` = -1, c_j).
inline void add_self_block(SelfBlock& d, const PairResistance& r, const Vec3& n, double lever,
                           double sign) {
    d.a.add_projected(n, r.normal, r.sliding);
    d.b.add_projected(n, r.twisting, r.sliding * lever * lever + r.rolling);
    d.k += (sign * r.sliding * lever) * n;
}

inline void add_self_block(SelfBlock& d, const BodyResistance& r) {
    d.a.xx += r.tangential;
    d.a.yy += r.tangential;
    d.a.zz += r.normal;
    d.b.xx += r.rotation_t;
    d.b.yy += r.rotation_t;
    d.b.zz += r.rotation_n;
    d.k.z -= r.coupling; // T = b ẑ × v: D_ωv = -b [ẑ]×
}

/// Inverse of a symmetric 3×3 matrix by cofactors (one division).
inline Sym3 inverse(const Sym3& m) {
    const double c_xx = m.yy * m.zz - m.yz * m.yz;
    const double c_xy = m.xz * m.yz - m.xy * m.zz;
    const double c_xz = m.xy * m.yz - m.xz * m.yy;
    const double inv_det = 1.0 / (m.xx * c_xx + m.xy * c_xy + m.xz * c_xz);
    return {c_xx * inv_det,
            (m.xx * m.zz - m.xz * m.xz) * inv_det,
            (m.xx * m.yy - m.xy * m.xy) * inv_det,
            c_xy * inv_det,
            c_xz * inv_det,
            (m.xy * m.xz - m.xx * m.yz) * inv_det};
}
inline Vec3 operator*(const Sym3& m, const Vec3& v) {
    return {m.xx * v.x + m.xy * v.y + m.xz * v.z, m.xy * v.x + m.yy * v.y + m.yz * v.z,
            m.xz * v.x + m.yz * v.y + m.zz * v.z};
}

/// (M + s D)⁻¹ of one particle, M = diag(m, m, m, I, I, I), factored once for many solves. With
/// P = m + s A, Q = I + s B and C = s [k]× (so that the matrix is [[P, C^T], [C, Q]]), by the
/// Schur complement S = Q - C P⁻¹ C^T: α = S⁻¹ (T - C P⁻¹ F), a = P⁻¹ (F - C^T α). Two 3×3
/// inverses by cofactors: two divisions and no square root, so the solve is not bound by their
/// latency (a 6×6 Cholesky took three times as long).
struct SelfBlockInverse {
    Sym3 p_inv; ///< P⁻¹
    Vec3 k;     ///< s k: C x = k × x, C^T x = x × k
    Sym3 s_inv; ///< S⁻¹
};

inline SelfBlockInverse factor_self_block(const SelfBlock& d, double s, double mass,
                                          double inertia) {
    Sym3 p = d.a, q = d.b;
    p.xx *= s, p.yy *= s, p.zz *= s, p.xy *= s, p.xz *= s, p.yz *= s;
    q.xx *= s, q.yy *= s, q.zz *= s, q.xy *= s, q.xz *= s, q.yz *= s;
    p.xx += mass, p.yy += mass, p.zz += mass;
    q.xx += inertia, q.yy += inertia, q.zz += inertia;
    const Sym3 pi = inverse(p);
    const Vec3 k = s * d.k;
    // C P⁻¹ C^T: columns c_e = k × (P⁻¹ (e × k)) for the unit vectors e.
    const Vec3 cx = cross(k, pi * Vec3{0.0, -k.z, k.y});
    const Vec3 cy = cross(k, pi * Vec3{k.z, 0.0, -k.x});
    const Vec3 cz = cross(k, pi * Vec3{-k.y, k.x, 0.0});
    const Sym3 schur{q.xx - cx.x, q.yy - cy.y, q.zz - cz.z, q.xy - cy.x, q.xz - cz.x, q.yz - cz.y};
    return {pi, k, inverse(schur)};
}

/// [a; α] = (M + s D)⁻¹ [F; T] with the factored block.
inline void solve_self_block(const SelfBlockInverse& f, const Vec3& force, const Vec3& torque,
                             Vec3& accel, Vec3& alpha) {
    const Vec3 pf = f.p_inv * force;
    alpha = f.s_inv * (torque - cross(f.k, pf));
    accel = f.p_inv * (force - cross(alpha, f.k));
}

/// Solves (M + s D) [a; α] = [F; T] for the accelerations of one particle (one solve).
inline void solve_self_block(const SelfBlock& d, double s, double mass, double inertia,
                             const Vec3& force, const Vec3& torque, Vec3& accel, Vec3& alpha) {
    solve_self_block(factor_self_block(d, s, mass, inertia), force, torque, accel, alpha);
}

} // namespace drydem
