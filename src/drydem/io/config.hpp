// SPDX-License-Identifier: MIT
// Run configuration: every value in SI, converted once from the TOML at the edge. Every key is
// declared once, in io/config_keys.def (the paper's 20.1 mg/cm2 case, model.md M-1 ... M-9): the
// struct below, the validation, the embedded default text and docs/configuration.md follow from it.
#pragma once
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace toml {
inline namespace v3 {
class table;
}
} // namespace toml

namespace drydem {

/// One parameter of a calibration (docs/calibration.md): a numeric config key and its bounds [SI].
struct CalibrationParameter {
    std::string key;
    double min = 0.0, max = 0.0;
    bool log = false; ///< search over log(value) (scale = "log")
};
/// One measured target of a calibration: a run's result quantity, its value and uncertainty [SI].
struct CalibrationTarget {
    std::string quantity;
    double value = 0.0, uncertainty = 0.0;
    double at =
        -1.0; ///< process time of a time-series quantity [s] (a point of a measured curve); < 0: none
};
/// A run result a calibration can fit: its name in [[calibration.targets]], its dimension, the
/// key in the run's summary.json and that key's unit (value in summary = SI / si_per_unit).
struct CalibrationQuantity {
    std::string_view name;
    int dimension; ///< a drydem::Dimension (io/units.hpp)
    std::string_view summary_key;
    double si_per_unit;
    std::string_view unit;
    double lo, hi; ///< allowed target values [SI]
    /// A point of a measured curve (e.g. thickness vs time): summary_key is then a column of the
    /// run's timeseries.csv, read at the target's process time `at`; false for a result of the
    /// whole run.
    bool curve = false;
};
/// Every quantity [[calibration.targets]] accepts.
const std::vector<CalibrationQuantity>& calibration_quantities();
/// The name a target's values go by in the calibration's ledger, tables and plots: the quantity,
/// and for a point of a curve its time ("film_thickness_at_40s").
std::string calibration_target_name(const CalibrationTarget& t);

/// A list default in io/config_keys.def: DRYDEM_LIST(6.5e-6, 7.58e-6) is {6.5e-6, 7.58e-6}.
#define DRYDEM_LIST(...)                                                                           \
    { __VA_ARGS__ }

/// The configuration, every value in SI. Its keys are the rows of io/config_keys.def, where each
/// field's TOML key, default, unit, allowed range and meaning are declared once.
struct Config {
#define DRYDEM_SECTION(name, comment)
#define DRYDEM_NOTE(text)
#define DRYDEM_KEY(key, Type, member, default_si, default_text, dimension, allowed, doc)           \
    Type member = default_si;
#include "drydem/io/config_keys.def"
#undef DRYDEM_KEY
#undef DRYDEM_NOTE
#undef DRYDEM_SECTION

    // [calibration] arrays of tables ([[calibration.parameters]], [[calibration.targets]]; docs/
    // calibration.md): parsed on their own, not written by to_toml.
    std::vector<CalibrationParameter> calibration_parameters;
    std::vector<CalibrationTarget> calibration_targets;

