// SPDX-License-Identifier: MIT
// Run configuration: every value in SI, converted once from the TOML at the edge. The defaults
// are the paper's 20.1 mg/cm2 case (model.md M-1 ... M-9); the embedded default configuration
// (default_config_toml()) lists the same values with units and is tested to agree with them.
#pragma once
#include <cstdint>
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
};
/// Every quantity [[calibration.targets]] accepts.
const std::vector<CalibrationQuantity>& calibration_quantities();

struct Config {
    // [run]
    std::string name = "lippke2022-20.1mgcm2";
    std::uint64_t seed = 12345;
    double time_step = 0.0;              ///< largest simulated (scaled) Δt [s]; 0 = by integrator
    int threads = 0;                     ///< 0 = all cores
    double max_process_time = 300.0;     ///< safety stop [s physical]

    // [film]
    double areal_loading = 0.201;        ///< dry areal mass L [kg/m^2] (= 20.1 mg/cm2)
    double solids_mass_fraction = 0.70;  ///< x_s
    double box_x = 75e-6, box_y = 75e-6; ///< periodic base [m]

    // [formulation]
    double ncm_mass_fraction = 0.94, pvdf_mass_fraction = 0.03, cb_mass_fraction = 0.03;
    std::vector<double> ncm_diameters = {6.50e-6, 7.58e-6, 8.60e-6, 9.82e-6, 11.35e-6};
    double cb_diameter = 1.5e-6;
    double cb_porosity = 0.75;           ///< ε_CB (paper Sec. 9)

    // [materials]
    double ncm_density = 4740, cb_density = 1660, pvdf_density = 1780, solvent_density = 1030;
    double viscosity = 1.801;            ///< PVDF-in-NMP liquid η [Pa s]
    double surface_tension = 0.041;      ///< σ [N/m]
    double contact_angle = 0.69813170079773179; ///< θ = 40° [rad]
    double ncm_youngs_modulus = 142e9, cb_youngs_modulus = 142e9; ///< C-9
    double poisson_ratio = 0.3;          ///< C-10
    double substrate_youngs_modulus = 70e9, substrate_poisson_ratio = 0.33; ///< C-8

    // [contact]
    double friction = 0.8, substrate_friction = 0.8; ///< μ_s (paper Sec. 9; C-6)
    double restitution = 0.5;            ///< C-11
    double rolling_friction = 0.0;       ///< C-7

    // [van_der_waals] physical Hamaker constants [J] and minimum gaps [m] (M-3)
    double hamaker_cb_cb = 4.64e-20, hamaker_ncm_cb = 9.5e-20, hamaker_ncm_ncm = 2.11e-19;
    double min_gap_cb_cb = 5e-9, min_gap_ncm_cb = 10e-9, min_gap_ncm_ncm = 50e-9;
    double vdw_cutoff = 0.0;             ///< h_cut [m]; 0 = the pair's lubrication range r_L (C-13)

    // [lubrication] (M-4)
    bool lubrication = true;
    bool substrate_lubrication = true;
    double kappa_c = 0.1;
    bool lubrication_uses_reduced_viscosity = false; ///< C-17

    // [double_layer] electrostatic double-layer repulsion (DLVO; off, as in the paper)
    bool double_layer = false;
    double double_layer_potential = -0.025;       ///< surface potential ψ₀ [V]
    double double_layer_debye_length = 100e-9;    ///< λ_D [m]
    double double_layer_permittivity = 32.2;      ///< ε_r of the liquid (NMP)
    double double_layer_cutoff = 0.0;             ///< h_cut [m]; 0 = the pair's r_L, as van der Waals

    // [scaling] (M-7)
    double time_factor = 1e7;            ///< k
    double viscosity_reduction = 10;     ///< b
    double capillary_factor = 9e3;
    double hamaker_factor = 1e7;
    double gravity = 9.81;               ///< physical g [m/s^2]

