// SPDX-License-Identifier: MIT
// Config parsing: the schema (io/config_keys.def) maps every TOML key to a Config member, its
// physical dimension and what it allows; units are converted here and nowhere else.
#include "drydem/io/config.hpp"
#include "drydem/core/error.hpp"
#include "drydem/io/config_schema.hpp"
#include "drydem/io/units.hpp"
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <tuple>
#include <variant>

namespace drydem {
namespace {

using config_schema::Field;
using config_schema::max_density;
using D = Dimension;

const std::vector<Field>& schema() { return config_schema::schema().fields; }

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

std::string nearest_key(std::string_view key) {
    std::string_view best;
    std::size_t best_d = SIZE_MAX;
    for (const Field& f : schema()) {
        const std::size_t d = edit_distance(key, f.key);
        if (d < best_d) {
            best_d = d;
            best = f.key;
        }
    }
    return std::string(best);
}

std::string node_text(const toml::node& n) {
    std::ostringstream s;
    if (auto str = n.as_string())
        s << '"' << str->get() << '"';
    else
        n.visit([&](auto&& v) { s << v; });
    // Error messages only: a 60,000-character value is cut to its two ends.
    std::string t = s.str();
    if (t.size() > 120)
        t = fmt::format("{}...{} ({} characters)", t.substr(0, 60), t.substr(t.size() - 30),
                        t.size());
    return t;
}

double read_number(const toml::node& n, const Field& f) {
    if (auto v = n.as_floating_point()) return v->get();
    if (auto v = n.as_integer()) return double(v->get());
    if (auto v = n.as_string()) return parse_quantity(v->get(), f.dim, f.key);
    throw InputError(fmt::format("config key '{}': {} is not a number or a quantity with a unit",
                                 f.key, node_text(n)));
}

void check_range(const Field& f, double v, const std::string& text) {
    const config_schema::Allowed& a = f.allowed;
    const bool low = a.lo_open ? !(v > a.lo) : !(v >= a.lo);
    if (!std::isfinite(v) || low || !(v <= a.hi))
        throw InputError(fmt::format("config key '{}': {} is out of range; allowed {}{:g}, {:g}] "
                                     "(SI units, {})",
                                     f.key, text, a.lo_open ? "(" : "[", a.lo, a.hi,
                                     dimension_name(f.dim)));
}

/// Well-formed UTF-8 (RFC 3629: no overlong forms, surrogates or code points above U+10FFFF).
bool valid_utf8(std::string_view s) {
    for (std::size_t i = 0; i < s.size();) {
        const auto b = static_cast<unsigned char>(s[i]);
        const int n = b < 0x80           ? 0
                      : (b >> 5) == 0x6  ? 1
                      : (b >> 4) == 0xe  ? 2
                      : (b >> 3) == 0x1e ? 3
                                         : -1;
        if (n < 0 || i + std::size_t(n) >= s.size()) return false;
        char32_t cp = n == 0 ? b : b & (0x3f >> n);
        for (int k = 1; k <= n; ++k) {
            const auto cont = static_cast<unsigned char>(s[i + std::size_t(k)]);
            if ((cont >> 6) != 0x2) return false;
            cp = (cp << 6) | (cont & 0x3f);
        }
        constexpr char32_t least[] = {0, 0x80, 0x800, 0x10000};
        if (cp < least[n] || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) return false;
        i += std::size_t(n) + 1;
    }
    return true;
}

/// run.name names the default output folder (out/<name>-<time>) and the study's run folders, and
/// is written back into config.toml: one line of valid UTF-8 without a path separator ('/').
void check_name(const Field& f, const std::string& v, const std::string& text) {
    const bool control = std::any_of(v.begin(), v.end(), [](char ch) {
        return static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f;
    });
    if (v.empty() || v.size() > 200 || control || v.find('/') != std::string::npos || v == "." ||
        v == ".." || !valid_utf8(v))
        throw InputError(
            fmt::format("config key '{}': {} is not allowed; allowed: 1 to 200 characters of "
                        "UTF-8 without control characters (newline, tab) or '/', "
                        "not \".\" or \"..\" (it names the output folder)",
                        f.key, text));
}

void assign(Config& c, const Field& f, const toml::node& n,
            std::vector<std::string>& bare_lengths) {
    const std::string text = node_text(n);
    std::visit(
        [&](auto member) {
            using T = std::remove_cvref_t<decltype(c.*member)>;
            if constexpr (std::is_same_v<T, double>) {
                const double v = read_number(n, f);
                check_range(f, v, text);
                c.*member = v;
                if (f.dim == D::length && !n.is_string()) bare_lengths.emplace_back(f.key);
            } else if constexpr (std::is_same_v<T, int> || std::is_same_v<T, std::uint64_t>) {
                auto v = n.as_integer();
                if (!v)
                    throw InputError(
                        fmt::format("config key '{}': {} must be an integer", f.key, text));
                check_range(f, double(v->get()), text);
                c.*member = T(v->get());
            } else if constexpr (std::is_same_v<T, bool>) {
                auto v = n.as_boolean();
                if (!v)
                    throw InputError(
                        fmt::format("config key '{}': {} must be true or false", f.key, text));
                c.*member = v->get();
            } else if constexpr (std::is_same_v<T, std::optional<bool>>) {
                if (auto b = n.as_boolean())
                    c.*member = b->get();
                else if (auto s = n.as_string(); s && s->get() == "auto")
                    c.*member = std::nullopt;
                else
                    throw InputError(fmt::format(
                        "config key '{}': {} must be true, false or \"auto\"", f.key, text));
            } else if constexpr (std::is_same_v<T, std::string>) {
                auto v = n.as_string();
                if (!v)
                    throw InputError(
                        fmt::format("config key '{}': {} must be a string", f.key, text));
                const std::vector<std::string_view> choices = f.choices();
                if (!choices.empty() &&
                    std::find(choices.begin(), choices.end(), v->get()) == choices.end()) {
                    std::string allowed;
                    for (auto ch : choices)
                        allowed += fmt::format("{}\"{}\"", allowed.empty() ? "" : ", ", ch);
                    throw InputError(fmt::format("config key '{}': {} is not allowed; allowed: {}",
                                                 f.key, text, allowed));
                }
                if (f.key == "run.name") check_name(f, v->get(), text);
                c.*member = v->get();
            } else {
                auto arr = n.as_array();
                if (!arr || (arr->empty() && !f.allowed.may_be_empty))
                    throw InputError(
                        fmt::format("config key '{}': {} must be a non-empty array", f.key, text));
                T values;
                for (const toml::node& e : *arr) {
                    const double v = read_number(e, f);
                    check_range(f, v, node_text(e));
                    values.push_back(v);
                }
                c.*member = values;
            }
        },
        f.member);
}

/// The array-of-tables keys of [calibration]: each entry a table with exactly the keys listed.
const toml::table& calibration_entry(const toml::node& e, const std::string& label,
                                     std::initializer_list<std::string_view> allowed,
                                     std::initializer_list<std::string_view> required) {
    const toml::table* t = e.as_table();
    if (!t)
        throw InputError(fmt::format(
            "config key '{}': {} must be a table with keys {} (e.g. "
            "[[calibration.parameters]] key = \"contact.friction\" min = 0.4 max = 1.2)",
            label, node_text(e), fmt::join(allowed, ", ")));
    for (const auto& [k, v] : *t)
        if (std::find(allowed.begin(), allowed.end(), k.str()) == allowed.end())
            throw InputError(
                fmt::format("unknown config key '{}.{}' (value {}); allowed in this table: {}",
                            label, k.str(), node_text(v), fmt::join(allowed, ", ")));
    for (std::string_view r : required)
        if (!t->contains(r))
            throw InputError(fmt::format("config key '{}': missing '{}' (a table needs {})", label,
                                         r, fmt::join(required, ", ")));
    return *t;
}

/// [[calibration.parameters]]: key (a numeric config key), min, max (in that key's unit and range),
/// scale ("linear" | "log").
void parse_calibration_parameters(const toml::node& n, Config& c) {
    const toml::array* arr = n.as_array();
    if (!arr)
        throw InputError(
            fmt::format("config key 'calibration.parameters': {} must be an array of tables "
                        "([[calibration.parameters]])",
                        node_text(n)));
    c.calibration_parameters.clear();
    for (std::size_t i = 0; i < arr->size(); ++i) {
        const std::string label = fmt::format("calibration.parameters[{}]", i + 1);
        const toml::table& t = calibration_entry((*arr)[i], label, {"key", "min", "max", "scale"},
                                                 {"key", "min", "max"});
        const auto key = t["key"].value<std::string>();
        if (!key)
            throw InputError(
                fmt::format("config key '{}.key': {} must be a string naming a config key", label,
                            node_text(*t.get("key"))));
        const auto& fields = schema();
        auto it = std::find_if(fields.begin(), fields.end(),
                               [&](const Field& f) { return f.key == *key; });
        if (it == fields.end())
            throw InputError(
                fmt::format("config key '{}.key': \"{}\" is not a config key; did you mean '{}'? "
                            "(`drydem config default` lists every key)",
                            label, *key, nearest_key(*key)));
        if (!std::holds_alternative<double Config::*>(it->member) ||
            key->starts_with("calibration.") || key->starts_with("scheduler.") ||
            key->starts_with("study.") || key->starts_with("output."))
            throw InputError(
                fmt::format("config key '{}.key': \"{}\" cannot be calibrated; allowed: a single "
                            "numeric key of the model (not an integer, string, list, or a "
                            "[study], [output], [scheduler] or [calibration] key)",
                            label, *key));
        for (const CalibrationParameter& p : c.calibration_parameters)
            if (p.key == *key)
                throw InputError(
                    fmt::format("config key '{}.key': \"{}\" is already a calibration parameter; "
                                "allowed: each key once",
                                label, *key));
        CalibrationParameter p;
        p.key = *key;
        double bounds[2];
        int k = 0;
        for (const char* which : {"min", "max"}) {
            const std::string bl = fmt::format("{}.{} ({})", label, which, *key);
            Field g = *it;
            g.key = bl;
            bounds[k] = read_number(*t.get(which), g);
            check_range(g, bounds[k], node_text(*t.get(which)));
            ++k;
        }
        p.min = bounds[0];
        p.max = bounds[1];
        if (!(p.min < p.max))
            throw InputError(
                fmt::format("config key '{}': min {} is not below max {}; allowed: min < max",
                            label, node_text(*t.get("min")), node_text(*t.get("max"))));
        if (t.contains("scale")) {
            const auto scale = t["scale"].value<std::string>();
            if (!scale || (*scale != "linear" && *scale != "log"))
                throw InputError(fmt::format(
                    "config key '{}.scale': {} is not allowed; allowed: \"linear\", \"log\"", label,
                    node_text(*t.get("scale"))));
            p.log = *scale == "log";
            if (p.log && !(p.min > 0.0))
                throw InputError(
                    fmt::format("config key '{}.min': {} with scale = \"log\"; allowed: > 0", label,
                                node_text(*t.get("min"))));
        }
        c.calibration_parameters.push_back(p);
    }
}

/// The names of the calibration quantities, quoted, for messages; only the points of curves (the
/// ones that take `at`) with `curves_only`.
std::string quoted_quantities(bool curves_only) {
    std::string names;
    for (const auto& q : calibration_quantities())
        if (q.curve || !curves_only)
            names += fmt::format("{}\"{}\"", names.empty() ? "" : ", ", q.name);
    return names;
}

/// [[calibration.targets]]: quantity (calibration_quantities()), value, uncertainty (with units),
/// and for a point of a curve its process time `at`.
void parse_calibration_targets(const toml::node& n, Config& c) {
    const toml::array* arr = n.as_array();
    if (!arr)
        throw InputError(
            fmt::format("config key 'calibration.targets': {} must be an array of tables "
                        "([[calibration.targets]])",
                        node_text(n)));
    c.calibration_targets.clear();
    for (std::size_t i = 0; i < arr->size(); ++i) {
        const std::string label = fmt::format("calibration.targets[{}]", i + 1);
        const toml::table& t =
            calibration_entry((*arr)[i], label, {"quantity", "value", "uncertainty", "at"},
                              {"quantity", "value", "uncertainty"});
        const auto name = t["quantity"].value<std::string>();
        const auto& qs = calibration_quantities();
        auto q = std::find_if(qs.begin(), qs.end(), [&](const CalibrationQuantity& x) {
            return name && x.name == *name;
        });
        if (q == qs.end())
            throw InputError(fmt::format("config key '{}.quantity': {} is not allowed; allowed: {}",
                                         label, node_text(*t.get("quantity")),
                                         quoted_quantities(false)));
        CalibrationTarget target;
        target.quantity = *name;
        for (const char* which : {"value", "uncertainty"}) {
            const std::string bl = fmt::format("{}.{} ({})", label, which, *name);
            Field g{bl,
                    &Config::time_step,
                    Dimension(q->dimension),
                    config_schema::above(which[0] == 'v' ? q->lo : 0.0,
                                         which[0] == 'v' ? q->hi : q->hi - q->lo),
                    {},
                    {}};
            const toml::node& v = *t.get(which);
            const double x = read_number(v, g);
            if (g.dim == D::length && !v.is_string() && x > 1e-3)
                throw InputError(
                    fmt::format("config key '{}': {} is {:g} m; did you mean \"{} um\"?", bl,
                                node_text(v), x, node_text(v)));
            check_range(g, x, node_text(v));
            (which[0] == 'v' ? target.value : target.uncertainty) = x;
        }
        if (q->curve && !t.contains("at"))
            throw InputError(
                fmt::format("config key '{}': missing 'at' (\"{}\" is a point of a curve: give its "
                            "process time, e.g. at = \"40 s\")",
                            label, *name));
        if (t.contains("at")) {
            if (!q->curve)
                throw InputError(
                    fmt::format("config key '{}.at': {} is not allowed for \"{}\", a result of the "
                                "whole run; allowed only for a point of a curve ({})",
                                label, node_text(*t.get("at")), *name, quoted_quantities(true)));
            const std::string bl = fmt::format("{}.at ({})", label, *name);
            Field g{bl, &Config::time_step, D::time, config_schema::above(0.0, 1e6), {}, {}};
            target.at = read_number(*t.get("at"), g);
            check_range(g, target.at, node_text(*t.get("at")));
        }
        c.calibration_targets.push_back(target);
    }
}

void walk(const toml::table& t, const std::string& prefix, Config& c,
          std::vector<std::string>& bare_lengths) {
    for (const auto& [k, node] : t) {
        const std::string key =
            prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
        if (auto sub = node.as_table()) {
            walk(*sub, key, c, bare_lengths);
            continue;
        }
        if (key == "calibration.parameters") {
            parse_calibration_parameters(node, c);
            continue;
        }
        if (key == "calibration.targets") {
            parse_calibration_targets(node, c);
            continue;
        }
        const auto& fields = schema();
        auto it = std::find_if(fields.begin(), fields.end(),
                               [&](const Field& f) { return f.key == key; });
        if (it == fields.end())
            throw InputError(fmt::format("unknown config key '{}' (value {}); did you mean '{}'? "
                                         "(`drydem config default` lists every key)",
                                         key, node_text(node), nearest_key(key)));
        assign(c, *it, node, bare_lengths);
    }
}

void apply_override(toml::table& root, const std::string& spec) {
    const auto eq = spec.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError(
            fmt::format("--set '{}': expected KEY=VALUE, e.g. --set run.seed=7", spec));
    const std::string key = spec.substr(0, eq), value = spec.substr(eq + 1);
    toml::table* t = &root;
    std::size_t start = 0;
    for (std::size_t dot; (dot = key.find('.', start)) != std::string::npos; start = dot + 1) {
        const std::string part = key.substr(start, dot - start);
        if (!t->contains(part)) t->insert(part, toml::table{});
        t = (*t)[part].as_table();
        if (!t) throw InputError(fmt::format("--set '{}': '{}' is not a table", spec, part));
    }
    const std::string leaf = key.substr(start);
    // The value is TOML when it parses as such (numbers, booleans, arrays, quoted strings),
    // otherwise a bare string such as 6.5um.
    std::optional<toml::table> parsed;
    try {
        parsed = toml::parse("v = " + value);
    } catch (const toml::parse_error&) {
        t->insert_or_assign(leaf, value);
        return;
    }
    // "1\nfoo=2" parses as two keys: the value must be exactly one TOML value, never more keys.
    if (parsed->size() != 1)
        throw InputError(
            fmt::format("--set '{}': the value defines further keys; give one value per --set "
                        "(no newlines)",
                        spec));
    t->insert_or_assign(leaf, *parsed->get("v"));
}

/// Cross-key rules of the [scaling] section: under "force_ratio" the capillary and Hamaker factors
/// follow from k/b (docs/model.md M-7), so a value of the paper scheme's own is refused, not ignored.
void check_scaling(const Config& c) {
    if (c.scaling_scheme != "force_ratio") return;
    for (const auto& [key, value] : {std::pair{"scaling.capillary_factor", c.capillary_factor},
                                     std::pair{"scaling.hamaker_factor", c.hamaker_factor}})
        if (value != 0.0)
            throw InputError(fmt::format("config key '{}': {:g} is not allowed with scaling.scheme "
                                         "= \"force_ratio\", which scales "
                                         "every conservative force by time_factor / "
                                         "viscosity_reduction = {:g}; allowed: 0 (remove the "
                                         "key), or scaling.scheme = \"paper\"",
                                         key, value, c.time_factor / c.viscosity_reduction));
}

/// Cross-key rules of the [dryer] section (per-key ranges are in the schema).
void check_dryer(const Config& c) {
    const std::size_t n = c.dryer_zone_lengths.size();
    if (c.dryer_air_temperatures.size() != n || c.dryer_heat_transfer_coefficients.size() != n)
        throw InputError(fmt::format(
            "config keys 'dryer.zone_lengths' ({} zones), 'dryer.air_temperatures' ({} values) and "
            "'dryer.heat_transfer_coefficients' ({} values) must have one entry per dryer zone",
            n, c.dryer_air_temperatures.size(), c.dryer_heat_transfer_coefficients.size()));
    for (std::size_t k = 0; k < n; ++k)
        if (c.dryer_air_temperatures[k] < c.dryer_initial_temperature)
            throw InputError(fmt::format(
                "config key 'dryer.air_temperatures': {:g} K ({:g} degC) in zone {} is below the "
                "film's "
                "initial temperature dryer.initial_film_temperature = {:g} K; allowed >= {:g} K",
                c.dryer_air_temperatures[k], c.dryer_air_temperatures[k] - 273.15, k + 1,
                c.dryer_initial_temperature, c.dryer_initial_temperature));
    if (c.dryer_schedule == "model")
        for (std::size_t k = 0; k < n; ++k)
            if (std::abs(c.dryer_zone_lengths[k] - c.zone_length) > 1e-9 * c.zone_length)
                throw InputError(fmt::format(
                    "config key 'dryer.zone_lengths': zone {} is {:g} m but the DEM liquid-level "
                    "schedule uses equal zones of dryer.zone_length = {:g} m; with dryer.schedule "
                    "= "
                    "\"model\" every entry must equal dryer.zone_length",
                    k + 1, c.dryer_zone_lengths[k], c.zone_length));
}

} // namespace

const std::vector<CalibrationQuantity>& calibration_quantities() {
    constexpr int L = int(Dimension::length), R = int(Dimension::density),
                  N = int(Dimension::dimensionless), T = int(Dimension::time);
    static const std::vector<CalibrationQuantity> q = {
        {"final_thickness", L, "final_thickness_um", 1e-6, "um", 0.0, 1e-2},
        {"final_thickness_relaxed", L, "final_thickness_relaxed_um", 1e-6, "um", 0.0, 1e-2},
        {"thickness_half_solid", L, "thickness_half_solid_um", 1e-6, "um", 0.0, 1e-2},
        {"density", R, "density_g_cm3", 1e3, "g/cm^3", 0.0, max_density},
        {"porosity", N, "porosity", 1.0, "", 0.0, 1.0},
        {"cb_binder_porosity_eq2", N, "cb_binder_porosity_eq2", 1.0, "", 0.0, 1.0},
        {"process_time_final", T, "process_time_final_s", 1.0, "s", 0.0, 1e6},
        {"psd_peak", L, "psd_peak_um", 1e-6, "um", 0.0, 1e-3},
        {"coordination_mean", N, "coordination_mean", 1.0, "", 0.0, 100.0},
        // Fig. 5: the top of the highest particle at a process time (a measured drying curve)
        {"film_thickness", L, "film_thickness_um", 1e-6, "um", 0.0, 1e-2, true},
    };
    return q;
}

std::string calibration_target_name(const CalibrationTarget& t) {
    return t.at < 0.0 ? t.quantity : fmt::format("{}_at_{:g}s", t.quantity, t.at);
}

ParsedConfig parse_config(std::string_view toml_text, std::string_view source_name,
                          const std::vector<std::string>& overrides) {
    toml::table root;
    try {
        root = toml::parse(toml_text, source_name);
    } catch (const toml::parse_error& e) {
        throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", source_name,
                                     e.source().begin.line, e.source().begin.column,
                                     e.description()));
    }
    for (const std::string& o : overrides) apply_override(root, o);
    ParsedConfig parsed;
    Config& c = parsed.config;
    walk(root, "", c, parsed.bare_lengths);
    const double mass_sum = c.ncm_mass_fraction + c.pvdf_mass_fraction + c.cb_mass_fraction;
    if (std::abs(mass_sum - 1.0) > 1e-6)
        throw InputError(fmt::format("config keys 'formulation.*_mass_fraction': NCM + PVDF + CB = "
                                     "{:g}, must sum to 1",
                                     mass_sum));
    const std::size_t n_measured = c.measured_loadings.size();
    for (const auto& [key, values, optional] :
         {std::tuple{"study.measured_thickness", &c.measured_thickness, false},
          std::tuple{"study.measured_thickness_std", &c.measured_thickness_std, true},
          std::tuple{"study.measured_density", &c.measured_density, true},
          std::tuple{"study.measured_density_std", &c.measured_density_std, true}})
        if (values->size() != n_measured && !(optional && values->empty()))
            throw InputError(
                fmt::format("config key '{}': {} values for {} study.measured_loadings; "
                            "allowed: one per measured loading{}",
                            key, values->size(), n_measured, optional ? " or none" : ""));
    check_dryer(c);
    check_scaling(c);
    if (c.calibration_initial_points > c.calibration_evaluations)
        throw InputError(fmt::format("config key 'calibration.initial_points': {} is more than "
                                     "calibration.evaluations = {}; allowed 0..{}",
                                     c.calibration_initial_points, c.calibration_evaluations,
                                     c.calibration_evaluations));
    // sbatch --partition: a partition name (letters, digits, '_', '-', '.', ',' for a list).
    if (c.slurm_partition.find_first_not_of(
            "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.,") !=
        std::string::npos)
        throw InputError(
            fmt::format("config key 'scheduler.partition': \"{}\" is not allowed; allowed: a "
                        "partition name of letters, digits, '_', '-', '.' (',' between names)",
                        c.slurm_partition));
    return parsed;
}

