// SPDX-License-Identifier: MIT
// The study's plan and statistics (paper Fig. 6: mean and standard deviation over seeds), and its
// tolerance of failed runs.
#include "drydem/core/error.hpp"
#include "drydem/study/study.hpp"
#include <gtest/gtest.h>
#include "test_dirs.hpp"
#include <nlohmann/json.hpp>
#include <cmath>
#include <fstream>

using namespace drydem;

TEST(Study, PlanIsLoadingsTimesSeeds) {
    Config c;
    c.seed = 7;
    const auto cases = plan_study(c, {0.201, 0.252}, 3);
    ASSERT_EQ(cases.size(), 6u);
    EXPECT_DOUBLE_EQ(cases[0].areal_loading, 0.201);
    EXPECT_EQ(cases[0].seed, 7u);
    EXPECT_EQ(cases[2].seed, 9u);
    EXPECT_DOUBLE_EQ(cases[3].areal_loading, 0.252);
    EXPECT_EQ(cases[3].seed, 7u);
    EXPECT_EQ(cases[4].name, "L25.20_s8");
    // No loadings: the config's own.
    const auto own = plan_study(c, {}, 1);
    ASSERT_EQ(own.size(), 1u);
    EXPECT_DOUBLE_EQ(own[0].areal_loading, c.areal_loading);
    EXPECT_THROW(plan_study(c, {0.2}, 0), InputError);
    EXPECT_THROW(plan_study(c, {-0.2}, 1), InputError);
}

TEST(Study, ShrinkageRateFactorsMultiplyThePlanAndGroupTheStatistics) {
    Config c;
    c.seed = 3;
    c.dryer_schedule = "rates";
    c.study_shrinkage_rate_factors = {0.5, 2.0};
    const auto cases = plan_study(c, {0.03}, 2);
    ASSERT_EQ(cases.size(), 4u);
    EXPECT_EQ(cases[0].name, "L3.00_r0.5_s3");
    EXPECT_DOUBLE_EQ(cases[1].shrinkage_rate_factor, 0.5);
    EXPECT_EQ(cases[3].name, "L3.00_r2_s4");
    std::vector<StudyRow> rows;
    for (const StudyCase& k : cases) {
        StudyRow r;
        r.c = k;
        r.status = "completed";
        r.thickness_um = k.shrinkage_rate_factor * 10.0 + double(k.seed);
        rows.push_back(r);
    }
    const auto stats = study_statistics(rows);
    ASSERT_EQ(stats.size(), 2u); // one group per factor, not one per loading
    EXPECT_DOUBLE_EQ(stats[0].shrinkage_rate_factor, 0.5);
    EXPECT_DOUBLE_EQ(stats[0].thickness_mean_um, 8.5);
    EXPECT_DOUBLE_EQ(stats[1].thickness_mean_um, 23.5);
    // The dryer model sets its own rates: factors on them are refused, naming the key.
    c.dryer_schedule = "model";
    try {
        (void)plan_study(c, {0.03}, 1);
        FAIL() << "factors with the dryer model were accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("study.shrinkage_rate_factors"), std::string::npos)
            << e.what();
    }
}

TEST(Study, StatisticsAreMeanAndSampleStdOverCompletedRuns) {
    auto row = [](double l, std::uint64_t seed, const char* status, double h, double rho,
                  double eps) {
        StudyRow r;
        r.c = {l, seed, "x"};
        r.status = status;
        if (std::string(status) == "completed") {
            r.thickness_um = h;
            r.density_g_cm3 = rho;
            r.porosity = eps;
        }
        return r;
    };
    const std::vector<StudyRow> rows = {
        row(0.201, 1, "completed", 83.0, 2.40, 0.44), row(0.201, 2, "completed", 85.0, 2.38, 0.45),
        row(0.201, 3, "completed", 84.0, 2.39, 0.46), row(0.252, 1, "failed", 0, 0, 0),
        row(0.252, 2, "completed", 105.0, 2.41, 0.43)};
    const auto s = study_statistics(rows);
    ASSERT_EQ(s.size(), 2u);
    EXPECT_DOUBLE_EQ(s[0].areal_loading_mg_cm2, 20.1);
    EXPECT_EQ(s[0].completed, 3);
    EXPECT_EQ(s[0].failed, 0);
    EXPECT_NEAR(s[0].thickness_mean_um, 84.0, 1e-12);
    EXPECT_NEAR(s[0].thickness_std_um, 1.0, 1e-12); // sample s.d. of 83, 84, 85
    EXPECT_NEAR(s[0].density_mean_g_cm3, 2.39, 1e-12);
    EXPECT_NEAR(s[0].porosity_std, 0.01, 1e-12);
    EXPECT_EQ(s[1].completed, 1);
    EXPECT_EQ(s[1].failed, 1);
    EXPECT_NEAR(s[1].thickness_mean_um, 105.0, 1e-12);
    EXPECT_EQ(s[1].thickness_std_um, 0.0); // one run: no spread
}

