// SPDX-License-Identifier: MIT
// The dissipative laws' resistances (forces/resistance.hpp): each law's force equals its
// resistance applied to the velocities, checked against the law's own force function column by
// column (finite differences in the velocities, exact for linear laws); the matrix is
// symmetric, dissipative and blind to rigid-body motion; the self-block accumulator equals the
// diagonal blocks; the semi-implicit solve inverts M + s D.
#include "drydem/forces/force_field.hpp"
#include "drydem/forces/resistance.hpp"
#include <Eigen/Dense>
#include <gtest/gtest.h>
#include <array>
#include <functional>

using namespace drydem;

namespace {

using Mat = Eigen::MatrixXd;
/// Forces and torques on (i, j) as a 12-vector for the velocities u = (v_i, ω_i, v_j, ω_j).
using PairLaw = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

Vec3 part(const Eigen::VectorXd& u, int k) { return {u[3 * k], u[3 * k + 1], u[3 * k + 2]}; }

Eigen::VectorXd pack(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    Eigen::VectorXd f(12);
    f << a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z;
    return f;
}

/// R = -dF/du of a law that is linear in the velocities (columns by unit velocities).
Mat resistance_matrix(const PairLaw& law, int dofs) {
    Mat r(dofs, dofs);
    const Eigen::VectorXd f0 = law(Eigen::VectorXd::Zero(dofs));
    for (int k = 0; k < dofs; ++k) r.col(k) = -(law(Eigen::VectorXd::Unit(dofs, k)) - f0);
    return r;
}

/// A pair with unequal radii, not aligned with the axes; gap h (negative: overlap).
PairGeometry geometry(double h, const Eigen::VectorXd& u) {
    const double ri = 0.75e-6, rj = 5.675e-6;
    const Vec3 n = Vec3{0.3, -0.5, 0.81} / norm(Vec3{0.3, -0.5, 0.81});
    const double dist = ri + rj + h;
    return make_pair_geometry(dist * n, dist, ri, rj, 2.1e-15, 3.6e-12, part(u, 0), part(u, 2),
                              part(u, 1), part(u, 3));
}

void expect_rigid_blind(const Mat& r, const Vec3& n, double dist, double tol) {
    // Translation together, and rotation of the pair as one body about its centre i:
    // v_j = Ω × (x_j - x_i), ω_i = ω_j = Ω.
    for (int axis = 0; axis < 3; ++axis) {
        Eigen::VectorXd u = Eigen::VectorXd::Zero(12);
        u[axis] = u[6 + axis] = 1.0;
        EXPECT_LT((r * u).norm(), tol * r.norm()) << "translation " << axis;
        Vec3 omega{};
        (axis == 0 ? omega.x : axis == 1 ? omega.y : omega.z) = 1.0;
        const Vec3 vj = cross(omega, dist * n);
        u = pack({}, omega, vj, omega);
        EXPECT_LT((r * u).norm(), tol * r.norm() * dist) << "rotation " << axis;
    }
}

void expect_symmetric_psd(const Mat& r) {
    EXPECT_LT((r - r.transpose()).norm(), 1e-9 * r.norm());
    Eigen::SelfAdjointEigenSolver<Mat> es(0.5 * (r + r.transpose()));
    EXPECT_GT(es.eigenvalues().minCoeff(), -1e-9 * es.eigenvalues().maxCoeff());
}

/// The 12×12 matrix of a pair resistance, from resistance_force.
Mat pair_matrix(const PairResistance& c, const Vec3& n) {
    return resistance_matrix(
        [&](const Eigen::VectorXd& u) {
            const PairForce f =
                resistance_force(c, n, part(u, 0) - part(u, 2), part(u, 1), part(u, 3));
            return pack(f.force_i, f.torque_i, -f.force_i, f.torque_j);
        },
        12);
}

Mat block_matrix(const SelfBlock& d) {
    Mat m(6, 6);
    const Sym3 &a = d.a, &b = d.b;
    const Vec3 k = d.k;
    Eigen::Matrix3d am, bm, km;
    am << a.xx, a.xy, a.xz, a.xy, a.yy, a.yz, a.xz, a.yz, a.zz;
    bm << b.xx, b.xy, b.xz, b.xy, b.yy, b.yz, b.xz, b.yz, b.zz;
    km << 0, -k.z, k.y, k.z, 0, -k.x, -k.y, k.x, 0;
    m << am, km.transpose(), km, bm;
    return m;
}

const LubricationParams kLub{1.801, 0.1};

} // namespace

