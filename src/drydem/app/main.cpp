// SPDX-License-Identifier: MIT
// `drydem` command line (README "Command line"): run, calender, check, dryer, analyze, study,
// pool, calibrate, config, bench. Exit codes: 0 success,
// 1 run failure, 2 bad input.
#include "drydem/drying/analysis_inputs.hpp"
#include "drydem/app/commands.hpp"
#include "drydem/study/job_pool.hpp"
#include "drydem/core/error.hpp"
#include "drydem/core/stop_request.hpp"
#include "drydem/dryer_model/dryer_config.hpp"
#include "drydem/drying/drying_run.hpp"
#include "drydem/io/output_folder.hpp"
#include "drydem/io/units.hpp"
#include "drydem/parallel/mpi_world.hpp"
#include "drydem/drying/derived_checks.hpp"
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
        throw InputError(
            fmt::format("{} = {}: this machine has {} cores; allowed 1..{} (0 = all cores)", what,
                        threads, cores, cores));
}

/// Every option of every command, filled by CLI11; one command is parsed per call.
struct CommandLine {
    CLI::App cli{"DryDEM: DEM simulation of structure formation during electrode drying "
                 "(Lippke et al., Energy Technol. 2022)"};
    std::string config_file, out_dir, particles, resume_dir;
    std::vector<std::string> sets;
    std::string seed_text, threads_text, stop_after_text, which, study_loadings, scheduler;
    bool overwrite = false, quiet = false, no_plots = false, couple_dryer = false, table2 = false;
    app::StudyOptions study_opt;
    app::CalibrateOptions cal_opt;
    app::AnalyzeOptions an;
    std::string an_voxel, an_dz, an_gap, an_config, an_pore_top;
    bool an_no_voxels = false;
    app::BenchOptions bench_opt;
    app::CalenderCommand calender_opt;
    std::string calender_stop_text;
    CLI::Option* calender_stop_opt = nullptr;
    PoolOptions pool_opt;
    std::string pool_tasks;
    CLI::App* pool = nullptr;
    CLI::App *run = nullptr, *dryer = nullptr, *check = nullptr, *config = nullptr,
             *study = nullptr, *calibrate = nullptr, *analyze = nullptr, *bench = nullptr,
             *calender = nullptr;
    CLI::Option *seed_opt = nullptr, *threads_opt = nullptr, *stop_after_opt = nullptr;
    std::optional<std::uint64_t> seed, threads;
    std::optional<std::int64_t> stop_after;
};

void declare_run(CommandLine& a) {
    a.run = a.cli.add_subcommand(
        "run", "run the drying simulation (no CONFIG: the paper's 20.1 mg/cm2 case)");
    a.run->add_option("config", a.config_file, "TOML configuration")->check(CLI::ExistingFile);
    a.run->add_option("-o,--output", a.out_dir, "output folder (default out/<name>-<timestamp>)");
    a.run->add_option("--set", a.sets, "override a key, e.g. --set run.seed=7")->take_all();
    a.seed_opt =
        a.run->add_option("--seed", a.seed_text, "random seed 0..2^63-1 (= --set run.seed=N)");
    a.threads_opt = a.run->add_option("--threads", a.threads_text,
                                      "OpenMP threads, 0 = all cores (= --set run.threads=N)");
    a.run->add_flag(
        "--overwrite", a.overwrite,
        "replace the outputs of a previous run in the -o folder (default: refuse a folder "
        "that holds a run)");
    a.run
        ->add_option("--particles", a.particles,
                     "start from these particles (CSV, LAMMPS data or dump)")
        ->check(CLI::ExistingFile);
    a.run
        ->add_option("--resume", a.resume_dir,
                     "continue the run in this output folder from its checkpoint (same config, "
                     "same threads: bit-identical to an uninterrupted run)")
        ->check(CLI::ExistingDirectory);
    a.run->add_flag("--quiet", a.quiet, "only warnings and errors on the console");
    a.run->add_flag("--no-plots", a.no_plots, "skip the matplotlib plots");
    // For tests only: a deterministic stand-in for a signal or a kill at a given step.
    a.stop_after_opt =
        a.run
            ->add_option("--stop-after-steps", a.stop_after_text,
                         "for testing: stop after step N as SIGTERM would (checkpoint, results so "
                         "far, exit 1); also with --resume")
            ->group("Testing");
    a.run->add_flag("--couple-dryer", a.couple_dryer,
                    "iterate dryer model <-> DEM until the final thickness settles (paper Sec. 8; "
                    "each DEM run in DIR/iter_N, summary in DIR/coupling.json)");
}

