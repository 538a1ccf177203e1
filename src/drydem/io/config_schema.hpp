// SPDX-License-Identifier: MIT
// The configuration's schema, expanded from io/config_keys.def: per key its Config member, unit,
// allowed values, default text and meaning, and the order of sections and notes the default text
// and the key reference are written in. Used by the parser (io/config.cpp) and the writers of the
// default text and docs/configuration.md (io/default_config.cpp); not outside io/.
#pragma once
#include "drydem/io/config.hpp"
#include "drydem/io/units.hpp"
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace drydem::config_schema {

inline constexpr double inf = std::numeric_limits<double>::infinity();
inline constexpr double max_density = 1e5; ///< [kg/m^3], 4x the densest element

/// What a key accepts besides its unit: a range in SI, or a list of strings.
struct Allowed {
    double lo = -inf, hi = inf;
    bool lo_open = false;      ///< value must be > lo (else >= lo)
    std::string_view choices;  ///< allowed strings, separated by '|'; empty = any string
    bool may_be_empty = false; ///< lists: [] allowed

    /// A list that may also be empty ([]).
    [[nodiscard]] constexpr Allowed or_empty() const {
        Allowed a = *this;
        a.may_be_empty = true;
        return a;
    }
};
/// Any value of the key's type.
constexpr Allowed any() { return {}; }
/// lo <= value <= hi.
constexpr Allowed closed(double lo, double hi) { return {lo, hi, false, {}, false}; }
/// lo < value <= hi.
constexpr Allowed above(double lo, double hi) { return {lo, hi, true, {}, false}; }
/// One of the strings in `choices` ("a|b").
constexpr Allowed one_of(std::string_view choices) { return {-inf, inf, false, choices, false}; }

/// The C++ type of each kind of key. std::optional<bool>: true, false or "auto" (nullopt: the
/// setting follows from other keys; Config's accessor says how).
using Member = std::variant<double Config::*, int Config::*, std::uint64_t Config::*,
                            bool Config::*, std::optional<bool> Config::*, std::string Config::*,
                            std::vector<double> Config::*>;

/// One key of the configuration.
struct Field {
    std::string_view key; ///< "section.name"
    Member member;
    Dimension dim = Dimension::dimensionless;
    Allowed allowed;
    std::string_view default_text; ///< the default as TOML text, with its unit
    std::string_view doc;          ///< meaning; '\n' breaks the comment of the default text

    [[nodiscard]] std::string_view section() const { return key.substr(0, key.find('.')); }
    [[nodiscard]] std::string_view name() const { return key.substr(key.find('.') + 1); }
    /// The allowed strings of a choice key (empty for any string or a number).
    [[nodiscard]] std::vector<std::string_view> choices() const;
};

/// A row of io/config_keys.def in its order: a section header, a free comment line, or a key.
struct Row {
    enum Kind { section, note, key } kind;
    std::string_view text;    ///< section name, or the note's text
    std::string_view comment; ///< the section's comment
    std::size_t field = 0;    ///< index into Schema::fields (key rows)
};

struct Schema {
    std::vector<Field> fields;
    std::vector<Row> rows;
};

/// The schema of io/config_keys.def (built once).
const Schema& schema();

/// The field of `key`, or nullptr.
const Field* find(std::string_view key);

} // namespace drydem::config_schema
