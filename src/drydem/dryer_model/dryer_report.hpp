// SPDX-License-Identifier: MIT
// Output of `drydem dryer` (README "Command line", docs/dryer.md): dryer.json (per-zone shrinkage rates, wet-film steady
// states, consolidation and dry positions, preset and every input) and dryer.csv (the drying
// curve along the dryer, paper Figs. 2-3).
#pragma once
#include "drydem/dryer_model/film_dryer.hpp"
#include <filesystem>
#include <nlohmann/json.hpp>

namespace drydem::dryer {

/// Every model input (SI, names with units).
[[nodiscard]] nlohmann::json inputs_json(const FilmDryerParams& p);

/// The content of dryer.json.
[[nodiscard]] nlohmann::json dryer_json(const FilmDryerParams& p, const DryerRun& run,
                                        const std::vector<SectionRate>& sections);

/// Writes dryer.json and dryer.csv (one row per 0.1 s) into dir (created if needed).
void write_dryer_outputs(const std::filesystem::path& dir, const FilmDryerParams& p,
                         const DryerRun& run, const std::vector<SectionRate>& sections);

} // namespace drydem::dryer