void declare_dryer_check_config(CommandLine& a) {
    a.dryer = a.cli.add_subcommand("dryer", "the dryer model alone: film temperature, solvent "
                                            "content, shrinkage rate per zone (docs/dryer.md)");
    a.dryer->add_option("config", a.config_file, "TOML configuration")->check(CLI::ExistingFile);
    a.dryer->add_option("-o,--output", a.out_dir,
                        "output folder (default out/<name>-dryer-<timestamp>)");
    a.dryer->add_option("--set", a.sets, "override a key, e.g. --set dryer.preset=physical")
        ->take_all();
    a.dryer->add_flag("--no-plots", a.no_plots, "skip the matplotlib plot");
    a.dryer->add_flag("--overwrite", a.overwrite,
                      "replace a previous dryer model run's outputs in the -o folder");
    a.dryer->add_flag("--table2", a.table2,
                      "print paper Table 2 against the model (both presets) instead");

    a.check =
        a.cli.add_subcommand("check", "validate a configuration and print every derived quantity");
    a.check->add_option("config", a.config_file, "TOML configuration")->check(CLI::ExistingFile);
    a.check->add_option("--set", a.sets, "override a key")->take_all();

    a.config =
        a.cli.add_subcommand("config", "print the default configuration or the key reference");
    a.config
        ->add_option("which", a.which,
                     "'default': the embedded default configuration; 'doc': the "
                     "key reference (docs/configuration.md)")
        ->required()
        ->check(CLI::IsMember({"default", "doc"}));
}

void declare_calender(CommandLine& a) {
    app::CalenderCommand& o = a.calender_opt;
    a.calender = a.cli.add_subcommand(
        "calender", "press the dried film of a finished run with a rigid plate, unload it, and "
                    "analyse the calendered film (docs/calendering.md)");
    a.calender->add_option("run_dir", o.run_dir, "the drying run's folder (its final.csv)")
        ->check(CLI::ExistingDirectory);
    a.calender
        ->add_option("--resume", o.resume_dir,
                     "continue the stopped calendering in DIR from its checkpoint, with its "
                     "config (only --threads, --quiet, --no-plots, --stop-after-steps besides)")
        ->check(CLI::ExistingDirectory);
    a.calender->add_option("-o,--output", o.output_dir,
                           "output folder (default: RUN_DIR-calendered beside the run)");
    a.calender
        ->add_option("--set", o.sets,
                     "override a key of the run's config, e.g. "
                     "calendering.target_porosity=0.35")
        ->take_all();
    a.calender->add_option("--threads", o.threads, "OpenMP threads (default run.threads)");
    a.calender_stop_opt = a.calender->add_option("--stop-after-steps", a.calender_stop_text,
                                                 "stop after this step (testing)");
    a.calender->add_flag("--quiet", o.quiet, "only warnings and the result lines");
    a.calender->add_flag("--no-plots", a.no_plots, "skip the matplotlib plots");
    a.calender->add_flag("--overwrite", o.overwrite,
                         "replace a previous calendering run in the output folder");
}

