// SPDX-License-Identifier: MIT
// The stability guard's estimate against the exact largest eigenvalues of the reference
// clusters (drying/stability_clusters.hpp: a CB on one NCM, a CB between two NCM, an fcc
// cluster of 13 CB, a CB on the substrate under an NCM), every drying law on.
// Exact: the resistance R and stiffness K are measured from the engine's own force evaluation
// by finite differences (R: unit velocities; K: unit displacements for the normal and van der
// Waals springs, the tangential spring from the history increment v_t Δt), then the dense
// generalised eigenproblems R x = λ M x (explicit integrator) and K x = ω² (M + Δt D) x
// (semi-implicit, D the 6×6 diagonal blocks of R) are solved with Eigen.
#include "drydem/drying/stability_clusters.hpp"
#include <Eigen/Dense>
#include <gtest/gtest.h>
#include <functional>

using namespace drydem;

namespace {
using Mat = Eigen::MatrixXd;

/// Forces and torques of a fresh engine (no contact history) on `p`, evaluated at step `dt`.
using Factory = std::function<Simulation(const ParticleStore&)>;
Eigen::VectorXd forces(const Factory& make, const ParticleStore& p, double dt) {
    Simulation sim = make(p);
    sim.set_time_step(dt);
    sim.compute_forces(); // fresh: every tangential spring starts at zero and moves by v_t Δt
    const ParticleStore& q = sim.particles();
    Eigen::VectorXd f(6 * q.size());
    for (std::size_t i = 0; i < q.size(); ++i) {
        const std::size_t k = std::size_t(q.id[i] - 1); // by id: a rebuild may re-sort
        f.segment<3>(6 * k) << q.force[i].x, q.force[i].y, q.force[i].z;
        f.segment<3>(6 * k + 3) << q.torque[i].x, q.torque[i].y, q.torque[i].z;
    }
    return f;
}

ParticleStore with_dof(ParticleStore p, int k, double value, bool position) {
    const std::size_t i = std::size_t(k / 6);
    const int c = k % 6;
    Vec3& v = position ? p.position[i] : (c < 3 ? p.velocity[i] : p.omega[i]);
    (c % 3 == 0 ? v.x : c % 3 == 1 ? v.y : v.z) += value;
    return p;
}

struct Exact {
    Mat r, k, m;
};

/// R and K of the cluster `p` (particles in id order 1..n) from the engine's force evaluation.
Exact measure(const Factory& make, const ParticleStore& p, double dt) {
    const int n = int(6 * p.size());
    Exact e{Mat::Zero(n, n), Mat::Zero(n, n), Mat::Zero(n, n)};
    for (std::size_t i = 0; i < p.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            e.m(6 * i + c, 6 * i + c) = p.mass[i];
            e.m(6 * i + 3 + c, 6 * i + 3 + c) = 1.0 / p.inv_inertia[i];
        }
    constexpr double v0 = 1e-4, x0 = 1e-13, none = 1e-30;
    const Eigen::VectorXd f0 = forces(make, p, none);
    for (int k = 0; k < n; ++k) {
        // Velocities at Δt → 0: the viscous forces alone.
        const Eigen::VectorXd fv = forces(make, with_dof(p, k, v0, false), none);
        e.r.col(k) = -(fv - f0) / v0;
        // Tangential springs: at Δt the history moves by v_t Δt.
        e.k.col(k) = -(forces(make, with_dof(p, k, v0, false), dt) - fv) / (v0 * dt);
        if (k % 6 < 3) // normal springs and van der Waals: displacements
            e.k.col(k) -= (forces(make, with_dof(p, k, x0, true), none) -
                           forces(make, with_dof(p, k, -x0, true), none)) /
                          (2 * x0);
    }
    e.r = 0.5 * (e.r + e.r.transpose());
    e.k = 0.5 * (e.k + e.k.transpose());
    return e;
}

double largest(const Mat& a, const Mat& b) {
    Eigen::GeneralizedSelfAdjointEigenSolver<Mat> es(a, b);
    return es.eigenvalues().maxCoeff();
}

/// The engine computes its forces when it is built, which already moves every tangential spring
/// by v_t Δt: built at a vanishing step, the springs hold nothing before `forces` evaluates them
/// at its own step (built at the run's step, R picked up S_t Δt, 23 % of ω at Δt = 1e-9 s).
Factory factory(const Config& c, const FilmRecipe& r, const ReferenceCluster& k) {
    Config fresh = c;
    fresh.time_step = 1e-30;
    return [fresh, &r, &k](const ParticleStore& p) {
        ReferenceCluster moved{k.name, p};
        return cluster_simulation(fresh, r, moved, 1e-12);
    };
}

Config drying_config(const char* integrator) {
    Config c;
    c.box_x = c.box_y = 60e-6;
    c.integrator = integrator;
    return c;
}
} // namespace

