// SPDX-License-Identifier: MIT
#include "drydem/io/install_paths.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
#include <cstdlib>
#include <string>
#include <system_error>
#include <vector>

namespace drydem {
namespace {

std::vector<std::filesystem::path> candidates() {
    namespace fs = std::filesystem;
    std::vector<fs::path> out;
    if (const char* env = std::getenv("DRYDEM_DATA_DIR"); env && *env) out.emplace_back(env);
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        out.push_back(exe.parent_path() / "share" / "drydem");
        out.push_back(exe.parent_path().parent_path() / "share" / "drydem");
    }
    return out;
}

} // namespace

std::filesystem::path data_dir() {
    std::error_code ec;
    for (const auto& d : candidates())
        if (std::filesystem::is_directory(d / "scripts", ec)) return d;
    return {};
}

std::filesystem::path script_path(std::string_view name) {
    const std::filesystem::path dir = data_dir();
    if (!dir.empty()) return dir / "scripts" / std::string(name);
    std::string tried;
    for (const auto& d : candidates()) tried += (tried.empty() ? "" : ", ") + d.string();
    throw InputError(fmt::format("cannot find DryDEM's scripts (looked in {}/scripts): set "
                                 "DRYDEM_DATA_DIR to the folder that holds scripts/, or reinstall",
                                 tried.empty() ? std::string("nothing") : tried));
}

} // namespace drydem