void declare_study_calibrate(CommandLine& a) {
    a.study = a.cli.add_subcommand(
        "study", "loadings x seeds: runs, study.csv/.json and the thickness/density "
                 "vs loading plot (paper Fig. 6)");
    a.study->add_option("config", a.config_file, "TOML configuration")->check(CLI::ExistingFile);
    a.study->add_option("-o,--output", a.out_dir,
                        "output folder (default out/<name>-study-<timestamp>)");
    a.study->add_option("--set", a.sets, "override a key")->take_all();
    a.study->add_option(
        "--loadings", a.study_loadings,
        "areal loadings, comma separated, in mg/cm^2 or with units (default study.loadings, "
        "else film.areal_loading)");
    a.study->add_option("--seeds", a.study_opt.seeds, "runs per loading (default study.seeds)")
        ->check(CLI::PositiveNumber);
    a.study->add_option("--threads", a.study_opt.threads, "threads per run (default cores / runs)")
        ->check(CLI::PositiveNumber);
    a.study->add_option("--jobs", a.study_opt.jobs, "runs at a time (default cores / threads)")
        ->check(CLI::PositiveNumber);
    a.study->add_flag("--quiet", a.study_opt.quiet, "only the final table");
    a.study->add_flag("--no-plots", a.no_plots, "skip the matplotlib plots");
    a.study->add_flag("--overwrite", a.overwrite,
                      "replace a previous study's outputs (its runs included) in the -o folder");
    a.study->add_flag(
        "--resume", a.study_opt.resume,
        "continue the stopped study in -o DIR: completed runs are kept, stopped ones continue "
        "from their checkpoints, the rest start");
    a.study
        ->add_option("--scheduler", a.scheduler,
                     "where the runs run: local (child processes) or slurm (a job array; = --set "
                     "scheduler.type=...)")
        ->check(CLI::IsMember({"local", "slurm"}));

    a.pool = a.cli.add_subcommand(
        "pool", "bring the drydem runs of a task file to their end, --jobs at a time (the job "
                "pool of `study`; scripts/calibrate.py hands its runs here)");
    a.pool
        ->add_option("tasks", a.pool_tasks,
                     "JSON: {\"tasks\": [{\"dir\": DIR, \"args\": "
                     "[\"run\", CONFIG, ...]}]}")
        ->required()
        ->check(CLI::ExistingFile);
    a.pool->add_option("--jobs", a.pool_opt.jobs, "runs at a time, 1..1024 (default 1)")
        ->check(CLI::Range(1, 1024));
    a.pool->add_option("--threads", a.pool_opt.threads, "threads per run (default 1)")
        ->check(CLI::PositiveNumber);
    a.pool->add_flag("--quiet", a.quiet, "print nothing");
    a.pool->add_flag("--no-plots", a.no_plots, "skip the runs' matplotlib plots");

    a.calibrate = a.cli.add_subcommand(
        "calibrate", "fit config parameters to measured targets ([calibration]; "
                     "docs/calibration.md): evaluations.csv, calibrated.toml, plots");
    a.calibrate
        ->add_option("config", a.config_file, "TOML configuration with a [calibration] section")
        ->required()
        ->check(CLI::ExistingFile);
    a.calibrate->add_option("-o,--output", a.out_dir,
                            "output folder (default out/<name>-calibrate-<timestamp>)");
    a.calibrate->add_option("--set", a.sets, "override a key")->take_all();
    a.calibrate
        ->add_option("--jobs", a.cal_opt.jobs,
                     "local: runs at a time; slurm: evaluations per job array (default 1)")
        ->check(CLI::PositiveNumber);
    a.calibrate
        ->add_option("--threads", a.cal_opt.threads, "threads per local run (default cores / jobs)")
        ->check(CLI::PositiveNumber);
    a.calibrate->add_flag(
        "--resume", a.cal_opt.resume,
        "continue the calibration in -o DIR where it stopped (finished evaluations are kept)");
    a.calibrate
        ->add_option("--scheduler", a.scheduler, "local or slurm (= --set scheduler.type=...)")
        ->check(CLI::IsMember({"local", "slurm"}));
    a.calibrate->add_flag("--quiet", a.cal_opt.quiet, "only warnings and the result");
    a.calibrate->add_flag("--no-plots", a.no_plots, "skip the matplotlib plots");
}

