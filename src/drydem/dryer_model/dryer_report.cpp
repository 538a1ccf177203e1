// SPDX-License-Identifier: MIT
#include "drydem/dryer_model/dryer_report.hpp"
#include "drydem/core/error.hpp"
#include "drydem/git_hash.hpp"
#include <fmt/format.h>
#include <cmath>
#include <fstream>

namespace drydem::dryer {

namespace {
nlohmann::json opt(const std::optional<double>& v, double scale = 1.0) {
    return v ? nlohmann::json(*v * scale) : nlohmann::json(nullptr);
}
constexpr double kelvin_offset = 273.15;
} // namespace

nlohmann::json inputs_json(const FilmDryerParams& p) {
    nlohmann::json zones = nlohmann::json::array();
    for (const DryerZone& z : p.zones)
        zones.push_back({{"length_m", z.length},
                         {"air_temperature_K", z.air_temperature},
                         {"heat_transfer_top_W_m2_K", z.heat_transfer_top}});
    return {
        {"preset", p.preset},
        {"mass_fractions", {{"ncm", p.w_ncm}, {"pvdf", p.w_pvdf}, {"cb", p.w_cb}}},
        {"densities_kg_m3",
         {{"ncm", p.rho_ncm}, {"pvdf", p.rho_pvdf}, {"cb", p.rho_cb}, {"nmp", p.liquid_density}}},
        {"heat_capacities_J_kg_K", {{"ncm", p.cp_ncm}, {"pvdf", p.cp_pvdf}, {"cb", p.cp_cb}}},
        {"areal_loading_kg_m2", p.areal_loading},
        {"solids_mass_fraction", p.solids_mass_fraction},
        {"liquid_density_temperature_dependent", p.liquid_density_temperature},
        {"substrate",
         {{"thickness_m", p.substrate_thickness},
          {"density_kg_m3", p.substrate_density},
          {"heat_capacity_J_kg_K", p.substrate_heat_capacity}}},
        {"line_speed_m_s", p.line_speed},
        {"zones", zones},
        {"bottom_heat_transfer_factor", p.bottom_factor},
        {"supply_air_solvent_mole_fraction", p.supply_air_solvent},
        {"pressure_Pa", p.pressure},
        {"analogy_exponent", p.analogy_exponent},
        {"stefan_correction", p.stefan},
        {"ackermann_correction", p.ackermann},
        {"vapour_pressure", p.vapour_pressure.name},
        {"initial_film_temperature_K", p.initial_temperature},
        {"final_porosity", p.final_porosity},
        {"dry_layer_tortuosity", p.tortuosity},
        {"time_step_s", p.time_step},
    };
}

nlohmann::json dryer_json(const FilmDryerParams& p, const DryerRun& run,
                          const std::vector<SectionRate>& sections) {
    nlohmann::json zones = nlohmann::json::array();
    double x0 = 0.0;
    for (std::size_t k = 0; k < p.zones.size(); ++k) {
        const DryerZone& z = p.zones[k];
        const SectionRate& s = sections.at(k);
        const WetFilmSteadyState w = wet_film_steady_state(p, k);
        zones.push_back({
            {"zone", k + 1},
            {"position_m", {x0, x0 + z.length}},
            {"time_s", {s.t_begin, s.t_end}},
            {"air_temperature_C", z.air_temperature - kelvin_offset},
            {"heat_transfer_top_W_m2_K", z.heat_transfer_top},
            {"heat_transfer_bottom_W_m2_K", p.bottom_factor * z.heat_transfer_top},
            {"shrinkage_rate_um_s", opt(s.rate, 1e6)},
            {"shrinkage_rate_um_per_m", opt(s.rate, 1e6 / p.line_speed)},
            {"fit_samples", s.samples},
            {"wet_film_steady_state",
             {{"temperature_C", w.temperature - kelvin_offset},
              {"evaporation_rate_g_m2_s", w.evaporation_rate * 1e3},
              {"shrinkage_rate_um_s", w.shrinkage_rate * 1e6},
              {"mass_transfer_coefficient_m_s", w.mass_transfer},
              {"lewis_number", w.lewis}}},
        });
        x0 += z.length;
    }
    std::vector<double> schedule;
    for (const SectionRate& s : sections) {
        if (!s.rate) break;
        schedule.push_back(*s.rate * 1e6);
    }
    const DryerSample& end = run.samples.back();
    return {
        {"model", "lumped film dryer (dryer.md D-1..D-4; Lippke et al. 2022 Sec. 6, Table A1)"},
        {"preset", p.preset},
        {"analogy_exponent", p.analogy_exponent},
        {"areal_loading_mg_cm2", p.areal_loading * 100.0},
        {"solids_density_g_cm3", run.geometry.solids_density * 1e-3},
        {"wet_film_height_um", run.geometry.wet_height * 1e6},
        {"final_thickness_um", run.geometry.final_height * 1e6},
        {"final_porosity", p.final_porosity},
        {"consolidation_time_s", opt(run.consolidation_time)},
        {"consolidation_position_m", opt(run.consolidation_time, p.line_speed)},
        {"dry_time_s", opt(run.dry_time)},
        {"dry_position_m", opt(run.dry_time, p.line_speed)},
        {"film_temperature_end_C", end.temperature - kelvin_offset},
        {"solvent_left_g_m2", end.liquid_mass * 1e3},
        {"zones", zones},
        {"schedule_rates_um_s", schedule},
        {"balances",
         {{"initial_solvent_g_m2", run.geometry.initial_liquid * 1e3},
          {"evaporated_g_m2", run.evaporated_mass * 1e3},
          {"heat_in_J_m2", run.heat_in},
          {"latent_heat_out_J_m2", run.latent_heat_out},
          {"liquid_sensible_enthalpy_out_J_m2", run.liquid_enthalpy_out}}},
        {"warnings", run.warnings},
        {"inputs", inputs_json(p)},
        {"version", fmt::format("{} ({})", DRYDEM_VERSION, DRYDEM_GIT_HASH)},
    };
}

void write_dryer_outputs(const std::filesystem::path& dir, const FilmDryerParams& p,
                         const DryerRun& run, const std::vector<SectionRate>& sections) {
    std::filesystem::create_directories(dir);
    {
        std::ofstream j(dir / "dryer.json");
        j << dryer_json(p, run, sections).dump(2) << "\n";
        if (!j) throw RunError(fmt::format("cannot write {}", (dir / "dryer.json").string()));
    }
    std::ofstream csv(dir / "dryer.csv");
    csv << "position_m,time_s,film_temperature_C,dryer_temperature_C,solvent_mass_fraction,"
           "film_thickness_um,evaporation_rate_g_m2_s,consolidated\n";
    const std::size_t stride =
        std::max<std::size_t>(1, std::size_t(std::lround(0.1 / p.time_step)));
    for (std::size_t i = 0; i < run.samples.size(); ++i) {
        if (i % stride != 0 && i + 1 != run.samples.size()) continue;
        const DryerSample& s = run.samples[i];
        csv << fmt::format("{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{}\n", s.position,
                           s.time, s.temperature - kelvin_offset, s.air_temperature - kelvin_offset,
                           s.solvent_fraction, s.thickness * 1e6, s.evaporation_rate * 1e3,
                           int(s.consolidated));
    }
    if (!csv) throw RunError(fmt::format("cannot write {}", (dir / "dryer.csv").string()));
}

} // namespace drydem::dryer
