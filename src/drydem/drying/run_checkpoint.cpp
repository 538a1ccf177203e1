// SPDX-License-Identifier: MIT
#include "drydem/drying/run_checkpoint.hpp"
#include "drydem/core/error.hpp"
#include "drydem/drying/drying_run.hpp"
#include "drydem/output/checkpoint.hpp"
#include <fmt/format.h>

namespace drydem {

std::filesystem::path checkpoint_file(const std::filesystem::path& output_dir) {
    return output_dir / "checkpoint" / "state.bin";
}

RunCheckpoint read_run_checkpoint(const std::filesystem::path& output_dir) {
    const auto file = checkpoint_file(output_dir);
    const std::vector<unsigned char> bytes = read_checkpoint_file(file);
    BinaryReader r(bytes, file.string());
    std::string config_toml = r.str();
    StateFields progress(r, file.string());
    EngineState engine = read_engine_state(r);
    if (!r.at_end())
        throw InputError(fmt::format("{}: unexpected data after the state", file.string()));
    return {std::move(config_toml), std::move(progress), std::move(engine)};
}

void write_run_checkpoint(const std::filesystem::path& output_dir, const std::string& config_toml,
                          const std::function<void(StateFields&)>& visit_state,
                          const EngineState& engine) {
    StateFields progress;
    visit_state(progress);
    BinaryWriter w;
    w.str(config_toml);
    progress.write(w);
    write_engine_state(w, engine);
    std::filesystem::create_directories(checkpoint_file(output_dir).parent_path());
    write_checkpoint_file(checkpoint_file(output_dir), w);
}

void truncate_to_checkpoint(const std::filesystem::path& file, std::uint64_t size) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) {
        if (size == 0) return;
        throw InputError(fmt::format("--resume: {} is missing", file.string()));
    }
    if (std::filesystem::file_size(file) < size)
        throw InputError(
            fmt::format("--resume: {} is shorter than at the checkpoint", file.string()));
    std::filesystem::resize_file(file, size, ec);
    if (ec) throw RunError(fmt::format("cannot truncate {}: {}", file.string(), ec.message()));
}

} // namespace drydem
