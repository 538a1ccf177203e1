// SPDX-License-Identifier: MIT
// The two texts written from io/config_keys.def: the embedded default configuration (the paper's
// 20.1 mg/cm2 case in the full 75 x 75 um box; what `drydem run` without a config runs) and the
// key reference docs/configuration.md. A unit test parses the first back into Config{} bit for
// bit and compares the second with the file in docs/.
#include "drydem/io/config.hpp"
#include "drydem/io/config_schema.hpp"
#include "drydem/io/units.hpp"
#include <fmt/format.h>
#include <cmath>
#include <string>
#include <variant>

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
        if (line.size() < kCommentColumn)
            line.resize(kCommentColumn, ' ');
        else
            line += "  ";
        out += fmt::format("{}# {}\n", line, rest.substr(0, nl));
        if (nl == std::string_view::npos) return;
        rest = rest.substr(nl + 1);
        line.clear();
    }
}

std::string write_default_toml() {
    std::string out = "# DryDEM configuration: the paper's 20.1 mg/cm2 case (Lippke et al., Energy "
                      "Technol. 2022).\n"
                      "# Values are SI numbers or strings with units (\"6.5 um\", \"20.1 "
                      "mg/cm^2\", \"1.801 Pa*s\", "
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

/// Markdown table cell: one line, '|' and the HTML brackets escaped ("out/<name>" is no tag).
std::string cell(std::string_view text) {
    std::string out;
    for (char ch : text) {
        if (ch == '\n')
            out += ' ';
        else if (ch == '|')
            out += "\\|";
        else if (ch == '<')
            out += "&lt;";
        else if (ch == '>')
            out += "&gt;";
        else
            out += ch;
    }
    return out;
}

/// What a key allows, in SI, as the errors of load_config state it.
std::string allowed_text(const Field& f) {
    const config_schema::Allowed& a = f.allowed;
    const auto interval = [&] {
        return fmt::format("{}{:g}, {:g}{}", a.lo_open ? "(" : "[", a.lo, a.hi,
                           std::isinf(a.hi) ? ")" : "]");
    };
    return std::visit(
        [&](auto member) -> std::string {
            using T = std::remove_cvref_t<decltype(Config{}.*member)>;
            if constexpr (std::is_same_v<T, bool>) {
                return "true, false";
            } else if constexpr (std::is_same_v<T, std::optional<bool>>) {
                return "true, false, `\"auto\"`";
            } else if constexpr (std::is_same_v<T, std::string>) {
                std::string list;
                for (std::string_view ch : f.choices())
                    list += fmt::format("{}`\"{}\"`", list.empty() ? "" : ", ", ch);
                return list.empty() ? "a string" : list;
            } else if constexpr (std::is_same_v<T, std::vector<double>>) {
                return fmt::format("a list{}, each in {}", a.may_be_empty ? " (may be empty)" : "",
                                   interval());
            } else if constexpr (std::is_same_v<T, double>) {
                return interval();
            } else {
                return "integer in " + interval();
            }
        },
        f.member);
}

} // namespace

std::string_view default_config_toml() {
    static const std::string text = write_default_toml();
    return text;
}

std::string config_reference_markdown() {
    std::string out =
        "# Configuration keys\n\n"
        "<!-- Written by `drydem config doc` from src/drydem/io/config_keys.def; a test compares "
        "the two.\n"
        "     Regenerate: build/drydem config doc > docs/configuration.md -->\n\n"
        "A configuration is a TOML file; a key it leaves out keeps the default below (the paper's\n"
        "20.1 mg/cm² case, which `drydem config default` prints as a file and `drydem run` runs\n"
        "without one). Values are SI numbers or strings with units (`\"6.5 um\"`, `\"20.1 "
        "mg/cm^2\"`,\n"
        "`\"1.801 Pa*s\"`, `\"40 deg\"`, `\"80 degC\"`); *allowed* is in the SI unit of its row.\n"
        "Unknown keys, wrong units and values outside *allowed* are refused, naming the key. The\n"
        "calibration's parameters and targets (`[[calibration.parameters]]`,\n"
        "`[[calibration.targets]]`) are described in docs/calibration.md.\n";
    const auto& s = config_schema::schema();
    for (const Row& r : s.rows) {
        if (r.kind == Row::section) {
            out += fmt::format("\n## [{}]\n\n", r.text);
            if (!r.comment.empty()) out += cell(r.comment) + "\n\n";
            out += "| key | default | SI unit | allowed | meaning |\n|---|---|---|---|---|\n";
        } else if (r.kind == Row::key) {
            const Field& f = s.fields[r.field];
            const std::string_view unit = si_unit(f.dim);
            out += fmt::format("| `{}` | `{}` | {} | {} | {} |\n", f.key, cell(f.default_text),
                               unit.empty() ? "" : fmt::format("`{}`", unit), allowed_text(f),
                               cell(f.doc));
        }
    }
    return out;
}

} // namespace drydem
