// SPDX-License-Identifier: MIT
// The dryer model's parameters from the run configuration ([film], [formulation], [materials],
// [dryer]), and the DEM liquid-level schedule from the dryer model (dryer.schedule = "model").
#pragma once
#include "drydem/dryer_model/film_dryer.hpp"
#include "drydem/io/config.hpp"

namespace drydem::dryer {

/// FilmDryerParams of the configured preset with every configured value applied (SI).
[[nodiscard]] FilmDryerParams film_dryer_params(const Config& c);

/// The embedded default configuration's parameters under the named preset (D-3): "physical"
/// (Chilton-Colburn n = 1/3) or "table2" (n = 0.42, calibrated to paper Table 2). InputError for
/// any other name.
[[nodiscard]] FilmDryerParams film_dryer_preset(std::string_view name);

/// The configuration with dryer.shrinkage_rates replaced by the dryer model's section rates (D-4)
/// for the configured final porosity; the sections after consolidation are left out (the DEM
/// keeps the last rate, model.md C-21).
[[nodiscard]] Config with_model_schedule(const Config& c);

} // namespace drydem::dryer
