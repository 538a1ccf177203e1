// SPDX-License-Identifier: MIT
// Checkpoints (README "Outputs", `checkpoint/`): a versioned little binary format holding the engine's
// complete state (particles in storage order, neighbor list with contact histories, step, time,
// liquid level, Δt), the drying run's own progress (a versioned list of named fields,
// drying/run_state.hpp), the seed and the resolved config. Doubles are
// stored as their bytes, so a resumed run continues bit for bit. The file ends with its size and
// an FNV-1a checksum and is written atomically (temporary file + rename): a run killed while
// writing leaves the previous checkpoint intact, and a damaged file is refused with a clear error.
#pragma once
#include "drydem/engine/simulation.hpp"
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <type_traits>
#include <vector>

namespace drydem {

/// Appends plain values and vectors of them to a byte buffer.
class BinaryWriter {
public:
    template <class T>
    void pod(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        append(&v, sizeof(T));
    }
    template <class T>
    void vec(const std::vector<T>& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        pod(std::uint64_t(v.size()));
        append(v.data(), v.size() * sizeof(T));
    }
    void str(const std::string& s) {
        pod(std::uint64_t(s.size()));
        append(s.data(), s.size());
    }
    [[nodiscard]] const std::vector<unsigned char>& bytes() const { return bytes_; }

private:
    // resize + memcpy rather than vector::insert of a byte range: GCC 12 warns falsely
    // (-Wstringop-overflow) on the inlined insert into an empty vector.
    void append(const void* data, std::size_t n) {
        if (n == 0) return;
        const std::size_t at = bytes_.size();
        bytes_.resize(at + n);
        std::memcpy(bytes_.data() + at, data, n);
    }
    std::vector<unsigned char> bytes_;
};

/// Reads what BinaryWriter wrote; throws InputError (naming `source`) when the data run out.
class BinaryReader {
public:
    BinaryReader(const std::vector<unsigned char>& bytes, std::string source)
        : bytes_(bytes), source_(std::move(source)) {}
    template <class T>
    T pod() {
        static_assert(std::is_trivially_copyable_v<T>);
        T v;
        std::memcpy(&v, take(sizeof(T)), sizeof(T));
        return v;
    }
    template <class T>
    std::vector<T> vec() {
        const auto n = pod<std::uint64_t>();
        if (n > (bytes_.size() - pos_) / sizeof(T)) truncated();
        std::vector<T> v(n);
        if (n) std::memcpy(v.data(), take(n * sizeof(T)), n * sizeof(T));
        return v;
    }
    std::string str() {
        const auto n = pod<std::uint64_t>();
        if (n > bytes_.size() - pos_) truncated();
        const auto* b = reinterpret_cast<const char*>(take(n));
        return {b, b + n};
    }
    [[nodiscard]] bool at_end() const { return pos_ == bytes_.size(); }

private:
    const unsigned char* take(std::size_t n) {
        if (n > bytes_.size() - pos_) truncated();
        const unsigned char* p = bytes_.data() + pos_;
        pos_ += n;
        return p;
    }
    [[noreturn]] void truncated() const;
    const std::vector<unsigned char>& bytes_;
    std::string source_;
    std::size_t pos_ = 0;
};

/// The pair and body laws this build composes ("pair name:state size;... body ..."), written
/// ahead of the engine state: a checkpoint of another composition is refused.
[[nodiscard]] std::string law_layout_text();
void write_engine_state(BinaryWriter& w, const EngineState& s);
[[nodiscard]] EngineState read_engine_state(BinaryReader& r);

/// Writes payload with header (magic, format version) and trailer (size, checksum), atomically.
void write_checkpoint_file(const std::filesystem::path& file, const BinaryWriter& payload);
/// Reads and verifies a checkpoint file; returns its payload. InputError when the file is missing,
/// not a DryDEM checkpoint, of another format version, truncated or damaged.
[[nodiscard]] std::vector<unsigned char> read_checkpoint_file(const std::filesystem::path& file);

} // namespace drydem