TEST(Resistance, LubricationForceIsItsResistanceAndIndependentOfTheFormula) {
    for (double h : {-0.02e-6, 0.01e-6, 0.2e-6, 1.0e-6}) {
        const Mat law = resistance_matrix(
            [&](const Eigen::VectorXd& u) {
                const PairGeometry g = geometry(h, u);
                const PairForce f = lubrication(g, kLub);
                return pack(f.force_i, f.torque_i, -f.force_i, f.torque_j);
            },
            12);
        const PairGeometry g = geometry(h, Eigen::VectorXd::Zero(12));
        const PairResistance c = lubrication_resistance(g, kLub);
        EXPECT_NEAR((law - pair_matrix(c, g.n)).norm(), 0.0, 1e-12 * law.norm()) << "h " << h;
        expect_symmetric_psd(law);
        expect_rigid_blind(law, g.n, g.distance, 1e-12);
        // Independent of the implementation: the squeeze coefficient of Eq. 6-7 by hand.
        const double r_l = 2.0 * g.r_eff, k = std::max(h / r_l, 0.1);
        const double x = 1 / (4 * k) - 0.225 * std::log(k) - 3.0 / 112.0 * k * std::log(k);
        const double q = k / 0.1;
        const double fstar = q / 3 * ((1 + q / 6) * std::log(1 + 6 / q) - 1);
        EXPECT_NEAR(c.normal, 6 * std::numbers::pi * 1.801 * r_l * x * fstar, 1e-12 * c.normal);
        EXPECT_NEAR(c.sliding, std::numbers::pi * 1.801 * r_l * -std::log(k), 1e-12 * c.sliding);
    }
}

TEST(Resistance, ContactDampingIsTheLawsViscousPart) {
    const HertzMindlinParams hm = mix_hertz_mindlin(142e9, 0.3, 142e9, 0.3, 0.5, 0.8, 0.0);
    const double h = -0.03e-6;
    // dt = 0: the tangential spring does not move, so F(u) - F(0) is the damping alone.
    PairResistance c{};
    const Mat law = resistance_matrix(
        [&](const Eigen::VectorXd& u) {
            Vec3 xi{};
            PairResistance r{};
            const PairForce f = hertz_mindlin(geometry(h, u), hm, xi, 0.0, &r);
            c = r;
            return pack(f.force_i, f.torque_i, -f.force_i, f.torque_j);
        },
        12);
    const PairGeometry g = geometry(h, Eigen::VectorXd::Zero(12));
    c.lever_i = g.r_i + 0.5 * g.gap;
    c.lever_j = g.r_j + 0.5 * g.gap;
    const HertzMindlinCoefficients co = hertz_mindlin_coefficients(g.r_eff, -h, g.m_eff, hm);
    EXPECT_NEAR(c.normal, co.gamma_n, 1e-12 * co.gamma_n);
    EXPECT_NEAR(c.sliding, co.gamma_t, 1e-12 * co.gamma_t); // sticking (no spring load)
    EXPECT_NEAR((law - pair_matrix(c, g.n)).norm(), 0.0, 1e-9 * law.norm());
    expect_symmetric_psd(law);
}

