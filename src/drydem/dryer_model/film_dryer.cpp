// SPDX-License-Identifier: MIT
#include "drydem/dryer_model/film_dryer.hpp"
#include "drydem/setup/solids.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace drydem::dryer {

using namespace constants;

double preset_analogy_exponent(std::string_view preset) {
    if (preset == "physical") return 1.0 / 3.0; // Chilton-Colburn (D-2.4)
    if (preset == "table2") return 0.42; // impinging-jet exponent, calibrated to Table 2 (D-3)
    throw InputError(
        fmt::format("dryer preset '{}' is unknown; allowed: \"physical\", \"table2\"", preset));
}

FilmGeometry film_geometry(const FilmDryerParams& p) {
    FilmGeometry g{};
    g.solids_density = solids_density(p.w_ncm, p.rho_ncm, p.w_pvdf, p.rho_pvdf, p.w_cb, p.rho_cb);
    g.solids_height = p.areal_loading / g.solids_density;
    g.initial_liquid =
        p.areal_loading * (1.0 - p.solids_mass_fraction) / p.solids_mass_fraction; // D-2.1
    const double rho_l0 =
        p.liquid_density_temperature ? liquid_density(p.initial_temperature) : p.liquid_density;
    g.wet_height = g.solids_height + g.initial_liquid / rho_l0;  // Eq. 3
    g.final_height = g.solids_height / (1.0 - p.final_porosity); // D-2.5
    g.solids_heat_capacity = p.w_ncm * p.cp_ncm + p.w_pvdf * p.cp_pvdf + p.w_cb * p.cp_cb;
    g.substrate_mass = p.substrate_density * p.substrate_thickness;
    return g;
}

GasSide gas_side(const FilmDryerParams& p, const DryerZone& z, double T) {
    GasSide g{};
    g.film_temperature = 0.5 * (T + z.air_temperature); // D-2.3: T_m
    const double Tm = g.film_temperature;
    const double rho_g = air_density(Tm, p.pressure), cp_g = air_heat_capacity(Tm);
    g.diffusion = diffusion_coefficient_nmp_air(Tm, p.pressure);
    g.lewis = air_thermal_conductivity(Tm) / (rho_g * cp_g) / g.diffusion; // D-2.4
    g.mass_transfer =
        z.heat_transfer_top / (rho_g * cp_g) * std::pow(g.lewis, p.analogy_exponent - 1.0);
    g.molar_density = p.pressure / (gas_constant * Tm);
    return g;
}

namespace {

/// Mole-fraction driving force of D-2.3 (Stefan log form or linear).
double driving_force(const FilmDryerParams& p, double y_s) {
    const double y_inf = p.supply_air_solvent;
    if (p.stefan && y_s > y_inf) return std::log((1.0 - y_inf) / (1.0 - y_s));
    return y_s - y_inf;
}

/// Augmented state: T, m_l and the running integrals of the balance checks.
struct State {
    double T, m_l, heat_in, evaporated, latent_out, liquid_enthalpy_out;
};
State axpy(const State& y, double a, const State& d) {
    return {y.T + a * d.T,
            y.m_l + a * d.m_l,
            y.heat_in + a * d.heat_in,
            y.evaporated + a * d.evaporated,
            y.latent_out + a * d.latent_out,
            y.liquid_enthalpy_out + a * d.liquid_enthalpy_out};
}

/// Tracks the temperatures each correlation has been evaluated at.
struct RangeLog {
    double film_min = std::numeric_limits<double>::infinity(), film_max = -film_min;
    double gas_min = film_min, gas_max = -film_min;
    void film(double T) { film_min = std::min(film_min, T), film_max = std::max(film_max, T); }
    void gas(double T) { gas_min = std::min(gas_min, T), gas_max = std::max(gas_max, T); }
};

struct Model {
    const FilmDryerParams& p;
    FilmGeometry g;
    RangeLog* ranges;

    double rho_l(double T) const {
        return p.liquid_density_temperature ? liquid_density(T) : p.liquid_density;
    }

