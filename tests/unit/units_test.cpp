// SPDX-License-Identifier: MIT
// Config quantities with units → SI (io/units.hpp).
#include "drydem/core/error.hpp"
#include "drydem/io/units.hpp"
#include <gtest/gtest.h>
#include <numbers>
#include <string>

using namespace drydem;
using D = Dimension;

namespace {
double q(const char* text, D d) { return parse_quantity(text, d, "test.key"); }

// Message of the InputError thrown by parsing `text`, or "" when nothing was thrown.
std::string error_of(const char* text, D d, const char* key = "film.particle_diameter") {
    try {
        (void)parse_quantity(text, d, key);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}
} // namespace

// Decimal prefixes are folded into the number's exponent, so these equal the SI literal exactly.
TEST(Units, DecimalUnitsGiveTheExactSiLiteral) {
    EXPECT_EQ(q("6.5 um", D::length), 6.5e-6);
    EXPECT_EQ(q("6.5um", D::length), 6.5e-6);
    EXPECT_EQ(q("6.5 µm", D::length), 6.5e-6); // micro sign U+00B5
    EXPECT_EQ(q("6.5 μm", D::length), 6.5e-6); // Greek mu U+03BC
    EXPECT_EQ(q("1e-6 m", D::length), 1e-6);
    EXPECT_EQ(q("  -3e2 um ", D::length), -3e-4);
    EXPECT_EQ(q("20.1 mg/cm^2", D::areal_density), 0.201);
    EXPECT_EQ(q("20.1 mg/cm2", D::areal_density), 0.201);
    EXPECT_EQ(q("20.1 mg / cm²", D::areal_density), 0.201);
    EXPECT_EQ(q("1.801 Pa*s", D::viscosity), 1.801);
    EXPECT_EQ(q("1801 mPa*s", D::viscosity), 1.801);
    EXPECT_EQ(q("1.801 Pa s", D::viscosity), 1.801);
    EXPECT_EQ(q("1.801 Pa·s", D::viscosity), 1.801);
    EXPECT_EQ(q("1801 cP", D::viscosity), 1.801);
    EXPECT_EQ(q("300 K", D::temperature), 300.0);
    EXPECT_EQ(q("4.74 g/cm^3", D::density), 4740.0);
    EXPECT_EQ(q("4740 kg/m^3", D::density), 4740.0);
    EXPECT_EQ(q("4740 kg m^-3", D::density), 4740.0);
    EXPECT_EQ(q("4.74 g/mL", D::density), 4740.0);
    EXPECT_EQ(q("142 GPa", D::pressure), 142e9);
    EXPECT_EQ(q("0.041 N/m", D::surface_tension), 0.041);
    EXPECT_EQ(q("41 mN/m", D::surface_tension), 0.041);
    EXPECT_EQ(q("0.7 rad", D::angle), 0.7);
    EXPECT_EQ(q("1.193 um/s", D::velocity), 1.193e-6);
    EXPECT_EQ(q("9.81 m/s^2", D::acceleration), 9.81);
    EXPECT_EQ(q("9.81 m s^-2", D::acceleration), 9.81);
    EXPECT_EQ(q("1e-11 s", D::time), 1e-11);
    EXPECT_EQ(q("10 ns", D::time), 1e-8);
    EXPECT_EQ(q("60 s", D::time), 60.0);
    EXPECT_EQ(q("2 min", D::time), 120.0);
    EXPECT_EQ(q("1 h", D::time), 3600.0);
    EXPECT_EQ(q("4.64e-20 J", D::energy), 4.64e-20);
    EXPECT_EQ(q("1 nN", D::force), 1e-9);
    EXPECT_EQ(q("3 pg", D::mass), 3e-15);
    EXPECT_EQ(q("3 ug", D::mass), 3e-9);
    EXPECT_EQ(q("3 mg", D::mass), 3e-6);
    EXPECT_EQ(q("3 kg", D::mass), 3.0);
    EXPECT_EQ(q("5 1/s", D::frequency), 5.0);
    EXPECT_EQ(q("5 kHz", D::frequency), 5e3);
    EXPECT_EQ(q("25 W/(m^2*K)", D::heat_transfer_coefficient), 25.0);
    EXPECT_EQ(q("900 J/kg/K", D::specific_heat), 900.0);
    EXPECT_EQ(q("7 %", D::dimensionless), 0.07);
}

TEST(Units, NonDecimalFactors) {
    EXPECT_EQ(q("2 m/min", D::velocity), 2.0 / 60.0);
    EXPECT_EQ(q("40 deg", D::angle), 40.0 * std::numbers::pi / 180.0);
    EXPECT_EQ(q("40 °", D::angle), 40.0 * std::numbers::pi / 180.0);
    EXPECT_EQ(q("80 degC", D::temperature), 80.0 + 273.15);
    EXPECT_DOUBLE_EQ(q("80 degC", D::temperature), 353.15);
    EXPECT_DOUBLE_EQ(q("80 °C", D::temperature), 353.15);
}

TEST(Units, BareNumbersAreSi) {
    EXPECT_EQ(q("2.5", D::length), 2.5);
    EXPECT_EQ(q("2.5", D::dimensionless), 2.5);
    EXPECT_EQ(q("0.7", D::angle), 0.7);         // radians
    EXPECT_EQ(q("300", D::temperature), 300.0); // kelvin
    EXPECT_EQ(q("+6.5e-6", D::length), 6.5e-6);
    EXPECT_EQ(q(".5", D::dimensionless), 0.5);
}

TEST(Units, DimensionMismatchNamesKeyValueAndWhatIsAllowed) {
    const auto msg = error_of("6.5 kg", D::length);
    EXPECT_EQ(msg, "config key 'film.particle_diameter': \"6.5 kg\" has unit kg (mass) but a "
                   "length is expected (e.g. \"6.5 um\" or 6.5e-6)");
    const auto msg2 = error_of("40 deg", D::dimensionless, "contact.friction");
    EXPECT_NE(msg2.find("contact.friction"), std::string::npos);
    EXPECT_NE(msg2.find("40 deg"), std::string::npos);
    EXPECT_NE(msg2.find("angle"), std::string::npos);
    // A compound unit with no name shows its SI base form.
    const auto msg3 = error_of("3 m^3/s", D::velocity, "k");
    EXPECT_NE(msg3.find("m^3 s^-1"), std::string::npos) << msg3;
    // One with a name shows the name.
    const auto msg4 = error_of("3 m^2/s", D::velocity, "k");
    EXPECT_NE(msg4.find("(diffusivity)"), std::string::npos) << msg4;
    EXPECT_NE(error_of("1 m", D::time).find("a time is expected"), std::string::npos);
    EXPECT_NE(error_of("1 m", D::acceleration).find("an acceleration"), std::string::npos);
    EXPECT_NE(error_of("20 mg/cm^3", D::areal_density).find("mg/cm^2"), std::string::npos);
}

TEST(Units, MalformedValuesThrow) {
    for (const char* bad :
         {"abc um",  "",       "   ",       "um",        "6.5 foo",   "6.5 m^",  "6.5 m^x",
          "6.5 m/",  "6.5 (m", "6.5 m)",    "nan",       "inf m",     "1e400 m", "6.5 m 2",
          "6.5 m 1", "1..2 m", "80 degC/s", "80 degC^2", "80 degC K", "6.5 um,"}) {
        const auto msg = error_of(bad, D::length, "film.particle_diameter");
        EXPECT_FALSE(msg.empty()) << "accepted: '" << bad << "'";
        EXPECT_NE(msg.find("film.particle_diameter"), std::string::npos) << msg;
    }
    EXPECT_NE(error_of("abc um", D::length).find("\"abc um\""), std::string::npos);
    EXPECT_NE(error_of("6.5 foo", D::length).find("unknown unit 'foo'"), std::string::npos);
    EXPECT_NE(error_of("80 degC/s", D::temperature).find("only allowed alone"), std::string::npos);
}

TEST(Units, FormatQuantityIsReadableAndReadsBack) {
    EXPECT_EQ(format_quantity(6.5e-6, D::length), "6.5 um");
    EXPECT_EQ(format_quantity(0.201, D::areal_density), "20.1 mg/cm^2");
    EXPECT_EQ(format_quantity(1.801, D::viscosity), "1.801 Pa*s");
    EXPECT_EQ(format_quantity(0.0018, D::viscosity), "1.8 mPa*s");
    EXPECT_EQ(format_quantity(142e9, D::pressure), "142 GPa");
    EXPECT_EQ(format_quantity(40.0 * std::numbers::pi / 180.0, D::angle), "40 deg");
    EXPECT_EQ(format_quantity(353.15, D::temperature), "353.15 K");
    EXPECT_EQ(format_quantity(0.5, D::dimensionless), "0.5");
    EXPECT_EQ(dimension_name(D::areal_density), "areal density");
    for (int k = 0; k <= static_cast<int>(D::specific_heat); ++k) {
        const auto d = static_cast<D>(k);
        for (const double v : {1.234e-9, 3.3e-6, 0.5, 7.0, 4.2e4}) {
            const auto text = format_quantity(v, d);
            EXPECT_NEAR(parse_quantity(text, d, "x"), v, 1e-5 * v) << text;
        }
    }
}
