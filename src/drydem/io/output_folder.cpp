// SPDX-License-Identifier: MIT
#include "drydem/io/output_folder.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sys/file.h>
#include <unistd.h>
#include <vector>

namespace drydem {

namespace fs = std::filesystem;

namespace {

/// An entry `kind` wrote: a known output, a coupled run's iter_N folder, or an atomic write's .tmp.
bool is_own_output(const OutputKind& kind, const std::string& name) {
    if (std::find(kind.names.begin(), kind.names.end(), name) != kind.names.end()) return true;
    if (kind.numbered_iterations && name.starts_with("iter_") && name.size() > 5 &&
        name.find_first_not_of("0123456789", 5) == std::string::npos)
        return true;
    return name.ends_with(".tmp") && is_own_output(kind, name.substr(0, name.size() - 4));
}

bool present(const fs::path& p) {
    std::error_code ec;
    return fs::exists(p, ec);
}

std::string listing(const std::vector<std::string>& names) {
    std::string out;
    for (std::size_t k = 0; k < names.size() && k < 5; ++k)
        out += fmt::format("{}{}", k ? ", " : "", names[k]);
    if (names.size() > 5) out += fmt::format(" and {} more", names.size() - 5);
    return out;
}

} // namespace

const OutputKind& run_output() {
    // A run's log beside its config, or a coupled run's coupling.json; a study's folder (which
    // has the first two as well) is not a run's.
    static const OutputKind k{
        "run",
        {"config.toml", "log.txt", "summary.json", "timeseries.csv", "initial.csv", "final.csv",
         "snapshots", "checkpoint", "analysis", "plots", "coupling.json"},
        true,
        [](const fs::path& d) {
            return present(d / "log.txt") &&
                   (present(d / "config.toml") || present(d / "coupling.json")) &&
                   !present(d / "runs");
        },
        "continue that run with `drydem run --resume {dir}`, "};
    return k;
}

const OutputKind& study_output() {
    // Its log and resolved config are written before the first case starts.
    static const OutputKind k{
        "study",
        {"config.toml", "log.txt", "runs", "study.csv", "study.json", "plots"},
        false,
        [](const fs::path& d) { return present(d / "runs") && present(d / "log.txt"); },
        ""};
    return k;
}

const OutputKind& dryer_output() {
    static const OutputKind k{
        "dryer model run",
        {"dryer.json", "dryer.csv", "plots"},
        false,
        [](const fs::path& d) { return present(d / "dryer.json") || present(d / "dryer.csv"); },
        ""};
    return k;
}

const OutputKind& analysis_output() {
    static const OutputKind k{
        "analysis",
        {"analysis.json", "profiles.csv", "transport_convergence.csv", "binder_profile.csv",
         "psd_chord.csv", "psd_local_thickness.csv", "structure.raw", "structure.json",
         "structure.mhd", "structure.tif", "plots"},
        false,
        [](const fs::path& d) {
            return present(d / "analysis.json") || present(d / "profiles.csv");
        },
        ""};
    return k;
}

const OutputKind& calender_output() {
    static const OutputKind k{"calendering run",
                              {"config.toml", "log.txt", "summary.json", "compaction.csv",
                               "final.csv", "particle_bonds.csv", "snapshots", "analysis", "plots",
                               "checkpoint"},
                              false,
                              [](const fs::path& d) { return present(d / "compaction.csv"); },
                              ""};
    return k;
}

void prepare_output_folder(const fs::path& dir, const OutputKind& kind, bool overwrite) {
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw InputError(fmt::format("output folder {}: exists and is not a folder", dir.string()));
    fs::create_directories(dir, ec);
    if (ec)
        throw InputError(
            fmt::format("output folder {}: cannot create it: {}", dir.string(), ec.message()));
    std::vector<std::string> ours, foreign;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        // The lock, and the console capture a study opens before it starts the run here.
        if (name == output_lock_name || name == "console.txt") continue;
        (is_own_output(kind, name) ? ours : foreign).push_back(name);
    }
    if (ours.empty() && foreign.empty()) return;
    std::sort(ours.begin(), ours.end());
    std::sort(foreign.begin(), foreign.end());
    if (!kind.holds(dir))
        throw InputError(fmt::format("output folder {} is not empty ({}) and holds no DryDEM {}; "
                                     "choose a new or empty folder "
                                     "with -o (it is not cleared, not even with --overwrite)",
                                     dir.string(), listing(foreign.empty() ? ours : foreign),
                                     kind.noun));
    if (!overwrite)
        throw InputError(fmt::format(
            "output folder {} holds a previous {} ({}); choose another folder with -o, {}or "
            "replace its "
            "outputs with --overwrite",
            dir.string(), kind.noun, listing(ours),
            fmt::format(fmt::runtime(kind.resume_hint), fmt::arg("dir", dir.string()))));
    // --overwrite: remove what the old output was made of (old frames would mix with the new
    // ones); the user's own files stay.
    for (const std::string& name : ours) {
        fs::remove_all(dir / name, ec);
        if (ec)
            throw InputError(fmt::format("--overwrite: cannot remove {}: {}", (dir / name).string(),
                                         ec.message()));
    }
}

OutputLock::OutputLock(const fs::path& dir) {
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw InputError(fmt::format("output folder {}: exists and is not a folder", dir.string()));
    fs::create_directories(dir, ec);
    if (ec)
        throw InputError(
            fmt::format("output folder {}: cannot create it: {}", dir.string(), ec.message()));
    const fs::path file = dir / output_lock_name;
    fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
        throw InputError(fmt::format("output folder {}: cannot create the lock file {}: {}",
                                     dir.string(), file.string(), std::strerror(errno)));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        std::string holder;
        std::ifstream(file) >> holder;
        ::close(fd_);
        fd_ = -1;
        throw InputError(
            fmt::format("output folder {} is in use by another drydem run{}; two runs cannot "
                        "write into one folder (choose another -o)",
                        dir.string(), holder.empty() ? "" : fmt::format(" (process {})", holder)));
    }
    // Who holds it, for the message above; the lock itself is the flock, not this text.
    const std::string pid = fmt::format("{}\n", ::getpid());
    if (::ftruncate(fd_, 0) != 0 || ::write(fd_, pid.data(), pid.size()) < 0) {
        // Only the message of a second run loses the process id; the lock holds.
    }
}

OutputLock::~OutputLock() {
    if (fd_ >= 0) ::close(fd_); // releases the flock
}

} // namespace drydem
