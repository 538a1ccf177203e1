// SPDX-License-Identifier: MIT
// Extrusion of an agglomerate pressed past its densest state (model.md M-2.13): the dense lens
// against the closed form of two intersecting spheres and of a cap on a plane, the threshold at
// the depth where M-2.12's contact reaches ε_min, the pore room, the sharing of the solid
// nearest first, and the key's checks.
#include "drydem/core/error.hpp"
#include "drydem/drying/law_parameters.hpp"
#include "drydem/forces/agglomerate_extrusion.hpp"
#include "drydem/io/config.hpp"
#include <string>
#include <gtest/gtest.h>
#include "expect_rel.hpp"
#include "sphere_lens.hpp"
#include <cmath>
#include <numbers>

namespace {
using namespace drydem;
using testing_support::expect_rel;
using testing_support::lens_volume;

constexpr double kPi = std::numbers::pi;
constexpr double kRcb = 0.75e-6, kRncm = 5e-6;

AgglomerateExtrusionParams extrusion() { return {0.75, 0.383, true}; }

TEST(AgglomerateExtrusion, ADensePartnerTakesTheWholeLens) {
    for (double f : {0.05, 0.5, 1.2}) {
        const double overlap = f * kRcb;
        expect_rel(dense_lens(kRcb, kRncm, overlap),
                   lens_volume(kRcb, kRncm, kRcb + kRncm - overlap), 1e-9);
        // On a plane: the cap of height δ.
        expect_rel(dense_lens(kRcb, 0.0, overlap),
                   kPi * overlap * overlap * (3 * kRcb - overlap) / 3, 1e-12);
    }
    EXPECT_EQ(dense_lens(kRcb, kRncm, 0.0), 0.0);
    EXPECT_EQ(dense_lens(kRcb, kRncm, -1e-9), 0.0);
}

TEST(AgglomerateExtrusion, ExtrudedWhereTheLensesLeaveNoRoomAtTheDensestState) {
    const AgglomerateExtrusionParams p = extrusion();
    const double v = 4.0 / 3.0 * kPi * kRcb * kRcb * kRcb;
    // The rest of the envelope holds the solid (1 − ε_0) V at ε_min: V − V_l = (1 − ε_0) V / (1 − ε_min).
    const double threshold = v - 0.25 * v / (1.0 - 0.383);
    expect_rel(v * densest_lens_fraction(0.75, 0.383), threshold, 1e-12);
    EXPECT_FALSE(extruded(p, kRcb, threshold * (1 - 1e-9)));
    EXPECT_TRUE(extruded(p, kRcb, threshold * (1 + 1e-9)));
    // One contact on a plane: the cap height at which it happens, 1.13 r for 0.75 → 0.383.
    double lo = 0.0, hi = 2 * kRcb;
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        (extruded(p, kRcb, dense_lens(kRcb, 0.0, mid)) ? hi : lo) = mid;
    }
    EXPECT_NEAR(hi / kRcb, 1.13, 0.005);
    // Two NCM particles from either side extrude it at less depth each than one does.
    const double one = [&] {
        double a = 0.0, b = 2 * kRcb;
        for (int k = 0; k < 200; ++k) {
            const double m = 0.5 * (a + b);
            (extruded(p, kRcb, dense_lens(kRcb, kRncm, m)) ? b : a) = m;
        }
        return b;
    }();
    EXPECT_TRUE(extruded(p, kRcb, 2 * dense_lens(kRcb, kRncm, 0.7 * one)));
    EXPECT_FALSE(extruded(p, kRcb, dense_lens(kRcb, kRncm, 0.7 * one)));
    // Switched off: never.
    AgglomerateExtrusionParams off = p;
    off.on = false;
    EXPECT_FALSE(extruded(off, kRcb, v));
    // The threshold is M-2.12's: the contact's lens porosity reaches ε_min there.
    const AgglomerateHardening h{0.75, 0.383, 600e6, AgglomerateSides::i};
    EXPECT_DOUBLE_EQ(lens_porosity(h, kRcb, threshold * (1 + 1e-9), 0.0).porosity, 0.383);
    EXPECT_GT(lens_porosity(h, kRcb, threshold * (1 - 1e-6), 0.0).porosity, 0.383);
}

TEST(AgglomerateExtrusion, PoreRoomIsWhatCompactionToTheDensestStateFrees) {
    const AgglomerateExtrusionParams p = extrusion();
    const double v = 4.0 / 3.0 * kPi * kRcb * kRcb * kRcb;
    expect_rel(pore_room(p, kRcb, 0.75), (0.75 - 0.383) * v, 1e-12);
    EXPECT_EQ(pore_room(p, kRcb, 0.383), 0.0);
    EXPECT_EQ(pore_room(p, kRcb, 0.3), 0.0); // never negative
}

TEST(AgglomerateExtrusion, SolidIsSharedNearestFirstAndNothingIsLost) {
    const ExtrusionShares a = share_extruded_solid(1.0, {0.4, 0.5, 0.7, 2.0});
    EXPECT_DOUBLE_EQ(a.taken[0], 0.4);
    EXPECT_DOUBLE_EQ(a.taken[1], 0.5);
    EXPECT_NEAR(a.taken[2], 0.1, 1e-15);
    EXPECT_EQ(a.taken[3], 0.0);
    EXPECT_NEAR(a.taken[0] + a.taken[1] + a.taken[2] + a.left, 1.0, 1e-15);
    EXPECT_EQ(a.left, 0.0);
    const ExtrusionShares b = share_extruded_solid(1.0, {0.25, 0.25});
    EXPECT_DOUBLE_EQ(b.left, 0.5);
    const ExtrusionShares c = share_extruded_solid(1.0, {});
    EXPECT_DOUBLE_EQ(c.left, 1.0);
}

TEST(AgglomerateExtrusion, KeyReadsTheMinimalPorosityAndRefusesABadOne) {
    Config on;
    on.cb_extrusion = true;
    const AgglomerateExtrusionParams p = agglomerate_extrusion(on);
    EXPECT_TRUE(p.on);
    EXPECT_DOUBLE_EQ(p.initial_porosity, on.cb_porosity);
    EXPECT_DOUBLE_EQ(p.minimal_porosity, agglomerate_binder_porosity(on)); // 0 = binder-filled
    EXPECT_FALSE(agglomerate_extrusion(Config{}).on);
    for (const double e : {0.8, 0.3}) {
        Config c = on;
        c.cb_minimal_porosity = e;
        try {
            (void)agglomerate_extrusion(c);
            ADD_FAILURE() << "expected InputError for " << e;
        } catch (const InputError& err) {
            EXPECT_NE(std::string(err.what()).find("calendering.cb_minimal_porosity"),
                      std::string::npos)
                << err.what();
        }
        c.cb_extrusion = false; // not used: not checked
        EXPECT_NO_THROW((void)agglomerate_extrusion(c));
    }
}

} // namespace