void declare_analyze_bench(CommandLine& a) {
    a.analyze = a.cli.add_subcommand(
        "analyze", "structure analysis of a particle snapshot (ours, the peers' CSV, "
                   "LAMMPS/LIGGGHTS data or dump): thickness, density, profiles, "
                   "coordination, pore sizes, voxel image");
    a.analyze
        ->add_option("snapshot", a.an.snapshot,
                     "particle file (final.csv, CSV, LAMMPS data or dump), or a run "
                     "folder (its final.csv)")
        ->required()
        ->check(CLI::ExistingPath);
    a.analyze->add_option("-o,--output", a.out_dir,
                          "output folder (default: analysis/ beside the snapshot)");
    a.analyze
        ->add_option(
            "--config", a.an_config,
            "config with the formulation and box (default: config.toml beside the snapshot, "
            "else the embedded default)")
        ->check(CLI::ExistingFile);
    a.analyze->add_option("--set", a.sets, "override a config key")->take_all();
    a.analyze->add_option("--voxel", a.an_voxel,
                          "voxel edge, e.g. 0.1um (a bare number is um; 0 = no voxel analysis; "
                          "default analysis.voxel_size)");
    a.analyze->add_option(
        "--dz", a.an_dz,
        "slab width of the height profiles (bare number: um; default analysis.profile_dz)");
    a.analyze->add_option("--contact-gap", a.an_gap,
                          "surface gap still counted as contact for coordination (bare: um; "
                          "default analysis.contact_gap)");
    a.analyze
        ->add_option(
            "--pore-top", a.an_pore_top,
            "top of the pore statistics: half_solid (robust thickness) or highest (highest top)")
        ->check(CLI::IsMember({"half_solid", "highest"}));
    a.analyze
        ->add_option("--cb-type", a.an.cb_type,
                     "the file's particle type of the CB spheres (default: n + 1 for n "
                     "NCM classes in the config); every other type is NCM")
        ->check(CLI::PositiveNumber);
    a.analyze->add_flag("--export", a.an.export_voxels,
                        "write the voxel image: structure.raw + .json + .mhd");
    a.analyze->add_flag("--tiff", a.an.tiff,
                        "also write structure.tif (multi-page, one page per z layer)");
    a.analyze->add_flag("--no-voxels", a.an_no_voxels,
                        "only the particle-based numbers (no pore sizes, no transport solves)");
    a.analyze->add_option("--threads", a.an.threads, "OpenMP threads (default all cores)")
        ->check(CLI::PositiveNumber);
    a.analyze->add_flag("--quiet", a.an.quiet, "only the result lines");
    a.analyze->add_flag("--no-plots", a.no_plots, "skip the matplotlib plots");
    a.analyze->add_flag("--overwrite", a.overwrite,
                        "replace a previous analysis in the output folder");

    a.bench = a.cli.add_subcommand("bench",
                                   "the peers' granular benchmark (bench/peer_bench.sh) in DryDEM");
    a.bench->add_option("data", a.bench_opt.data, "settled bed (LAMMPS data or CSV)")
        ->required()
        ->check(CLI::ExistingFile);
    a.bench->add_option("--steps", a.bench_opt.steps, "timed steps");
    a.bench->add_option("--warmup", a.bench_opt.warmup, "untimed warm-up steps");
    a.bench->add_option("--threads", a.bench_opt.threads, "OpenMP threads");
    a.bench->add_flag("--whole-list", a.bench_opt.whole_list,
                      "walk the whole neighbour list every step, no near list (A/B timing)");
}

/// The command-line integers, checked as the issue of hostile input asks (no sign, no overflow,
/// threads within the cores); --seed and --threads become --set overrides of a new run.
void check_integers(CommandLine& a) {
    // count(), not empty(): `--threads ''` is a bad value, not a missing option.
    if (a.seed_opt->count() > 0)
        a.seed = cli_integer("--seed", a.seed_text, std::numeric_limits<std::int64_t>::max(),
                             "an integer 0..9223372036854775807");
    if (a.threads_opt->count() > 0) {
        a.threads =
            cli_integer("--threads", a.threads_text, 1024, "an integer 0..1024 (0 = all cores)");
        check_threads("--threads", long(*a.threads));
    }
    if (a.stop_after_opt->count() > 0)
        a.stop_after = std::int64_t(cli_integer("--stop-after-steps", a.stop_after_text,
                                                std::numeric_limits<std::int64_t>::max(),
                                                "a step count 0..9223372036854775807"));
    if (a.calender_stop_opt && a.calender_stop_opt->count() > 0)
        a.calender_opt.stop_after = std::int64_t(cli_integer(
            "--stop-after-steps", a.calender_stop_text, std::numeric_limits<std::int64_t>::max(),
            "a step count 0..9223372036854775807"));
    for (const int n : {a.study_opt.threads, a.an.threads, a.bench_opt.threads, a.cal_opt.threads,
                        a.pool_opt.threads, a.calender_opt.threads})
        check_threads("--threads", n);
    if (!a.scheduler.empty()) a.sets.push_back("scheduler.type=\"" + a.scheduler + "\"");
    if (a.seed && a.resume_dir.empty()) a.sets.push_back(fmt::format("run.seed={}", *a.seed));
    if (a.threads && a.resume_dir.empty())
        a.sets.push_back(fmt::format("run.threads={}", *a.threads));
}

