// SPDX-License-Identifier: MIT
#include "drydem/io/units.hpp"
#include "drydem/core/error.hpp"
#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <cstdlib>

namespace drydem {

namespace {

// Exponents of the base quantities: metre, kilogram, second, kelvin, radian, ampere. The radian is
// kept as a base so that angles and plain numbers cannot be confused.
using Dims = std::array<int, 6>;
constexpr Dims kNone{0, 0, 0, 0, 0, 0};

// A unit's SI factor is kept as num/den * 10^pow10 rather than one double: the decimal part is
// applied by shifting the exponent of the number *text* ("6.5 um" → "6.5e-6"), so results equal
// the correctly rounded literal (parse_quantity("20.1 mg/cm^2") == 0.201 exactly); num and den are
// small integers or pi, so multiplying them stays exact.
struct Unit {
    double num = 1.0, den = 1.0;
    int pow10 = 0;
    Dims dims = kNone;
    bool celsius = false; ///< affine, only valid alone
};

struct Symbol {
    std::string_view name;
    Unit unit;
    bool prefixable;
};

constexpr Dims L{1, 0, 0, 0, 0}, M{0, 1, 0, 0, 0}, T{0, 0, 1, 0, 0}, K{0, 0, 0, 1, 0},
    A{0, 0, 0, 0, 1}, PRESSURE{-1, 1, -2, 0, 0}, ENERGY{2, 1, -2, 0, 0};

const std::array kSymbols{
    Symbol{"m", {1, 1, 0, L}, true},
    Symbol{"g", {1, 1, -3, M}, true},
    Symbol{"s", {1, 1, 0, T}, true},
    Symbol{"min", {60, 1, 0, T}, false},
    Symbol{"h", {3600, 1, 0, T}, false},
    Symbol{"K", {1, 1, 0, K}, false},
    Symbol{"degC", {1, 1, 0, K, true}, false},
    Symbol{"°C", {1, 1, 0, K, true}, false},
    Symbol{"rad", {1, 1, 0, A}, false},
    Symbol{"deg", {std::numbers::pi, 180, 0, A}, false},
    Symbol{"°", {std::numbers::pi, 180, 0, A}, false},
    Symbol{"Hz", {1, 1, 0, {0, 0, -1, 0, 0}}, true},
    Symbol{"N", {1, 1, 0, {1, 1, -2, 0, 0}}, true},
    Symbol{"Pa", {1, 1, 0, PRESSURE}, true},
    Symbol{"bar", {1, 1, 5, PRESSURE}, true},
    Symbol{"P", {1, 1, -1, {-1, 1, -1, 0, 0}}, true}, // poise, for "cP"
    Symbol{"J", {1, 1, 0, ENERGY}, true},
    Symbol{"eV", {1.602176634, 1, -19, ENERGY}, false},
    Symbol{"W", {1, 1, 0, {2, 1, -3, 0, 0}}, true},
    Symbol{"V", {1, 1, 0, {2, 1, -3, 0, 0, -1}}, true},
    Symbol{"S", {1, 1, 0, {-2, -1, 3, 0, 0, 2}}, true}, // siemens = A/V
    Symbol{"L", {1, 1, -3, {3, 0, 0, 0, 0}}, true},
    Symbol{"%", {1, 1, -2, kNone}, false},
};

struct Prefix {
    std::string_view name;
    int pow10;
};
const std::array kPrefixes{Prefix{"f", -15}, Prefix{"p", -12}, Prefix{"n", -9}, Prefix{"u", -6},
                           Prefix{"µ", -6},  Prefix{"μ", -6},  Prefix{"m", -3}, Prefix{"c", -2},
                           Prefix{"k", 3},   Prefix{"M", 6},   Prefix{"G", 9},  Prefix{"T", 12}};

constexpr std::array<Dims, 21> kExpected{{
    kNone,                // dimensionless
    L,                    // length
    T,                    // time
    M,                    // mass
    {1, 0, -1, 0, 0},     // velocity
    {1, 0, -2, 0, 0},     // acceleration
    {-3, 1, 0, 0, 0},     // density
    PRESSURE,             // pressure
    {-1, 1, -1, 0, 0},    // viscosity
    {0, 1, -2, 0, 0},     // surface tension
    ENERGY,               // energy
    {1, 1, -2, 0, 0},     // force
    {-2, 1, 0, 0, 0},     // areal density
    K,                    // temperature
    A,                    // angle
    {0, 0, -1, 0, 0},     // frequency
    {0, 1, -3, -1, 0},    // heat transfer coefficient
    {2, 0, -2, -1, 0},    // specific heat
    {2, 1, -3, 0, 0, -1}, // electric potential
    {-3, -1, 3, 0, 0, 2}, // electrical conductivity
    {2, 0, -1, 0, 0},     // diffusivity
}};
constexpr std::array<std::string_view, 21> kNames{"dimensionless",
                                                  "length",
                                                  "time",
                                                  "mass",
                                                  "velocity",
                                                  "acceleration",
                                                  "density",
                                                  "pressure",
                                                  "viscosity",
                                                  "surface tension",
                                                  "energy",
                                                  "force",
                                                  "areal density",
                                                  "temperature",
                                                  "angle",
                                                  "frequency",
                                                  "heat transfer coefficient",
                                                  "specific heat capacity",
                                                  "electric potential",
                                                  "electrical conductivity",
                                                  "diffusivity"};
// The SI unit of each dimension, as parse_quantity reads it ("" for plain numbers).
constexpr std::array<std::string_view, 21> kSiUnits{
    "",  "m",      "s", "kg",  "m/s", "m/s^2",     "kg/m^3",   "Pa", "Pa*s", "N/m",  "J",
    "N", "kg/m^2", "K", "rad", "Hz",  "W/(m^2*K)", "J/(kg*K)", "V",  "S/m",  "m^2/s"};
// Unit used in the "e.g." part of error messages, with its decimal exponent (0 = SI already).
struct Example {
    std::string_view unit;
    int pow10;
};
constexpr std::array<Example, 21> kExamples{
    {{"", 0},         {"um", -6}, {"s", 0},      {"mg", -6},   {"um/s", -6},     {"m/s^2", 0},
     {"g/cm^3", 3},   {"MPa", 6}, {"mPa*s", -3}, {"mN/m", -3}, {"J", 0},         {"nN", -9},
     {"mg/cm^2", -2}, {"K", 0},   {"deg", 0},    {"Hz", 0},    {"W/(m^2*K)", 0}, {"J/(kg*K)", 0},
     {"mV", -3},      {"S/m", 0}, {"m^2/s", 0}}};

std::size_t index(Dimension d) { return static_cast<std::size_t>(d); }

// A parse failure inside the unit expression; turned into an InputError with the key by the caller.
struct UnitSyntax : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::string_view trim(std::string_view s) {
    const auto ws = " \t\r\n";
    const auto b = s.find_first_not_of(ws);
    if (b == std::string_view::npos) return {};
    return s.substr(b, s.find_last_not_of(ws) - b + 1);
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// A value as error messages show it: a 60,000-character value is cut to its two ends.
std::string shorten(std::string_view s) {
    if (s.size() <= 80) return std::string(s);
    return fmt::format("{}...{} ({} characters)", s.substr(0, 40), s.substr(s.size() - 20),
                       s.size());
}

// Raises a unit to an integer power exactly (num and den are small integers or pi).
Unit power(Unit u, int e) {
    if (e < 0) {
        std::swap(u.num, u.den);
        e = -e;
        u.pow10 = -u.pow10;
        for (int& d : u.dims) d = -d;
    }
    Unit r{1, 1, 0, kNone, u.celsius};
    for (int k = 0; k < e; ++k) {
        r.num *= u.num;
        r.den *= u.den;
    }
    // Nested powers ("((m^9)^9)^9") would overflow the int exponents: no real unit goes near.
    constexpr long max_dim = 64, max_pow10 = 100000;
    auto too_big = [&](long v, long limit) { return v * e > limit || v * e < -limit; };
    if (too_big(u.pow10, max_pow10) ||
        std::any_of(u.dims.begin(), u.dims.end(), [&](int d) { return too_big(d, max_dim); }))
        throw UnitSyntax("the unit's exponents are too large");
    r.pow10 = u.pow10 * e;
    for (std::size_t k = 0; k < r.dims.size(); ++k) r.dims[k] = u.dims[k] * e;
    return r;
}

Unit times(Unit a, const Unit& b) {
    a.num *= b.num;
    a.den *= b.den;
    a.pow10 += b.pow10;
    for (std::size_t k = 0; k < a.dims.size(); ++k) a.dims[k] += b.dims[k];
    a.celsius = a.celsius || b.celsius;
    return a;
}

std::optional<Unit> lookup(std::string_view name) {
    for (const auto& s : kSymbols)
        if (s.name == name) return s.unit;
    // Exact names first, so "min" is minutes and not milli-"in"; then prefix + prefixable symbol.
    for (const auto& p : kPrefixes) {
        if (name.size() <= p.name.size() || !name.starts_with(p.name)) continue;
        const auto rest = name.substr(p.name.size());
        for (const auto& s : kSymbols)
            if (s.prefixable && s.name == rest) {
                Unit u = s.unit;
                u.pow10 += p.pow10;
                return u;
            }
    }
    return std::nullopt;
}

// Recursive-descent parser of a unit expression: expr := factor (op? factor)*, op := * · /,
// factor := (symbol | "1" | '(' expr ')') exponent?, exponent := ^int | int | ² | ³.
class UnitParser {
public:
    explicit UnitParser(std::string_view s) : s_(s) {}

