// SPDX-License-Identifier: MIT
#include "drydem/drying/run_state.hpp"
#include "drydem/core/error.hpp"
#include "drydem/git_hash.hpp"
#include <fmt/format.h>
#include <stdexcept>

namespace drydem {
namespace {
std::string this_build() { return fmt::format("DryDEM {} ({})", DRYDEM_VERSION, DRYDEM_GIT_HASH); }
} // namespace

StateFields::StateFields(BinaryReader& r, std::string source)
    : loading_(true), source_(std::move(source)) {
    const auto format = r.pod<std::uint32_t>();
    written_by_ = r.str();
    if (format != kFormat)
        mismatch(fmt::format("its run progress has format {}, this build reads format {}", format,
                             kFormat));
    const auto n = r.pod<std::uint64_t>();
    for (std::uint64_t i = 0; i < n; ++i) {
        std::string name = r.str();
        fields_[std::move(name)] = r.vec<unsigned char>();
    }
}

void StateFields::write(BinaryWriter& w) const {
    w.pod(kFormat);
    w.str(this_build());
    w.pod(std::uint64_t(fields_.size()));
    for (const auto& [name, bytes] : fields_) {
        w.str(name);
        w.vec(bytes);
    }
}

void StateFields::store(std::string_view name, std::vector<unsigned char> bytes) {
    // Two parts claiming one name is a programming error, caught by every checkpoint test.
    if (!fields_.emplace(std::string(name), std::move(bytes)).second)
        throw std::logic_error(fmt::format("run progress field '{}' saved twice", name));
}

const std::vector<unsigned char>& StateFields::find(std::string_view name, std::size_t size) {
    const auto it = fields_.find(name);
    if (it == fields_.end()) mismatch(fmt::format("it has no run progress field '{}'", name));
    if (it->second.size() != size)
        mismatch(fmt::format("its run progress field '{}' has {} bytes, this build expects {}",
                             name, it->second.size(), size));
    loaded_.emplace(name);
    return it->second;
}

const std::vector<unsigned char>& StateFields::find_multiple(std::string_view name,
                                                             std::size_t element) {
    const auto it = fields_.find(name);
    if (it == fields_.end()) mismatch(fmt::format("it has no run progress field '{}'", name));
    if (it->second.size() % element != 0)
        mismatch(fmt::format("its run progress field '{}' has {} bytes, this build expects a "
                             "multiple of {}",
                             name, it->second.size(), element));
    loaded_.emplace(name);
    return it->second;
}

void StateFields::operator()(std::string_view name, std::string& text) {
    std::vector<char> chars(text.begin(), text.end());
    (*this)(name, chars);
    if (loading_) text.assign(chars.begin(), chars.end());
}

void StateFields::check_all_loaded() const {
    for (const auto& [name, bytes] : fields_)
        if (!loaded_.contains(name))
            mismatch(fmt::format("its run progress field '{}' is unknown to this build", name));
}

void StateFields::mismatch(const std::string& what) const {
    throw InputError(fmt::format("{}: the checkpoint was written by {} and {}; this build is {}. "
                                 "Resume it with the build that wrote it, or start the run again",
                                 source_, written_by_, what, this_build()));
}

} // namespace drydem