std::string read_config_text(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError(fmt::format("cannot read config file '{}'", path));
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string to_toml(const Config& c) {
    // Through the TOML library, so that any string (quotes, backslashes, non-ASCII) is escaped
    // and reads back; doubles are written with the shortest digits that read back bit-exact.
    toml::table root;
    for (const Field& f : schema()) {
        const auto dot = f.key.find('.');
        const std::string tab(f.key.substr(0, dot)), leaf(f.key.substr(dot + 1));
        if (!root.contains(tab)) root.insert(tab, toml::table{});
        toml::table& t = *root[tab].as_table();
        std::visit(
            [&](auto member) {
                using T = std::remove_cvref_t<decltype(c.*member)>;
                const T& v = c.*member;
                if constexpr (std::is_same_v<T, std::vector<double>>) {
                    toml::array a;
                    for (double x : v) a.push_back(x);
                    t.insert(leaf, std::move(a));
                } else if constexpr (std::is_same_v<T, std::uint64_t> || std::is_same_v<T, int>) {
                    t.insert(leaf,
                             std::int64_t(v)); // TOML integers are 64-bit signed (seed <= 2^63 - 1)
                } else if constexpr (std::is_same_v<T, std::optional<bool>>) {
                    if (v)
                        t.insert(leaf, *v);
                    else
                        t.insert(leaf, "auto");
                } else {
                    t.insert(leaf, v);
                }
            },
            f.member);
    }
    std::ostringstream out;
    out << "# Resolved DryDEM configuration, every value in SI units.\n"
        << toml::toml_formatter(root, toml::format_flags::allow_unicode_strings) << "\n";
    return out.str();
}

} // namespace drydem