    Unit parse() {
        Unit u = expr();
        skip_ws();
        if (pos_ != s_.size())
            throw UnitSyntax(fmt::format("unexpected '{}'", shorten(s_.substr(pos_))));
        // degC is an offset scale: "80 degC" is fine, "J/degC" or "degC^2" would be meaningless.
        if (u.celsius && (factors_ != 1 || u.dims != K))
            throw UnitSyntax("degC is an offset scale and only allowed alone (\"80 degC\"); use K "
                             "in compound units");
        return u;
    }

private:
    std::string_view s_;
    std::size_t pos_ = 0;
    int factors_ = 0;
    int depth_ = 0; ///< open parentheses: the recursion is bounded, never a stack overflow
    static constexpr int max_depth = 16;

    bool at(std::string_view t) const { return s_.substr(pos_).starts_with(t); }
    void skip_ws() {
        while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t')) ++pos_;
    }
    bool at_factor_start() const {
        if (pos_ >= s_.size()) return false;
        const auto c = static_cast<unsigned char>(s_[pos_]);
        return c == '(' || one_over() || symbol_char();
    }
    // "1/s": a literal 1 is only allowed as the numerator of a reciprocal.
    bool one_over() const {
        if (pos_ >= s_.size() || s_[pos_] != '1') return false;
        const auto next = s_.find_first_not_of(" \t", pos_ + 1);
        return next != std::string_view::npos && s_[next] == '/';
    }
    bool symbol_char() const {
        if (pos_ >= s_.size()) return false;
        const auto c = static_cast<unsigned char>(s_[pos_]);
        if (at("·") || at("²") || at("³")) return false;
        return std::isalpha(c) || c == '%' || c >= 0x80; // µ, μ, ° are multi-byte UTF-8
    }

