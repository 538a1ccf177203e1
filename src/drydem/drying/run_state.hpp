// SPDX-License-Identifier: MIT
// The drying run's own progress in a checkpoint, beside the engine state: what a resumed run needs
// to continue its end criterion, guard, diagnostics and outputs exactly where the checkpoint was
// taken. Each part of the run (the end criterion, the stability guard, each output) declares its
// fields in one function, `void fields(StateFields&)`, used both to save and to load them, so the
// two cannot drift apart.
//
// On disk the fields are a versioned list of named values: the format number, the DryDEM build
// that wrote it, then (name, size, bytes) per field. Loading looks each field up by name and
// checks its size; a field missing, of another size or not claimed by any part is refused with
// an error that names the field and both builds, never read as the wrong value.
#pragma once
#include "drydem/output/checkpoint.hpp"
#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace drydem {

class StateFields {
public:
    /// Format of the field list; raise it when a field changes meaning (not only when one is added
    /// or removed: those are caught by name).
    static constexpr std::uint32_t kFormat = 1;

    /// An empty list to save into.
    StateFields() = default;
    /// The list stored in a checkpoint, to load from. InputError if it is of another format.
    StateFields(BinaryReader& r, std::string source);

    /// Saves `value` under `name` (saving), or sets `value` from the stored field (loading).
    template <class T>
    void operator()(std::string_view name, T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        if (!loading_) {
            std::vector<unsigned char> bytes(sizeof(T));
            std::memcpy(bytes.data(), &value, sizeof(T));
            store(name, std::move(bytes));
        } else {
            const std::vector<unsigned char>& bytes = find(name, sizeof(T));
            std::memcpy(&value, bytes.data(), sizeof(T));
        }
    }

    /// The same for a vector of plain values (its length stored with it).
    template <class T>
    void operator()(std::string_view name, std::vector<T>& values) {
        static_assert(std::is_trivially_copyable_v<T>);
        if (!loading_) {
            std::vector<unsigned char> bytes(values.size() * sizeof(T));
            if (!values.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
            store(name, std::move(bytes));
        } else {
            const std::vector<unsigned char>& bytes = find_multiple(name, sizeof(T));
            values.resize(bytes.size() / sizeof(T));
            if (!values.empty()) std::memcpy(values.data(), bytes.data(), bytes.size());
        }
    }
    /// The same for a text.
    void operator()(std::string_view name, std::string& text);

    [[nodiscard]] bool loading() const { return loading_; }
    /// Whether the stored list has a field `name` (loading): which kind of run wrote it.
    [[nodiscard]] bool has(std::string_view name) const { return fields_.contains(name); }
    /// Writes the list (saving).
    void write(BinaryWriter& w) const;
    /// After loading: InputError if a stored field was not claimed by any part of this build.
    void check_all_loaded() const;

private:
    void store(std::string_view name, std::vector<unsigned char> bytes);
    const std::vector<unsigned char>& find(std::string_view name, std::size_t size);
    /// A field whose size is a multiple of `element` bytes.
    const std::vector<unsigned char>& find_multiple(std::string_view name, std::size_t element);
    [[noreturn]] void mismatch(const std::string& what) const;

    bool loading_ = false;
    std::string source_, written_by_;
    std::map<std::string, std::vector<unsigned char>, std::less<>> fields_;
    std::set<std::string, std::less<>> loaded_;
};

} // namespace drydem