    /// Right-hand side of D-2.1/D-2.2 in zone z; returns d(state)/dt and ṁ.
    State rhs(const DryerZone& z, bool consolidated, double m_l_crit, const State& y,
              double& mdot) const {
        const double T = y.T, m_l = std::max(0.0, y.m_l);
        const GasSide gs = gas_side(p, z, T);
        if (ranges) ranges->film(T), ranges->gas(gs.film_temperature);
        mdot = 0.0;
        if (m_l > 0.0) {
            const double y_s =
                std::min(vapour_pressure(T, p.vapour_pressure) / p.pressure, 0.999); // D-2.3
            double k_eff = gs.mass_transfer;
            if (consolidated) {
                // D-2.6: receding front, vapour diffuses through the dry layer of depth s_d.
                const double saturation = m_l / m_l_crit;
                const double s_dry = (1.0 - saturation) * g.final_height;
                const double d_eff = gs.diffusion * p.final_porosity / p.tortuosity;
                k_eff = 1.0 / (1.0 / gs.mass_transfer + s_dry / d_eff);
            }
            mdot = std::max(0.0, k_eff * gs.molar_density * molar_mass_nmp * driving_force(p, y_s));
        }
        double f_ack = 1.0; // D-2.2 Ackermann correction (optional)
        if (p.ackermann && mdot > 0.0) {
            const double phi =
                mdot * vapour_heat_capacity(gs.film_temperature) / z.heat_transfer_top;
            f_ack = phi / std::expm1(phi);
        }
        const double q_top = f_ack * z.heat_transfer_top * (z.air_temperature - T);
        const double q_bot = p.bottom_factor * z.heat_transfer_top * (z.air_temperature - T); // A1
        const double heat_capacity = p.areal_loading * g.solids_heat_capacity +
                                     m_l * liquid_heat_capacity(T) +
                                     g.substrate_mass * p.substrate_heat_capacity; // C(t)
        const double latent = mdot * enthalpy_of_vaporisation(T) / molar_mass_nmp;
        State d{};
        d.T = (q_top + q_bot - latent) / heat_capacity; // Eq. 14 / D-2.2
        d.m_l = -mdot;                                  // D-2.1
        d.heat_in = q_top + q_bot;
        d.evaporated = mdot;
        d.latent_out = latent;
        d.liquid_enthalpy_out = mdot * liquid_sensible_enthalpy(p.initial_temperature, T);
        return d;
    }

    State rk4(const DryerZone& z, bool cons, double m_c, const State& y, double h) const {
        double md;
        const State k1 = rhs(z, cons, m_c, y, md);
        const State k2 = rhs(z, cons, m_c, axpy(y, 0.5 * h, k1), md);
        const State k3 = rhs(z, cons, m_c, axpy(y, 0.5 * h, k2), md);
        const State k4 = rhs(z, cons, m_c, axpy(y, h, k3), md);
        State out = y;
        out = axpy(out, h / 6.0, k1);
        out = axpy(out, h / 3.0, k2);
        out = axpy(out, h / 3.0, k3);
        out = axpy(out, h / 6.0, k4);
        return out;
    }
};

void check_params(const FilmDryerParams& p) {
    auto bad = [](const std::string& what) { throw InputError("dryer model: " + what); };
    if (p.zones.empty()) bad("no dryer zones");
    if (!(p.line_speed > 0)) bad(fmt::format("line speed {} m/s must be > 0", p.line_speed));
    if (!(p.time_step > 0 && p.time_step <= 0.05))
        bad(fmt::format("time step {} s outside (0, 0.05] s (D-2.7)", p.time_step));
    if (!(p.final_porosity > 0 && p.final_porosity < 1))
        bad(fmt::format("final porosity {} outside (0, 1)", p.final_porosity));
    if (!(p.areal_loading > 0)) bad("areal loading must be > 0");
    for (std::size_t k = 0; k < p.zones.size(); ++k) {
        const DryerZone& z = p.zones[k];
        if (!(z.length > 0)) bad(fmt::format("zone {} length {} m must be > 0", k + 1, z.length));
        if (!(z.heat_transfer_top > 0))
            bad(fmt::format("zone {} heat transfer coefficient {} W/(m^2 K) must be > 0", k + 1,
                            z.heat_transfer_top));
        if (z.air_temperature < p.initial_temperature)
            bad(fmt::format(
                "zone {} air temperature {} K is below the initial film temperature {} K", k + 1,
                z.air_temperature, p.initial_temperature));
    }
}

} // namespace