    Unit expr() {
        skip_ws();
        Unit u = factor();
        for (;;) {
            skip_ws();
            if (pos_ >= s_.size() || s_[pos_] == ')') return u;
            bool divide = false;
            if (s_[pos_] == '*') {
                ++pos_;
            } else if (at("·")) {
                pos_ += std::string_view("·").size();
            } else if (s_[pos_] == '/') {
                ++pos_;
                divide = true;
            } else if (!at_factor_start()) {
                throw UnitSyntax(fmt::format("unexpected '{}'", shorten(s_.substr(pos_))));
            } // else: space-separated factors multiply ("Pa s")
            skip_ws();
            const Unit f = factor();
            u = times(u, divide ? power(f, -1) : f);
        }
    }

    Unit factor() {
        Unit u;
        if (pos_ < s_.size() && s_[pos_] == '(') {
            if (++depth_ > max_depth)
                throw UnitSyntax(fmt::format("more than {} nested parentheses", max_depth));
            ++pos_;
            u = expr();
            --depth_;
            if (pos_ >= s_.size() || s_[pos_] != ')') throw UnitSyntax("missing ')'");
            ++pos_;
        } else if (one_over()) {
            ++pos_;
        } else {
            const auto b = pos_;
            while (symbol_char()) ++pos_;
            if (b == pos_)
                throw UnitSyntax(pos_ < s_.size()
                                     ? fmt::format("unexpected '{}'", shorten(s_.substr(pos_)))
                                     : std::string("a unit is missing at the end"));
            const auto name = s_.substr(b, pos_ - b);
            const auto found = lookup(name);
            if (!found)
                throw UnitSyntax(fmt::format(
                    "unknown unit '{}' (known: m g s min h K degC rad deg Hz N Pa bar P J eV W L "
                    "%, with prefixes f p n u µ m c k M G T)",
                    name));
            u = *found;
            ++factors_;
        }
        return power(u, exponent());
    }

