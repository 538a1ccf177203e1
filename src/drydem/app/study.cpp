// SPDX-License-Identifier: MIT
// `drydem study`: loadings x shrinkage-rate factors x seeds, each case a `drydem run` child process (so a blow-up or a bad
// set-up of one case is recorded and the others go on), up to `jobs` at a time; then study.csv,
// study.json and the Fig. 6 plot.
#include "drydem/app/commands.hpp"
#include "drydem/study/job_pool.hpp"
#include "drydem/core/error.hpp"
#include "drydem/core/stop_request.hpp"
#include "drydem/io/install_paths.hpp"
#include "drydem/io/particle_io.hpp"
#include "drydem/output/python_script.hpp"
#include "drydem/study/study.hpp"
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstring>
#include <cstdlib>
#include <fstream>
#include <map>
#include <thread>

extern char** environ;

namespace drydem::app {

std::string self_executable() {
    std::error_code ec;
    const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) throw RunError(fmt::format("cannot locate the drydem executable: {}", ec.message()));
    return p.string();
}

namespace {

/// What the parts of a study share: its options, its plan and its results so far.
struct Study {
    const Config& base;
    const StudyOptions& o;
    std::vector<StudyCase> cases;
    std::filesystem::path config_file;
    int threads = 1, jobs = 1;
    std::vector<StudyRow> rows;
    std::ofstream log;
    void say(const std::string& line) {
        if (!o.quiet) fmt::print(stderr, "{}\n", line);
        log << line << std::endl;
    }
    [[nodiscard]] std::filesystem::path run_dir(std::size_t k) const {
        return o.output_dir / "runs" / cases[k].name;
    }
    /// The `drydem run` arguments of case k (after the executable).
    [[nodiscard]] std::vector<std::string> run_args(std::size_t k,
                                                    const std::filesystem::path& dir) const {
        const StudyCase& c = cases[k];
        std::vector<std::string> args{
            "run",   config_file.string(),
            "-o",    dir.string(),
            "--set", fmt::format("film.areal_loading={:.17g}", c.areal_loading),
            "--set", fmt::format("run.seed={}", c.seed),
            "--set", fmt::format("run.name=\"{}-{}\"", base.name, c.name)};
        if (!base.study_shrinkage_rate_factors.empty()) {
            std::vector<std::string> rates;
            for (double r : base.shrinkage_rates)
                rates.push_back(fmt::format("{:.17g}", r * c.shrinkage_rate_factor));
            args.insert(args.end(), {"--set", fmt::format("dryer.shrinkage_rates=[{}]",
                                                          fmt::join(rates, ", "))});
        }
        return args;
    }
    void report(std::size_t k, std::size_t done, int code) {
        const StudyRow& r = rows[k];
        say(r.status == "completed"
                ? fmt::format("[{}/{}] {} completed: thickness {:.3f} um, density {:.4f} g/cm3, "
                              "porosity {:.4f} ({:.0f} s)",
                              done, cases.size(), r.c.name, *r.thickness_um,
                              r.density_g_cm3.value_or(NAN), r.porosity.value_or(NAN),
                              r.wall_time_s)
                : fmt::format("[{}/{}] {} FAILED (exit {}): {}", done, cases.size(), r.c.name, code,
                              r.error));
    }
};

/// One Slurm job array, one run per task (scripts/slurm_array.py: threads from
/// SLURM_CPUS_PER_TASK, a task stopped at its time limit resubmitted and resumed).
void run_on_slurm(Study& st, const std::string& exe) {
    namespace fs = std::filesystem;
    const Config& base = st.base;
    nlohmann::json spec = {{"drydem", exe},
                           {"work", fs::absolute(st.o.output_dir).string()},
                           {"name", base.name},
                           {"plots", st.o.plots},
                           {"scheduler", scheduler_settings(base)}};
    spec["tasks"] = nlohmann::json::array();
    for (std::size_t k = 0; k < st.cases.size(); ++k) {
        const fs::path dir = fs::absolute(st.run_dir(k));
        std::vector<std::string> args = st.run_args(k, dir);
        args[1] = fs::absolute(st.config_file).string();
        spec["tasks"].push_back({{"dir", dir.string()}, {"args", args}});
    }
    const fs::path tasks_file = st.o.output_dir / "slurm_tasks.json";
    write_file_atomically(tasks_file, [&](std::ostream& os) { os << spec.dump(1) << "\n"; });
    const fs::path script = script_path("slurm_array.py");
    st.say(fmt::format("slurm: {} runs as one job array, {} rank(s) x {} cpu(s) per run",
                       st.cases.size(), base.slurm_ranks_per_run, base.slurm_cpus_per_task));
    const pid_t pid = spawn_process({"/usr/bin/python3", script.string(), tasks_file.string()},
                                    st.o.output_dir / "slurm.txt");
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) throw RunError(fmt::format("waitpid failed: {}", std::strerror(errno)));
        if (stop_requested()) kill(pid, SIGTERM); // cancels the job array
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw RunError(fmt::format("the Slurm submission failed (see {})",
                                   (st.o.output_dir / "slurm.txt").string()));
    for (std::size_t k = 0; k < st.cases.size(); ++k) {
        st.rows[k] = read_study_row(st.cases[k], st.run_dir(k), -1);
        st.report(k, k + 1, -1);
    }
}

