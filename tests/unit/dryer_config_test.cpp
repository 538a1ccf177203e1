// SPDX-License-Identifier: MIT
// The [dryer] keys of the dryer model: defaults, units ("80 degC", "40 W/(m^2*K)"), the mapping
// to FilmDryerParams, and every bad-input rule (InputError naming key, value and what is allowed).
#include "drydem/drying/derived_checks.hpp"
#include "drydem/core/error.hpp"
#include "drydem/dryer_model/dryer_config.hpp"
#include "drydem/io/config.hpp"
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace {
using namespace drydem;

Config load(const std::vector<std::string>& sets) {
    return load_config(default_config_toml(), "default", sets);
}

std::string input_error(const std::vector<std::string>& sets) {
    try {
        (void)load(sets);
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no InputError";
    return {};
}

void expect_contains(const std::string& text, const std::vector<std::string>& parts) {
    for (const std::string& p : parts)
        EXPECT_NE(text.find(p), std::string::npos) << "'" << p << "' not in: " << text;
}

TEST(DryerConfig, DefaultsAreTableA1AndPresetTable2) {
    const Config c = load({});
    EXPECT_EQ(c.dryer_schedule, "rates");
    EXPECT_EQ(c.dryer_preset, "table2");
    ASSERT_EQ(c.dryer_air_temperatures.size(), 3u);
    EXPECT_DOUBLE_EQ(c.dryer_air_temperatures[0], 353.15);
    EXPECT_DOUBLE_EQ(c.dryer_air_temperatures[2], 393.15);
    EXPECT_EQ(c.dryer_heat_transfer_coefficients, (std::vector<double>{40, 40, 55}));
    EXPECT_DOUBLE_EQ(c.dryer_initial_temperature, 298.15);
    EXPECT_DOUBLE_EQ(c.dryer_substrate_heat_capacity, 900.0);
    EXPECT_DOUBLE_EQ(c.coupling_tolerance, 0.5e-6);
    const dryer::FilmDryerParams p = dryer::film_dryer_params(c);
    EXPECT_DOUBLE_EQ(p.analogy_exponent, 0.42);
    EXPECT_DOUBLE_EQ(p.areal_loading, 0.201);
    EXPECT_DOUBLE_EQ(p.liquid_density, 1030.0);
    ASSERT_EQ(p.zones.size(), 3u);
    EXPECT_DOUBLE_EQ(p.zones[2].heat_transfer_top, 55.0);
}

TEST(DryerConfig, UnitsAndOverridesApply) {
    const Config c =
        load({"dryer.air_temperatures=[\"70 degC\", \"373.15 K\"]",
              "dryer.zone_lengths=[\"1.5 m\", \"250 cm\"]",
              "dryer.heat_transfer_coefficients=[\"30 W/(m^2*K)\", 45]", "dryer.preset=physical",
              "dryer.analogy_exponent=0.4", "dryer.vapour_pressure=landolt",
              "dryer.initial_film_temperature=20degC"});
    EXPECT_DOUBLE_EQ(c.dryer_air_temperatures[0], 343.15);
    EXPECT_DOUBLE_EQ(c.dryer_zone_lengths[1], 2.5);
    EXPECT_DOUBLE_EQ(c.dryer_heat_transfer_coefficients[0], 30.0);
    const dryer::FilmDryerParams p = dryer::film_dryer_params(c);
    EXPECT_EQ(p.preset, "physical");
    EXPECT_DOUBLE_EQ(p.analogy_exponent, 0.4); // the override wins over the preset's 1/3
    EXPECT_EQ(p.vapour_pressure.name, "landolt");
    EXPECT_DOUBLE_EQ(p.initial_temperature, 293.15);
    ASSERT_EQ(p.zones.size(), 2u);
    EXPECT_DOUBLE_EQ(p.zones[1].length, 2.5);
}

TEST(DryerConfig, ZeroOrNegativeZoneLengthIsRejected) {
    expect_contains(input_error({"dryer.zone_lengths=[\"2 m\", \"0 m\", \"2 m\"]"}),
                    {"dryer.zone_lengths", "\"0 m\"", "out of range", "(0"});
    expect_contains(input_error({"dryer.zone_lengths=[2, -1, 2]"}), {"dryer.zone_lengths", "-1"});
}

TEST(DryerConfig, ZeroLineSpeedIsRejected) {
    expect_contains(input_error({"dryer.line_speed=0"}),
                    {"dryer.line_speed", "0", "out of range", "(0"});
}

TEST(DryerConfig, AirBelowInitialFilmTemperatureIsRejected) {
    expect_contains(
        input_error({"dryer.air_temperatures=[\"80 degC\", \"20 degC\", \"120 degC\"]"}),
        {"dryer.air_temperatures", "293.15 K", "zone 2", "dryer.initial_film_temperature",
         "allowed >= 298.15 K"});
    // and raising the initial temperature above the air of zone 1
    expect_contains(input_error({"dryer.initial_film_temperature=\"85 degC\""}),
                    {"dryer.air_temperatures", "zone 1"});
}

TEST(DryerConfig, ZeroHeatTransferCoefficientIsRejected) {
    expect_contains(input_error({"dryer.heat_transfer_coefficients=[40, 0, 55]"}),
                    {"dryer.heat_transfer_coefficients", "0", "out of range", "(0"});
}

TEST(DryerConfig, MismatchedZoneArraysAreRejected) {
    expect_contains(input_error({"dryer.air_temperatures=[\"80 degC\", \"100 degC\"]"}),
                    {"dryer.zone_lengths", "3 zones", "dryer.air_temperatures", "2 values"});
    expect_contains(input_error({"dryer.heat_transfer_coefficients=[40, 40, 55, 55]"}),
                    {"dryer.heat_transfer_coefficients", "4 values"});
}

TEST(DryerConfig, OtherBadValuesAreRejected) {
    expect_contains(input_error({"dryer.preset=calibrated"}),
                    {"dryer.preset", "\"table2\"", "\"physical\""});
    expect_contains(input_error({"dryer.schedule=dryer"}),
                    {"dryer.schedule", "\"rates\"", "\"model\""});
    expect_contains(input_error({"dryer.final_porosity=1"}), {"dryer.final_porosity"});
    expect_contains(input_error({"dryer.time_step=\"0.1 s\""}), {"dryer.time_step"});
    expect_contains(
        input_error({"dryer.air_temperatures=[\"80 degC\", \"100 degC\", \"250 degC\"]"}),
        {"dryer.air_temperatures", "480"});
    expect_contains(input_error({"dryer.air_temperatures=[\"80 m\", \"100 degC\", \"120 degC\"]"}),
                    {"dryer.air_temperatures"});
    // the model schedule needs the DEM's equal zones
    expect_contains(input_error({"dryer.schedule=model", "dryer.zone_lengths=[2, 3, 2]"}),
                    {"dryer.zone_lengths", "zone 2", "dryer.zone_length"});
}

// dryer.schedule = "model": the DEM's shrinkage rates come from the dryer model (D-6 step 2).
TEST(DryerConfig, ModelScheduleReplacesRates) {
    const Config c = dryer::with_model_schedule(load({"dryer.schedule=model"}));
    ASSERT_EQ(c.shrinkage_rates.size(), 2u); // 20.1 mg/cm2 consolidates in zone 2
    EXPECT_NEAR(c.shrinkage_rates[0] * 1e6, 0.669, 0.004);
    EXPECT_NEAR(c.shrinkage_rates[1] * 1e6, 1.198, 0.006);
    const Config thin =
        dryer::with_model_schedule(load({"dryer.schedule=model", "film.areal_loading=3mg/cm^2"}));
    EXPECT_EQ(thin.shrinkage_rates.size(), 1u); // the quick case consolidates in zone 1
}

} // namespace