    // [dryer] (M-8.1, paper Table 2)
    std::vector<double> shrinkage_rates = {0.670e-6, 1.193e-6}; ///< physical [m/s] per zone
    double line_speed = 2.0 / 60.0;      ///< [m/s]
    double zone_length = 2.0;            ///< [m] zone length of the DEM liquid-level schedule
    // [dryer] the dryer model (dryer.md D-1 ... D-6; paper Sec. 6, Table A1)
    std::string dryer_schedule = "rates"; ///< DEM level from "rates" (shrinkage_rates) or "model"
    std::string dryer_preset = "table2";  ///< "table2" (n = 0.42, calibrated) | "physical" (D-3)
    std::vector<double> dryer_zone_lengths = {2.0, 2.0, 2.0};          ///< ℓ_k [m]
    std::vector<double> dryer_air_temperatures = {80.0 + 273.15, 100.0 + 273.15,
                                                  120.0 + 273.15};     ///< T_g,k [K]
    std::vector<double> dryer_heat_transfer_coefficients = {40.0, 40.0, 55.0}; ///< α_top,k [W m^-2 K^-1]
    double dryer_bottom_factor = 1.0;     ///< α_bot/α_top (A1)
    double dryer_analogy_exponent = 0.0;  ///< n of the heat/mass analogy; 0 = the preset's (D-2.4)
    double dryer_initial_temperature = 25.0 + 273.15; ///< film at the dryer inlet [K] (A4)
    double dryer_substrate_thickness = 20e-6;   ///< Al foil [m] (A3)
    double dryer_substrate_density = 2700.0;    ///< [kg/m^3]
    double dryer_substrate_heat_capacity = 900.0; ///< [J kg^-1 K^-1]
    double dryer_supply_air_solvent = 0.0;      ///< NMP mole fraction in the supply air (A2)
    double dryer_final_porosity = 0.44;         ///< ε_f guess for the end of shrinkage (D-6)
    std::string dryer_vapour_pressure = "anchored"; ///< "anchored" | "landolt" (D-5.1)
    bool dryer_ackermann = false;               ///< Ackermann correction (D-2.2)
    double dryer_time_step = 0.02;              ///< RK4 step of the dryer model [s] (D-2.7)
    double coupling_tolerance = 0.5e-6;         ///< stop when |Δh_f| < this [m] (D-6)
    int coupling_max_iterations = 6;            ///< dryer <-> DEM iterations at most (D-6)

    // [drying]
    double final_gap = 0.0;              ///< end criterion top - z_L [m]; 0 = largest diameter (M-8.2)
    double relaxation = 10.0;            ///< relaxation window [s physical] (C-22)
    std::string fluid_forces_above_level = "keep"; ///< C-19: "keep" (only option implemented)

    // [numerics]
    double skin = 0.0; ///< neighbour skin [m]; 0 = by integrator (neighbor_skin)
    double overlap_limit = 1.0;
    std::string stability_guard = "adapt"; ///< "adapt" | "refuse" | "warn" (M-9.2)
    std::string integrator = "semi_implicit"; ///< "semi_implicit" | "explicit" (docs/model.md)
    int sort_every = 10;

    // [study] (drydem study; paper Fig. 6)
    std::vector<double> study_loadings;  ///< [kg/m^2]; empty = film.areal_loading
    int study_seeds = 3;                 ///< runs per loading (seeds run.seed, run.seed + 1, ...)
    /// Drying-rate study: each factor multiplies dryer.shrinkage_rates (schedule "rates"); empty = x1.
    std::vector<double> study_shrinkage_rate_factors;
    std::vector<double> measured_loadings;        ///< [kg/m^2] of the measured points
    std::vector<double> measured_thickness;       ///< [m], one per measured loading
    std::vector<double> measured_thickness_std;   ///< [m]; empty or one per measured loading
    std::vector<double> measured_density;         ///< [kg/m^3]; empty or one per measured loading
    std::vector<double> measured_density_std;     ///< [kg/m^3]; empty or one per measured loading

    // [calibration] (drydem calibrate; docs/calibration.md). The parameters and targets are arrays
    // of tables ([[calibration.parameters]], [[calibration.targets]]), not written by to_toml.
    std::vector<CalibrationParameter> calibration_parameters;
    std::vector<CalibrationTarget> calibration_targets;
    int calibration_seeds = 1;           ///< runs per evaluation (seeds run.seed, run.seed + 1, ...)
    int calibration_initial_points = 0;  ///< space-filling start; 0 = max(4, 2 x parameters)
    int calibration_evaluations = 20;    ///< evaluations in all, the start included
    std::string calibration_sampler = "sobol"; ///< "sobol" | "lhs" (SciPy qmc)

