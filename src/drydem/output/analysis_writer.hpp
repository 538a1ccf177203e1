// SPDX-License-Identifier: MIT
// Files of a structure analysis (README "Outputs", docs/analysis.md, `drydem analyze`): analysis.json, profiles.csv,
// psd_chord.csv, psd_local_thickness.csv (with the simulated mercury intrusion beside it).
#pragma once
#include "drydem/analysis/analyze.hpp"
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace drydem {

/// The analysis as JSON (the content of analysis.json); `source` names the snapshot.
[[nodiscard]] nlohmann::ordered_json analysis_json(const analysis::AnalysisResult& r,
                                                   const analysis::AnalysisOptions& o,
                                                   const std::string& source);

/// Writes analysis.json, profiles.csv and, when voxelized, psd_chord.csv and psd_local_thickness.csv
/// into `dir` (atomically each).
void write_analysis(const std::filesystem::path& dir, const analysis::AnalysisResult& r,
                    const analysis::AnalysisOptions& o, const std::string& source);

} // namespace drydem
