// SPDX-License-Identifier: MIT
// `drydem calibrate`: checks the [calibration] section, prepares the output folder (config.toml,
// calibration.json) and hands over to the search driver scripts/calibrate.py, which runs every
// evaluation as `drydem run` processes (locally or as Slurm job arrays) and keeps DIR/ledger.json
// (docs/calibration.md). The process is replaced by the driver (execv), so that a signal to it
// reaches the driver, and the folder's lock stays held until the driver ends.
#include "drydem/app/commands.hpp"
#include "drydem/core/error.hpp"
#include "drydem/io/install_paths.hpp"
#include "drydem/io/particle_io.hpp"
#include "drydem/study/calibration.hpp"
#include <fmt/format.h>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

namespace drydem::app {
namespace {

std::string read_text(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// The first line where two texts differ, for the message of a resume with another config.
std::string first_difference(const std::string& a, const std::string& b) {
    std::istringstream sa(a), sb(b);
    std::string la, lb;
    while (true) {
        const bool ga = bool(std::getline(sa, la)), gb = bool(std::getline(sb, lb));
        if (!ga && !gb) return "";
        if (!ga || !gb || la != lb)
            return fmt::format("stored '{}', now '{}'", ga ? la : "", gb ? lb : "");
    }
}

/// True when `now` has the parameters of `before` (same keys, order and scales), each range
/// containing the old one: a calibration whose best fit sat at a bound may continue wider.
bool bounds_widened(const nlohmann::json& before, const nlohmann::json& now) {
    if (before.size() != now.size()) return false;
    for (std::size_t i = 0; i < before.size(); ++i) {
        const auto &b = before[i], &n = now[i];
        if (b["key"] != n["key"] || b["log"] != n["log"]) return false;
        if (n["min"].get<double>() > b["min"].get<double>() ||
            n["max"].get<double>() < b["max"].get<double>())
            return false;
    }
    return true;
}

} // namespace

/// One calibration per folder: an exclusive lock on DIR/.drydem.lock holding the pid. The lock is
/// held by this process and, through execv, by the driver (no FD_CLOEXEC).
static void lock_folder(const std::filesystem::path& dir) {
    const std::string lock_path = (dir / ".drydem.lock").string();
    const int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT, 0644);
    if (fd < 0) throw RunError(fmt::format("cannot open {}: {}", lock_path, std::strerror(errno)));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        const std::string holder = read_text(lock_path);
        throw InputError(fmt::format(
            "-o {}: another calibration is running in this folder (process {}); allowed: "
            "one at a time",
            dir.string(), holder.empty() ? "?" : holder));
    }
    if (::ftruncate(fd, 0) == 0) {
        const std::string pid = std::to_string(::getpid());
        if (::write(fd, pid.data(), pid.size()) < 0) { /* the pid is only for the message above */
        }
    }
}

int run_calibrate(const Config& c, const CalibrateOptions& o) {
    namespace fs = std::filesystem;
    for (const std::string& w : check_calibration(c)) fmt::print(stderr, "warning: {}\n", w);
    const fs::path dir = o.output_dir;
    const fs::path spec_file = dir / "calibration.json", config_file = dir / "config.toml";
    nlohmann::json spec = calibration_spec(c, self_executable());
    const std::string config_text = to_toml(c);
    if (o.resume) {
        if (!fs::exists(spec_file) || !fs::exists(dir / "ledger.json"))
            throw InputError(fmt::format(
                "--resume: {} holds no calibration (no calibration.json and ledger.json); "
                "start one without --resume",
                dir.string()));
        // The same calibration, only the budget may grow and a bound widen: a changed parameter,
        // target or run config would mix evaluations of two problems in one ledger, while every
        // finished evaluation still lies inside widened bounds.
        nlohmann::json stored = nlohmann::json::parse(read_text(spec_file));
        for (const char* k :
             {"parameters", "targets", "seeds", "initial_points", "sampler", "base_seed"})
            if (stored[k] != spec[k] &&
                !(std::string_view(k) == "parameters" && bounds_widened(stored[k], spec[k])))
                throw InputError(fmt::format(
                    "--resume: the config's calibration.{} ({}) differs from the one of the "
                    "calibration in {} ({}); allowed: the same calibration, only "
                    "calibration.evaluations and [scheduler] may change and a parameter's "
                    "min/max widen",
                    k, spec[k].dump(), dir.string(), stored[k].dump()));
        // The runs' config: identical but for the keys a resume may change.
        auto strip = [](const std::string& text) {
            std::istringstream in(text);
            std::string line, out, section;
            while (std::getline(in, line)) {
                if (!line.empty() && line[0] == '[') section = line;
                if (section == "[scheduler]" ||
                    (section == "[calibration]" && line.starts_with("evaluations")) ||
                    (section == "[run]" && line.starts_with("threads")))
                    continue;
                out += line + "\n";
            }
            return out;
        };
        const std::string stored_config = read_text(config_file);
        if (strip(stored_config) != strip(config_text))
            throw InputError(fmt::format(
                "--resume: the run configuration differs from the calibration's {} ({}); "
                "allowed: the same configuration (only calibration.evaluations, "
                "[scheduler] and run.threads may change)",
                config_file.string(), first_difference(strip(stored_config), strip(config_text))));
    } else if (fs::exists(dir) && !fs::is_empty(dir)) {
        if (fs::exists(spec_file))
            throw InputError(fmt::format(
                "-o {}: holds a calibration already; `drydem calibrate CONFIG -o {} --resume` "
                "continues it, or give a new folder",
                dir.string(), dir.string()));
        throw InputError(
            fmt::format("-o {}: not empty and holds no calibration; allowed: a new or empty folder",
                        dir.string()));
    }
    fs::create_directories(dir);
    lock_folder(dir);
    write_file_atomically(config_file, [&](std::ostream& os) { os << config_text; });
    write_file_atomically(spec_file, [&](std::ostream& os) { os << spec.dump(2) << "\n"; });

    const fs::path script = script_path("calibrate.py");
    if (!fs::exists("/usr/bin/python3") || !fs::exists(script))
        throw RunError(
            fmt::format("drydem calibrate needs /usr/bin/python3 and {} (scripts/install_deps.sh)",
                        script.string()));
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    const int threads = o.threads > 0 ? o.threads : std::max(1, cores / std::max(1, o.jobs));
    std::vector<std::string> args = {"/usr/bin/python3",
                                     script.string(),
                                     dir.string(),
                                     "--jobs",
                                     std::to_string(std::max(1, o.jobs)),
                                     "--threads",
                                     std::to_string(threads)};
    if (!o.plots) args.push_back("--no-plots");
    if (o.quiet) args.push_back("--quiet");
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::fflush(nullptr);
    ::execv(argv[0], argv.data());
    throw RunError(fmt::format("cannot start {}: {}", args[0], std::strerror(errno)));
}

} // namespace drydem::app