int analyze_command(CommandLine& a) {
    // Bare numbers are micrometres, the unit of the structure.
    auto length = [](std::string v, const char* key) {
        if (v.find_first_not_of("0123456789.eE+- ") == std::string::npos) v += " um";
        return parse_quantity(v, Dimension::length, key);
    };
    if (std::filesystem::is_directory(a.an.snapshot)) {
        if (!std::filesystem::exists(a.an.snapshot / "final.csv"))
            throw InputError(
                fmt::format("{} is a folder without final.csv (not a finished run); give "
                            "a particle file",
                            a.an.snapshot.string()));
        a.an.snapshot /= "final.csv";
    }
    const std::filesystem::path beside = a.an.snapshot.parent_path() / "config.toml";
    if (a.an_config.empty() && std::filesystem::exists(beside)) a.an_config = beside.string();
    const Config c = load(a.an_config, a.sets);
    a.an.analysis.voxel = a.an_no_voxels       ? 0.0
                          : a.an_voxel.empty() ? c.analysis_voxel_size
                                               : length(a.an_voxel, "--voxel");
    a.an.analysis.profile_dz = a.an_dz.empty() ? c.analysis_profile_dz : length(a.an_dz, "--dz");
    a.an.analysis.contact_gap =
        a.an_gap.empty() ? c.analysis_contact_gap : length(a.an_gap, "--contact-gap");
    a.an.analysis.pore_top = a.an_pore_top.empty() ? c.analysis_pore_top : a.an_pore_top;
    set_transport_options(a.an.analysis, c);
    if (a.an_no_voxels)
        a.an.analysis.transport.voxels.clear(); // the transport solves are voxel work too
    if (a.an.analysis.voxel < 0.0)
        throw InputError(fmt::format("--voxel {}: must be positive (0 = none)", a.an_voxel));
    if (!(a.an.analysis.profile_dz > 0.0))
        throw InputError(fmt::format("--dz {}: must be positive", a.an_dz));
    if (a.an.analysis.contact_gap < 0.0)
        throw InputError(fmt::format("--contact-gap {}: must be >= 0", a.an_gap));
    a.an.output_dir = a.out_dir.empty() ? a.an.snapshot.parent_path() / "analysis"
                                        : std::filesystem::path(a.out_dir);
    a.an.plots = !a.no_plots;
    const OutputLock lock(a.an.output_dir);
    prepare_output_folder(a.an.output_dir, analysis_output(), a.overwrite);
    if (!a.an.quiet)
        fmt::print("config: {}\n",
                   a.an_config.empty() ? std::string("<embedded default>") : a.an_config);
    return app::run_analyze(c, a.an);
}

int check_command(CommandLine& a) {
    Config c = load(a.config_file, a.sets);
    if (c.dryer_schedule == "model")
        c = dryer::with_model_schedule(c); // rates as the run uses them
    app::print_check(c);
    return 0;
}

int calibrate_command(CommandLine& a) {
    const Config c = load(a.config_file, a.sets);
    if (a.cal_opt.resume && a.out_dir.empty())
        throw InputError("--resume needs -o DIR, the folder of the calibration to continue");
    a.cal_opt.output_dir = a.out_dir.empty() ? default_output_dir(c, "-calibrate") : a.out_dir;
    a.cal_opt.plots = !a.no_plots;
    return app::run_calibrate(c, a.cal_opt);
}

