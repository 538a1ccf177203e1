// SPDX-License-Identifier: MIT
#include "drydem/io/config_schema.hpp"
#include <algorithm>

namespace drydem::config_schema {

std::vector<std::string_view> Field::choices() const {
    std::vector<std::string_view> out;
    for (std::string_view rest = allowed.choices; !rest.empty();) {
        const auto bar = rest.find('|');
        out.push_back(rest.substr(0, bar));
        rest = bar == std::string_view::npos ? std::string_view{} : rest.substr(bar + 1);
    }
    return out;
}

const Schema& schema() {
    static const Schema s = [] {
        Schema t;
        const auto section = [&t](std::string_view name, std::string_view comment) {
            t.rows.push_back({Row::section, name, comment});
        };
        const auto note = [&t](std::string_view text) { t.rows.push_back({Row::note, text, {}}); };
        const auto key = [&t](Field f) {
            t.rows.push_back({Row::key, f.key, {}, t.fields.size()});
            t.fields.push_back(f);
        };
#define DRYDEM_SECTION(name, comment) section(#name, comment);
#define DRYDEM_NOTE(text) note(text);
#define DRYDEM_KEY(key_, Type, member, default_si, default_text, dimension, allowed, doc)          \
    key(Field{key_, &Config::member, Dimension::dimension, allowed, default_text, doc});
#include "drydem/io/config_keys.def"
#undef DRYDEM_KEY
#undef DRYDEM_NOTE
#undef DRYDEM_SECTION
        return t;
    }();
    return s;
}

const Field* find(std::string_view key) {
    const auto& fields = schema().fields;
    const auto it =
        std::find_if(fields.begin(), fields.end(), [&](const Field& f) { return f.key == key; });
    return it == fields.end() ? nullptr : &*it;
}

} // namespace drydem::config_schema
