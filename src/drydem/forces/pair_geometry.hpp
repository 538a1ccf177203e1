// SPDX-License-Identifier: MIT
// Geometry and kinematics of one particle pair, computed once per pair and handed (read-only) to
// every pair law. Conventions of model.md M-0: n points from i to j, h = D - r_i - r_j (negative in
// overlap), v_n = (v_i - v_j)·n is positive when the particles approach.
#pragma once
#include "drydem/core/vec3.hpp"
#include <cmath>

namespace drydem {

struct PairGeometry {
    Vec3 n;                ///< unit normal from i to j
    double distance;       ///< centre distance D [m]
    double gap;            ///< surface gap h = D - r_i - r_j [m]
    double r_i, r_j;       ///< radii [m]
    double r_eff;          ///< R* = r_i r_j / (r_i + r_j) [m]
    double m_eff;          ///< m* = m_i m_j / (m_i + m_j) [kg]
    Vec3 v_rel;            ///< v_i - v_j [m/s]
    double v_n;            ///< v_rel·n, > 0 approaching [m/s]
    Vec3 omega_i, omega_j; ///< angular velocities [rad/s]
};

/// Builds the pair geometry from the minimum-image separation d = x_j - x_i.
inline PairGeometry make_pair_geometry(const Vec3& d, double distance, double r_i, double r_j,
                                       double m_i, double m_j, const Vec3& v_i, const Vec3& v_j,
                                       const Vec3& omega_i, const Vec3& omega_j) {
    PairGeometry g;
    g.distance = distance;
    g.n = d * (1.0 / distance);
    g.gap = distance - r_i - r_j;
    g.r_i = r_i;
    g.r_j = r_j;
    g.r_eff = r_i * r_j / (r_i + r_j);
    g.m_eff = m_i * m_j / (m_i + m_j);
    g.v_rel = v_i - v_j;
    g.v_n = dot(g.v_rel, g.n);
    g.omega_i = omega_i;
    g.omega_j = omega_j;
    return g;
}

/// Turns a vector of the old tangent plane onto the plane of the new normal n, keeping its length
/// (model.md C-4): the contact spring and the bond's shear and bending follow the pair's rotation.
inline Vec3 onto_plane(const Vec3& v, const Vec3& n) {
    const double v2 = norm2(v);
    if (v2 == 0.0) return v;
    const Vec3 vp = perp(v, n);
    const double vp2 = norm2(vp);
    return vp2 > 0.0 ? vp * std::sqrt(v2 / vp2) : Vec3{};
}

/// Result of a pair law: force on i (j receives -force_i) and the torques on i and j, which differ
/// in general because the lever arms differ.
struct PairForce {
    Vec3 force_i;
    Vec3 torque_i;
    Vec3 torque_j;
    PairForce& operator+=(const PairForce& o) {
        force_i += o.force_i;
        torque_i += o.torque_i;
        torque_j += o.torque_j;
        return *this;
    }
};

/// Result of a law acting on one particle (substrate, drag, fields).
struct BodyForce {
    Vec3 force;
    Vec3 torque;
    BodyForce& operator+=(const BodyForce& o) {
        force += o.force;
        torque += o.torque;
        return *this;
    }
};

} // namespace drydem
