// SPDX-License-Identifier: MIT
#include "drydem/output/python_script.hpp"
#include "drydem/io/install_paths.hpp"
#include <cerrno>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

extern char** environ;

namespace drydem {

ScriptRun run_python_script(const std::string& script, const std::vector<std::string>& args,
                            const std::filesystem::path& log) {
    namespace fs = std::filesystem;
    const std::string python = "/usr/bin/python3";
    const fs::path dir = data_dir();
    const fs::path file = dir / "scripts" / script;
    if (dir.empty() || !fs::exists(python) || !fs::exists(file)) return ScriptRun::unavailable;
    std::vector<std::string> words{python, file.string()};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    const std::string log_name = log.string();
    if (!log.empty()) {
        posix_spawn_file_actions_addopen(&actions, 1, log_name.c_str(),
                                         O_WRONLY | O_CREAT | O_APPEND, 0644);
        posix_spawn_file_actions_adddup2(&actions, 1, 2);
    }
    pid_t pid = 0;
    const int err = posix_spawn(&pid, python.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (err != 0) return ScriptRun::failed;
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return ScriptRun::failed;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? ScriptRun::ok : ScriptRun::failed;
}

} // namespace drydem
