// SPDX-License-Identifier: MIT
// `drydem study`: loadings x shrinkage-rate factors x seeds, each case a `drydem run` child process (so a blow-up or a bad
// set-up of one case is recorded and the others go on), up to `jobs` at a time; then study.csv,
// study.json and the Fig. 6 plot.
#include "drydem/app/commands.hpp"
#include "drydem/core/error.hpp"
#include "drydem/core/stop_request.hpp"
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

pid_t spawn(const std::vector<std::string>& args, const std::filesystem::path& console_log) {
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, console_log.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = 0;
    const int rc = posix_spawn(&pid, args[0].c_str(), &fa, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) throw RunError(fmt::format("cannot start {}: {}", args[0], std::strerror(rc)));
    return pid;
}

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

/// A case's run folder from an earlier, stopped study (--resume): completed, or stopped with a
/// checkpoint to continue from.
enum class Earlier { none, completed, stopped };
Earlier earlier_run(const StudyCase& c, const std::filesystem::path& dir) {
    if (read_study_row(c, dir, 0).status == "completed") return Earlier::completed;
    if (std::filesystem::exists(dir / "checkpoint" / "state.bin")) return Earlier::stopped;
    return Earlier::none;
}

/// One Slurm job array, one run per task (scripts/slurm_array.py: threads from
/// SLURM_CPUS_PER_TASK, a task stopped at its time limit resubmitted and resumed).
void run_on_slurm(Study& st, const std::string& exe) {
    namespace fs = std::filesystem;
    const Config& base = st.base;
    nlohmann::json spec = {{"drydem", exe},
                           {"work", fs::absolute(st.o.output_dir).string()},
                           {"name", base.name},
                           {"plots", st.o.plots},
                           {"scheduler",
                            {{"partition", base.slurm_partition},
                             {"time_limit_s", base.slurm_time_limit},
                             {"cpus_per_task", base.slurm_cpus_per_task},
                             {"resubmits", base.slurm_resubmits}}}};
    spec["tasks"] = nlohmann::json::array();
    for (std::size_t k = 0; k < st.cases.size(); ++k) {
        const fs::path dir = fs::absolute(st.run_dir(k));
        std::vector<std::string> args = st.run_args(k, dir);
        args[1] = fs::absolute(st.config_file).string();
        spec["tasks"].push_back({{"dir", dir.string()}, {"args", args}});
    }
    const fs::path tasks_file = st.o.output_dir / "slurm_tasks.json";
    write_file_atomically(tasks_file, [&](std::ostream& os) { os << spec.dump(1) << "\n"; });
    const fs::path script = fs::path(DRYDEM_SOURCE_DIR) / "scripts" / "slurm_array.py";
    st.say(fmt::format("slurm: {} runs as one job array, {} cpu(s) per task", st.cases.size(),
                       base.slurm_cpus_per_task));
    const pid_t pid = spawn({"/usr/bin/python3", script.string(), tasks_file.string()},
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

/// Up to `jobs` child processes at a time; on SIGINT/SIGTERM no new case starts and the running
/// ones stop themselves and write what they have. With --resume a completed case is read, a
/// stopped one continued from its checkpoint.
void run_locally(Study& st, const std::string& exe) {
    std::map<pid_t, std::size_t> running;
    std::size_t next = 0, finished = 0;
    bool stopping = false;
    auto start_case = [&](std::size_t k) {
        const std::filesystem::path dir = st.run_dir(k);
        const Earlier earlier = st.o.resume ? earlier_run(st.cases[k], dir) : Earlier::none;
        if (earlier == Earlier::completed) {
            st.rows[k] = read_study_row(st.cases[k], dir, 0);
            st.report(k, ++finished, 0);
            return;
        }
        std::filesystem::create_directories(dir);
        std::vector<std::string> args{exe};
        if (earlier == Earlier::stopped)
            args.insert(args.end(), {"run", "--resume", dir.string()});
        else
            for (auto& a : st.run_args(k, dir)) args.push_back(a);
        args.insert(args.end(), {"--threads", std::to_string(st.threads), "--quiet"});
        if (!st.o.plots) args.push_back("--no-plots");
        running[spawn(args, dir / "console.txt")] = k;
        const StudyCase& c = st.cases[k];
        st.say(fmt::format("{} {} ({:.2f} mg/cm2, shrinkage rates x{:g}, seed {})",
                           earlier == Earlier::stopped ? "resumed" : "started", c.name,
                           c.areal_loading * 100.0, c.shrinkage_rate_factor, c.seed));
    };
    while (finished < st.cases.size()) {
        while (!stopping && running.size() < std::size_t(st.jobs) && next < st.cases.size())
            start_case(next++);
        if (running.empty()) break;
        int status = 0;
        const pid_t pid = waitpid(-1, &status, 0);
        if (pid < 0) {
            if (errno != EINTR)
                throw RunError(fmt::format("waitpid failed: {}", std::strerror(errno)));
            if (stop_requested() && !stopping) {
                stopping = true;
                st.say("stop requested: no further runs are started; waiting for the running ones");
                for (const auto& [p, k] : running) kill(p, SIGTERM);
            }
            continue;
        }
        const auto it = running.find(pid);
        if (it == running.end()) continue;
        const std::size_t k = it->second;
        running.erase(it);
        const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        st.rows[k] = read_study_row(st.cases[k], st.run_dir(k), code);
        st.report(k, ++finished, code);
        write_study_results(st.o.output_dir, st.base,
                            st.rows); // a partial table survives a killed study
    }
    for (std::size_t k = next; k < st.cases.size(); ++k)
        st.rows[k] = StudyRow{st.cases[k],
                              "not started",
                              "the study was stopped",
                              {},
                              {},
                              {},
                              {},
                              0.0,
                              {},
                              {},
                              {},
                              {},
                              {},
                              {}};
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
    // Without SA_RESTART, so that SIGINT/SIGTERM interrupt waitpid and reach the running cases.
    struct sigaction sa {};
    sa.sa_handler = [](int sig) { request_stop(sig); };
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0;
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
    const std::string exe = self_executable();
    if (base.scheduler == "slurm")
        run_on_slurm(st, exe);
    else
        run_locally(st, exe);
    return finish_study(st, start);
}

} // namespace drydem::app
