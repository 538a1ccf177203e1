// SPDX-License-Identifier: MIT
// NMP and air property correlations at the check values of docs/dryer.md D-5 (relative 1e-4; the
// values come from an independent Python implementation of the same correlations, 6 digits).
#include "drydem/dryer_model/nmp_properties.hpp"
#include <gtest/gtest.h>
#include <cmath>

namespace {
using namespace drydem::dryer;

void expect_rel(double actual, double expected, double rel = 1e-4) {
    EXPECT_NEAR(actual, expected, rel * std::abs(expected)) << "expected " << expected;
}

TEST(DryerProperties, VapourPressureAnchoredAtCheckValues) {
    expect_rel(vapour_pressure(298.15), 47.4009);
    expect_rel(vapour_pressure(353.15), 1172.67);
    expect_rel(vapour_pressure(373.15), 2976.00); // Table A1
    expect_rel(vapour_pressure(393.15), 6867.32);
    expect_rel(vapour_pressure(475.2), 101325.0); // normal boiling point
}

TEST(DryerProperties, VapourPressureLandoltAtCheckValues) {
    expect_rel(vapour_pressure(353.15, antoine_landolt), 1294.55);
    expect_rel(vapour_pressure(373.15, antoine_landolt), 3362.02); // 13 % above Table A1
    expect_rel(vapour_pressure(393.15, antoine_landolt), 7728.19);
    EXPECT_FALSE(antoine_landolt.validity.contains(298.15));
    EXPECT_TRUE(antoine_anchored.validity.contains(298.15));
}

TEST(DryerProperties, EnthalpyOfVaporisationWatson) {
    expect_rel(enthalpy_of_vaporisation(298.15), 54930.0);
    expect_rel(enthalpy_of_vaporisation(353.15), 52101.3);
    expect_rel(enthalpy_of_vaporisation(373.15), 51008.0); // Table A1
    expect_rel(enthalpy_of_vaporisation(393.15), 49875.0);
}

TEST(DryerProperties, HeatCapacitiesOfNmp) {
    expect_rel(liquid_heat_capacity(298.15), 1679.11);
    expect_rel(liquid_heat_capacity(373.15), 1868.25); // 185.2 J/(mol K), Table A1
    expect_rel(vapour_heat_capacity(353.15), 1278.12);
    expect_rel(vapour_heat_capacity(373.15), 1344.70); // 133.3 J/(mol K), Table A1
    // the closed-form sensible enthalpy is the integral of c_p,l (Simpson is exact for a line)
    const double a = 298.15, b = 393.15;
    const double simpson = (b - a) / 6.0 *
                           (liquid_heat_capacity(a) + 4 * liquid_heat_capacity(0.5 * (a + b)) +
                            liquid_heat_capacity(b));
    expect_rel(liquid_sensible_enthalpy(a, b), simpson, 1e-12);
}

TEST(DryerProperties, LiquidDensity) {
    expect_rel(liquid_density(298.15), 1027.66);
    expect_rel(liquid_density(353.15), 978.841);
}

TEST(DryerProperties, FullerDiffusionCoefficient) {
    expect_rel(diffusion_coefficient_nmp_air(298.15), 8.65509e-6);
    expect_rel(diffusion_coefficient_nmp_air(353.15), 1.16396e-5);
    expect_rel(diffusion_coefficient_nmp_air(373.15), 1.28176e-5);
    // inversely proportional to the pressure
    expect_rel(diffusion_coefficient_nmp_air(353.15, 2 * 101325.0), 0.5 * 1.16396e-5);
}

TEST(DryerProperties, DryAir) {
    expect_rel(air_thermal_conductivity(298.15), 0.0261044);
    expect_rel(air_thermal_conductivity(353.15), 0.0302719);
    expect_rel(air_heat_capacity(298.15), 1006.83);
    expect_rel(air_heat_capacity(393.15), 1015.38);
    expect_rel(air_density(298.15), 1.18390);
    expect_rel(air_density(373.15), 0.945950);
}

} // namespace