int study_command(CommandLine& a) {
    const Config c = load(a.config_file, a.sets);
    a.study_opt.output_dir = a.out_dir.empty() ? default_output_dir(c) + "-study" : a.out_dir;
    a.study_opt.plots = !a.no_plots;
    std::size_t start = 0;
    while (start < a.study_loadings.size()) {
        std::size_t comma = a.study_loadings.find(',', start);
        if (comma == std::string::npos) comma = a.study_loadings.size();
        std::string item = a.study_loadings.substr(start, comma - start);
        start = comma + 1;
        if (item.find_first_not_of(" ") == std::string::npos) continue;
        // A bare number is mg/cm^2, the unit of the paper and of process engineers.
        if (item.find_first_not_of("0123456789.eE+- ") == std::string::npos) item += " mg/cm^2";
        a.study_opt.loadings.push_back(
            parse_quantity(item, Dimension::areal_density, "--loadings"));
    }
    const OutputLock lock(a.study_opt.output_dir);
    if (a.study_opt.resume && a.overwrite)
        throw InputError("study: --resume and --overwrite exclude each other");
    if (!a.study_opt.resume)
        prepare_output_folder(a.study_opt.output_dir, study_output(), a.overwrite);
    return app::run_study(c, a.study_opt);
}

int dryer_command(CommandLine& a) {
    const Config c = load(a.config_file, a.sets);
    if (a.table2) {
        app::print_table2_comparison(c);
        return 0;
    }
    app::DryerOptions d;
    d.output_dir = a.out_dir.empty() ? default_output_dir(c, "-dryer") : a.out_dir;
    d.plots = !a.no_plots;
    const OutputLock lock(d.output_dir);
    prepare_output_folder(d.output_dir, dryer_output(), a.overwrite);
    return app::run_dryer(c, d);
}

/// Runs `f` on rank 0 only when several MPI ranks run (on the one rank otherwise); an error there
/// is thrown on every rank as an InputError with its words.
template <class F>
void agree_on_rank0(F&& f) {
    const parallel::World w = parallel::world();
    if (w.size == 1) {
        f();
        return;
    }
    std::string failed;
    if (w.rank == 0) try {
            f();
        } catch (const std::exception& e) {
            failed = e.what();
        }
    failed = parallel::broadcast(failed);
    if (!failed.empty()) throw InputError(failed);
}

int run_command(CommandLine& a) {
    if (!a.resume_dir.empty()) {
        if (!a.config_file.empty() || !a.sets.empty() || !a.particles.empty() ||
            !a.out_dir.empty() || a.seed || a.couple_dryer || a.overwrite)
            throw InputError(
                "--resume DIR continues a run with the config stored in its "
                "checkpoint; CONFIG, --set, --seed, --particles, -o, --overwrite and "
                "--couple-dryer are not allowed with it (only --threads, --quiet, --no-plots)");
    }
    Config c = a.resume_dir.empty() ? load(a.config_file, a.sets) : resume_config(a.resume_dir);
    if (!a.resume_dir.empty() && a.threads) c.threads = int(*a.threads);
    if (a.resume_dir.empty()) {
        check_threads("config key 'run.threads'", c.threads);
        check_fits_this_machine(c);
    }
    // Ctrl-C / SIGTERM: finish the step, write the results so far, exit 1.
    std::signal(SIGINT, [](int sig) { request_stop(sig); });
    std::signal(SIGTERM, [](int sig) { request_stop(sig); });
    RunOptions o;
    o.output_dir = !a.resume_dir.empty() ? a.resume_dir
                   : a.out_dir.empty()   ? default_output_dir(c)
                                         : a.out_dir;
    o.resume = !a.resume_dir.empty();
    // Never two runs in one folder, never a new run over an old one's files (old frames would
    // mix with the new); a resumed run continues its own folder as it is. Several ranks: rank 0
    // holds the folder, and its refusal stops them all.
    // A rank count the film cannot be cut into is refused before the folder exists (a film read
    // from --particles or a checkpoint is decomposed as it is, by the engine).
    if (!o.resume && a.particles.empty()) check_rank_count(c, parallel::world().size);
    std::optional<OutputLock> lock;
    agree_on_rank0([&] {
        lock.emplace(o.output_dir);
        if (!o.resume) prepare_output_folder(o.output_dir, run_output(), a.overwrite);
    });
    if (!a.particles.empty()) o.particles_file = a.particles;
    o.quiet = a.quiet;
    o.plots = !a.no_plots;
    o.stop_after_steps = a.stop_after;
    if (a.couple_dryer) {
        if (parallel::world().size > 1)
            throw InputError("--couple-dryer runs on one MPI rank only (docs/parallel.md)");
        return app::run_coupled(c, o);
    }
    // dryer.schedule = "model": the liquid level follows the dryer model's rates (D-6 step 2).
    if (c.dryer_schedule == "model") c = dryer::with_model_schedule(c);
    const DryingResult r = run_drying(c, o);
    return r.completed ? 0 : 1;
}

} // namespace

