// SPDX-License-Identifier: MIT
// The [calibration] section (docs/calibration.md): parameters name numeric config keys with
// bounds in that key's unit and range, targets name a run quantity with value and uncertainty;
// every mistake is an InputError naming the key, the value and what is allowed. check_calibration
// adds the checks drydem calibrate needs (a parameter and a target at least, valid runs at the
// bounds) and the warning for fewer independent targets than parameters.
#include "drydem/drying/derived_checks.hpp"
#include "drydem/core/error.hpp"
#include "drydem/io/config.hpp"
#include "drydem/study/calibration.hpp"
#include <gtest/gtest.h>
#include <string>

namespace {
using namespace drydem;

std::string input_error(const std::string& text) {
    try {
        load_config(text, "test.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no InputError for: " << text;
    return {};
}

const std::string friction =
    "[[calibration.parameters]]\nkey = \"contact.friction\"\nmin = 0.4\nmax = 1.2\n";
const std::string porosity =
    "[[calibration.parameters]]\nkey = \"formulation.cb_porosity\"\nmin = 0.6\nmax = 0.85\n";
const std::string thickness = "[[calibration.targets]]\nquantity = \"final_thickness\"\nvalue = "
                              "\"83.8 um\"\nuncertainty = \"2 um\"\n";
const std::string eq2 = "[[calibration.targets]]\nquantity = \"cb_binder_porosity_eq2\"\nvalue = "
                        "0.506\nuncertainty = 0.02\n";

TEST(CalibrationConfig, ParsesParametersAndTargetsInSI) {
    const Config c = load_config("[calibration]\nseeds = 2\nevaluations = 12\n" + friction +
                                     porosity + thickness + eq2,
                                 "test.toml");
    ASSERT_EQ(c.calibration_parameters.size(), 2u);
    EXPECT_EQ(c.calibration_parameters[0].key, "contact.friction");
    EXPECT_DOUBLE_EQ(c.calibration_parameters[0].min, 0.4);
    EXPECT_DOUBLE_EQ(c.calibration_parameters[1].max, 0.85);
    ASSERT_EQ(c.calibration_targets.size(), 2u);
    EXPECT_NEAR(c.calibration_targets[0].value, 83.8e-6, 1e-15);
    EXPECT_NEAR(c.calibration_targets[0].uncertainty, 2e-6, 1e-15);
    EXPECT_DOUBLE_EQ(c.calibration_targets[1].value, 0.506);
    EXPECT_EQ(c.calibration_seeds, 2);
    EXPECT_EQ(c.calibration_evaluations, 12);
    EXPECT_TRUE(check_calibration(c).empty()); // 2 targets for 2 parameters: no warning
    const auto spec = calibration_spec(c, "/x/drydem");
    EXPECT_EQ(spec["initial_points"], 4);                               // max(4, 2 x 2)
    EXPECT_NEAR(spec["targets"][0]["value"].get<double>(), 83.8, 1e-9); // in the summary's um
    EXPECT_EQ(spec["targets"][0]["summary_key"], "final_thickness_um");
}

TEST(CalibrationConfig, BoundsInTheKeysUnitAndRange) {
    // a length parameter takes units; min >= max, and bounds outside the key's range, are refused
    const Config c =
        load_config("[[calibration.parameters]]\nkey = \"formulation.cb_diameter\"\nmin = \"1 "
                    "um\"\nmax = \"2 um\"\nscale = \"log\"\n",
                    "test.toml");
    EXPECT_DOUBLE_EQ(c.calibration_parameters[0].min, 1e-6);
    EXPECT_TRUE(c.calibration_parameters[0].log);
    const std::string inverted = input_error(
        "[[calibration.parameters]]\nkey = \"contact.friction\"\nmin = 0.9\nmax = 0.5\n");
    EXPECT_NE(inverted.find("calibration.parameters[1]"), std::string::npos) << inverted;
    EXPECT_NE(inverted.find("min < max"), std::string::npos) << inverted;
    const std::string range = input_error(
        "[[calibration.parameters]]\nkey = \"formulation.cb_porosity\"\nmin = 0.5\nmax = 1.5\n");
    EXPECT_NE(range.find("calibration.parameters[1].max (formulation.cb_porosity)"),
              std::string::npos)
        << range;
    EXPECT_NE(range.find("out of range"), std::string::npos) << range;
    const std::string unit =
        input_error("[[calibration.parameters]]\nkey = \"formulation.cb_diameter\"\nmin = \"1 "
                    "kg\"\nmax = \"2 um\"\n");
    EXPECT_NE(unit.find("calibration.parameters[1].min"), std::string::npos) << unit;
    const std::string log0 =
        input_error("[[calibration.parameters]]\nkey = \"contact.friction\"\nmin = 0\nmax = "
                    "1\nscale = \"log\"\n");
    EXPECT_NE(log0.find("> 0"), std::string::npos) << log0;
}

TEST(CalibrationConfig, UnknownOrUnfitKeysAreNamed) {
    const std::string typo =
        input_error("[[calibration.parameters]]\nkey = \"contact.frictoin\"\nmin = 0.4\nmax = 1\n");
    EXPECT_NE(
        typo.find("\"contact.frictoin\" is not a config key; did you mean 'contact.friction'"),
        std::string::npos)
        << typo;
    const std::string field = input_error(
        "[[calibration.parameters]]\nkey = \"contact.friction\"\nmin = 0.4\nmaks = 1\n");
    EXPECT_NE(field.find("unknown config key 'calibration.parameters[1].maks'"), std::string::npos)
        << field;
    const std::string section = input_error("[calibration]\nseed = 2\n");
    EXPECT_NE(section.find("unknown config key 'calibration.seed'"), std::string::npos) << section;
    EXPECT_NE(section.find("calibration.seeds"), std::string::npos) << section;
    const std::string integer =
        input_error("[[calibration.parameters]]\nkey = \"run.threads\"\nmin = 1\nmax = 2\n");
    EXPECT_NE(integer.find("cannot be calibrated"), std::string::npos) << integer;
    const std::string twice = input_error(friction + friction);
    EXPECT_NE(twice.find("already a calibration parameter"), std::string::npos) << twice;
    const std::string missing =
        input_error("[[calibration.parameters]]\nkey = \"contact.friction\"\nmin = 0.4\n");
    EXPECT_NE(missing.find("missing 'max'"), std::string::npos) << missing;
    const std::string quantity = input_error(
        "[[calibration.targets]]\nquantity = \"thickness\"\nvalue = 1\nuncertainty = 1\n");
    EXPECT_NE(quantity.find("\"final_thickness\""), std::string::npos) << quantity;
    const std::string bare =
        input_error("[[calibration.targets]]\nquantity = \"final_thickness\"\nvalue = "
                    "83.8\nuncertainty = \"2 um\"\n");
    EXPECT_NE(bare.find("did you mean"), std::string::npos) << bare;
    const std::string sigma = input_error(
        "[[calibration.targets]]\nquantity = \"porosity\"\nvalue = 0.4\nuncertainty = 0\n");
    EXPECT_NE(sigma.find("calibration.targets[1].uncertainty (porosity)"), std::string::npos)
        << sigma;
    const std::string budget =
        input_error("[calibration]\ninitial_points = 30\nevaluations = 20\n");
    EXPECT_NE(budget.find("calibration.initial_points"), std::string::npos) << budget;
    const std::string sched = input_error("[scheduler]\ntype = \"pbs\"\n");
    EXPECT_NE(sched.find("\"local\", \"slurm\""), std::string::npos) << sched;
    const std::string part = input_error("[scheduler]\npartition = \"a b\"\n");
    EXPECT_NE(part.find("scheduler.partition"), std::string::npos) << part;
}

TEST(CalibrationConfig, CalibrateNeedsParametersAndTargetsAndWarnsWhenUnderdetermined) {
    auto error_of = [](const Config& c) -> std::string {
        try {
            (void)check_calibration(c);
        } catch (const InputError& e) {
            return e.what();
        }
        return {};
    };
    EXPECT_NE(error_of(load_config(thickness, "t")).find("calibration.parameters': none given"),
              std::string::npos);
    EXPECT_NE(error_of(load_config(friction, "t")).find("calibration.targets': none given"),
              std::string::npos);
    const auto w = check_calibration(load_config(friction + porosity + thickness, "t"));
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NE(w[0].find("1 independent target(s) for 2 parameters"), std::string::npos) << w[0];
    // a bound that makes the run invalid (here: CB spheres too large for the 40 um box) is named
    const Config bad =
        load_config("[film]\nbox_x = \"40 um\"\nbox_y = \"40 um\"\n"
                    "[[calibration.parameters]]\nkey = \"formulation.cb_diameter\"\nmin = \"1 "
                    "um\"\nmax = \"20 um\"\n" +
                        thickness,
                    "t");
    const std::string e = error_of(bad);
    EXPECT_NE(e.find("formulation.cb_diameter = 2e-05 (max) makes the run configuration invalid"),
              std::string::npos)
        << e;
}

TEST(CalibrationConfig, APointOfADryingCurveTakesItsProcessTime) {
    // Fig. 5 as targets: the film thickness at two process times, each its own named target
    const auto point = [](const std::string& at, const std::string& value) {
        return "[[calibration.targets]]\nquantity = \"film_thickness\"\nat = " + at +
               "\nvalue = " + value + "\nuncertainty = \"1.5 um\"\n";
    };
    const Config c = load_config(friction + point("\"40 s\"", "\"150 um\"") +
                                     point("1.5", "\"120 um\"") + thickness,
                                 "test.toml");
    ASSERT_EQ(c.calibration_targets.size(), 3u);
    EXPECT_DOUBLE_EQ(c.calibration_targets[0].at, 40.0);
    EXPECT_DOUBLE_EQ(c.calibration_targets[1].at, 1.5);
    EXPECT_LT(c.calibration_targets[2].at, 0.0); // a result of the whole run has none
    EXPECT_EQ(calibration_target_name(c.calibration_targets[0]), "film_thickness_at_40s");
    EXPECT_EQ(calibration_target_name(c.calibration_targets[2]), "final_thickness");
    EXPECT_TRUE(check_calibration(c).empty()); // three distinct targets for one parameter
    const auto spec = calibration_spec(c, "/x/drydem");
    EXPECT_EQ(spec["targets"][0]["name"], "film_thickness_at_40s");
    EXPECT_DOUBLE_EQ(spec["targets"][0]["at_s"].get<double>(), 40.0);
    EXPECT_EQ(spec["targets"][0]["summary_key"], "film_thickness_um"); // its timeseries.csv column
    EXPECT_NEAR(spec["targets"][1]["value"].get<double>(), 120.0, 1e-9);
    EXPECT_FALSE(spec["targets"][2].contains("at_s")); // older calibrations resume unchanged
    // the same point twice counts once
    const auto w = check_calibration(load_config(
        friction + point("\"40 s\"", "\"150 um\"") + point("\"40 s\"", "\"151 um\""), "t"));
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NE(w[0].find("more than once"), std::string::npos) << w[0];

    const std::string missing =
        input_error("[[calibration.targets]]\nquantity = \"film_thickness\"\nvalue = \"150 "
                    "um\"\nuncertainty = \"1 um\"\n");
    EXPECT_NE(missing.find("calibration.targets[1]': missing 'at'"), std::string::npos) << missing;
    const std::string not_curve =
        input_error("[[calibration.targets]]\nquantity = \"final_thickness\"\nat = \"40 s\"\nvalue "
                    "= \"84 um\"\nuncertainty = \"1 um\"\n");
    EXPECT_NE(not_curve.find(
                  "calibration.targets[1].at': \"40 s\" is not allowed for \"final_thickness\""),
              std::string::npos)
        << not_curve;
    EXPECT_NE(not_curve.find("\"film_thickness\""), std::string::npos) << not_curve;
    const std::string negative = input_error(point("\"-3 s\"", "\"150 um\""));
    EXPECT_NE(negative.find("calibration.targets[1].at (film_thickness)"), std::string::npos)
        << negative;
    const std::string length = input_error(point("\"40 um\"", "\"150 um\""));
    EXPECT_NE(length.find("calibration.targets[1].at (film_thickness)"), std::string::npos)
        << length;
}

} // namespace