    // [scheduler] where drydem study / calibrate run their runs (docs/calibration.md "Slurm")
    std::string scheduler = "local";     ///< "local" (child processes) | "slurm" (a job array)
    std::string slurm_partition;         ///< "" = the cluster's default partition
    double slurm_time_limit = 0.0;       ///< per task [s]; 0 = the partition's default
    int slurm_cpus_per_task = 1;         ///< threads per run (SLURM_CPUS_PER_TASK)
    int slurm_resubmits = 3;             ///< a task stopped at its time limit is resubmitted (resumed) up to N times

    // [analysis] structure analysis of the final particles (drydem analyze; docs/analysis.md)
    bool analysis_at_end = true;          ///< analyse final.csv at the end of every run
    double analysis_voxel_size = 0.1e-6;  ///< [m]; 0 = only the particle-based numbers
    double analysis_profile_dz = 0.5e-6;  ///< slab width of the height profiles [m]
    double analysis_contact_gap = 0.0;    ///< coordination: surface gap counted as contact [m]
    std::string analysis_pore_top = "half_solid"; ///< "half_solid" | "highest"
    /// Transport (docs/analysis.md): voxel sizes of the tortuosity / conductivity solves, the finest
    /// solved one reported; empty = none. Sizes with more voxels than the limit are skipped.
    std::vector<double> analysis_transport_voxel_sizes = {0.8e-6, 0.4e-6, 0.2e-6};
    std::uint64_t analysis_transport_max_voxels = 25'000'000;
    double analysis_ncm_conductivity = 1.0e-2; ///< electronic conductivity of NCM [S/m]
    double analysis_cb_conductivity = 100.0;   ///< electronic conductivity of a CB agglomerate [S/m]
    int analysis_surface_points = 400;         ///< points per NCM sphere of the surface split; 0 = none
    double analysis_cb_coverage_gap = 0.1e-6;  ///< NCM surface within this of a CB surface is covered [m]
    double analysis_binder_diffusivity = 6.5e-12; ///< D₀ of dissolved PVDF in NMP [m²/s] (Stokes–Einstein)

    // [output]
    double timeseries_every = 0.5;       ///< [s physical]
    double snapshot_every = 10.0;        ///< [s physical]; 0 = no intermediate snapshots
    double progress_every = 10.0;        ///< wall-clock seconds between progress lines
    double checkpoint_every = 600.0;     ///< wall-clock seconds between checkpoints; 0 = none

    /// The largest time step: time_step, or with 0 the integrator's cap (explicit 1e-11 s, C-23;
    /// semi-implicit 1e-10 s, the contact limit; docs/model.md "Stability guard").
    [[nodiscard]] double time_step_cap() const {
        if (time_step > 0.0) return time_step;
        return integrator == "explicit" ? 1.0e-11 : 1.0e-10;
    }
    /// The neighbour skin: skin, or with 0 the integrator's default (explicit 0.1 um, M-9.4;
    /// semi-implicit 0.3 um: at its ~10x longer steps a 0.1 um skin is used up within a few dozen
    /// steps, and rebuilds and guard estimates would cost more than the wider list; docs/performance.md).
    [[nodiscard]] double neighbor_skin() const {
        if (skin > 0.0) return skin;
        return integrator == "explicit" ? 0.1e-6 : 0.3e-6;
    }
};

/// The embedded default configuration (the paper's 20.1 mg/cm2 case), as TOML text.
std::string_view default_config_toml();

/// Parses and validates a TOML document (unknown keys, wrong units and out-of-range values throw
/// InputError naming the key, the value and what is allowed). `overrides` are "dotted.key=value"
/// strings applied on top (value parsed as TOML, else taken as a string).
Config load_config(std::string_view toml_text, std::string_view source_name,
                   const std::vector<std::string>& overrides = {});
Config load_config_file(const std::string& path, const std::vector<std::string>& overrides = {});

/// The resolved configuration as TOML, every value in SI (written into each output folder).
std::string to_toml(const Config& c);

} // namespace drydem