/// The cases through the local job pool (app/job_pool.hpp), `jobs` at a time; with --resume a
/// completed case is read, a stopped one continued from its checkpoint.
void run_locally(Study& st) {
    std::vector<PoolTask> tasks;
    for (std::size_t k = 0; k < st.cases.size(); ++k) {
        const StudyCase& c = st.cases[k];
        tasks.push_back({st.run_dir(k), st.run_args(k, st.run_dir(k)),
                         fmt::format("{} ({:.2f} mg/cm2, shrinkage rates x{:g}, seed {})", c.name,
                                     c.areal_loading * 100.0, c.shrinkage_rate_factor, c.seed)});
    }
    std::size_t finished = 0;
    const std::size_t not_started = run_job_pool(
        self_executable(), tasks, {st.jobs, st.threads, st.o.plots},
        [&](const std::string& line) { st.say(line); },
        [&](std::size_t k, int code) {
            st.rows[k] = read_study_row(st.cases[k], st.run_dir(k), code);
            st.report(k, ++finished, code);
            write_study_results(st.o.output_dir, st.base, st.rows); // survives a killed study
        });
    for (std::size_t k = st.cases.size() - not_started; k < st.cases.size(); ++k) {
        st.rows[k] = StudyRow{};
        st.rows[k].c = st.cases[k];
        st.rows[k].status = "not started";
        st.rows[k].error = "the study was stopped";
    }
}

/// study.csv / study.json, the statistics per loading, the Fig. 6 plot; exit 1 if a run failed.
int finish_study(Study& st, std::chrono::steady_clock::time_point start) {
    namespace fs = std::filesystem;
    write_study_results(st.o.output_dir, st.base, st.rows);
    for (const auto& s : study_statistics(st.rows))
        st.say(fmt::format(
            "{:7.2f} mg/cm2, rates x{:g}: {} ok, {} failed; thickness {:.3f} +- {:.3f} um, density "
            "{:.4f} +- {:.4f} g/cm3, porosity {:.4f} +- {:.4f}",
            s.areal_loading_mg_cm2, s.shrinkage_rate_factor, s.completed, s.failed,
            s.thickness_mean_um, s.thickness_std_um, s.density_mean_g_cm3, s.density_std_g_cm3,
            s.porosity_mean, s.porosity_std));
    if (st.o.plots) {
        if (run_python_script("plot_study.py", {st.o.output_dir.string()},
                              st.o.output_dir / "log.txt") != ScriptRun::ok)
            st.say("plotting failed (see log.txt)");
    }
    const auto failed = std::count_if(st.rows.begin(), st.rows.end(),
                                      [](const StudyRow& r) { return r.status != "completed"; });
    st.say(fmt::format(
        "study done in {:.0f} s: {} of {} runs completed; study.csv, study.json{} in {}",
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
        st.rows.size() - std::size_t(failed), st.rows.size(), st.o.plots ? ", plots/" : "",
        st.o.output_dir.string()));
    return failed == 0 ? 0 : 1;
}

} // namespace

int run_study(const Config& base, const StudyOptions& o) {
    namespace fs = std::filesystem;
    const auto start = std::chrono::steady_clock::now();
    Study st{base, o, {}, o.output_dir / "config.toml", 1, 1, {}, {}};
    const std::vector<double> loadings = o.loadings.empty() ? base.study_loadings : o.loadings;
    const int seeds = o.seeds > 0 ? o.seeds : base.study_seeds;
    st.cases = plan_study(base, loadings, seeds);
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    st.threads = o.threads > 0 ? o.threads : std::max(1, cores / int(st.cases.size()));
    st.jobs = o.jobs > 0 ? o.jobs : std::max(1, cores / st.threads);
    st.rows.resize(st.cases.size());
    fs::create_directories(o.output_dir / "runs");
    st.log.open(o.output_dir / "log.txt", std::ios::app);
    // Every case reads the same resolved config; only loading, rates, seed and name differ.
    write_file_atomically(st.config_file, [&](std::ostream& os) { os << to_toml(base); });
    const std::size_t factors = std::max<std::size_t>(1, base.study_shrinkage_rate_factors.size());
    st.say(fmt::format("study '{}': {} loading(s) x {} shrinkage-rate factor(s) x {} seed(s) = {} "
                       "runs, {} at a time "
                       "with {} thread(s) each; results in {}",
                       base.name, st.cases.size() / std::size_t(seeds) / factors, factors, seeds,
                       st.cases.size(), st.jobs, st.threads, o.output_dir.string()));
    install_stop_handlers();        // SIGINT/SIGTERM reach the running cases
    (void)scheduler_settings(base); // refuses runs of several ranks on the local scheduler
    if (base.scheduler == "slurm")
        run_on_slurm(st, self_executable());
    else
        run_locally(st);
    return finish_study(st, start);
}

} // namespace drydem::app
