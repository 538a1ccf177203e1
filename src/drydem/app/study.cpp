// SPDX-License-Identifier: MIT
// `drydem study`: loadings x seeds, each case a `drydem run` child process (so a blow-up or a bad
// set-up of one case is recorded and the others go on), up to `jobs` at a time; then study.csv,
// study.json and the Fig. 6 plot.
#include "drydem/app/commands.hpp"
#include "drydem/core/error.hpp"
#include "drydem/core/stop_request.hpp"
#include "drydem/io/particle_io.hpp"
#include "drydem/study/study.hpp"
#include <fmt/format.h>
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
    posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, console_log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
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

} // namespace

int run_study(const Config& base, const StudyOptions& o) {
    namespace fs = std::filesystem;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<double> loadings = o.loadings.empty() ? base.study_loadings : o.loadings;
    const int seeds = o.seeds > 0 ? o.seeds : base.study_seeds;
    const std::vector<StudyCase> cases = plan_study(base, loadings, seeds);
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    const int threads = o.threads > 0 ? o.threads : std::max(1, cores / int(cases.size()));
    const int jobs = o.jobs > 0 ? o.jobs : std::max(1, cores / threads);
    fs::create_directories(o.output_dir / "runs");
    std::ofstream log(o.output_dir / "log.txt", std::ios::app);
    auto say = [&](const std::string& line) {
        if (!o.quiet) fmt::print(stderr, "{}\n", line);
        log << line << std::endl;
    };
    // Every case reads the same resolved config; only loading, seed and name differ.
    const fs::path config_file = o.output_dir / "config.toml";
    write_file_atomically(config_file, [&](std::ostream& os) { os << to_toml(base); });
    say(fmt::format("study '{}': {} loadings x {} seeds = {} runs, {} at a time with {} thread(s) "
                    "each; results in {}",
                    base.name, cases.size() / std::size_t(seeds), seeds, cases.size(), jobs, threads,
                    o.output_dir.string()));

    // Without SA_RESTART, so that SIGINT/SIGTERM interrupt waitpid and reach the running cases.
    struct sigaction sa {};
    sa.sa_handler = [](int sig) { request_stop(sig); };
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0;
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
    const std::string exe = self_executable();
    std::vector<StudyRow> rows(cases.size());
    std::map<pid_t, std::size_t> running;
    std::size_t next = 0, finished = 0;
    bool stopping = false;
    auto start_case = [&](std::size_t k) {
        const StudyCase& c = cases[k];
        const fs::path dir = o.output_dir / "runs" / c.name;
        fs::create_directories(dir);
        std::vector<std::string> args = {exe, "run", config_file.string(), "-o", dir.string(),
                                         "--set", fmt::format("film.areal_loading={:.17g}", c.areal_loading),
                                         "--set", fmt::format("run.seed={}", c.seed),
                                         "--set", fmt::format("run.name=\"{}-{}\"", base.name, c.name),
                                         "--threads", std::to_string(threads), "--quiet"};
        if (!o.plots) args.push_back("--no-plots");
        running[spawn(args, dir / "console.txt")] = k;
        say(fmt::format("started {} ({:.2f} mg/cm2, seed {})", c.name, c.areal_loading * 100.0, c.seed));
    };
    if (base.scheduler == "slurm") {
        // One Slurm job array, one run per task (scripts/slurm_array.py: threads from
        // SLURM_CPUS_PER_TASK, a task stopped at its time limit resubmitted and resumed).
        nlohmann::json spec = {{"drydem", exe}, {"work", fs::absolute(o.output_dir).string()}, {"name", base.name},
                               {"plots", o.plots},
                               {"scheduler", {{"partition", base.slurm_partition},
                                              {"time_limit_s", base.slurm_time_limit},
                                              {"cpus_per_task", base.slurm_cpus_per_task},
                                              {"resubmits", base.slurm_resubmits}}}};
        spec["tasks"] = nlohmann::json::array();
        for (const StudyCase& c : cases) {
            const fs::path dir = fs::absolute(o.output_dir / "runs" / c.name);
            spec["tasks"].push_back({{"dir", dir.string()},
                                     {"args", {"run", fs::absolute(config_file).string(), "-o", dir.string(),
                                               "--set", fmt::format("film.areal_loading={:.17g}", c.areal_loading),
                                               "--set", fmt::format("run.seed={}", c.seed),
                                               "--set", fmt::format("run.name=\"{}-{}\"", base.name, c.name)}}});
        }
        const fs::path tasks_file = o.output_dir / "slurm_tasks.json";
        write_file_atomically(tasks_file, [&](std::ostream& os) { os << spec.dump(1) << "\n"; });
        const fs::path script = fs::path(DRYDEM_SOURCE_DIR) / "scripts" / "slurm_array.py";
        say(fmt::format("slurm: {} runs as one job array, {} cpu(s) per task", cases.size(), base.slurm_cpus_per_task));
        const pid_t pid = spawn({"/usr/bin/python3", script.string(), tasks_file.string()}, o.output_dir / "slurm.txt");
        int status = 0;
        while (waitpid(pid, &status, 0) < 0) {
            if (errno != EINTR) throw RunError(fmt::format("waitpid failed: {}", std::strerror(errno)));
            if (stop_requested()) kill(pid, SIGTERM); // cancels the job array
        }
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
            throw RunError(fmt::format("the Slurm submission failed (see {})", (o.output_dir / "slurm.txt").string()));
        for (std::size_t k = 0; k < cases.size(); ++k) {
            rows[k] = read_study_row(cases[k], o.output_dir / "runs" / cases[k].name, -1);
            const StudyRow& r = rows[k];
            say(r.status == "completed"
                    ? fmt::format("[{}/{}] {} completed: thickness {:.3f} um, density {:.4f} g/cm3, porosity {:.4f}",
                                  k + 1, cases.size(), r.c.name, *r.thickness_um, r.density_g_cm3.value_or(NAN),
                                  r.porosity.value_or(NAN))
                    : fmt::format("[{}/{}] {} FAILED: {}", k + 1, cases.size(), r.c.name, r.error));
        }
        finished = next = cases.size();
    }
    while (finished < cases.size()) {
        while (!stopping && running.size() < std::size_t(jobs) && next < cases.size()) start_case(next++);
        if (running.empty()) break;
        int status = 0;
        const pid_t pid = waitpid(-1, &status, 0);
        if (pid < 0) {
            if (errno == EINTR) {
                if (stop_requested() && !stopping) {
                    stopping = true; // let the running cases stop themselves and write what they have
                    say("stop requested: no further runs are started; waiting for the running ones");
                    for (const auto& [p, k] : running) kill(p, SIGTERM);
                }
                continue;
            }
            throw RunError(fmt::format("waitpid failed: {}", std::strerror(errno)));
        }
        const auto it = running.find(pid);
        if (it == running.end()) continue;
        const std::size_t k = it->second;
        running.erase(it);
        ++finished;
        const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        rows[k] = read_study_row(cases[k], o.output_dir / "runs" / cases[k].name, code);
        const StudyRow& r = rows[k];
        say(r.status == "completed"
                ? fmt::format("[{}/{}] {} completed: thickness {:.3f} um, density {:.4f} g/cm3, "
                              "porosity {:.4f} ({:.0f} s)",
                              finished, cases.size(), r.c.name, *r.thickness_um,
                              r.density_g_cm3.value_or(NAN), r.porosity.value_or(NAN), r.wall_time_s)
                : fmt::format("[{}/{}] {} FAILED (exit {}): {}", finished, cases.size(), r.c.name,
                              code, r.error));
        write_study_results(o.output_dir, base, rows); // a partial table survives a killed study
    }
    for (std::size_t k = next; k < cases.size(); ++k)
        rows[k] = StudyRow{cases[k], "not started", "the study was stopped", {}, {}, {}, {}, 0.0, {}, {}, {}, {}, {}, {}};
    write_study_results(o.output_dir, base, rows);
    for (const auto& s : study_statistics(rows))
        say(fmt::format("{:7.2f} mg/cm2: {} ok, {} failed; thickness {:.3f} +- {:.3f} um, density "
                        "{:.4f} +- {:.4f} g/cm3, porosity {:.4f} +- {:.4f}",
                        s.areal_loading_mg_cm2, s.completed, s.failed, s.thickness_mean_um,
                        s.thickness_std_um, s.density_mean_g_cm3, s.density_std_g_cm3,
                        s.porosity_mean, s.porosity_std));
    if (o.plots) {
        const fs::path script = fs::path(DRYDEM_SOURCE_DIR) / "scripts" / "plot_study.py";
        const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}' >> '{}' 2>&1", script.string(),
                                            o.output_dir.string(), (o.output_dir / "log.txt").string());
        if (!fs::exists("/usr/bin/python3") || std::system(cmd.c_str()) != 0)
            say("plotting failed (see log.txt)");
    }
    const auto failed = std::count_if(rows.begin(), rows.end(), [](const StudyRow& r) { return r.status != "completed"; });
    say(fmt::format("study done in {:.0f} s: {} of {} runs completed; study.csv, study.json{} in {}",
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                    rows.size() - std::size_t(failed), rows.size(), o.plots ? ", plots/" : "",
                    o.output_dir.string()));
    return failed == 0 ? 0 : 1;
}

} // namespace drydem::app
