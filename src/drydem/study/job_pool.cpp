// SPDX-License-Identifier: MIT
#include "drydem/study/job_pool.hpp"
#include "drydem/core/error.hpp"
#include "drydem/core/stop_request.hpp"
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <array>
#include <csignal>
#include <cstring>
#include <fstream>
#include <map>

extern char** environ;

namespace drydem {

bool resumable_stop_reason(std::string_view reason) {
    constexpr std::array<std::string_view, 2> resumable{"interrupted", "stop_after_steps"};
    return std::find(resumable.begin(), resumable.end(), reason) != resumable.end();
}

RunFolder run_folder_state(const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    const bool checkpoint = fs::exists(dir / "checkpoint" / "state.bin");
    if (std::ifstream in(dir / "summary.json"); in) {
        nlohmann::json s;
        try {
            s = nlohmann::json::parse(in);
        } catch (const std::exception&) {
            s = nlohmann::json::object();
        }
        const std::string status = s.value("status", ""), reason = s.value("stop_reason", "");
        if (status == "completed") return RunFolder::completed;
        if (resumable_stop_reason(reason) && checkpoint) return RunFolder::stopped;
        if (status == "failed") return RunFolder::failed;
    }
    if (checkpoint) return RunFolder::stopped; // killed without warning: resumes
    if (fs::exists(dir / "config.toml")) return RunFolder::partial;
    return RunFolder::fresh;
}

std::string_view to_string(RunFolder s) {
    switch (s) {
    case RunFolder::fresh:
        return "new";
    case RunFolder::partial:
        return "partial";
    case RunFolder::stopped:
        return "stopped";
    case RunFolder::failed:
        return "failed";
    case RunFolder::completed:
        return "completed";
    }
    return "?";
}

pid_t spawn_process(const std::vector<std::string>& args,
                    const std::filesystem::path& console_log) {
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

void install_stop_handlers() {
    struct sigaction sa {};
    sa.sa_handler = [](int sig) { request_stop(sig); };
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0;
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
}

namespace {

/// The command that brings task t to its end from the state `s` of its folder.
std::vector<std::string> command_for(const std::string& exe, const PoolTask& t, RunFolder s,
                                     const PoolOptions& o) {
    std::vector<std::string> cmd{exe};
    if (s == RunFolder::stopped) {
        cmd.insert(cmd.end(), {"run", "--resume", t.dir.string()});
    } else {
        cmd.insert(cmd.end(), t.args.begin(), t.args.end());
        if (s == RunFolder::partial) cmd.push_back("--overwrite");
    }
    cmd.insert(cmd.end(), {"--threads", std::to_string(o.threads), "--quiet"});
    if (!o.plots) cmd.push_back("--no-plots");
    return cmd;
}

} // namespace

std::size_t run_job_pool(const std::string& exe, const std::vector<PoolTask>& tasks,
                         const PoolOptions& o, const std::function<void(const std::string&)>& say,
                         const std::function<void(std::size_t, int)>& done) {
    std::map<pid_t, std::size_t> running;
    std::size_t next = 0;
    bool stopping = false;
    auto start = [&](std::size_t k) {
        const PoolTask& t = tasks[k];
        const RunFolder s = run_folder_state(t.dir);
        if (s == RunFolder::completed || s == RunFolder::failed) {
            done(k, -1);
            return;
        }
        std::filesystem::create_directories(t.dir);
        running[spawn_process(command_for(exe, t, s, o), t.dir / "console.txt")] = k;
        say(fmt::format("{} {}", s == RunFolder::stopped ? "resumed" : "started", t.label));
    };
    while (true) {
        while (!stopping && running.size() < std::size_t(std::max(1, o.jobs)) &&
               next < tasks.size())
            start(next++);
        if (running.empty()) break;
        int status = 0;
        const pid_t pid = waitpid(-1, &status, 0);
        if (pid < 0) {
            if (errno != EINTR)
                throw RunError(fmt::format("waitpid failed: {}", std::strerror(errno)));
            if (stop_requested() && !stopping) {
                stopping = true;
                say("stop requested: no further runs are started; waiting for the running ones");
                for (const auto& [p, k] : running) kill(p, SIGTERM);
            }
            continue;
        }
        const auto it = running.find(pid);
        if (it == running.end()) continue;
        const std::size_t k = it->second;
        running.erase(it);
        done(k, WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status));
    }
    return tasks.size() - next;
}

int run_pool_command(const std::string& exe, const std::filesystem::path& tasks_file,
                     const PoolOptions& o, bool quiet) {
    std::ifstream in(tasks_file);
    if (!in) throw InputError(fmt::format("drydem pool: cannot read {}", tasks_file.string()));
    nlohmann::json spec;
    try {
        spec = nlohmann::json::parse(in);
    } catch (const std::exception& e) {
        throw InputError(
            fmt::format("drydem pool: {} is not JSON: {}", tasks_file.string(), e.what()));
    }
    if (!spec.contains("tasks") || !spec["tasks"].is_array())
        throw InputError(
            fmt::format("drydem pool: {} has no \"tasks\" array", tasks_file.string()));
    std::vector<PoolTask> tasks;
    for (const auto& t : spec["tasks"]) {
        if (!t.is_object() || !t.contains("dir") || !t["dir"].is_string() || !t.contains("args") ||
            !t["args"].is_array() || t["args"].empty() || t["args"][0] != "run")
            throw InputError(fmt::format("drydem pool: task {} of {} needs \"dir\" (a folder) and "
                                         "\"args\" (the drydem run arguments, starting with "
                                         "\"run\")",
                                         tasks.size() + 1, tasks_file.string()));
        PoolTask p{t["dir"].get<std::string>(), t["args"].get<std::vector<std::string>>(), ""};
        p.label = p.dir.filename().string();
        tasks.push_back(std::move(p));
    }
    install_stop_handlers();
    auto say = [&](const std::string& line) {
        if (!quiet) fmt::print(stderr, "{}\n", line);
    };
    std::size_t completed = 0, ended = 0;
    run_job_pool(exe, tasks, o, say, [&](std::size_t k, int code) {
        const RunFolder s = run_folder_state(tasks[k].dir);
        completed += s == RunFolder::completed;
        say(fmt::format("[{}/{}] {} {}{}", ++ended, tasks.size(), tasks[k].label, to_string(s),
                        code >= 0 ? fmt::format(" (exit {})", code) : std::string(" (earlier)")));
    });
    return completed == tasks.size() ? 0 : 1;
}

} // namespace drydem
