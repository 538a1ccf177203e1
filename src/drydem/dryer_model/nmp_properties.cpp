// SPDX-License-Identifier: MIT
#include "drydem/dryer_model/nmp_properties.hpp"
#include <cmath>

namespace drydem::dryer {

using namespace constants;

double vapour_pressure(double T, const Antoine& k) {
    return std::exp(k.a - k.b / (T + k.c)); // D-5.1
}

double enthalpy_of_vaporisation(double T) {
    // D-5.2: Watson, Δh_v(T) = Δh_v(T1) ((Tc - T)/(Tc - T1))^0.38 with T1 = 373.15 K.
    return 51008.0 *
           std::pow((nmp_critical_temperature - T) / (nmp_critical_temperature - 373.15), 0.38);
}

double liquid_heat_capacity(double T) {
    return (185.2 + 0.25 * (T - 373.15)) / molar_mass_nmp; // D-5.3
}

double liquid_sensible_enthalpy(double T0, double T) {
    // ∫_{T0}^{T} (185.2 + 0.25 (T' - 373.15)) dT' / M
    const double a = T0 - 373.15, b = T - 373.15;
    return (185.2 * (T - T0) + 0.125 * (b * b - a * a)) / molar_mass_nmp;
}

double vapour_heat_capacity(double T) {
    return (133.3 + 0.33 * (T - 373.15)) / molar_mass_nmp; // D-5.3
}

double liquid_density(double T) {
    return 1000.0 * (1.26202 - 7.0026e-4 * T - 2.8771e-7 * T * T); // D-5.6
}

double diffusion_coefficient_nmp_air(double T, double p) {
    // D-5.4: Fuller, Schettler, Giddings; molar masses in g/mol, result in cm^2/s -> m^2/s.
    constexpr double v_air = 19.7, v_nmp = 92.64, m_air = 28.96, m_nmp = 99.13;
    const double num = 1.00e-3 * std::pow(T, 1.75) * std::sqrt(1.0 / m_air + 1.0 / m_nmp);
    const double s = std::cbrt(v_air) + std::cbrt(v_nmp);
    return num / ((p / atmospheric_pressure) * s * s) * 1e-4;
}

double air_thermal_conductivity(double T) {
    return 2.646e-3 * std::pow(T, 1.5) / (T + 245.4 * std::pow(10.0, -12.0 / T)); // D-5.5
}

double air_heat_capacity(double T) { return 1007.0 + 0.09 * (T - 300.0); } // D-5.5

double air_density(double T, double p) { return p * molar_mass_air / (gas_constant * T); }

} // namespace drydem::dryer
