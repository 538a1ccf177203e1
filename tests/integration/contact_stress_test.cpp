// SPDX-License-Identifier: MIT
// The packing's contact stress (Simulation::contact_stress, Love-Weber): over a column between
// the substrate and a plate in equilibrium its s_zz is the plate's pressure, and nothing acts
// sideways; a pair alone gives f d / V. Each particle's own mean stress (particle_mean_stress)
// splits the same forces at the contact plane: f a_i / 3V_i, and Σ 3 σ_i V_i = tr(s) V.
#include "drydem/engine/fire.hpp"
#include "drydem/forces/hertz_mindlin.hpp"
#include <gtest/gtest.h>
#include <cmath>

using namespace drydem;

namespace {
constexpr double kR = 2e-6, kRho = 4700, kL = 40e-6;

/// Two spheres stacked on the substrate under a plate 30 nm low (the overlap shared among three
/// contacts), relaxed by FIRE to rest.
Simulation pressed_column(double plate) {
    ForceField ff = uniform_contact_force_field(1, 142e9, 0.3, 0.5, 0.5);
    for (BodyParams& b : ff.body) law<PlateContactLaw>(b) = law<SubstrateContactLaw>(b);
    ParticleStore p;
    p.add(1, 0, kR, kRho, {5e-6, 5e-6, kR});
    p.add(2, 0, kR, kRho, {5e-6, 5e-6, 3 * kR});
    Simulation sim(std::move(p), Box{kL, kL}, ff, {2e-10, 0.1e-6, 1});
    sim.set_plate_height(plate);
    FireRelaxation fire(2e-10);
    for (int k = 0; k < 40000 && fire.rms_force() > 1e-12; ++k) {
        sim.step();
        fire.after_step(sim);
    }
    return sim;
}

TEST(ContactStress, ColumnUnderThePlateCarriesThePlatePressure) {
    const double plate = 4 * kR - 30e-9;
    const Simulation sim = pressed_column(plate);
    const double pressure = -sim.body_law_total<PlateContactLaw>().force.z / (kL * kL);
    ASSERT_GT(pressure, 0.0);
    const Sym3 s = sim.contact_stress(kL * kL * plate);
    EXPECT_NEAR(s.zz, pressure, 1e-6 * pressure);
    EXPECT_NEAR(s.xx, 0.0, 1e-9 * pressure);
    EXPECT_NEAR(s.xz, 0.0, 1e-9 * pressure);
}

TEST(ContactStress, APairAloneGivesForceTimesBranchOverVolume) {
    ForceField ff = uniform_contact_force_field(1, 142e9, 0.3, 0.5, 0.5);
    ff.remove_substrate();
    ParticleStore p;
    const double delta = 10e-9;
    const Vec3 n = Vec3{1.0, 2.0, 2.0} / 3.0;
    p.add(1, 0, kR, kRho, {20e-6, 20e-6, 20e-6});
    p.add(2, 0, kR, kRho, Vec3{20e-6, 20e-6, 20e-6} + (2 * kR - delta) * n);
    Simulation sim(std::move(p), Box{kL, kL}, ff, {2e-10, 0.1e-6, 1});
    const double e_star = mix_hertz_mindlin(142e9, 0.3, 142e9, 0.3, 0.5, 0.5, 0.0).e_star;
    const double f = 4.0 / 3.0 * e_star * std::sqrt(kR / 2) * std::pow(delta, 1.5);
    const double v = 1e-15, d = 2 * kR - delta;
    const Sym3 s = sim.contact_stress(v);
    EXPECT_NEAR(s.xx, f * d * n.x * n.x / v, 1e-9 * f * d / v);
    EXPECT_NEAR(s.yz, f * d * n.y * n.z / v, 1e-9 * f * d / v);
    EXPECT_NEAR(s.zz, f * d * n.z * n.z / v, 1e-9 * f * d / v);
}

TEST(ContactStress, ParticleMeanStressSplitsThePairAtItsContactPlane) {
    ForceField ff = uniform_contact_force_field(2, 142e9, 0.3, 0.5, 0.5);
    ff.remove_substrate();
    ParticleStore p;
    const double r2 = 0.75e-6, delta = 10e-9;
    const Vec3 n = Vec3{2.0, 1.0, 2.0} / 3.0, x1{20e-6, 20e-6, 20e-6};
    p.add(1, 0, kR, kRho, x1);
    p.add(2, 1, r2, 1200.0, x1 + (kR + r2 - delta) * n);
    Simulation sim(std::move(p), Box{kL, kL}, ff, {2e-10, 0.1e-6, 1});
    const double e_star = mix_hertz_mindlin(142e9, 0.3, 142e9, 0.3, 0.5, 0.5, 0.0).e_star;
    const double f = 4.0 / 3.0 * e_star * std::sqrt(kR * r2 / (kR + r2)) * std::pow(delta, 1.5);
    const double d = kR + r2 - delta;
    // The intersection circle of the two spheres: a_1 + a_2 = d.
    const double a1 = (d * d + kR * kR - r2 * r2) / (2 * d), a2 = d - a1;
    const std::vector<double> sigma = sim.particle_mean_stress();
    const ParticleStore& q = sim.particles();
    for (std::size_t i = 0; i < 2; ++i) {
        const bool big = q.id[i] == 1;
        const double v = sphere_volume(big ? kR : r2);
        EXPECT_NEAR(sigma[i], f * (big ? a1 : a2) / (3 * v), 1e-9 * f * d / v);
    }
    const double cell = 1e-15;
    const Sym3 s = sim.contact_stress(cell);
    const double sum =
        3 * (sigma[0] * sphere_volume(q.radius[0]) + sigma[1] * sphere_volume(q.radius[1]));
    EXPECT_NEAR(sum, (s.xx + s.yy + s.zz) * cell, 1e-9 * f * d);
}

TEST(ContactStress, ParticleMeanStressOfAColumnUnderThePlate) {
    const double plate = 4 * kR - 30e-9;
    const Simulation sim = pressed_column(plate);
    // Each sphere carries the plate's force F through two contacts, levers summing to ~2 r:
    // σ = F 2r / 3V, compression positive; the sum matches the packing's stress.
    const double force = -sim.body_law_total<PlateContactLaw>().force.z;
    ASSERT_GT(force, 0.0);
    const std::vector<double> sigma = sim.particle_mean_stress();
    const double v = sphere_volume(kR);
    for (double s : sigma)
        EXPECT_NEAR(s, force * 2 * kR / (3 * v), 0.01 * force * 2 * kR / (3 * v));
    const Sym3 s = sim.contact_stress(kL * kL * plate);
    EXPECT_NEAR(3 * v * (sigma[0] + sigma[1]), (s.xx + s.yy + s.zz) * kL * kL * plate,
                1e-6 * force * kR);
}

} // namespace
