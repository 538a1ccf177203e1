// SPDX-License-Identifier: MIT
#include "drydem/dryer_model/dryer_config.hpp"

namespace drydem::dryer {

FilmDryerParams film_dryer_params(const Config& c) {
    FilmDryerParams p;
    p.preset = c.dryer_preset;
    p.w_ncm = c.ncm_mass_fraction;
    p.w_pvdf = c.pvdf_mass_fraction;
    p.w_cb = c.cb_mass_fraction;
    p.rho_ncm = c.ncm_density;
    p.rho_pvdf = c.pvdf_density;
    p.rho_cb = c.cb_density;
    p.areal_loading = c.areal_loading;
    p.solids_mass_fraction = c.solids_mass_fraction;
    p.liquid_density = c.solvent_density;
    p.substrate_thickness = c.dryer_substrate_thickness;
    p.substrate_density = c.dryer_substrate_density;
    p.substrate_heat_capacity = c.dryer_substrate_heat_capacity;
    p.line_speed = c.line_speed;
    p.zones.clear();
    for (std::size_t k = 0; k < c.dryer_zone_lengths.size(); ++k)
        p.zones.push_back({c.dryer_zone_lengths[k], c.dryer_air_temperatures.at(k),
                           c.dryer_heat_transfer_coefficients.at(k)});
    p.bottom_factor = c.dryer_bottom_factor;
    p.supply_air_solvent = c.dryer_supply_air_solvent;
    p.analogy_exponent = c.dryer_analogy_exponent > 0.0 ? c.dryer_analogy_exponent
                                                        : preset_analogy_exponent(c.dryer_preset);
    p.ackermann = c.dryer_ackermann;
    p.vapour_pressure = c.dryer_vapour_pressure == "landolt" ? antoine_landolt : antoine_anchored;
    p.initial_temperature = c.dryer_initial_temperature;
    p.final_porosity = c.dryer_final_porosity;
    p.time_step = c.dryer_time_step;
    return p;
}

FilmDryerParams film_dryer_preset(std::string_view name) {
    Config c; // the embedded defaults: the paper's 20.1 mg/cm2 film in its dryer
    c.dryer_preset = std::string(name);
    return film_dryer_params(c);
}

Config with_model_schedule(const Config& c) {
    const FilmDryerParams p = film_dryer_params(c);
    Config out = c;
    out.shrinkage_rates = schedule_rates(fit_section_rates(p, simulate_film_dryer(p)));
    return out;
}

} // namespace drydem::dryer
