// SPDX-License-Identifier: MIT
// Property correlations of the dryer model (dryer.md D-5): NMP vapour pressure, enthalpy of
// vaporisation, heat capacities, liquid density, NMP-air diffusion coefficient and dry air.
// Pure functions of the temperature T [K] (and the pressure where it matters), SI in and out.
//
// Every correlation has a validity range (ValidityRange below). The functions themselves do not
// throw, because the film passes briefly through temperatures below some ranges while heating up
// (e.g. the Landolt vapour pressure is fitted for 336-477 K but the film enters at 298 K); the
// dryer model records the temperatures it evaluated each correlation at and reports every
// excursion as a warning in its result (film_dryer.hpp, DryerRun::warnings), never silently.
#pragma once
#include <string_view>

namespace drydem::dryer {

/// Physical constants of the dryer model (dryer.md D-2, D-3).
namespace constants {
inline constexpr double gas_constant = 8.314462618;       ///< R [J mol^-1 K^-1]
inline constexpr double atmospheric_pressure = 101325.0;  ///< p [Pa]
inline constexpr double molar_mass_air = 0.0289647;       ///< M_air [kg/mol]
inline constexpr double molar_mass_nmp = 0.09913;         ///< M of NMP [kg/mol] (paper Table A1)
inline constexpr double nmp_critical_temperature = 721.6; ///< T_c [K] (Yaws / DIPPR)
} // namespace constants

/// Temperature range [K] in which a correlation is documented to hold.
struct ValidityRange {
    std::string_view correlation; ///< human name, e.g. "NMP vapour pressure (anchored Antoine)"
    double t_min, t_max;          ///< [K]
    [[nodiscard]] constexpr bool contains(double t) const { return t >= t_min && t <= t_max; }
};

/// Antoine form ln(p*/Pa) = A - B / (T/K + C) with its fitted range.
struct Antoine {
    double a, b, c;
    ValidityRange validity;
    std::string_view name; ///< config value of dryer.vapour_pressure
};

/// D-5.1 default: fitted through Table A1 (2976 Pa at 373.15 K), the Clausius-Clapeyron slope of
/// Table A1's Δh_v at 373.15 K and the normal boiling point 475.2 K. Valid 290-480 K.
inline constexpr Antoine antoine_anchored{
    24.37597,
    6087.867,
    -1.4317,
    {"NMP vapour pressure (anchored Antoine, D-5.1)", 290.0, 480.0},
    "anchored"};
/// D-5.1 alternative: Landolt-Börnstein IV/20C (Dykyj et al.), 13 % above Table A1 at 100 °C.
/// Valid 336-477 K.
inline constexpr Antoine antoine_landolt{
    21.137754179536273,
    3811.4460785821143,
    -80.355,
    {"NMP vapour pressure (Landolt Antoine, D-5.1)", 336.0, 477.0},
    "landolt"};

/// Saturation vapour pressure of NMP p*(T) [Pa] (D-5.1).
[[nodiscard]] double vapour_pressure(double T, const Antoine& coefficients = antoine_anchored);

/// Molar enthalpy of vaporisation Δh_v(T) [J/mol] (D-5.2): Watson scaling anchored to Table A1,
/// 51 008 J/mol at 373.15 K, exponent 0.38, T_c = 721.6 K.
[[nodiscard]] double enthalpy_of_vaporisation(double T);
inline constexpr ValidityRange enthalpy_of_vaporisation_validity{
    "NMP enthalpy of vaporisation (Watson, D-5.2)", 290.0, 480.0};

/// Specific heat capacity of liquid NMP c_p,l(T) [J kg^-1 K^-1] (D-5.3): 185.2 J/(mol K) at
/// 373.15 K (Table A1), slope 0.25 J/(mol K^2).
[[nodiscard]] double liquid_heat_capacity(double T);
inline constexpr ValidityRange liquid_heat_capacity_validity{"NMP liquid heat capacity (D-5.3)",
                                                             290.0, 420.0};

/// Specific sensible enthalpy of liquid NMP between T0 and T, ∫ c_p,l dT [J/kg] (closed form of
/// liquid_heat_capacity; used by the energy-balance check).
[[nodiscard]] double liquid_sensible_enthalpy(double T0, double T);

/// Specific heat capacity of NMP vapour c_p,vap(T) [J kg^-1 K^-1] (D-5.3): 133.3 J/(mol K) at
/// 373.15 K (Table A1), assumed slope 0.33 J/(mol K^2). Only the Ackermann option uses it.
[[nodiscard]] double vapour_heat_capacity(double T);
inline constexpr ValidityRange vapour_heat_capacity_validity{"NMP vapour heat capacity (D-5.3)",
                                                             290.0, 480.0};

/// Density of liquid NMP ρ_l(T) [kg/m^3] (D-5.6, optional; 1032 at 293 K, 979 at 353 K).
[[nodiscard]] double liquid_density(double T);
inline constexpr ValidityRange liquid_density_validity{"NMP liquid density (D-5.6)", 290.0, 420.0};

/// Binary diffusion coefficient NMP-air D [m^2/s] (D-5.4, Fuller-Schettler-Giddings; diffusion
/// volumes air 19.7, NMP 92.64; ±5-10 %).
[[nodiscard]] double diffusion_coefficient_nmp_air(double T,
                                                   double p = constants::atmospheric_pressure);
inline constexpr ValidityRange diffusion_coefficient_validity{
    "NMP-air diffusion coefficient (Fuller, D-5.4)", 250.0, 600.0};

/// Thermal conductivity of dry air λ_g(T) [W m^-1 K^-1] (D-5.5; 0.0263 at 300 K).
[[nodiscard]] double air_thermal_conductivity(double T);
inline constexpr ValidityRange air_thermal_conductivity_validity{"air thermal conductivity (D-5.5)",
                                                                 250.0, 600.0};

/// Specific heat capacity of dry air c_p,g(T) [J kg^-1 K^-1] (D-5.5, 280-420 K).
[[nodiscard]] double air_heat_capacity(double T);
inline constexpr ValidityRange air_heat_capacity_validity{"air heat capacity (D-5.5)", 280.0,
                                                          420.0};

/// Density of dry air ρ_g = p M_air / (R T) [kg/m^3] (ideal gas, D-5.5).
[[nodiscard]] double air_density(double T, double p = constants::atmospheric_pressure);

} // namespace drydem::dryer
