// SPDX-License-Identifier: MIT
// `drydem` command line (interface.md): run, check, dryer, analyze, study, calibrate, config, bench. Exit codes: 0 success,
// 1 run failure, 2 bad input.
#include "drydem/drying/analysis_inputs.hpp"
#include "drydem/app/commands.hpp"
#include "drydem/core/error.hpp"
#include "drydem/core/stop_request.hpp"
#include "drydem/dryer/dryer_config.hpp"
#include "drydem/drying/drying_run.hpp"
#include "drydem/io/output_folder.hpp"
#include "drydem/io/units.hpp"
#include "drydem/setup/derived_checks.hpp"
#include <CLI/CLI.hpp>
#include <fmt/chrono.h>
#include "drydem/git_hash.hpp"
#include <fmt/format.h>
#include <charconv>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <limits>
#include <omp.h>
#include <optional>

using namespace drydem;

namespace {

Config load(const std::string& file, const std::vector<std::string>& sets) {
    return file.empty() ? load_config(default_config_toml(), "<embedded default>", sets)
                        : load_config_file(file, sets);
}

std::string default_output_dir(const Config& c, std::string_view suffix = "") {
    const auto now = std::chrono::system_clock::now();
    return fmt::format("out/{}{}-{:%Y%m%d-%H%M%S}", c.name, suffix,
                       fmt::localtime(std::chrono::system_clock::to_time_t(now)));
}

/// A non-negative integer option given on the command line: digits only (no sign, fraction or
/// exponent) and at most `hi`; CLI11 alone would take "-1" and clamp 2^64 - 1.
std::uint64_t cli_integer(const std::string& option, const std::string& text, std::uint64_t hi,
                          const std::string& allowed) {
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos ||
        ec != std::errc{} || end != text.data() + text.size() || v > hi)
        throw InputError(fmt::format("{} {}: not allowed; allowed: {}", option, text, allowed));
    return v;
}

/// More threads than cores only slow a DEM run down (each step waits for the slowest thread).
void check_threads(const std::string& what, long threads) {
    const int cores = omp_get_num_procs();
    if (threads > cores)
        throw InputError(fmt::format("{} = {}: this machine has {} cores; allowed 1..{} (0 = all cores)",
                                     what, threads, cores, cores));
}

} // namespace