/// Only `drydem run` spreads its film over several MPI ranks; the other simulating commands would
/// run the same film on each rank into one folder (docs/parallel.md).
void refuse_several_ranks(const CommandLine& a) {
    const int ranks = parallel::launcher_ranks();
    if (ranks <= 1) return;
    for (const CLI::App* command : {a.calender, a.analyze, a.bench, a.study, a.calibrate, a.pool})
        if (*command)
            throw InputError(fmt::format(
                "drydem {}: started as one of {} MPI ranks, but only `drydem run` uses several "
                "ranks (docs/parallel.md). Start it without mpirun/srun, or with one rank; "
                "--threads uses the cores of one machine",
                command->get_name(), ranks));
    if (*a.run) {
        parallel::start_mpi();
        if (parallel::world().size != ranks)
            throw InputError(fmt::format("the launcher announced {} MPI ranks, MPI runs {}", ranks,
                                         parallel::world().size));
    }
}

/// The command line's command.
int dispatch(CommandLine& a) {
    check_integers(a);
    if (*a.config) {
        if (a.which == "doc")
            std::cout << config_reference_markdown();
        else
            std::cout << default_config_toml();
        return 0;
    }
    refuse_several_ranks(a);
    if (*a.bench) return app::run_bench(a.bench_opt);
    if (*a.analyze) return analyze_command(a);
    if (*a.calender) {
        a.calender_opt.plots = !a.no_plots;
        std::signal(SIGINT, [](int sig) { request_stop(sig); });
        std::signal(SIGTERM, [](int sig) { request_stop(sig); });
        return app::run_calender(a.calender_opt);
    }
    if (*a.check) return check_command(a);
    if (*a.calibrate) return calibrate_command(a);
    if (*a.study) return study_command(a);
    if (*a.pool) {
        a.pool_opt.plots = !a.no_plots;
        return run_pool_command(app::self_executable(), a.pool_tasks, a.pool_opt, a.quiet);
    }
    if (*a.dryer) return dryer_command(a);
    if (!*a.run) {
        std::cout << a.cli.help();
        return 0;
    }
    return run_command(a);
}

int main(int argc, char** argv) {
    CommandLine a;
    a.cli.require_subcommand(0, 1);
    a.cli.set_version_flag("--version",
                           fmt::format("drydem {} ({})", DRYDEM_VERSION, DRYDEM_GIT_HASH));
    declare_run(a);
    declare_dryer_check_config(a);
    declare_study_calibrate(a);
    declare_analyze_bench(a);
    declare_calender(a);
    try {
        a.cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = a.cli.exit(e);
        return code == 0 ? 0 : 2;
    }
    int code = 0;
    try {
        code = dispatch(a);
    } catch (const InputError& e) {
        // Bad input is found alike on every rank: rank 0 says it.
        if (parallel::world().rank == 0) std::cerr << "error: " << e.what() << "\n";
        code = 2;
    } catch (const std::exception& e) {
        const parallel::World w = parallel::world();
        std::cerr << (w.size > 1 ? fmt::format("error: rank {}: ", w.rank) : "error: ") << e.what()
                  << "\n";
        if (w.size > 1) parallel::abort_all(1); // the other ranks may wait for this one
        code = 1;
    }
    parallel::finish_mpi();
    return code;
}
