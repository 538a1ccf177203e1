// SPDX-License-Identifier: MIT
// Quantities with units in config values ("6.5 um", "20.1 mg/cm^2", "80 degC") → SI doubles.
//
// A small hand-written unit table (Debian has no run-time unit-string parser): symbols with SI
// prefixes, combined by '*', '·', space (multiplication), '/' (divides the next factor only),
// '^n' or a trailing integer ("cm2", "s-1") and parentheses. The result's dimension is checked
// against what the config key expects, so "6.5 kg" for a diameter is an error naming the key.
#pragma once
#include <string>
#include <string_view>

namespace drydem {

/// What a config key expects. Angles are kept apart from plain numbers so that "40 deg" cannot be
/// given where a ratio is expected (and vice versa).
enum class Dimension {
    dimensionless,
    length,
    time,
    mass,
    velocity,
    acceleration,
    density,
    pressure,
    viscosity,
    surface_tension,
    energy,
    force,
    areal_density,
    temperature,
    angle,
    frequency,
    heat_transfer_coefficient, ///< W/(m^2 K), dryer zones
    specific_heat,             ///< J/(kg K), dryer model
    electric_potential,        ///< V, double-layer repulsion
    electrical_conductivity,   ///< S/m, transport solves of the analysis
    diffusivity,               ///< m^2/s, binder migration of the analysis
};

/// Human name, e.g. "areal density".
[[nodiscard]] std::string_view dimension_name(Dimension d);

/// Its SI unit as parse_quantity reads it, e.g. "kg/m^2"; "" for dimensionless.
[[nodiscard]] std::string_view si_unit(Dimension d);

/// Parses `text` (a number with an optional unit) into SI. No unit means the number is already SI
/// ("2.5" → 2.5; for angles radians, for temperatures kelvin). "degC" is affine and only allowed
/// on its own ("80 degC" → 353.15). Throws InputError naming `key`, the value and what is allowed.
[[nodiscard]] double parse_quantity(std::string_view text, Dimension expected,
                                    std::string_view key);

/// Readable form of an SI value with a unit fitting its size, e.g. 6.5e-6 → "6.5 um",
/// 1.801 (viscosity) → "1.801 Pa*s"; 6 significant digits. parse_quantity reads it back.
[[nodiscard]] std::string format_quantity(double si, Dimension d);

} // namespace drydem