double film_sensible_enthalpy(const FilmDryerParams& p, double T, double m_l) {
    const FilmGeometry g = film_geometry(p);
    return (p.areal_loading * g.solids_heat_capacity +
            g.substrate_mass * p.substrate_heat_capacity) *
               (T - p.initial_temperature) +
           m_l * liquid_sensible_enthalpy(p.initial_temperature, T);
}

WetFilmSteadyState wet_film_steady_state(const FilmDryerParams& p, std::size_t zone) {
    const DryerZone& z = p.zones.at(zone);
    const Model m{p, film_geometry(p), nullptr};
    // Bisection on the heat balance q_top + q_bot - ṁ Δh_v/M = 0 with a wet surface (D-7.1).
    double lo = 273.15, hi = z.air_temperature, mdot = 0.0;
    State d{};
    for (int i = 0; i < 100; ++i) {
        const double T = 0.5 * (lo + hi);
        d = m.rhs(z, false, 0.0, State{T, 1.0, 0, 0, 0, 0}, mdot);
        // sign of the net heat flux = sign of dT/dt (the heat capacity is positive)
        (d.T > 0 ? lo : hi) = T;
    }
    const double T = 0.5 * (lo + hi);
    m.rhs(z, false, 0.0, State{T, 1.0, 0, 0, 0, 0}, mdot);
    const GasSide gs = gas_side(p, z, T);
    return {T, mdot, mdot / m.rho_l(T), gs.mass_transfer, gs.lewis};
}

DryerRun simulate_film_dryer(const FilmDryerParams& p) {
    check_params(p);
    DryerRun run;
    RangeLog ranges;
    const Model model{p, film_geometry(p), &ranges};
    const FilmGeometry& g = model.g;
    run.geometry = g;

    State y{p.initial_temperature, g.initial_liquid, 0, 0, 0, 0};
    bool consolidated = false;
    double m_l_crit = 0.0;
    const std::size_t nz = p.zones.size();

    auto sample = [&](double t, std::size_t k) {
        // D-2.5: consolidation is evaluated at the start of each step.
        double h = g.final_height;
        if (!consolidated) {
            const double liquid_volume = y.m_l / model.rho_l(y.T);
            h = g.solids_height + liquid_volume;
            if (liquid_volume <= p.final_porosity * g.final_height) {
                consolidated = true;
                m_l_crit = y.m_l;
                run.consolidation_time = t;
                h = g.final_height;
            }
        }
        double mdot;
        model.rhs(p.zones[k], consolidated, m_l_crit, y, mdot);
        run.samples.push_back({t, t * p.line_speed, y.T, y.m_l, h, mdot, p.zones[k].air_temperature,
                               int(k), consolidated, y.m_l / (y.m_l + p.areal_loading)});
    };
    // One RK4 step of length h; the step in which the liquid runs out is split at m_l = 0.
    auto step = [&](double t, double h, std::size_t k) {
        const DryerZone& z = p.zones[k];
        State next = model.rk4(z, consolidated, m_l_crit, y, h);
        if (y.m_l > 0.0 && next.m_l < 0.0) {
            // Secant iteration on the step fraction θ at which m_l(θ h) = 0, so that the step
            // ends where ṁ switches off and the balances stay exact.
            double th0 = 0.0, f0 = y.m_l, th1 = 1.0, f1 = next.m_l;
            State dry = next;
            for (int it = 0; it < 50; ++it) {
                const double th = th1 - f1 * (th1 - th0) / (f1 - f0);
                dry = model.rk4(z, consolidated, m_l_crit, y, th * h);
                th0 = th1, f0 = f1, th1 = th, f1 = dry.m_l;
                if (std::abs(dry.m_l) <= 1e-13 * g.initial_liquid || f1 == f0) break;
            }
            const double theta = th1;
            // Move the remaining rounding residual (≤ 1e-13 of m_l(0)) from the liquid to the
            // evaporated mass, so that m_l + ∫ṁ dt stays exact.
            dry.evaporated += dry.m_l;
            dry.m_l = 0.0;
            y = dry;
            run.dry_time = t + theta * h;
            next = model.rk4(z, consolidated, m_l_crit, y, (1.0 - theta) * h);
        }
        next.m_l = std::max(0.0, next.m_l);
        if (next.m_l == 0.0 && !run.dry_time) run.dry_time = t + h;
        y = next;
    };

    double t_begin = 0.0;
    for (std::size_t k = 0; k < nz; ++k) {
        const double duration = p.zones[k].length / p.line_speed;
        const auto n = static_cast<long>(std::ceil(duration / p.time_step - 1e-9)); // aligned steps
        const double h = duration / double(n);
        for (long i = 0; i < n; ++i) {
            const double t = t_begin + double(i) * h;
            sample(t, k);
            step(t, h, k);
        }
        t_begin += duration;
    }
    sample(t_begin, nz - 1);

    run.heat_in = y.heat_in;
    run.evaporated_mass = y.evaporated;
    run.latent_heat_out = y.latent_out;
    run.liquid_enthalpy_out = y.liquid_enthalpy_out;

    // Out-of-range use of a correlation is reported, never silent (D-5).
    auto check = [&](const ValidityRange& v, double lo, double hi) {
        if (lo < v.t_min || hi > v.t_max)
            run.warnings.push_back(
                fmt::format("{} evaluated at {:.2f}-{:.2f} K, outside its validity "
                            "range {:g}-{:g} K",
                            v.correlation, lo, hi, v.t_min, v.t_max));
    };
    check(p.vapour_pressure.validity, ranges.film_min, ranges.film_max);
    check(enthalpy_of_vaporisation_validity, ranges.film_min, ranges.film_max);
    check(liquid_heat_capacity_validity, ranges.film_min, ranges.film_max);
    if (p.liquid_density_temperature)
        check(liquid_density_validity, ranges.film_min, ranges.film_max);
    check(diffusion_coefficient_validity, ranges.gas_min, ranges.gas_max);
    check(air_thermal_conductivity_validity, ranges.gas_min, ranges.gas_max);
    check(air_heat_capacity_validity, ranges.gas_min, ranges.gas_max);
    if (p.ackermann) check(vapour_heat_capacity_validity, ranges.gas_min, ranges.gas_max);
    return run;
}

