// SPDX-License-Identifier: MIT
// The quantities a configuration implies (particle counts, wet height, scaled parameters, steps,
// memory, the dryer model's step count) checked before anything runs: every key may be in range
// and still give 1e20 particles (a bare `box_x = 40` is 40 m) or 1e300 steps. Each refusal names
// the keys that caused it.
#pragma once
#include "drydem/drying/scaling.hpp"
#include "drydem/io/config.hpp"
#include "drydem/setup/formulation.hpp"
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace drydem {

/// Upper limits of what DryDEM sets up: far beyond any electrode film (the paper's largest case
/// has ~1.6e5 particles and ~1e8 steps), far below what overflows (32-bit particle ids, doubles).
inline constexpr double max_particles = 1e8;
inline constexpr double max_steps = 1e12;           ///< estimated DEM steps of the run
inline constexpr double max_wet_film_height = 0.01; ///< [m]; wet electrode films are < 1 mm
inline constexpr double max_dryer_steps = 1e6;      ///< RK4 steps of the dryer model (D-2.7)
/// Memory per particle: state (13 Vec3), species and ids, ~20 neighbour entries with history
/// (the estimate `drydem check` prints).
inline constexpr double bytes_per_particle = 13 * 24.0 + 6 * 8 + 20 * 40;

/// What a configuration implies, as plain doubles (never overflowing integers).
struct DerivedQuantities {
    double particles = 0.0;       ///< unrounded total count
    double wet_film_height = 0.0; ///< [m]
    double solids_density = 0.0;  ///< [kg/m^3]
    double final_thickness = 0.0; ///< at an uncalendered density (setup/solids.hpp) [m] (M-8.3)
    double level_travel = 0.0;    ///< of the liquid level until the end criterion [m] (M-8.3)
    double sim_time = 0.0;        ///< estimated simulated time of the run [s] (M-8.3)
    double steps = 0.0;           ///< sim_time / the largest step
    double particle_steps_per_core = 0.0; ///< the rate the wall time is estimated at [1/s]
    double memory_bytes = 0.0;            ///< particles x bytes_per_particle + 5 MB
    double dryer_steps = 0.0;             ///< RK4 steps of the dryer model over all zones
};

/// Particle-steps per second and core a run is estimated at (the semi-implicit paper scheme
/// measured 2.3e6-3.4e6 on one core of the 2-core reference machine, docs/performance.md); a
/// run whose estimate passes a day is warned about.
inline constexpr double reference_particle_steps_per_core = 2e6;
/// The same for the quasi-static step, counted in its largest steps (the level's): the quick case
/// at the process's settings took ~90x as many steps in its first 10.5 s (17,469 against 188),
/// at ~2.7e4 particle-steps/s on one core, so ~300 per largest step (CG iterations per step grow
/// with the contacts; docs/performance.md, "Quasi-static step").
inline constexpr double reference_quasi_static_particle_steps_per_core = 300;
inline constexpr double wall_time_warning = 86400.0; ///< [s]

/// parse_config, then check_derived_quantities: a configuration every command can run.
Config load_config(std::string_view toml_text, std::string_view source_name,
                   const std::vector<std::string>& overrides = {});
Config load_config_file(const std::string& path, const std::vector<std::string>& overrides = {});

/// Computes the derived quantities without checking them (InputError only from make_recipe).
[[nodiscard]] DerivedQuantities derived_quantities(const Config& c);

/// Estimated wall time of the run's DEM part on `threads` cores [s]: steps at the largest step x
/// particles / (the integrator's particle-steps per core x threads); the guard may lower the step.
[[nodiscard]] double estimated_wall_time(const DerivedQuantities& d, int threads);

/// Voxels of the end-of-run voxel image (analysis.voxel_size) for a film of this thickness [m].
[[nodiscard]] double voxel_image_voxels(const Config& c, const FilmRecipe& r,
                                        double final_thickness);

/// The time scales of the smallest particle that bound the step (M-9.2, `drydem check`): Rayleigh
/// time, Hertz contact time at 1 m/s and at the first level speed, twice the drag relaxation time,
/// the period of the capillary spring (infinite when the capillary force is off) [s].
struct TimeScales {
    double diameter = 0.0, mass = 0.0; ///< of the smallest particle [m], [kg]
    double rayleigh = 0.0, contact_at_1m_s = 0.0, contact_at_level_speed = 0.0;
    double drag_relaxation = 0.0, capillary_period = 0.0;
};
[[nodiscard]] TimeScales time_scales(const Config& c, const FilmRecipe& r,
                                     const ScaledParameters& s, const ForceField& ff);

/// Throws InputError when a derived quantity is not finite and positive or beyond the limits
/// above, naming the keys behind it. `bare_lengths`: length keys the input gave as bare numbers
/// (SI metres); a suspicious one gets a hint ("film.box_x = 40 is 40 m; did you mean \"40 um\"?").
void check_derived_quantities(const Config& c, const std::vector<std::string>& bare_lengths = {});

/// Physical memory of this machine [bytes] (0 if unknown).
[[nodiscard]] double physical_memory_bytes();

/// Throws InputError when the run needs more memory than 80 % of this machine has (the check of
/// `drydem run`; `drydem check` only reports it, a config may be meant for a bigger machine).
void check_fits_this_machine(const Config& c);

} // namespace drydem
