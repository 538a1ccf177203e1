// SPDX-License-Identifier: MIT
// The calendering run (`drydem calender RUN_DIR`, docs/calendering.md): the dried film of a
// finished drying run pressed by a rigid plate over the periodic cell, held, unloaded and
// relaxed, in the dry state (make_calendering_force_field). Outputs: compaction.csv (the plate's
// pressure and the porosity below it over time), summary.json (peak, unloaded, springback, the
// fitted compaction curve), final.csv, snapshots/ and the structure analysis of the calendered film.
#pragma once
#include "drydem/io/config.hpp"
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace drydem {

struct CalenderOptions {
    std::filesystem::path run_dir;    ///< the drying run's folder: its final.csv is the start
    std::filesystem::path output_dir; ///< prepared (empty or --overwrite) by the caller
    bool quiet = false;
    bool plots = true; ///< scripts/plot_calender.py with Debian's python3 at the end
    /// For testing: stop after this many steps as a stop request would (results so far).
    std::optional<std::int64_t> stop_after_steps;
    /// Continue the calendering in output_dir from its checkpoint (checkpoint/state.bin, written
    /// every output.checkpoint_every of wall time and when stopped); run_dir and the config are
    /// the checkpoint's (read_calender_resume).
    bool resume = false;
};

struct CalenderResult {
    bool completed = false;
    std::string error;               ///< why it stopped early, or empty
    double dried_thickness = 0.0;    ///< highest top of a touching particle before [m]
    double dried_porosity = 0.0;     ///< at that thickness
    double peak_pressure = 0.0;      ///< largest plate pressure [Pa]
    double peak_thickness = 0.0;     ///< the plate's height at the end of the hold [m]
    double peak_porosity = 0.0;      ///< at the plate height at the end of the hold
    double unloaded_thickness = 0.0; ///< the same after relaxation [m]
    double unloaded_porosity = 0.0;
    double springback = 0.0;          ///< (unloaded - peak) / peak thickness
    bool unloaded_at_rest = false;    ///< force tolerance reached or top standing still
    double max_inertial_number = 0.0; ///< while loading above 1 % of the peak pressure
    int passes = 0; ///< press-unload-relax cycles (more than one in unloaded_porosity mode)
    std::int64_t steps = 0;
    double wall_time = 0.0; ///< [s], the end-of-run analysis excluded (a resumed run: all sessions)
    bool resumable = false; ///< stopped with a checkpoint of its state (`--resume` continues it)
};

/// What a stopped calendering run in output_dir continues with: the config it ran with (its
/// thread count included, so that it continues bit for bit) and its drying run's folder.
/// InputError where output_dir holds no calendering checkpoint.
struct CalenderResume {
    Config config;
    std::filesystem::path run_dir;
};
[[nodiscard]] CalenderResume read_calender_resume(const std::filesystem::path& output_dir);

/// Runs the calendering of the film in options.run_dir with the configuration c (the drying
/// run's config.toml with the caller's overrides). InputError before the first step for bad
/// input (no final.csv, a box that is not the config's); a run that fails (blow-up, stop request)
/// returns completed = false after writing what it has.
CalenderResult run_calendering(const Config& c, const CalenderOptions& options);

} // namespace drydem
