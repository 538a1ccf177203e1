// SPDX-License-Identifier: MIT
// dryer.json / dryer.csv of `drydem dryer` (README "Command line"): the keys users script against.
#include "drydem/dryer_model/dryer_config.hpp"
#include "drydem/dryer_model/dryer_report.hpp"
#include <gtest/gtest.h>
#include <filesystem>
#include <fstream>
#include <string>

namespace {
using namespace drydem::dryer;

TEST(DryerReport, JsonHasZonesRatesAndPositions) {
    const FilmDryerParams p = film_dryer_preset("table2");
    const DryerRun run = simulate_film_dryer(p);
    const auto sections = fit_section_rates(p, run);
    const nlohmann::json j = dryer_json(p, run, sections);
    EXPECT_EQ(j["preset"], "table2");
    ASSERT_EQ(j["zones"].size(), 3u);
    EXPECT_NEAR(j["zones"][0]["shrinkage_rate_um_s"].get<double>(), 0.669, 0.002);
    EXPECT_NEAR(j["zones"][0]["shrinkage_rate_um_per_m"].get<double>(), 20.08, 0.06); // Eq. 15
    EXPECT_TRUE(j["zones"][2]["shrinkage_rate_um_s"].is_null());
    EXPECT_NEAR(j["zones"][1]["wet_film_steady_state"]["temperature_C"].get<double>(), 90.31, 0.05);
    EXPECT_NEAR(j["consolidation_position_m"].get<double>(), 2.26, 0.01);
    EXPECT_NEAR(j["dry_position_m"].get<double>(), 3.33, 0.01);
    EXPECT_EQ(j["schedule_rates_um_s"].size(), 2u);
    EXPECT_EQ(j["inputs"]["analogy_exponent"], 0.42);
    EXPECT_TRUE(j["warnings"].empty());
}

TEST(DryerReport, CsvHasHeaderAndRowsEveryTenthSecond) {
    const FilmDryerParams p = film_dryer_preset("physical");
    const DryerRun run = simulate_film_dryer(p);
    const auto dir = std::filesystem::temp_directory_path() / "drydem_dryer_report_test";
    std::filesystem::remove_all(dir);
    write_dryer_outputs(dir, p, run, fit_section_rates(p, run));
    std::ifstream csv(dir / "dryer.csv");
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header,
              "position_m,time_s,film_temperature_C,dryer_temperature_C,solvent_mass_fraction,"
              "film_thickness_um,evaporation_rate_g_m2_s,consolidated");
    int rows = 0;
    while (std::getline(csv, line)) ++rows;
    EXPECT_EQ(rows, 1801); // 180 s every 0.1 s, plus the exit
    EXPECT_TRUE(std::filesystem::exists(dir / "dryer.json"));
    std::filesystem::remove_all(dir);
}

} // namespace
