// SPDX-License-Identifier: MIT
// The outputs of a drying run's end: final particles (final.csv), the structure analysis of the
// dried film (analysis/), summary.json and the plots.
#pragma once
#include "drydem/drying/run_observer.hpp"
#include <memory>
#include <vector>

namespace drydem {

/// Where an engine's wall time went (summary.json `wall_time_phases_s`): pair forces (bonds
/// included), neighbour-list rebuilds, integration, and the stability guard's estimates.
nlohmann::json wall_time_phases(const Simulation& sim, const StabilityGuard& guard);

/// Appends, in this order: final particles, structure analysis, summary, plots.
void append_end_outputs(const RunContext& ctx, std::vector<std::unique_ptr<RunObserver>>& list);

} // namespace drydem
