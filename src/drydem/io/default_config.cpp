// SPDX-License-Identifier: MIT
// The embedded default configuration, written from io/config_keys.def: the paper's 20.1 mg/cm2
// case in the full 75 x 75 um box (what `drydem run` without a config runs). A unit test parses
// it back into Config{} bit for bit.
#include "drydem/io/config.hpp"
#include "drydem/io/config_schema.hpp"
#include <fmt/format.h>
#include <string>

namespace drydem {
namespace {

using config_schema::Field;
using config_schema::Row;

/// The column of the comments in the default text, as in the hand-written files of examples/.
constexpr std::size_t kCommentColumn = 33;

/// `line` with `comment` beside it; each further line of the comment ('\n') on a line of its own,
/// in the same column.
void append_commented(std::string& out, std::string line, std::string_view comment) {
    if (comment.empty()) {
        out += line + "\n";
        return;
    }
    for (std::string_view rest = comment;;) {
        const auto nl = rest.find('\n');
        if (line.size() < kCommentColumn) line.resize(kCommentColumn, ' ');
        else line += "  ";
        out += fmt::format("{}# {}\n", line, rest.substr(0, nl));
        if (nl == std::string_view::npos) return;
        rest = rest.substr(nl + 1);
        line.clear();
    }
}

std::string write_default_toml() {
    std::string out =
        "# DryDEM configuration: the paper's 20.1 mg/cm2 case (Lippke et al., Energy Technol. 2022).\n"
        "# Values are SI numbers or strings with units (\"6.5 um\", \"20.1 mg/cm^2\", \"1.801 Pa*s\", "
        "\"40 deg\").\n";
    const auto& s = config_schema::schema();
    for (const Row& r : s.rows) {
        if (r.kind == Row::section) {
            out += "\n";
            append_commented(out, fmt::format("[{}]", r.text), r.comment);
        } else if (r.kind == Row::note) {
            out += fmt::format("# {}\n", r.text);
        } else {
            const Field& f = s.fields[r.field];
            append_commented(out, fmt::format("{} = {}", f.name(), f.default_text), f.doc);
        }
    }
    return out;
}

} // namespace

std::string_view default_config_toml() {
    static const std::string text = write_default_toml();
    return text;
}

} // namespace drydem