std::optional<double> fitted_shrinkage_rate(std::span<const double> t, std::span<const double> h) {
    const std::size_t n = std::min(t.size(), h.size());
    if (n < 5) return std::nullopt;
    const auto [tmin, tmax] = std::minmax_element(t.begin(), t.begin() + std::ptrdiff_t(n));
    if (*tmax - *tmin < 0.1) return std::nullopt;
    double mt = 0, mh = 0;
    for (std::size_t i = 0; i < n; ++i) mt += t[i], mh += h[i];
    mt /= double(n), mh /= double(n);
    double sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < n; ++i) {
        sxx += (t[i] - mt) * (t[i] - mt);
        sxy += (t[i] - mt) * (h[i] - mh);
    }
    return -sxy / sxx;
}

std::vector<SectionRate> fit_section_rates(const FilmDryerParams& p, const DryerRun& run) {
    std::vector<SectionRate> out;
    double t0 = 0.0, x = 0.0;
    for (const DryerZone& z : p.zones) {
        x += z.length;
        const double t1 = x / p.line_speed;
        std::vector<double> ts, hs;
        for (const DryerSample& s : run.samples)
            // Half a step of slack so that a sample exactly on the boundary belongs to the next
            // section despite rounding of x/v_l.
            if (s.time >= t0 - 1e-9 && s.time < t1 - 1e-9 && !s.consolidated) {
                ts.push_back(s.time);
                hs.push_back(s.thickness);
            }
        out.push_back({t0, t1, fitted_shrinkage_rate(ts, hs), ts.size()});
        t0 = t1;
    }
    return out;
}

std::vector<double> schedule_rates(const std::vector<SectionRate>& sections) {
    std::vector<double> rates;
    for (const SectionRate& s : sections) {
        if (!s.rate) break;
        rates.push_back(*s.rate);
    }
    if (rates.empty())
        throw InputError(
            "dryer model: the film consolidates before a shrinkage rate can be fitted in "
            "the first dryer section (D-4); no liquid-level schedule for the DEM");
    return rates;
}

double porosity_from_thickness(const FilmDryerParams& p, double final_thickness) {
    return 1.0 - p.areal_loading / (film_geometry(p).solids_density * final_thickness);
}

} // namespace drydem::dryer