int main(int argc, char** argv) {
    CLI::App cli{"DryDEM: DEM simulation of structure formation during electrode drying "
                 "(Lippke et al., Energy Technol. 2022)"};
    cli.require_subcommand(0, 1);
    cli.set_version_flag("--version", fmt::format("drydem {} ({})", DRYDEM_VERSION, DRYDEM_GIT_HASH));

    std::string config_file, out_dir, particles, resume_dir;
    std::vector<std::string> sets;
    std::string seed_text, threads_text, stop_after_text;
    bool overwrite = false;
    bool quiet = false, no_plots = false, couple_dryer = false, table2 = false;

    auto* run = cli.add_subcommand("run", "run the drying simulation (no CONFIG: the paper's 20.1 mg/cm2 case)");
    run->add_option("config", config_file, "TOML configuration")->check(CLI::ExistingFile);
    run->add_option("-o,--output", out_dir, "output folder (default out/<name>-<timestamp>)");
    run->add_option("--set", sets, "override a key, e.g. --set run.seed=7")->take_all();
    auto* seed_opt = run->add_option("--seed", seed_text, "random seed 0..2^63-1 (= --set run.seed=N)");
    auto* threads_opt = run->add_option("--threads", threads_text, "OpenMP threads, 0 = all cores (= --set run.threads=N)");
    run->add_flag("--overwrite", overwrite,
                  "replace the outputs of a previous run in the -o folder (default: refuse a folder "
                  "that holds a run)");
    run->add_option("--particles", particles, "start from these particles (CSV, LAMMPS data or dump)")
        ->check(CLI::ExistingFile);
    run->add_option("--resume", resume_dir,
                    "continue the run in this output folder from its checkpoint (same config, "
                    "same threads: bit-identical to an uninterrupted run)")
        ->check(CLI::ExistingDirectory);
    run->add_flag("--quiet", quiet, "only warnings and errors on the console");
    run->add_flag("--no-plots", no_plots, "skip the matplotlib plots");
    // For tests only: a deterministic stand-in for a signal or a kill at a given step.
    auto* stop_after_opt =
        run->add_option("--stop-after-steps", stop_after_text,
                        "for testing: stop after step N as SIGTERM would (checkpoint, results so "
                        "far, exit 1); also with --resume")
            ->group("Testing");
    run->add_flag("--couple-dryer", couple_dryer,
                  "iterate dryer model <-> DEM until the final thickness settles (paper Sec. 8; "
                  "each DEM run in DIR/iter_N, summary in DIR/coupling.json)");

    auto* dryer = cli.add_subcommand("dryer", "the dryer model alone: film temperature, solvent "
                                              "content, shrinkage rate per zone (docs/dryer.md)");
    dryer->add_option("config", config_file, "TOML configuration")->check(CLI::ExistingFile);
    dryer->add_option("-o,--output", out_dir, "output folder (default out/<name>-dryer-<timestamp>)");
    dryer->add_option("--set", sets, "override a key, e.g. --set dryer.preset=physical")->take_all();
    dryer->add_flag("--no-plots", no_plots, "skip the matplotlib plot");
    dryer->add_flag("--overwrite", overwrite, "replace a previous dryer model run's outputs in the -o folder");
    dryer->add_flag("--table2", table2, "print paper Table 2 against the model (both presets) instead");

    auto* check = cli.add_subcommand("check", "validate a configuration and print every derived quantity");
    check->add_option("config", config_file, "TOML configuration")->check(CLI::ExistingFile);
    check->add_option("--set", sets, "override a key")->take_all();

    auto* config = cli.add_subcommand("config", "print a configuration");
    std::string which;
    config->add_option("which", which, "'default': the embedded default configuration")
        ->required()->check(CLI::IsMember({"default"}));

    app::StudyOptions study_opt;
    std::string study_loadings;
    auto* study = cli.add_subcommand("study", "loadings x seeds: runs, study.csv/.json and the thickness/density "
                                              "vs loading plot (paper Fig. 6)");
    study->add_option("config", config_file, "TOML configuration")->check(CLI::ExistingFile);
    study->add_option("-o,--output", out_dir, "output folder (default out/<name>-study-<timestamp>)");
    study->add_option("--set", sets, "override a key")->take_all();
    study->add_option("--loadings", study_loadings,
                      "areal loadings, comma separated, in mg/cm^2 or with units (default study.loadings, "
                      "else film.areal_loading)");
    study->add_option("--seeds", study_opt.seeds, "runs per loading (default study.seeds)")
        ->check(CLI::PositiveNumber);
    study->add_option("--threads", study_opt.threads, "threads per run (default cores / runs)")
        ->check(CLI::PositiveNumber);
    study->add_option("--jobs", study_opt.jobs, "runs at a time (default cores / threads)")
        ->check(CLI::PositiveNumber);
    study->add_flag("--quiet", study_opt.quiet, "only the final table");
    study->add_flag("--no-plots", no_plots, "skip the matplotlib plots");
    study->add_flag("--overwrite", overwrite, "replace a previous study's outputs (its runs included) in the -o folder");
    study->add_flag("--resume", study_opt.resume,
                    "continue the stopped study in -o DIR: completed runs are kept, stopped ones continue "
                    "from their checkpoints, the rest start");
    std::string scheduler;
    study->add_option("--scheduler", scheduler,
                      "where the runs run: local (child processes) or slurm (a job array; = --set "
                      "scheduler.type=...)")
        ->check(CLI::IsMember({"local", "slurm"}));

    app::CalibrateOptions cal_opt;
    auto* calibrate = cli.add_subcommand("calibrate", "fit config parameters to measured targets ([calibration]; "
                                                      "docs/calibration.md): evaluations.csv, calibrated.toml, plots");
    calibrate->add_option("config", config_file, "TOML configuration with a [calibration] section")
        ->required()->check(CLI::ExistingFile);
    calibrate->add_option("-o,--output", out_dir, "output folder (default out/<name>-calibrate-<timestamp>)");
    calibrate->add_option("--set", sets, "override a key")->take_all();
    calibrate->add_option("--jobs", cal_opt.jobs, "local: runs at a time; slurm: evaluations per job array (default 1)")
        ->check(CLI::PositiveNumber);
    calibrate->add_option("--threads", cal_opt.threads, "threads per local run (default cores / jobs)")
        ->check(CLI::PositiveNumber);
    calibrate->add_flag("--resume", cal_opt.resume,
                        "continue the calibration in -o DIR where it stopped (finished evaluations are kept)");
    calibrate->add_option("--scheduler", scheduler, "local or slurm (= --set scheduler.type=...)")
        ->check(CLI::IsMember({"local", "slurm"}));
    calibrate->add_flag("--quiet", cal_opt.quiet, "only warnings and the result");
    calibrate->add_flag("--no-plots", no_plots, "skip the matplotlib plots");

    app::AnalyzeOptions an;
    std::string an_voxel, an_dz, an_gap, an_config, an_pore_top;
    bool an_no_voxels = false;
    auto* analyze = cli.add_subcommand("analyze", "structure analysis of a particle snapshot (ours, the peers' CSV, "
                                                  "LAMMPS/LIGGGHTS data or dump): thickness, density, profiles, "
                                                  "coordination, pore sizes, voxel image");
    analyze->add_option("snapshot", an.snapshot, "particle file (final.csv, CSV, LAMMPS data or dump), or a run "
                                                 "folder (its final.csv)")
        ->required()->check(CLI::ExistingPath);
    analyze->add_option("-o,--output", out_dir, "output folder (default: analysis/ beside the snapshot)");
    analyze->add_option("--config", an_config,
                        "config with the formulation and box (default: config.toml beside the snapshot, "
                        "else the embedded default)")->check(CLI::ExistingFile);
    analyze->add_option("--set", sets, "override a config key")->take_all();
    analyze->add_option("--voxel", an_voxel, "voxel edge, e.g. 0.1um (a bare number is um; 0 = no voxel analysis; default analysis.voxel_size)");
    analyze->add_option("--dz", an_dz, "slab width of the height profiles (bare number: um; default analysis.profile_dz)");
    analyze->add_option("--contact-gap", an_gap, "surface gap still counted as contact for coordination (bare: um; default analysis.contact_gap)");
    analyze->add_option("--pore-top", an_pore_top,
                        "top of the pore statistics: half_solid (robust thickness) or highest (highest top)")
        ->check(CLI::IsMember({"half_solid", "highest"}));
    analyze->add_option("--cb-type", an.cb_type, "the file's particle type of the CB spheres (default: n + 1 for n "
                                                 "NCM classes in the config); every other type is NCM")
        ->check(CLI::PositiveNumber);
    analyze->add_flag("--export", an.export_voxels, "write the voxel image: structure.raw + .json + .mhd");
    analyze->add_flag("--tiff", an.tiff, "also write structure.tif (multi-page, one page per z layer)");
    analyze->add_flag("--no-voxels", an_no_voxels, "only the particle-based numbers (no pore sizes)");
    analyze->add_option("--threads", an.threads, "OpenMP threads (default all cores)")->check(CLI::PositiveNumber);
    analyze->add_flag("--quiet", an.quiet, "only the result lines");
    analyze->add_flag("--no-plots", no_plots, "skip the matplotlib plots");
    analyze->add_flag("--overwrite", overwrite, "replace a previous analysis in the output folder");

    app::BenchOptions bench_opt;
    auto* bench = cli.add_subcommand("bench", "the peers' granular benchmark (../shared/peers) in DryDEM");
    bench->add_option("data", bench_opt.data, "settled bed (LAMMPS data or CSV)")->required()->check(CLI::ExistingFile);
    bench->add_option("--steps", bench_opt.steps, "timed steps");
    bench->add_option("--warmup", bench_opt.warmup, "untimed warm-up steps");
    bench->add_option("--threads", bench_opt.threads, "OpenMP threads");

    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = cli.exit(e);
        return code == 0 ? 0 : 2;
    }
    try {
        std::optional<std::uint64_t> seed, threads;
        // count(), not empty(): `--threads ''` is a bad value, not a missing option.
        if (seed_opt->count() > 0)
            seed = cli_integer("--seed", seed_text, std::numeric_limits<std::int64_t>::max(),
                               "an integer 0..9223372036854775807");
        if (threads_opt->count() > 0) {
            threads = cli_integer("--threads", threads_text, 1024, "an integer 0..1024 (0 = all cores)");
            check_threads("--threads", long(*threads));
        }
        std::optional<std::int64_t> stop_after;
        if (stop_after_opt->count() > 0)
            stop_after = std::int64_t(cli_integer("--stop-after-steps", stop_after_text,
                                                  std::numeric_limits<std::int64_t>::max(),
                                                  "a step count 0..9223372036854775807"));
        for (const int n : {study_opt.threads, an.threads, bench_opt.threads, cal_opt.threads})
            check_threads("--threads", n);
        if (!scheduler.empty()) sets.push_back("scheduler.type=\"" + scheduler + "\"");
        if (seed && resume_dir.empty()) sets.push_back(fmt::format("run.seed={}", *seed));
        if (threads && resume_dir.empty()) sets.push_back(fmt::format("run.threads={}", *threads));
        if (*config) {
            std::cout << default_config_toml();
            return 0;
        }
        if (*bench) return app::run_bench(bench_opt);
        if (*analyze) {
            // Bare numbers are micrometres, the unit of the structure.
            auto length = [](std::string v, const char* key) {
                if (v.find_first_not_of("0123456789.eE+- ") == std::string::npos) v += " um";
                return parse_quantity(v, Dimension::length, key);
            };
            if (std::filesystem::is_directory(an.snapshot)) {
                if (!std::filesystem::exists(an.snapshot / "final.csv"))
                    throw InputError(fmt::format("{} is a folder without final.csv (not a finished run); give "
                                                 "a particle file", an.snapshot.string()));
                an.snapshot /= "final.csv";
            }
            const std::filesystem::path beside = an.snapshot.parent_path() / "config.toml";
            if (an_config.empty() && std::filesystem::exists(beside)) an_config = beside.string();
            const Config c = load(an_config, sets);
            an.analysis.voxel = an_no_voxels ? 0.0 : an_voxel.empty() ? c.analysis_voxel_size : length(an_voxel, "--voxel");
            an.analysis.profile_dz = an_dz.empty() ? c.analysis_profile_dz : length(an_dz, "--dz");
            an.analysis.contact_gap = an_gap.empty() ? c.analysis_contact_gap : length(an_gap, "--contact-gap");
            an.analysis.pore_top = an_pore_top.empty() ? c.analysis_pore_top : an_pore_top;
            set_transport_options(an.analysis, c);
            if (an.analysis.voxel < 0.0) throw InputError(fmt::format("--voxel {}: must be positive (0 = none)", an_voxel));
            if (!(an.analysis.profile_dz > 0.0)) throw InputError(fmt::format("--dz {}: must be positive", an_dz));
            if (an.analysis.contact_gap < 0.0) throw InputError(fmt::format("--contact-gap {}: must be >= 0", an_gap));
            an.output_dir = out_dir.empty() ? an.snapshot.parent_path() / "analysis" : std::filesystem::path(out_dir);
            an.plots = !no_plots;
            const OutputLock lock(an.output_dir);
            prepare_output_folder(an.output_dir, analysis_output(), overwrite);
            if (!an.quiet)
                fmt::print("config: {}\n", an_config.empty() ? std::string("<embedded default>") : an_config);
            return app::run_analyze(c, an);
        }
        if (*check) {
            Config c = load(config_file, sets);
            if (c.dryer_schedule == "model") c = dryer::with_model_schedule(c); // rates as the run uses them
            app::print_check(c);
            return 0;
        }
        if (*calibrate) {
            const Config c = load(config_file, sets);
            if (cal_opt.resume && out_dir.empty())
                throw InputError("--resume needs -o DIR, the folder of the calibration to continue");
            cal_opt.output_dir = out_dir.empty() ? default_output_dir(c, "-calibrate") : out_dir;
            cal_opt.plots = !no_plots;
            return app::run_calibrate(c, cal_opt);
        }
        if (*study) {
            const Config c = load(config_file, sets);
            study_opt.output_dir = out_dir.empty() ? default_output_dir(c) + "-study" : out_dir;
            study_opt.plots = !no_plots;
            std::size_t start = 0;
            while (start < study_loadings.size()) {
                std::size_t comma = study_loadings.find(',', start);
                if (comma == std::string::npos) comma = study_loadings.size();
                std::string item = study_loadings.substr(start, comma - start);
                start = comma + 1;
                if (item.find_first_not_of(" ") == std::string::npos) continue;
                // A bare number is mg/cm^2, the unit of the paper and of process engineers.
                if (item.find_first_not_of("0123456789.eE+- ") == std::string::npos) item += " mg/cm^2";
                study_opt.loadings.push_back(parse_quantity(item, Dimension::areal_density, "--loadings"));
            }
            const OutputLock lock(study_opt.output_dir);
            if (study_opt.resume && overwrite) throw InputError("study: --resume and --overwrite exclude each other");
            if (!study_opt.resume) prepare_output_folder(study_opt.output_dir, study_output(), overwrite);
            return app::run_study(c, study_opt);
        }
        if (*dryer) {
            const Config c = load(config_file, sets);
            if (table2) {
                app::print_table2_comparison(c);
                return 0;
            }
            app::DryerOptions d;
            d.output_dir = out_dir.empty() ? default_output_dir(c, "-dryer") : out_dir;
            d.plots = !no_plots;
            const OutputLock lock(d.output_dir);
            prepare_output_folder(d.output_dir, dryer_output(), overwrite);
            return app::run_dryer(c, d);
        }
        if (!*run) {
            std::cout << cli.help();
            return 0;
        }
        if (!resume_dir.empty()) {
            if (!config_file.empty() || !sets.empty() || !particles.empty() || !out_dir.empty() ||
                seed || couple_dryer || overwrite)
                throw InputError("--resume DIR continues a run with the config stored in its "
                                 "checkpoint; CONFIG, --set, --seed, --particles, -o, --overwrite and "
                                 "--couple-dryer are not allowed with it (only --threads, --quiet, --no-plots)");
        }
        Config c = resume_dir.empty() ? load(config_file, sets) : resume_config(resume_dir);
        if (!resume_dir.empty() && threads) c.threads = int(*threads);
        if (resume_dir.empty()) {
            check_threads("config key 'run.threads'", c.threads);
            check_fits_this_machine(c);
        }
        // Ctrl-C / SIGTERM: finish the step, write the results so far, exit 1.
        std::signal(SIGINT, [](int sig) { request_stop(sig); });
        std::signal(SIGTERM, [](int sig) { request_stop(sig); });
        RunOptions o;
        o.output_dir = !resume_dir.empty() ? resume_dir : out_dir.empty() ? default_output_dir(c) : out_dir;
        o.resume = !resume_dir.empty();
        // Never two runs in one folder, never a new run over an old one's files (old frames would
        // mix with the new); a resumed run continues its own folder as it is.
        const OutputLock lock(o.output_dir);
        if (!o.resume) prepare_output_folder(o.output_dir, run_output(), overwrite);
        if (!particles.empty()) o.particles_file = particles;
        o.quiet = quiet;
        o.plots = !no_plots;
        o.stop_after_steps = stop_after;
        if (couple_dryer) return app::run_coupled(c, o);
        // dryer.schedule = "model": the liquid level follows the dryer model's rates (D-6 step 2).
        if (c.dryer_schedule == "model") c = dryer::with_model_schedule(c);
        const DryingResult r = run_drying(c, o);
        return r.completed ? 0 : 1;
    } catch (const InputError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
}
