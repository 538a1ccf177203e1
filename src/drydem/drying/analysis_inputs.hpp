// SPDX-License-Identifier: MIT
// The structure analysis' inputs from a configuration: the analysis (analysis/) takes its own
// option and formulation structs and never reads a Config; this is where the [formulation],
// [materials], [film] and [analysis] keys are mapped onto them, for a run's end-of-run analysis
// and for `drydem analyze`.
#pragma once
#include "drydem/analysis/analyze.hpp"
#include "drydem/analysis/structure.hpp"
#include "drydem/io/config.hpp"

namespace drydem {

/// The formulation constants of the analysis (densities, mass fractions, CB porosity).
[[nodiscard]] analysis::Formulation analysis_formulation(const Config& c);

/// What a particle file may leave out: formulation, box (film.box_x, film.box_y), NCM classes.
[[nodiscard]] analysis::FileDefaults file_defaults(const Config& c);

/// The options of the end-of-run analysis of a run's final.csv ([analysis] keys: voxel, profile
/// slab, contact gap, pore top, transport and surfaces), for the drying and the calendering run.
[[nodiscard]] analysis::AnalysisOptions end_of_run_analysis_options(const Config& c);

/// The transport and surface options of a config (analysis.transport_voxel_sizes, *_conductivity,
/// surface_points, cb_coverage_gap, binder_diffusivity) into `o`.
void set_transport_options(analysis::AnalysisOptions& o, const Config& c);

} // namespace drydem
