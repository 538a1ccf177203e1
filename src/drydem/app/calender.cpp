// SPDX-License-Identifier: MIT
// `drydem calender RUN_DIR`: the run's config with the caller's overrides, the output folder
// (never another output's), the calendering run, its plots and result lines. `drydem calender
// --resume DIR` continues a stopped one from its checkpoint.
#include "drydem/app/commands.hpp"
#include "drydem/calendering/calender_run.hpp"
#include "drydem/core/error.hpp"
#include "drydem/drying/derived_checks.hpp"
#include "drydem/io/output_folder.hpp"
#include <fmt/format.h>

namespace drydem::app {

namespace fs = std::filesystem;

namespace {

/// The plots and the result lines; the exit status.
int report(const CalenderResult& r, const CalenderOptions& o) {
    if (o.plots) run_plot_script("plot_calender.py", o.output_dir);
    if (r.completed)
        fmt::print(
            "dried {:.3f} um (porosity {:.4f}) -> peak {:.3f} MPa at {:.3f} um (porosity {:.4f}) "
            "-> unloaded {:.3f} um (porosity {:.4f}, springback {:.2f} %)\n",
            r.dried_thickness * 1e6, r.dried_porosity, r.peak_pressure * 1e-6,
            r.peak_thickness * 1e6, r.peak_porosity, r.unloaded_thickness * 1e6,
            r.unloaded_porosity, 100.0 * r.springback);
    else // a stopped run has no peak or unloaded state: say how far it got, not zeros
        fmt::print(
            "dried {:.3f} um (porosity {:.4f}) -> stopped before the end, at most {:.3f} MPa "
            "reached (compaction.csv holds the curve so far)\n",
            r.dried_thickness * 1e6, r.dried_porosity, r.peak_pressure * 1e-6);
    fmt::print("{} in {} steps, {:.1f} s; written to {}\n", r.completed ? "completed" : "stopped",
               r.steps, r.wall_time, o.output_dir.string());
    if (!r.completed)
        fmt::print(stderr, "error: {}{}\n", r.error,
                   r.resumable ? fmt::format(" (continue it: drydem calender --resume {})",
                                             o.output_dir.string())
                               : "");
    return r.completed ? 0 : 1;
}

/// `drydem calender --resume DIR`: the stopped calendering in DIR continues from its checkpoint
/// with its own config and drying run (the drying run is only read).
int resume_calender(const CalenderCommand& cmd, CalenderOptions o) {
    if (!cmd.run_dir.empty() || !cmd.output_dir.empty() || !cmd.sets.empty() || cmd.overwrite)
        throw InputError("calender --resume DIR continues a calendering with the config and the "
                         "drying run stored in its checkpoint; RUN_DIR, -o, --set and --overwrite "
                         "are not allowed with it (only --threads, --quiet, --no-plots, "
                         "--stop-after-steps)");
    const OutputLock lock(cmd.resume_dir);
    CalenderResume resume = read_calender_resume(cmd.resume_dir);
    if (cmd.threads > 0) resume.config.threads = cmd.threads;
    o.run_dir = resume.run_dir;
    o.output_dir = cmd.resume_dir;
    o.resume = true;
    o.stop_after_steps = cmd.stop_after;
    return report(run_calendering(resume.config, o), o);
}

} // namespace

int run_calender(const CalenderCommand& cmd) {
    CalenderOptions o;
    o.quiet = cmd.quiet;
    o.plots = cmd.plots;
    if (!cmd.resume_dir.empty()) return resume_calender(cmd, o);
    if (cmd.run_dir.empty())
        throw InputError("calender: give RUN_DIR, the folder of a finished drying run, or "
                         "--resume DIR to continue a stopped calendering");
    fs::path run_dir = fs::path(cmd.run_dir).lexically_normal();
    if (run_dir.filename().empty()) run_dir = run_dir.parent_path(); // "dir/" -> "dir"
    const fs::path config = run_dir / "config.toml";
    if (!fs::exists(config))
        throw InputError(fmt::format("{}: no config.toml; give the folder of a drying run "
                                     "(drydem run -o DIR)",
                                     run_dir.string()));
    Config c = load_config_file(config.string(), cmd.sets);
    if (cmd.threads > 0) c.threads = cmd.threads;
    o.run_dir = run_dir;
    o.output_dir =
        cmd.output_dir.empty() ? fs::path(run_dir.string() + "-calendered") : cmd.output_dir;
    o.stop_after_steps = cmd.stop_after;
    const OutputLock lock(o.output_dir);
    prepare_output_folder(o.output_dir, calender_output(), cmd.overwrite);
    return report(run_calendering(c, o), o);
}

} // namespace drydem::app