    /// The semi-implicit kick in the paper's scheme runs with the guard alone (cap 1e-9 s, critical
    /// fraction 0.65): measured not to move the film on the quick case and the 20.1 recipe, 3 seeds
    /// each, at ~1.9x fewer steps (docs/performance.md "The guard alone at a critical-step fraction
    /// of 0.65"); the
    /// force-ratio scheme's film moved at 0.65, so it keeps 1e-10 s and 0.5.
    [[nodiscard]] bool guard_alone_sets_step() const {
        return integrator == "semi_implicit" && scaling_scheme == "paper";
    }
    /// The largest time step: time_step, or with 0 the integrator's cap (explicit 1e-11 s, C-23;
    /// semi-implicit 1e-10 s, the contact limit, or 1e-9 s in the paper's scheme; docs/model.md
    /// "Stability guard"; quasi-static none here: the level's motion bounds it,
    /// drying/scaling.hpp largest_time_step).
    [[nodiscard]] double time_step_cap() const {
        if (time_step > 0.0) return time_step;
        if (integrator == "quasi_static") return 1.0;
        if (integrator == "explicit") return 1.0e-11;
        return guard_alone_sets_step() ? 1.0e-9 : 1.0e-10;
    }
    /// Whether each particle's own stiffness joins the semi-implicit kick (docs/model.md M-9.1):
    /// implicit_stiffness, or with "auto" where the guard alone sets the step (the paper's
    /// scheme): measured there not to move the film at the 1e-9 s cap, on the quick case and the
    /// 20.1 recipe (3 seeds each) and the main job's 75 um box, at ~5x fewer steps
    /// (docs/validation.md "Implicit self-stiffness in the paper's scheme"); in the force-ratio
    /// scheme the film moved at 1.6e-10 s, so it stays off there.
    [[nodiscard]] bool implicit_stiffness_on() const {
        return implicit_stiffness.value_or(guard_alone_sets_step());
    }
    /// The stability guard's fraction of the critical step 2/omega: critical_step_fraction, or with
    /// 0 the integrator's own (0.65 for the semi-implicit kick in the paper's scheme, else 0.5).
    [[nodiscard]] double critical_step_fraction_value() const {
        if (critical_step_fraction > 0.0) return critical_step_fraction;
        return guard_alone_sets_step() ? 0.65 : 0.5;
    }
    /// The quasi-static step's largest displacement [m]: max_displacement, or with 0 5 % of the
    /// smallest particle radius.
    [[nodiscard]] double max_displacement_value() const {
        if (max_displacement > 0.0) return max_displacement;
        double d = cb_diameter;
        for (double x : ncm_diameters) d = std::min(d, x);
        return 0.05 * 0.5 * d;
    }
    /// The neighbour skin: skin, or with 0 the integrator's default (explicit 0.1 um, M-9.4;
    /// semi-implicit 0.3 um: at its ~10x longer steps a 0.1 um skin is used up within a few dozen
    /// steps, and rebuilds and guard estimates would cost more than the wider list;
    /// docs/performance.md). Where the guard alone sets the semi-implicit step, 0.2 um: the guard
    /// reduces every gap by the skin, so a thinner one lets it step longer, and the list is
    /// shorter (the main job 15 % faster, the film within its seeds). A calendering run (explicit,
    /// on the dried run's configuration) keeps 0.3 um after a semi-implicit drying.
    [[nodiscard]] double neighbor_skin(bool for_calendering = false) const {
        if (skin > 0.0) return skin;
        if (integrator == "explicit") return 0.1e-6;
        return guard_alone_sets_step() && !for_calendering ? 0.2e-6 : 0.3e-6;
    }
};

/// The embedded default configuration (the paper's 20.1 mg/cm2 case), as TOML text with units and
/// a comment per key (`drydem config default`), written from io/config_keys.def.
std::string_view default_config_toml();

/// The key reference, docs/configuration.md (`drydem config doc`), written from io/config_keys.def:
/// per section a table of key, default, SI unit, allowed values and meaning.
std::string config_reference_markdown();

/// A configuration validated key by key and across keys, and the length keys it gave as bare
/// numbers (SI metres: the derived checks hint "did you mean ... um?" where they make no sense).
struct ParsedConfig {
    Config config;
    std::vector<std::string> bare_lengths;
};

/// Parses and validates a TOML document (unknown keys, wrong units and out-of-range values throw
/// InputError naming the key, the value and what is allowed). `overrides` are "dotted.key=value"
/// strings applied on top (value parsed as TOML, else taken as a string). What the keys imply
/// together (particle counts, steps, memory) is checked a layer up: load_config
/// (drying/derived_checks.hpp) is what the commands read.
ParsedConfig parse_config(std::string_view toml_text, std::string_view source_name,
                          const std::vector<std::string>& overrides = {});
/// The text of a config file; InputError naming it where it cannot be read.
std::string read_config_text(const std::string& path);

/// The resolved configuration as TOML, every value in SI (written into each output folder).
std::string to_toml(const Config& c);

} // namespace drydem