    int exponent() {
        if (at("²")) {
            pos_ += std::string_view("²").size();
            return 2;
        }
        if (at("³")) {
            pos_ += std::string_view("³").size();
            return 3;
        }
        const bool caret = pos_ < s_.size() && s_[pos_] == '^';
        if (caret) ++pos_;
        const auto b = pos_;
        if (pos_ < s_.size() && (s_[pos_] == '-' || s_[pos_] == '+')) ++pos_;
        if (pos_ >= s_.size() || !is_digit(s_[pos_])) {
            if (caret) throw UnitSyntax("'^' must be followed by an integer");
            pos_ = b; // a '-' not followed by digits is not an exponent
            return 1;
        }
        while (pos_ < s_.size() && is_digit(s_[pos_])) ++pos_;
        int e = 0;
        auto t = s_.substr(b, pos_ - b);
        if (t.starts_with('+')) t.remove_prefix(1);
        std::from_chars(t.data(), t.data() + t.size(), e);
        if (e == 0 || std::abs(e) > 9)
            throw UnitSyntax(fmt::format("exponent {} is not allowed", t));
        return e;
    }
};

// The number part of a value: sign and mantissa as text, decimal exponent separately, so unit
// prefixes can be folded into the exponent before the one and only rounding.
struct Number {
    std::string mantissa;
    long exp10 = 0;
    std::size_t length = 0; ///< characters consumed
};

std::optional<Number> scan_number(std::string_view s) {
    Number n;
    std::size_t i = 0;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) {
        if (s[i] == '-') n.mantissa += '-';
        ++i;
    }
    const auto b = i;
    bool digits = false;
    while (i < s.size() && is_digit(s[i])) {
        ++i;
        digits = true;
    }
    if (i < s.size() && s[i] == '.') {
        ++i;
        while (i < s.size() && is_digit(s[i])) {
            ++i;
            digits = true;
        }
    }
    if (!digits) return std::nullopt;
    n.mantissa += s.substr(b, i - b);
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        std::size_t j = i + 1;
        if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
        if (j < s.size() && is_digit(s[j])) { // otherwise the 'e' starts a unit ("2 eV")
            const auto eb = s[i + 1] == '+' ? i + 2 : i + 1;
            while (j < s.size() && is_digit(s[j])) ++j;
            const auto [p, ec] = std::from_chars(s.data() + eb, s.data() + j, n.exp10);
            if (ec != std::errc{} || std::abs(n.exp10) > 100000) return std::nullopt;
            i = j;
        }
    }
    n.length = i;
    return n;
}

std::optional<double> to_double(const Number& n, int pow10) {
    const auto text = fmt::format("{}e{}", n.mantissa, n.exp10 + pow10);
    double v = 0.0;
    const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc{} || p != text.data() + text.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

// Shortest round-trip form without the leading zeros of the exponent: 6.5e-06 → 6.5e-6.
std::string short_number(double v) {
    auto s = fmt::format("{}", v);
    const auto e = s.find('e');
    if (e == std::string::npos) return s;
    auto exp = s.substr(e + 1);
    const bool neg = exp.starts_with('-');
    if (exp.starts_with('-') || exp.starts_with('+')) exp.erase(0, 1);
    exp.erase(0, std::min(exp.find_first_not_of('0'), exp.size() - 1));
    return s.substr(0, e + 1) + (neg ? "-" : "") + exp;
}

std::string dims_text(const Dims& d) {
    static constexpr std::array<std::string_view, 5> base{"m", "kg", "s", "K", "rad"};
    std::string out;
    for (std::size_t k = 0; k < d.size(); ++k) {
        if (d[k] == 0) continue;
        if (!out.empty()) out += ' ';
        out += d[k] == 1 ? std::string(base[k]) : fmt::format("{}^{}", base[k], d[k]);
    }
    return out.empty() ? "dimensionless" : out;
}

std::string describe(const Dims& d) {
    for (std::size_t k = 0; k < kExpected.size(); ++k)
        if (kExpected[k] == d) return std::string(kNames[k]);
    return dims_text(d);
}

std::string with_article(std::string_view name) {
    if (name == "dimensionless") return "a plain number";
    const bool vowel = std::string_view("aeiou").find(name.front()) != std::string_view::npos;
    return fmt::format("{} {}", vowel ? "an" : "a", name);
}

// `(e.g. "6.5 um" or 6.5e-6)` using the number the user typed.
std::string example(Dimension d, const std::optional<Number>& n) {
    const Number num = n ? *n : Number{"1", 0, 1};
    const auto& ex = kExamples[index(d)];
    const auto plain = num.mantissa + (num.exp10 ? fmt::format("e{}", num.exp10) : "");
    if (ex.unit.empty()) return fmt::format("e.g. {}", plain);
    std::optional<double> si = to_double(num, ex.pow10);
    if (d == Dimension::angle && si) *si = *si * std::numbers::pi / 180.0;
    const auto si_text = si ? short_number(*si) : std::string("<SI value>");
    if (d == Dimension::temperature)
        return fmt::format("e.g. \"{0} degC\", \"{0} K\" or {0}", plain);
    return fmt::format("e.g. \"{} {}\" or {}{}", plain, ex.unit, si_text,
                       d == Dimension::angle ? " (radians)" : "");
}

} // namespace

std::string_view dimension_name(Dimension d) {
    const auto i = index(d);
    return i < kNames.size() ? kNames[i] : "unknown";
}

std::string_view si_unit(Dimension d) {
    const auto i = index(d);
    return i < kSiUnits.size() ? kSiUnits[i] : "";
}

double parse_quantity(std::string_view text, Dimension expected, std::string_view key) {
    const std::string shown = shorten(text);
    const auto value = trim(text);
    const auto where = key.empty() ? std::string("value") : fmt::format("config key '{}'", key);
    const auto number = scan_number(value);
    if (!number)
        throw InputError(fmt::format("{}: \"{}\" is not a number with an optional unit ({})", where,
                                     shown, example(expected, std::nullopt)));
    const auto unit_text = trim(value.substr(number->length));
    Unit u;
    if (!unit_text.empty()) {
        try {
            u = UnitParser(unit_text).parse();
        } catch (const UnitSyntax& e) {
            throw InputError(fmt::format("{}: \"{}\": {} ({})", where, shown, e.what(),
                                         example(expected, number)));
        }
    } else {
        u.dims = kExpected[index(expected)]; // bare number: already SI
    }
    if (u.dims != kExpected[index(expected)])
        throw InputError(fmt::format(
            "{}: \"{}\" has unit {} ({}) but {} is expected ({})", where, shown, shorten(unit_text),
            describe(u.dims), with_article(dimension_name(expected)), example(expected, number)));
    auto v = to_double(*number, u.pow10);
    if (!v)
        throw InputError(
            fmt::format("{}: \"{}\" is out of the range of double precision", where, shown));
    if (u.num != 1.0 || u.den != 1.0) *v = *v * u.num / u.den;
    if (u.celsius) *v += 273.15;
    return *v;
}

std::string format_quantity(double si, Dimension d) {
    struct Choice {
        std::string_view unit;
        double scale;
    };
    static const auto pick = [](double v, std::span<const Choice> units) {
        // Largest unit in which |v| >= 1; the smallest one for tiny values, the first for zero.
        const Choice* best = &units[0];
        for (const auto& c : units)
            if (std::abs(v) >= c.scale * (1 - 1e-12)) best = &c;
        return *best;
    };
    using D = Dimension;
    static const Choice length[]{{"nm", 1e-9}, {"um", 1e-6}, {"mm", 1e-3}, {"m", 1}};
    static const Choice time[]{{"ps", 1e-12}, {"ns", 1e-9}, {"us", 1e-6}, {"ms", 1e-3}, {"s", 1}};
    static const Choice mass[]{{"pg", 1e-15}, {"ng", 1e-12}, {"ug", 1e-9},
                               {"mg", 1e-6},  {"g", 1e-3},   {"kg", 1}};
    static const Choice velocity[]{{"nm/s", 1e-9}, {"um/s", 1e-6}, {"mm/s", 1e-3}, {"m/s", 1}};
    static const Choice pressure[]{{"Pa", 1}, {"kPa", 1e3}, {"MPa", 1e6}, {"GPa", 1e9}};
    static const Choice viscosity[]{{"mPa*s", 1e-3}, {"Pa*s", 1}};
    static const Choice tension[]{{"mN/m", 1e-3}, {"N/m", 1}};
    static const Choice force[]{{"pN", 1e-12}, {"nN", 1e-9}, {"uN", 1e-6}, {"mN", 1e-3}, {"N", 1}};
    static const Choice frequency[]{{"Hz", 1}, {"kHz", 1e3}, {"MHz", 1e6}, {"GHz", 1e9}};
    static const Choice potential[]{{"mV", 1e-3}, {"V", 1}};
    Choice c{"", 1};
    switch (d) {
    case D::dimensionless:
        return fmt::format("{:.6g}", si);
    case D::length:
        c = pick(si, length);
        break;
    case D::time:
        c = pick(si, time);
        break;
    case D::mass:
        c = pick(si, mass);
        break;
    case D::velocity:
        c = pick(si, velocity);
        break;
    case D::acceleration:
        c = {"m/s^2", 1};
        break;
    case D::density:
        c = {"kg/m^3", 1};
        break;
    case D::pressure:
        c = pick(si, pressure);
        break;
    case D::viscosity:
        c = pick(si, viscosity);
        break;
    case D::surface_tension:
        c = pick(si, tension);
        break;
    case D::energy:
        c = {"J", 1};
        break;
    case D::force:
        c = pick(si, force);
        break;
    case D::areal_density:
        c = {"mg/cm^2", 1e-2};
        break;
    case D::temperature:
        c = {"K", 1};
        break;
    case D::angle:
        c = {"deg", std::numbers::pi / 180.0};
        break;
    case D::frequency:
        c = pick(si, frequency);
        break;
    case D::heat_transfer_coefficient:
        c = {"W/(m^2*K)", 1};
        break;
    case D::specific_heat:
        c = {"J/(kg*K)", 1};
        break;
    case D::electric_potential:
        c = pick(si, potential);
        break;
    case D::electrical_conductivity:
        c = {"S/m", 1};
        break;
    case D::diffusivity:
        c = {"m^2/s", 1};
        break;
    }
    return fmt::format("{:.6g} {}", si / c.scale, c.unit);
}

} // namespace drydem
