// SPDX-License-Identifier: MIT
// A simple cubic array of equal elastic spheres between the substrate and the calendering plate
// (periodic sides) gives the Hertz stress-strain law: each column of n spheres carries the plate's
// force F through n - 1 sphere-sphere contacts (R* = R/2) and two wall contacts (R* = R), so its
// compression is
//   ΔH = 2 δ(F; R) + (n - 1) δ(F; R/2),   δ(F; R*) = (3F / (4 E* sqrt(R*)))^{2/3}
// and the plate's pressure F / (2R)² grows as ΔH^{3/2}. FIRE brings the array to rest at each
// plate height; the pressure must match the closed form.
#include "drydem/engine/fire.hpp"
#include "drydem/forces/hertz_mindlin.hpp"
#include <gtest/gtest.h>
#include <cmath>

using namespace drydem;

namespace {
constexpr double kR = 2e-6, kRho = 4700, kE = 142e9, kNu = 0.3;
constexpr int kSide = 2, kLayers = 3;
constexpr double kCell = 2 * kR * kSide;

/// The column force F that compresses a column by dh (bisection on the monotone closed form).
double column_force(double dh, double e_star) {
    auto compression = [&](double f) {
        return 2 * hertz_overlap(f, kR, e_star) + (kLayers - 1) * hertz_overlap(f, kR / 2, e_star);
    };
    double lo = 0.0, hi = 1.0;
    while (compression(hi) < dh) hi *= 2;
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        (compression(mid) < dh ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

double plate_pressure_at(double dh) {
    ForceField ff = uniform_contact_force_field(1, kE, kNu, 0.5, 0.5);
    for (BodyParams& b : ff.body) law<PlateContactLaw>(b) = law<SubstrateContactLaw>(b);
    ParticleStore p;
    std::uint32_t id = 1;
    for (int a = 0; a < kSide; ++a)
        for (int b = 0; b < kSide; ++b)
            for (int c = 0; c < kLayers; ++c) {
                // Spheres touching: the plate overlaps the top one by dh at the start.
                p.add(id++, 0, kR, kRho, {kR * (1 + 2 * a), kR * (1 + 2 * b), kR * (1 + 2 * c)});
            }
    Simulation sim(std::move(p), Box{kCell, kCell}, ff, {2e-10, 0.1e-6, 1});
    sim.set_plate_height(2 * kR * kLayers - dh);
    FireRelaxation fire(2e-10);
    for (int k = 0; k < 100000 && fire.rms_force() > 1e-9; ++k) {
        sim.step();
        fire.after_step(sim);
    }
    return -sim.body_law_total<PlateContactLaw>().force.z / (kCell * kCell);
}

TEST(PlateHertz, SimpleCubicArrayFollowsTheHertzStressStrainLaw) {
    const double e_star = mix_hertz_mindlin(kE, kNu, kE, kNu, 0.5, 0.5, 0.0).e_star;
    for (double dh : {20e-9, 60e-9, 180e-9}) {
        const double expected = column_force(dh, e_star) / (4 * kR * kR);
        EXPECT_NEAR(plate_pressure_at(dh), expected, 1e-4 * expected) << "dh = " << dh;
    }
    // The law itself: pressure ∝ strain^{3/2} (a ninefold strain, a 27-fold pressure).
    EXPECT_NEAR(column_force(180e-9, e_star) / column_force(20e-9, e_star), 27.0, 1e-9);
}

} // namespace