TEST(Study, RowsComeFromSummariesAndMissingOnesAreFailures) {
    const auto dir = testing_support::temp_dir();
    std::ofstream(dir / "summary.json") << R"({"status": "completed", "final_thickness_um": 12.5,
        "density_g_cm3": 2.0, "porosity": 0.5, "process_time_final_s": 20.0, "wall_time_s": 3.0})";
    const StudyRow ok = read_study_row({0.02, 1, "a"}, dir, 0);
    EXPECT_EQ(ok.status, "completed");
    EXPECT_DOUBLE_EQ(*ok.thickness_um, 12.5);
    EXPECT_DOUBLE_EQ(*ok.porosity, 0.5);
    const StudyRow missing = read_study_row({0.02, 2, "b"}, dir / "nowhere", 2);
    EXPECT_EQ(missing.status, "failed");
    EXPECT_NE(missing.error.find("exit code 2"), std::string::npos) << missing.error;
    std::ofstream(dir / "summary.json") << R"({"status": "failed", "error": "blow-up at particle 7",
        "final_thickness_um": null})";
    const StudyRow failed = read_study_row({0.02, 3, "c"}, dir, 1);
    EXPECT_EQ(failed.status, "failed");
    EXPECT_EQ(failed.error, "blow-up at particle 7");
    EXPECT_FALSE(failed.thickness_um);

    // The table keeps every case, failures included.
    Config base;
    base.measured_loadings = {0.02};
    base.measured_thickness = {12e-6};
    write_study_results(dir, base, {ok, missing, failed});
    std::ifstream csv(dir / "study.csv");
    std::string line;
    int lines = 0;
    while (std::getline(csv, line)) ++lines;
    EXPECT_EQ(lines, 4);
    const auto j = nlohmann::json::parse(std::ifstream(dir / "study.json"));
    EXPECT_EQ(j["completed"], 1);
    EXPECT_EQ(j["failed"], 2);
    EXPECT_NEAR(j["measured"][0]["thickness_um"].get<double>(), 12.0, 1e-9);
    EXPECT_NEAR(j["loadings"][0]["thickness_mean_um"].get<double>(), 12.5, 1e-12);
}

TEST(Study, RowsCarryTheRunsTransportAndBinderNumbers) {
    const auto dir = testing_support::temp_dir();
    std::ofstream(dir / "summary.json") << R"({"status": "completed", "final_thickness_um": 12.5})";
    std::filesystem::create_directories(dir / "analysis");
    std::ofstream(dir / "analysis" / "analysis.json") << R"({"transport": {"tortuosity_factor":
        {"through_plane": 2.5, "in_plane": 1.8}, "bruggeman_exponent": {"through_plane": null},
        "electronic_conductivity_S_m": 3.25, "cb_percolates": true},
        "binder_migration": {"bottom10_over_mean": 0.75}})";
    const StudyRow r = read_study_row({0.02, 1, "a"}, dir, 0);
    EXPECT_DOUBLE_EQ(*r.tortuosity_z, 2.5);
    EXPECT_DOUBLE_EQ(*r.tortuosity_in_plane, 1.8);
    EXPECT_FALSE(r.bruggeman_z); // null: undefined exponent stays empty
    EXPECT_DOUBLE_EQ(*r.electronic_conductivity, 3.25);
    EXPECT_DOUBLE_EQ(*r.cb_percolates, 1.0);
    EXPECT_DOUBLE_EQ(*r.binder_bottom10, 0.75);
    Config base;
    write_study_results(dir, base, {r});
    std::ifstream csv(dir / "study.csv");
    std::string header, row;
    std::getline(csv, header);
    std::getline(csv, row);
    EXPECT_NE(header.find("tortuosity_through_plane,tortuosity_in_plane,bruggeman_exponent"),
              std::string::npos);
    EXPECT_NE(row.find(",2.5,1.8,,3.25,1,0.75"), std::string::npos) << row;
}
