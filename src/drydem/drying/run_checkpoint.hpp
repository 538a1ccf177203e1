// SPDX-License-Identifier: MIT
// A drying run's checkpoint (checkpoint/state.bin, file format of output/checkpoint.hpp): the resolved
// config, the run's own progress as a versioned list of named fields (run_state.hpp) and the
// engine state.
#pragma once
#include "drydem/drying/run_state.hpp"
#include "drydem/engine/simulation.hpp"
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

namespace drydem {

struct RunCheckpoint {
    std::string config_toml;
    StateFields progress; ///< to load from
    EngineState engine;
};

/// InputError where there is no valid checkpoint in output_dir.
[[nodiscard]] RunCheckpoint read_run_checkpoint(const std::filesystem::path& output_dir);

/// Writes the checkpoint atomically; `visit_state` saves every part's resume state.
void write_run_checkpoint(const std::filesystem::path& output_dir, const std::string& config_toml,
                          const std::function<void(StateFields&)>& visit_state,
                          const EngineState& engine);

/// Cuts an output file back to its `size` at the checkpoint: what was written after it is
/// written again by the resumed run. InputError where it is missing or shorter.
void truncate_to_checkpoint(const std::filesystem::path& file, std::uint64_t size);

} // namespace drydem
