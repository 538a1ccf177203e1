// SPDX-License-Identifier: MIT
#include "drydem/drying/law_parameters.hpp"
#include "drydem/drying/derived_checks.hpp"
#include "drydem/setup/solids.hpp"
#include "drydem/core/error.hpp"
#include "drydem/analysis/analyze.hpp"
#include "drydem/drying/dimensionless_groups.hpp"
#include "drydem/drying/scaling.hpp"
#include "drydem/drying/stability_clusters.hpp"
#include "drydem/drying/stability_guard.hpp"
#include "drydem/setup/formulation.hpp"
#include "drydem/core/sphere.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <unistd.h>
#include <tuple>
#include <utility>

namespace drydem {

namespace {

bool positive_finite(double v) { return std::isfinite(v) && v > 0.0; }

/// Scalar length keys that may appear among the causes of a refusal, for the bare-number hint.
struct LengthKey {
    std::string_view key;
    double Config::*member;
};
constexpr LengthKey kLengthKeys[] = {
    {"film.box_x", &Config::box_x},
    {"film.box_y", &Config::box_y},
    {"formulation.cb_diameter", &Config::cb_diameter},
    {"dryer.zone_length", &Config::zone_length},
    {"drying.final_gap", &Config::final_gap},
};

/// "; film.box_x = 40 is a bare number, i.e. 40 m (bare numbers are SI); did you mean "40 um"?"
/// for every cause given as a bare number of a millimetre or more (a DEM film is micrometres).
std::string bare_length_hints(const Config& c, const std::vector<std::string_view>& causes,
                              const std::vector<std::string>& bare_lengths) {
    std::string out;
    for (const LengthKey& k : kLengthKeys) {
        const double v = c.*k.member;
        const bool cause = std::find(causes.begin(), causes.end(), k.key) != causes.end();
        const bool bare =
            std::find(bare_lengths.begin(), bare_lengths.end(), k.key) != bare_lengths.end();
        if (cause && bare && v >= 1e-3 && v < 1e6) // read as um, a length a user may mean
            out +=
                fmt::format("; {} = {:g} is a bare number, i.e. {:g} m (bare numbers are SI): did "
                            "you mean \"{:g} um\"?",
                            k.key, v, v, v);
    }
    return out;
}

[[noreturn]] void refuse(const Config& c, const std::string& what,
                         const std::vector<std::string_view>& causes,
                         const std::vector<std::string>& bare_lengths) {
    std::string keys;
    for (std::string_view k : causes) keys += fmt::format("{}{}", keys.empty() ? "" : ", ", k);
    throw InputError(
        fmt::format("{} (set by {}){}", what, keys, bare_length_hints(c, causes, bare_lengths)));
}

/// The level's travel until it is a largest diameter above the film of an uncalendered coating
/// (setup/solids.hpp), and the simulated time of that travel plus the relaxation window (the cost
/// estimate of `drydem check`, M-8.3).
struct TravelEstimate {
    double final_thickness, travel, sim_time;
};
TravelEstimate estimated_travel(const Config& c, const FilmRecipe& r, const ScaledParameters& s) {
    const double gap = c.final_gap > 0 ? c.final_gap : r.largest_diameter();
    const double h_final = c.areal_loading / uncalendered_density;
    const double travel = std::max(0.0, r.wet_film_height - h_final + gap);
    double left = travel, t = 0.0;
    for (std::size_t z = 0; z < s.level_speeds_scaled.size() && left > 0; ++z) {
        const bool last = z + 1 == s.level_speeds_scaled.size();
        const double dz =
            last ? left : std::min(left, s.level_speeds_scaled[z] * s.zone_duration_scaled);
        t += dz / s.level_speeds_scaled[z];
        left -= dz;
    }
    return {h_final, travel, t + s.sim_time(c.relaxation)};
}

/// Minimum image: a pair's reach plus the neighbour skin must stay below half the periodic length,
/// the reach being what the pair laws say (forces/force_field.hpp interaction_range: for two of the
/// largest spheres d + r_L = 1.5 d with the defaults, M-4.1, C-13; wider with a van der Waals or
/// double-layer cutoff beyond r_L).
void check_minimum_image(const Config& c, const FilmRecipe& r, const ScaledParameters& s) {
    const PairReach widest = widest_pair_reach(make_drying_force_field(c, r, s), r);
    const double need = 2.0 * (widest.reach + c.neighbor_skin());
    for (const auto& [key, side] :
         {std::pair{"film.box_x", c.box_x}, std::pair{"film.box_y", c.box_y}})
        if (side < need)
            throw InputError(fmt::format("config key '{}': {:g} um is below twice the largest "
                                         "interaction range plus skin ({:g} um "
                                         "for {:g} and {:g} um spheres); allowed >= {:g} um",
                                         key, side * 1e6, need * 0.5e6, widest.diameter_i * 1e6,
                                         widest.diameter_j * 1e6, need * 1e6));
}

/// The keys behind the scaled forces and viscosities, named by every refusal of a model quantity.
constexpr std::string_view kScalingKeys[] = {"scaling.scheme",
                                             "scaling.time_factor",
                                             "scaling.viscosity_reduction",
                                             "scaling.capillary_factor",
                                             "scaling.hamaker_factor",
                                             "scaling.stiffness_factor",
                                             "scaling.cb_density_scaling"};

std::vector<std::string_view> with_scaling(std::vector<std::string_view> keys) {
    keys.insert(keys.end(), std::begin(kScalingKeys), std::end(kScalingKeys));
    return keys;
}

/// Every dimensionless group `drydem check` prints (docs/model.md M-7), physical and as simulated:
/// finite and not negative. A law's parameters can each be in range and still overflow together.
void check_groups(const Config& c, const std::vector<std::string>& bare) {
    using G = double Groups::*;
    const std::vector<std::string_view> fluid = {"materials.viscosity", "materials.surface_tension",
                                                 "materials.contact_angle"};
    const std::vector<std::string_view> contact = {
        "materials.ncm_youngs_modulus", "materials.cb_youngs_modulus",
        "materials.substrate_youngs_modulus", "materials.poisson_ratio",
        "materials.substrate_poisson_ratio"};
    const std::vector<std::string_view> vdw = {
        "van_der_waals.hamaker_cb_cb", "van_der_waals.hamaker_ncm_cb",
        "van_der_waals.min_gap_cb_cb", "van_der_waals.min_gap_ncm_cb"};
    const auto plus = [](std::vector<std::string_view> a, const std::vector<std::string_view>& b) {
        a.insert(a.end(), b.begin(), b.end());
        return a;
    };
    const std::tuple<std::string_view, G, std::vector<std::string_view>> rows[] = {
        {"capillary number (drag)", &Groups::capillary_drag, fluid},
        {"capillary number (lubrication)", &Groups::capillary_lubrication,
         plus(fluid, {"lubrication.kappa_c"})},
        {"push number", &Groups::push, plus(fluid, {"film.areal_loading"})},
        {"Stokes number (NCM)", &Groups::stokes_ncm, plus(fluid, {"materials.ncm_density"})},
        {"Stokes number (CB)", &Groups::stokes_cb, plus(fluid, {"materials.cb_density"})},
        {"inertial number", &Groups::inertial, plus(fluid, {"materials.ncm_density"})},
        {"van der Waals / capillary (CB-CB)", &Groups::vdw_capillary_cb_cb, plus(fluid, vdw)},
        {"van der Waals / capillary (NCM-CB)", &Groups::vdw_capillary_ncm_cb, plus(fluid, vdw)},
        {"Bond number", &Groups::bond_ncm,
         plus(fluid, {"scaling.gravity", "materials.ncm_density"})},
        {"expected Hertz overlap (CB-CB)", &Groups::overlap_cb_cb, plus(contact, vdw)},
        {"expected Hertz overlap (NCM-CB)", &Groups::overlap_ncm_cb, plus(contact, fluid)},
        {"expected Hertz overlap (NCM-substrate)", &Groups::overlap_ncm_substrate,
         plus(contact, fluid)},
    };
    const DimensionlessGroups d = dimensionless_groups(c);
    for (std::size_t z = 0; z < d.simulated.size(); ++z)
        for (const auto& [name, member, keys] : rows)
            for (const auto& [which, g] :
                 {std::pair{"physical", d.physical[z]}, std::pair{"simulated", d.simulated[z]}})
                if (!(std::isfinite(g.*member) && g.*member >= 0.0))
                    refuse(c,
                           fmt::format("the {} {} in dryer zone {} is {:g}; it must be finite",
                                       which, name, z + 1, g.*member),
                           with_scaling(keys), bare);
}

/// The time scales `drydem check` prints: finite and positive (the capillary period may be infinite
/// only with the capillary force off).
void check_time_scales(const Config& c, const FilmRecipe& r, const ScaledParameters& s,
                       const std::vector<std::string>& bare) {
    const TimeScales t = time_scales(c, r, s, make_drying_force_field(c, r, s));
    const bool capillary_off = s.surface_tension_scaled == 0.0;
    for (const auto& [name, value] :
         {std::pair{"Rayleigh time", t.rayleigh},
          std::pair{"Hertz contact time", t.contact_at_1m_s},
          std::pair{"Hertz contact time at the level speed", t.contact_at_level_speed},
          std::pair{"drag relaxation time", t.drag_relaxation},
          std::pair{"capillary spring period", capillary_off ? 1.0 : t.capillary_period}})
        if (!positive_finite(value))
            refuse(c,
                   fmt::format(
                       "the {} of the smallest particle is {:g} s; it must be finite and positive",
                       name, value),
                   with_scaling({"materials.cb_youngs_modulus", "materials.ncm_youngs_modulus",
                                 "materials.poisson_ratio", "materials.viscosity",
                                 "materials.surface_tension", "formulation.cb_diameter"}),
                   bare);
}

/// The stability guard's rates on its reference clusters, for both integrators (as `drydem check`
/// prints them): finite, and the guarded step they give positive.
void check_guard_rates(const Config& c, const FilmRecipe& r, const std::vector<std::string>& bare) {
    for (const char* integrator : {"explicit", "semi_implicit"}) {
        for (const ClusterEstimate& k : guard_on_reference_clusters(c, r, integrator)) {
            const Simulation::StabilityEstimate& e = k.estimate;
            const double dt = k.dt;
            if (std::isfinite(e.damping_rate) && std::isfinite(e.stiffness_rate) &&
                positive_finite(dt))
                continue;
            refuse(
                c,
                fmt::format("the stability guard ({}) on the reference cluster '{}' gives a "
                            "damping rate of {:g} "
                            "/s, a stiffness rate of {:g} rad/s and a step of {:g} s; they must be "
                            "finite and "
                            "the step positive",
                            integrator, k.name, e.damping_rate, e.stiffness_rate, dt),
                with_scaling({"materials.viscosity", "lubrication.kappa_c",
                              "materials.cb_youngs_modulus", "materials.ncm_youngs_modulus",
                              "materials.poisson_ratio", "contact.restitution", "run.time_step"}),
                bare);
        }
    }
}

/// numerics.critical_step_fraction above the explicit integrator's 0.5 only with the semi-implicit
/// kick (its damping is implicit: the stiffness bound stands alone); the quasi-static step has no
/// guarded step at all.
void check_critical_step_fraction(const Config& c, const std::vector<std::string>& bare) {
    const double f = c.critical_step_fraction;
    if (c.integrator == "explicit" && f > kExplicitCriticalFraction)
        refuse(c,
               fmt::format("numerics.critical_step_fraction = {:g} with numerics.integrator = "
                           "\"explicit\": allowed up to {:g} there, where the damping and "
                           "stiffness bounds combine ((dt omega)^2 + 2 dt lambda < 4); larger "
                           "only with \"semi_implicit\" (docs/model.md \"Stability guard\")",
                           f, kExplicitCriticalFraction),
               {"numerics.critical_step_fraction", "numerics.integrator"}, bare);
    if (c.integrator == "quasi_static" && f != 0.0)
        refuse(c,
               fmt::format("numerics.critical_step_fraction = {:g} with numerics.integrator = "
                           "\"quasi_static\": that step has no stability guard (numerics."
                           "max_displacement sets it); leave the key at 0",
                           f),
               {"numerics.critical_step_fraction", "numerics.integrator"}, bare);
    if (c.implicit_stiffness.value_or(false) && c.integrator != "semi_implicit")
        refuse(c,
               fmt::format("numerics.implicit_stiffness = true with numerics.integrator = "
                           "\"{}\": the self-stiffness joins the semi-implicit kick only "
                           "(docs/model.md M-9.1)",
                           c.integrator),
               {"numerics.implicit_stiffness", "numerics.integrator"}, bare);
}

/// The end-of-run voxel image (docs/analysis.md): a finite size that fits in this machine's memory
/// where that is known, else in 1e11 voxels.
void check_voxel_image(const Config& c, const FilmRecipe& r, double final_thickness,
                       const std::vector<std::string>& bare) {
    if (!c.analysis_at_end || c.analysis_voxel_size <= 0.0) return;
    const double voxels = voxel_image_voxels(c, r, final_thickness);
    const double have = physical_memory_bytes(), bytes = analysis::voxel_analysis_bytes * voxels;
    const double limit = have > 0.0 ? have : analysis::voxel_analysis_bytes * 1e11;
    if (!positive_finite(voxels) || bytes > limit)
        refuse(c,
               fmt::format("the end-of-run voxel image would have ~{:.3g} voxels at {:g} um "
                           "(~{:.3g} GB); allowed "
                           "what fits in {:.3g} GB",
                           voxels, c.analysis_voxel_size * 1e6, bytes / 1e9, limit / 1e9),
               {"analysis.voxel_size", "analysis.at_end", "film.box_x", "film.box_y",
                "film.areal_loading"},
               bare);
}

/// Film (M-1): the wet height and the particles the loading puts into the box.
void check_film(const Config& c, const FilmRecipe& r, const std::vector<std::string>& bare) {
    const std::vector<std::string_view> film_keys = {
        "film.areal_loading",     "film.solids_mass_fraction", "materials.ncm_density",
        "materials.pvdf_density", "materials.cb_density",      "materials.solvent_density"};
    if (!positive_finite(r.wet_film_height) || r.wet_film_height > max_wet_film_height)
        refuse(c,
               fmt::format("the wet film height (Eq. 3) is {:g} m; allowed (0, {:g} m]",
                           r.wet_film_height, max_wet_film_height),
               film_keys, bare);
    double total = 0.0;
    for (const SizeClass& sc : r.species) {
        if (!(std::isfinite(sc.count_exact) && sc.count_exact <= max_particles)) {
            const std::vector<std::string_view> causes =
                sc.is_cb ? std::vector<std::string_view>{"formulation.cb_diameter",
                                                         "formulation.cb_mass_fraction",
                                                         "formulation.cb_porosity",
                                                         "film.areal_loading",
                                                         "film.box_x",
                                                         "film.box_y"}
                         : std::vector<std::string_view>{
                               "formulation.ncm_diameters", "formulation.ncm_mass_fraction",
                               "film.areal_loading", "film.box_x", "film.box_y"};
            refuse(c,
                   fmt::format("the film would hold {:.3g} {} particles of {:.4g} um in a {:.4g} x "
                               "{:.4g} um box; "
                               "allowed at most {:g} particles in all",
                               sc.count_exact, sc.is_cb ? "CB" : "NCM", sc.diameter * 1e6,
                               c.box_x * 1e6, c.box_y * 1e6, max_particles),
                   causes, bare);
        }
        total += sc.count_exact;
    }
    if (total > max_particles)
        refuse(c,
               fmt::format("the film would hold {:.3g} particles in a {:.4g} x {:.4g} um box; "
                           "allowed at most {:g}",
                           total, c.box_x * 1e6, c.box_y * 1e6, max_particles),
               {"film.areal_loading", "film.box_x", "film.box_y", "formulation.ncm_diameters",
                "formulation.cb_diameter"},
               bare);
    if (r.particle_count() == 0)
        refuse(c,
               fmt::format(
                   "the film has no particles: {:.3g} mg/cm2 on a {:.4g} x {:.4g} um base round to "
                   "0 NCM "
                   "and 0 CB particles ({:.3g} unrounded); raise film.areal_loading or the box, or "
                   "the NCM or CB mass fraction",
                   c.areal_loading * 100, c.box_x * 1e6, c.box_y * 1e6, total),
               {"film.areal_loading", "film.box_x", "film.box_y", "formulation.ncm_mass_fraction",
                "formulation.cb_mass_fraction"},
               bare);
}

/// Scaling (M-7): every scaled value finite, the level moving and the zones lasting.
void check_scaled_values(const Config& c, const ScaledParameters& s,
                         const std::vector<std::string>& bare) {
    for (double v : s.level_speeds_scaled)
        if (!positive_finite(v))
            refuse(
                c,
                fmt::format(
                    "the scaled liquid-level speed is {:g} m/s; it must be finite and positive", v),
                {"dryer.shrinkage_rates", "scaling.time_factor"}, bare);
    if (!positive_finite(s.zone_duration_scaled))
        refuse(
            c,
            fmt::format("the scaled dryer zone duration is {:g} s; it must be finite and positive",
                        s.zone_duration_scaled),
            {"dryer.zone_length", "dryer.line_speed", "scaling.time_factor"}, bare);
    if (!std::isfinite(s.gravity_scaled))
        refuse(c,
               fmt::format("the scaled gravity is {:g} m/s2; it must be finite", s.gravity_scaled),
               {"scaling.gravity", "scaling.time_factor", "scaling.viscosity_reduction"}, bare);
    if (!std::isfinite(s.hamaker_ncm_ncm[1]) || !std::isfinite(s.hamaker_ncm_cb[1]) ||
        !std::isfinite(s.hamaker_cb_cb[1]))
        refuse(c, "a scaled Hamaker constant is not finite",
               {"scaling.hamaker_factor", "scaling.scheme", "scaling.time_factor",
                "scaling.viscosity_reduction"},
               bare);
    if (!std::isfinite(s.surface_tension_scaled))
        refuse(c,
               fmt::format("the scaled surface tension is {:g} N/m; it must be finite",
                           s.surface_tension_scaled),
               {"materials.surface_tension", "scaling.capillary_factor", "scaling.scheme",
                "scaling.time_factor", "scaling.viscosity_reduction"},
               bare);
    for (double e : {s.youngs_ncm[1], s.youngs_cb[1], s.youngs_substrate[1]})
        if (!positive_finite(e))
            refuse(c,
                   fmt::format(
                       "a scaled Young's modulus is {:g} Pa; it must be finite and positive", e),
                   {"scaling.stiffness_factor", "materials.ncm_youngs_modulus",
                    "materials.cb_youngs_modulus", "materials.substrate_youngs_modulus"},
                   bare);
}

/// Steps (M-8.3), the end criterion's window and the dryer model's steps (D-2.7).
void check_steps(const Config& c, const FilmRecipe& r, const ScaledParameters& s,
                 const std::vector<std::string>& bare) {
    // Steps (M-8.3) and the end criterion's window.
    if (!(c.relaxation < c.max_process_time))
        refuse(c,
               fmt::format("drying.relaxation = {:g} s is not shorter than run.max_process_time = "
                           "{:g} s: the run "
                           "would stop before its relaxation window ends",
                           c.relaxation, c.max_process_time),
               {"drying.relaxation", "run.max_process_time"}, bare);
    const double steps = estimated_travel(c, r, s).sim_time / largest_time_step(c, s);
    if (!positive_finite(steps) || steps > max_steps)
        refuse(c,
               fmt::format("the run would take about {:.3g} steps of {:g} s; allowed at most {:g}",
                           steps, largest_time_step(c, s), max_steps),
               {"run.time_step", "scaling.time_factor", "drying.relaxation",
                "dryer.shrinkage_rates", "film.areal_loading"},
               bare);

    // The dryer model (D-2.7): its RK4 steps over all zones, each kept as a sample.
    double dryer_steps = 0.0;
    for (double len : c.dryer_zone_lengths)
        dryer_steps += std::ceil(len / c.line_speed / c.dryer_time_step);
    if (!positive_finite(dryer_steps) || dryer_steps > max_dryer_steps)
        refuse(
            c,
            fmt::format(
                "the dryer model would take {:.3g} steps of {:g} s for {:g} m/s through the zones; "
                "allowed at most {:g}",
                dryer_steps, c.dryer_time_step, c.line_speed, max_dryer_steps),
            {"dryer.time_step", "dryer.line_speed", "dryer.zone_lengths"}, bare);
}

} // namespace

double voxel_image_voxels(const Config& c, const FilmRecipe& r, double final_thickness) {
    // The image reaches the film top, which stands above the uncalendered estimate by up to one
    // large particle (docs/analysis.md).
    return c.box_x / c.analysis_voxel_size * (c.box_y / c.analysis_voxel_size) *
           ((final_thickness + r.largest_diameter()) / c.analysis_voxel_size);
}

TimeScales time_scales(const Config& c, const FilmRecipe& r, const ScaledParameters& s,
                       const ForceField& ff) {
    int smallest = 0;
    for (int k = 0; k < int(r.species.size()); ++k)
        if (r.species[std::size_t(k)].diameter < r.species[std::size_t(smallest)].diameter)
            smallest = k;
    const SizeClass& p = r.species[std::size_t(smallest)];
    TimeScales t;
    t.diameter = p.diameter;
    const double rad = 0.5 * p.diameter;
    const double inertial_density = p.density * s.inertia_factor(p);
    t.mass = inertial_density * sphere_volume(rad);
    const double e = p.is_cb ? s.youngs_cb[1] : s.youngs_ncm[1];
    const HertzMindlinParams& hm = law<HertzMindlinLaw>(ff.pair_params(smallest, smallest));
    t.rayleigh = rayleigh_time(rad, inertial_density, e, c.poisson_ratio);
    t.contact_at_1m_s = hertz_contact_time(t.mass / 2, rad / 2, hm.e_star, 1.0);
    t.contact_at_level_speed =
        hertz_contact_time(t.mass / 2, rad / 2, hm.e_star, s.level_speeds_scaled.front());
    t.drag_relaxation =
        2 * stokes_relaxation_time(t.mass, rad, StokesDragParams{s.drag_viscosity_scaled});
    const double k_cap = capillary_stiffness(law<CapillaryFrontLaw>(ff.body_params(smallest)));
    t.capillary_period = k_cap > 0 ? 2 * std::numbers::pi * std::sqrt(t.mass / k_cap) : INFINITY;
    return t;
}

double estimated_wall_time(const DerivedQuantities& d, int threads) {
    return d.steps * d.particles / (d.particle_steps_per_core * std::max(1, threads));
}

DerivedQuantities derived_quantities(const Config& c) {
    DerivedQuantities d;
    const FilmRecipe r = make_recipe(c);
    const ScaledParameters s = scale_parameters(c);
    for (const SizeClass& sc : r.species) d.particles += sc.count_exact;
    d.wet_film_height = r.wet_film_height;
    d.solids_density = r.solids_density;
    const TravelEstimate e = estimated_travel(c, r, s);
    d.final_thickness = e.final_thickness;
    d.level_travel = e.travel;
    d.sim_time = e.sim_time;
    d.steps = d.sim_time / largest_time_step(c, s);
    d.particle_steps_per_core = c.integrator == "quasi_static"
                                    ? reference_quasi_static_particle_steps_per_core
                                    : reference_particle_steps_per_core;
    d.memory_bytes = d.particles * bytes_per_particle + 5e6;
    for (double len : c.dryer_zone_lengths)
        d.dryer_steps += std::ceil(len / c.line_speed / c.dryer_time_step);
    return d;
}

void check_derived_quantities(const Config& c, const std::vector<std::string>& bare) {
    const FilmRecipe r = make_recipe(c);
    check_film(c, r, bare);
    const ScaledParameters s = scale_parameters(c);
    check_scaled_values(c, s, bare);
    check_minimum_image(c, r, s);
    check_groups(c, bare);
    check_time_scales(c, r, s, bare);
    check_critical_step_fraction(c, bare);
    check_guard_rates(c, r, bare);
    check_voxel_image(c, r, estimated_travel(c, r, s).final_thickness, bare);

    check_steps(c, r, s, bare);
}

double physical_memory_bytes() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    return pages > 0 && page > 0 ? double(pages) * double(page) : 0.0;
}

void check_fits_this_machine(const Config& c) {
    const DerivedQuantities d = derived_quantities(c);
    const double have = physical_memory_bytes();
    if (have > 0.0 && d.memory_bytes > 0.8 * have)
        throw InputError(fmt::format("the film's {:.3g} particles need about {:.3g} GB, more than "
                                     "80 % of this machine's {:.3g} GB "
                                     "(film.areal_loading, film.box_x, film.box_y, "
                                     "formulation.cb_diameter); make the box smaller",
                                     d.particles, d.memory_bytes / 1e9, have / 1e9));
}

Config load_config(std::string_view toml_text, std::string_view source_name,
                   const std::vector<std::string>& overrides) {
    ParsedConfig p = parse_config(toml_text, source_name, overrides);
    check_derived_quantities(p.config, p.bare_lengths);
    return std::move(p.config);
}

Config load_config_file(const std::string& path, const std::vector<std::string>& overrides) {
    return load_config(read_config_text(path), path, overrides);
}

} // namespace drydem
