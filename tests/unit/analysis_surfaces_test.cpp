// SPDX-License-Identifier: MIT
// NCM surface split against sphere caps (issue 15): a cap of height h on a sphere of radius r has the
// area 2π r h; the cut of a sphere R by a sphere ρ at centre distance d lies at x = (d² + R² − ρ²)/(2d).
#include "drydem/analysis/surfaces.hpp"
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace drydem;
using namespace drydem::analysis;

namespace {
constexpr double pi = std::numbers::pi;
double cap_fraction(double R, double rho, double d) { // of sphere R inside sphere rho
    const double x = (d * d + R * R - rho * rho) / (2.0 * d);
    return (R - x) / (2.0 * R);
}
Structure box20() {
    Structure s;
    s.box.lx = s.box.ly = 20e-6;
    return s;
}
} // namespace

TEST(Surfaces, LoneSphereIsAllElectrolyte) {
    Structure s = box20();
    s.add({10e-6, 10e-6, 5e-6}, 4e-6, Phase::ncm, 4740);
    const Surfaces a = ncm_surfaces(s, {2000, 0.1e-6});
    EXPECT_NEAR(a.total, 4 * pi * 16e-12, 1e-20);
    EXPECT_NEAR(a.electrolyte_fraction(), 1.0, 1e-12);
    EXPECT_EQ(a.cb_covered, 0.0);
}

TEST(Surfaces, SubstrateCutsACapOfHeightRMinusZ) {
    Structure s = box20();
    s.add({10e-6, 10e-6, 2e-6}, 4e-6, Phase::ncm, 4740); // cap height 2 um below z = 0
    const Surfaces a = ncm_surfaces(s, {2000, 0.0});
    EXPECT_NEAR(a.substrate / a.total, 2.0 / 8.0, 2e-3);
    EXPECT_NEAR(a.electrolyte / a.total, 6.0 / 8.0, 2e-3);
}

TEST(Surfaces, OverlappingNcmSpheresShareTheirCaps) {
    Structure s = box20();
    s.add({5e-6, 10e-6, 8e-6}, 4e-6, Phase::ncm, 4740);
    s.add({11e-6, 10e-6, 8e-6}, 3e-6, Phase::ncm, 4740);
    const Surfaces a = ncm_surfaces(s, {4000, 0.0});
    const double expect =
        4 * pi * 16e-12 * cap_fraction(4, 3, 6) + 4 * pi * 9e-12 * cap_fraction(3, 4, 6);
    EXPECT_NEAR(a.ncm_contact / expect, 1.0, 1e-2);
    EXPECT_NEAR(a.electrolyte + a.ncm_contact, a.total, 1e-20);
}

TEST(Surfaces, CbCoverageIsTheCapInsideTheGapInflatedAgglomerate) {
    // NCM R = 4 um, CB ρ = 0.75 um, centres 4.6 um apart (overlap 0.15 um), across the periodic side.
    Structure s = box20();
    s.add({1e-6, 10e-6, 8e-6}, 4e-6, Phase::ncm, 4740);
    s.add({16.4e-6, 10e-6, 8e-6}, 0.75e-6, Phase::cb);
    const Surfaces a = ncm_surfaces(s, {20000, 0.25e-6});
    const double A = 4 * pi * 16e-12;
    EXPECT_NEAR(a.cb_overlap / A, cap_fraction(4, 0.75, 4.6), 3e-4);
    EXPECT_NEAR(a.cb_covered / A, cap_fraction(4, 1.0, 4.6), 3e-4);
    EXPECT_GT(a.cb_covered, 2.0 * a.cb_overlap); // the gap matters for touching agglomerates
    EXPECT_NEAR(a.cb_covered_fraction() + a.electrolyte_fraction(), 1.0, 1e-12);
}
