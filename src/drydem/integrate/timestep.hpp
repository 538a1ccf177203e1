// SPDX-License-Identifier: MIT
// Time-step criteria (model.md M-9.2), printed by `drydem check`.
#pragma once
#include <cmath>
#include <numbers>

namespace drydem {

/// Rayleigh wave time π r sqrt(ρ/G) / (0.1631 ν + 0.8766), G = E / (2(1+ν)) [s].
inline double rayleigh_time(double r, double density, double youngs_modulus, double poisson_ratio) {
    const double g = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
    return std::numbers::pi * r * std::sqrt(density / g) / (0.1631 * poisson_ratio + 0.8766);
}

/// Duration of an elastic Hertz collision 2.868 (m*² / (R* E*² v))^{1/5} [s].
inline double hertz_contact_time(double m_eff, double r_eff, double e_star, double impact_speed) {
    return 2.868 * std::pow(m_eff * m_eff / (r_eff * e_star * e_star * impact_speed), 0.2);
}

/// Relaxation time m / (6π η r) of Stokes drag [s]; explicit integration needs Δt < 2 m/(6πηr).
inline double stokes_relaxation_time(double mass, double r, double viscosity) {
    return mass / (6.0 * std::numbers::pi * viscosity * r);
}

} // namespace drydem