TEST(Resistance, BodyLawsAreTheirResistance) {
    const SubstrateLubricationParams wl{1.801, 0.1};
    const StokesDragParams drag{0.1801, true};
    const HertzMindlinParams hm = mix_hertz_mindlin(142e9, 0.3, 70e9, 0.33, 0.5, 0.8, 0.0);
    const double r = 0.75e-6, m = 2.1e-15;
    for (double z : {0.97 * r, 1.05 * r, 1.5 * r, 2.5 * r}) {
        // Through the body-law list: the three dissipative laws, the conservative ones off.
        BodyParams bp{};
        law<SubstrateContactLaw>(bp) = hm;
        law<SubstrateLubricationLaw>(bp) = wl;
        law<StokesDragLaw>(bp) = drag;
        BodyResistance reported{};
        auto body = [&](const Eigen::VectorXd& u) {
            BodyState s{};
            reported = BodyResistance{};
            const BodyForce f = BodyLaws::force({{0, 0, z}, part(u, 0), part(u, 1), r, m, 0, 0, 0},
                                                bp, s, 0.0, &reported);
            Eigen::VectorXd out(6);
            out << f.force.x, f.force.y, f.force.z, f.torque.x, f.torque.y, f.torque.z;
            return out;
        };
        const Mat law = resistance_matrix(body, 6);
        const BodyResistance c = BodyLaws::resistance({{0, 0, z}, {}, {}, r, m, 0, 0, 0}, bp);
        EXPECT_NEAR(reported.normal, c.normal, 1e-12 * c.normal) << "z/r " << z / r;
        EXPECT_NEAR(reported.coupling, c.coupling, 1e-12 * std::abs(c.coupling) + 1e-30);
        const Mat mine = resistance_matrix(
            [&](const Eigen::VectorXd& u) {
                const BodyForce f = resistance_force(c, part(u, 0), part(u, 1));
                Eigen::VectorXd out(6);
                out << f.force.x, f.force.y, f.force.z, f.torque.x, f.torque.y, f.torque.z;
                return out;
            },
            6);
        EXPECT_NEAR((law - mine).norm(), 0.0, 1e-9 * law.norm()) << "z/r " << z / r;
        expect_symmetric_psd(law);
        SelfBlock d{};
        add_self_block(d, c);
        EXPECT_NEAR((block_matrix(d) - law).norm(), 0.0, 1e-12 * law.norm());
    }
}

TEST(Resistance, SelfBlocksAreTheDiagonalBlocksAndBoundTheMatrix) {
    const HertzMindlinParams hm = mix_hertz_mindlin(142e9, 0.3, 142e9, 0.3, 0.5, 0.8, 0.0);
    for (double h : {-0.03e-6, 0.05e-6}) {
        const PairGeometry g = geometry(h, Eigen::VectorXd::Zero(12));
        PairState xi{};
        PairResistance c{};
        PairParams pp{};
        law<HertzMindlinLaw>(pp) = hm;
        law<LubricationLaw>(pp) = kLub;
        pair_interaction(g, pp, xi, 0.0, &c);
        const Mat r = pair_matrix(c, g.n);
        SelfBlock di{}, dj{};
        add_self_block(di, c, g.n, c.lever_i, 1.0);
        add_self_block(dj, c, g.n, c.lever_j, -1.0);
        EXPECT_NEAR((block_matrix(di) - r.topLeftCorner(6, 6)).norm(), 0.0, 1e-12 * r.norm());
        EXPECT_NEAR((block_matrix(dj) - r.bottomRightCorner(6, 6)).norm(), 0.0, 1e-12 * r.norm());
        // R ≤ 2 D: 2D - R is positive semi-definite (the semi-implicit kick's stability).
        Mat d2 = Mat::Zero(12, 12);
        d2.topLeftCorner(6, 6) = 2 * block_matrix(di);
        d2.bottomRightCorner(6, 6) = 2 * block_matrix(dj);
        Eigen::SelfAdjointEigenSolver<Mat> es(d2 - r);
        EXPECT_GT(es.eigenvalues().minCoeff(), -1e-9 * r.norm());
    }
}

TEST(Resistance, SolveInvertsMassPlusScaledBlock) {
    const PairGeometry g = geometry(0.02e-6, Eigen::VectorXd::Zero(12));
    SelfBlock d{};
    add_self_block(d, lubrication_resistance(g, kLub), g.n, g.r_i + 0.01e-6, 1.0);
    add_self_block(d, BodyResistance{1e-6, 2e-6, 3e-13, 4e-19, 5e-19});
    const double m = 2.1e-15, inertia = 4.7e-28, s = 5e-11;
    const Vec3 f{1e-6, -2e-6, 3e-7}, t{2e-12, 1e-12, -3e-12};
    Vec3 a, alpha;
    solve_self_block(d, s, m, inertia, f, t, a, alpha);
    Mat mm = s * block_matrix(d);
    for (int k = 0; k < 3; ++k) mm(k, k) += m, mm(3 + k, 3 + k) += inertia;
    Eigen::VectorXd x(6), rhs(6);
    x << a.x, a.y, a.z, alpha.x, alpha.y, alpha.z;
    rhs << f.x, f.y, f.z, t.x, t.y, t.z;
    EXPECT_LT((mm * x - rhs).norm(), 1e-12 * rhs.norm());
}
