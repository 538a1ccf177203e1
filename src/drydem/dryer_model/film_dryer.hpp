// SPDX-License-Identifier: MIT
// Lumped heat- and mass-transfer model of the wet film in the convective dryer (dryer.md D-1 ...
// D-4; paper Sec. 6, Eq. 14, Table A1, Table 2, after Kumberg et al.).
//
// A material element of coated web (dry solids + liquid NMP + aluminium foil) travels through the
// dryer zones at line speed v_l. Its state per unit area is (T, m_l): one uniform temperature
// (Biot ≈ 0.04) and the NMP mass per area. Before consolidation the film surface is wet with pure
// NMP and the film shrinks by the volume of evaporated NMP; at consolidation (liquid volume = pore
// volume of the final layer, D-2.5) the thickness freezes and the liquid recedes into the pores
// (D-2.6). The per-section least-squares slope of the thickness h(t) is the shrinkage rate s_k
// that drives the DEM's liquid level (D-4, paper Eq. 15).
#pragma once
#include "drydem/dryer_model/nmp_properties.hpp"
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace drydem::dryer {

/// One dryer section (paper Table A1): length, supply-air temperature, top heat transfer
/// coefficient.
struct DryerZone {
    double length = 2.0;             ///< ℓ_k [m]
    double air_temperature = 353.15; ///< T_g,k [K]
    double heat_transfer_top = 40.0; ///< α_top,k [W m^-2 K^-1]
};

/// Every parameter of the model (dryer.md D-3), SI. The members marked (config) mirror a key of the
/// run configuration and have no default here: the defaults are the configuration's, declared once
/// (io/config_keys.def); build the struct with film_dryer_params(config) or film_dryer_preset(name)
/// (dryer_model/dryer_config.hpp). The others are the model's own constants.
struct FilmDryerParams {
    std::string preset; ///< (config) recorded in every output (D-8.2)
    // formulation (paper Table 1, Sec. 7, Eq. 4)
    double w_ncm{}, w_pvdf{}, w_cb{};                       ///< (config) solids mass fractions
    double rho_ncm{}, rho_pvdf{}, rho_cb{};                 ///< (config) [kg/m^3]
    double cp_ncm = 750.0, cp_pvdf = 1300.0, cp_cb = 710.0; ///< [J kg^-1 K^-1] (A)
    double areal_loading{};        ///< (config) L, dry mass per area [kg/m^2]
    double solids_mass_fraction{}; ///< (config) x_s of the slurry
    double liquid_density{};       ///< (config) ρ_l used for the thickness [kg/m^3] (D-2.5)
    bool liquid_density_temperature = false; ///< use ρ_l(T) (D-5.6) instead (off, D-2.5)
    // substrate (A3: Al foil)
    double substrate_thickness{};     ///< (config) d_sub [m]
    double substrate_density{};       ///< (config) [kg/m^3]
    double substrate_heat_capacity{}; ///< (config) [J kg^-1 K^-1]
    // dryer (paper Sec. 5, Table A1)
    double line_speed{};          ///< (config) v_l [m/s]
    std::vector<DryerZone> zones; ///< (config)
    double bottom_factor{};       ///< (config) α_bot = factor · α_top (A1, decisive, D-2.2)
    double supply_air_solvent{};  ///< (config) ỹ_∞, NMP mole fraction in the supply air (A2)
    double pressure = constants::atmospheric_pressure; ///< p [Pa]
    double analogy_exponent{}; ///< (config or preset) n in β = α/(ρ c_p) Le^(n-1) (D-2.4)
    bool stefan = true;        ///< Stefan (log) form of the driving force (D-2.3)
    bool ackermann = false;    ///< (config) Ackermann correction of the top heat flux (D-2.2)
    Antoine vapour_pressure = antoine_anchored; ///< (config) D-5.1
    double initial_temperature{}; ///< (config) T_0 of the film at the dryer inlet [K] (A4)
    // end of shrinkage (from the DEM, D-6)
    double final_porosity{}; ///< (config) ε_f
    double tortuosity = 2.0; ///< τ of the dry layer after consolidation (A6)
    // numerics (D-2.7)
    double time_step{}; ///< (config) RK4 step [s], ≤ 0.05 s
};

/// The analogy exponent n of a preset of D-3: "physical" (Chilton-Colburn, 1/3) and "table2"
/// (0.42, calibrated to paper Table 2). Throws InputError for any other name.
[[nodiscard]] double preset_analogy_exponent(std::string_view preset);

/// Derived film quantities (D-2.1, D-2.5, paper Eqs. 3-4).
struct FilmGeometry {
    double solids_density;       ///< ρ_s (Eq. 4) [kg/m^3]
    double solids_height;        ///< h_sol = L/ρ_s [m]
    double initial_liquid;       ///< m_l(0) = L (1 - x_s)/x_s [kg/m^2]
    double wet_height;           ///< h_wet (Eq. 3) [m]
    double final_height;         ///< h_f = L/(ρ_s (1 - ε_f)) [m]
    double solids_heat_capacity; ///< c_p,s = Σ w_i c_p,i [J kg^-1 K^-1]
    double substrate_mass;       ///< ρ_sub d_sub [kg/m^2]
};
[[nodiscard]] FilmGeometry film_geometry(const FilmDryerParams& p);

/// Gas-side transfer in a zone at film temperature T (D-2.3, D-2.4).
struct GasSide {
    double film_temperature; ///< T_m = (T + T_g)/2 [K]
    double lewis;            ///< Le = λ/(ρ c_p D)
    double mass_transfer;    ///< β [m/s]
    double molar_density;    ///< c_g = p/(R T_m) [mol/m^3]
    double diffusion;        ///< D_NMP,air(T_m) [m^2/s]
};
[[nodiscard]] GasSide gas_side(const FilmDryerParams& p, const DryerZone& z, double T);

/// Wet-film (constant-rate) steady state of a zone: q_top + q_bot = ṁ Δh_v/M (D-7.1).
struct WetFilmSteadyState {
    double temperature;      ///< T_wet [K]
    double evaporation_rate; ///< ṁ [kg m^-2 s^-1]
    double shrinkage_rate;   ///< ṁ/ρ_l [m/s]
    double mass_transfer;    ///< β [m/s]
    double lewis;            ///< Le
};
[[nodiscard]] WetFilmSteadyState wet_film_steady_state(const FilmDryerParams& p, std::size_t zone);

/// One output sample (the state at the start of a step, D-2.7).
struct DryerSample {
    double time;             ///< t [s]
    double position;         ///< x = v_l t [m]
    double temperature;      ///< T [K]
    double liquid_mass;      ///< m_l [kg/m^2]
    double thickness;        ///< h [m]
    double evaporation_rate; ///< ṁ [kg m^-2 s^-1]
    double air_temperature;  ///< T_g of the zone [K]
    int zone;                ///< 0-based
    bool consolidated;
    /// Solvent mass fraction m_l/(m_l + L) (paper Fig. 3).
    double solvent_fraction;
};

/// Result of one pass through the dryer.
struct DryerRun {
    std::vector<DryerSample> samples;
    FilmGeometry geometry{};
    std::optional<double> consolidation_time; ///< t at which shrinkage ends [s]
    std::optional<double> dry_time;           ///< t at which m_l reaches 0 [s]
    // Integrals carried alongside the state by the same RK4 (for the balance checks):
    double heat_in = 0.0;         ///< ∫ (q_top + q_bot) dt [J/m^2]
    double evaporated_mass = 0.0; ///< ∫ ṁ dt [kg/m^2]
    double latent_heat_out = 0.0; ///< ∫ ṁ Δh_v/M dt [J/m^2]
    double liquid_enthalpy_out =
        0.0; ///< ∫ ṁ h_l(T) dt, sensible enthalpy of the leaving liquid [J/m^2]
    /// Correlations evaluated outside their validity range (ValidityRange), one line each.
    std::vector<std::string> warnings;
};

/// Integrates the film through all zones (RK4, steps aligned with the zone boundaries, at most
/// params.time_step long; consolidation evaluated at the start of each step; the step in which
/// the film dries is shortened to end at m_l = 0). D-2.1 ... D-2.7.
[[nodiscard]] DryerRun simulate_film_dryer(const FilmDryerParams& p);

/// Sensible enthalpy of the film relative to T_0 [J/m^2]: (L c_p,s + ρ_sub d_sub c_p,sub)(T - T_0)
/// + m_l ∫_{T_0}^{T} c_p,l dT. With it the energy balance of Eq. 14 reads
/// heat_in = ΔH_sensible + liquid_enthalpy_out + latent_heat_out.
[[nodiscard]] double film_sensible_enthalpy(const FilmDryerParams& p, double T, double m_l);

/// D-4: minus the least-squares slope of h over t [same unit per s]; nullopt for fewer than 5
/// samples or less than 0.1 s of data.
[[nodiscard]] std::optional<double> fitted_shrinkage_rate(std::span<const double> t,
                                                          std::span<const double> h);

/// Per-section result of D-4.
struct SectionRate {
    double t_begin, t_end;      ///< section k covers [t_begin, t_end) [s]
    std::optional<double> rate; ///< s_k [m/s] (positive = shrinking)
    std::size_t samples = 0;    ///< unconsolidated samples in the fit
};
/// D-4: s_k for every zone from the unconsolidated samples of that zone.
[[nodiscard]] std::vector<SectionRate> fit_section_rates(const FilmDryerParams& p,
                                                         const DryerRun& run);

/// Eq. 15: rate per position s_p [m/m] from rate per time s_t [m/s] and v_l [m/s]; s_t = s_p v_l.
[[nodiscard]] constexpr double rate_per_position(double rate_per_time, double line_speed) {
    return rate_per_time / line_speed;
}
[[nodiscard]] constexpr double rate_per_time(double rate_per_position, double line_speed) {
    return rate_per_position * line_speed;
}

/// The leading defined section rates, in order (the DEM's liquid-level schedule, D-6 step 3):
/// sections after consolidation have no rate and are left out. Throws InputError if the first
/// section has none.
[[nodiscard]] std::vector<double> schedule_rates(const std::vector<SectionRate>& sections);

/// Final porosity from the final thickness: ε_f = 1 - L/(ρ_s h_f) (D-6 step 5).
[[nodiscard]] double porosity_from_thickness(const FilmDryerParams& p, double final_thickness);

/// Paper Table 2 (shrinkage rates s_1, s_2 [m/s] per areal loading [kg/m^2]) for comparisons.
struct Table2Row {
    double areal_loading, s1, s2;
};
inline constexpr Table2Row paper_table2[] = {{0.201, 0.670e-6, 1.193e-6},
                                             {0.252, 0.683e-6, 1.323e-6},
                                             {0.303, 0.667e-6, 1.360e-6},
                                             {0.354, 0.650e-6, 1.383e-6}};

} // namespace drydem::dryer