TEST(GuardClusters, DampingRateIsTheExactLargestEigenvalue) {
    const Config c = drying_config("explicit");
    const FilmRecipe r = make_recipe(c);
    for (const ReferenceCluster& k : reference_clusters(r, 0.015e-6)) {
        Simulation sim = cluster_simulation(c, r, k, 1e-12);
        const double estimate = sim.stability_estimate().damping_rate;
        const Exact e = measure(factory(c, r, k), k.particles, sim.settings().dt);
        const double exact = largest(e.r, e.m);
        EXPECT_NEAR(estimate, exact, 0.02 * exact) << k.name;
        EXPECT_LE(estimate, exact * 1.0001) << k.name; // a Rayleigh quotient never overshoots
    }
}

// At the force-ratio cap (1e-10 s) and the paper scheme's (1e-9 s), where Δt D outweighs M; the
// kick without the self-stiffness (with it the stiffness sets no rate: ImplicitStiffness tests).
TEST(GuardClusters, StiffnessRateIsTheExactLargestEigenvalueWithTheImplicitMass) {
    for (const double cap : {1e-10, 1e-9}) {
        Config c = drying_config("semi_implicit");
        c.time_step = cap;
        c.implicit_stiffness = false;
        const FilmRecipe r = make_recipe(c);
        for (const ReferenceCluster& k : reference_clusters(r, 0.015e-6)) {
            Simulation sim = cluster_simulation(c, r, k, 1e-12);
            const double estimate = sim.stability_estimate().stiffness_rate;
            const Exact e = measure(factory(c, r, k), k.particles, sim.settings().dt);
            Mat m_eff = e.m;
            const double dt = sim.settings().dt;
            for (int i = 0; i < e.m.rows(); i += 6)
                m_eff.block(i, i, 6, 6) += dt * e.r.block(i, i, 6, 6);
            const double exact = std::sqrt(largest(e.k, m_eff));
            EXPECT_NEAR(estimate, exact, 0.03 * exact) << k.name << " at " << cap << " s";
        }
    }
}

// The explicit integrator's damping bound is what the old per-pair guard missed: for a CB on one
// NCM the exact λ_max is about twice max(γ_n, 3.5 γ_t) / m (rolling torques, lever arms).
TEST(GuardClusters, ExplicitBoundExceedsThePerPairEstimate) {
    const Config c = drying_config("explicit");
    const FilmRecipe r = make_recipe(c);
    const ReferenceCluster k = reference_clusters(r, 0.015e-6).front();
    Simulation sim = cluster_simulation(c, r, k, 1e-12);
    const ParticleStore& p = sim.particles();
    const Vec3 d = p.position[1] - p.position[0];
    const PairGeometry g = make_pair_geometry(d, norm(d), p.radius[0], p.radius[1], p.mass[0],
                                              p.mass[1], {}, {}, {}, {});
    const PairResistance lub = lubrication_resistance(
        g, law<LubricationLaw>(sim.forces().pair_params(p.species[0], p.species[1])));
    const double per_pair =
        std::max(lub.normal, 3.5 * lub.sliding) * (p.inv_mass[1] + p.inv_mass[0]);
    EXPECT_GT(sim.stability_estimate().damping_rate, 1.8 * per_pair);
}

// Density scaling of the CB (scaling.cb_density_scaling S): on the all-CB fcc cluster every mass
// is × S and K is unchanged, so the guard's stiffness rate falls by exactly √S and the reference
// clusters' step may grow; where an NCM takes part, by less.
TEST(GuardClusters, CbDensityScalingLowersTheAllCbClustersStiffnessRateBySqrtS) {
    Config c = drying_config("explicit");
    const FilmRecipe r = make_recipe(c);
    const auto plain = guard_on_reference_clusters(c, r, "explicit");
    c.drying_cb_density_scaling = 16;
    const auto scaled = guard_on_reference_clusters(c, r, "explicit");
    ASSERT_EQ(plain.size(), scaled.size());
    ASSERT_EQ(plain[2].name, "fcc cluster of 13 CB");
    const double ratio = scaled[2].estimate.stiffness_rate / plain[2].estimate.stiffness_rate;
    EXPECT_NEAR(ratio, 0.25, 0.01);
    for (std::size_t k = 0; k < plain.size(); ++k) {
        EXPECT_LT(scaled[k].estimate.stiffness_rate, plain[k].estimate.stiffness_rate)
            << plain[k].name;
        EXPECT_GE(scaled[k].dt, plain[k].dt) << plain[k].name;
    }
}
