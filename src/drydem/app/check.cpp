// SPDX-License-Identifier: MIT
// `drydem check`: every derived quantity of a configuration (counts, wet height, scaled
// parameters, time step and its limits, memory and cost estimate).
#include "drydem/drying/law_parameters.hpp"
#include "drydem/app/commands.hpp"
#include "drydem/core/sphere.hpp"
#include "drydem/analysis/analyze.hpp"
#include "drydem/drying/dimensionless_groups.hpp"
#include "drydem/drying/scaling.hpp"
#include "drydem/drying/stability_clusters.hpp"
#include "drydem/drying/stability_guard.hpp"
#include "drydem/drying/derived_checks.hpp"
#include "drydem/setup/formulation.hpp"
#include <fmt/format.h>
#include <omp.h>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace drydem::app {
namespace {

/// The stability guard's own estimate (the code a run uses at every rebuild) on the reference
/// clusters, touching at 2 % of the CB radius, gaps reduced by the configured skin. Returns the
/// smallest guarded step of the configured integrator (infinite for the quasi-static step).
double print_guard_clusters(const Config& c, const FilmRecipe& r) {
    const auto expl = guard_on_reference_clusters(c, r, "explicit");
    const auto semi = guard_on_reference_clusters(c, r, "semi_implicit");
    fmt::print(
        "  stability guard on reference clusters (docs/model.md \"Stability guard\"; dt <= 1.5 / "
        "damping and f 2 / stiff, critical-step fraction f = {:g} explicit, {:g} "
        "semi-implicit):\n",
        critical_fraction_for(c, "explicit"), critical_fraction_for(c, "semi_implicit"));
    fmt::print("    {:<34} {:>12} {:>12} {:>12} | {:>12} {:>12}\n", "cluster", "damping /s",
               "stiff rad/s", "explicit dt", "stiff rad/s", "semi-impl dt");
    for (std::size_t k = 0; k < expl.size(); ++k)
        fmt::print("    {:<34} {:>12.3g} {:>12.3g} {:>12.3g} | {:>12.3g} {:>12.3g}\n", expl[k].name,
                   expl[k].estimate.damping_rate, expl[k].estimate.stiffness_rate, expl[k].dt,
                   semi[k].estimate.stiffness_rate, semi[k].dt);
    double smallest = INFINITY;
    if (c.integrator != "quasi_static")
        for (const ClusterEstimate& k : c.integrator == "explicit" ? expl : semi)
            smallest = std::min(smallest, k.dt);
    return smallest;
}

/// The dimensionless groups per dryer zone, physical and as simulated, with their ratio: what the
/// scheme distorts (docs/model.md "Dimensionless groups").
void print_groups(const DimensionlessGroups& d) {
    fmt::print("Dimensionless groups (docs/model.md \"Dimensionless groups\"; film H = {:.4g} um, "
               "push length l* = {:.4g} um)\n",
               d.film_thickness * 1e6, d.push_length * 1e6);
    using G = double Groups::*;
    const std::pair<const char*, G> rows[] = {
        {"capillary number, drag", &Groups::capillary_drag},
        {"capillary number, lubrication CB-CB", &Groups::capillary_lubrication},
        {"push number Ca H / l*", &Groups::push},
        {"Stokes number, largest NCM", &Groups::stokes_ncm},
        {"Stokes number, CB", &Groups::stokes_cb},
        {"inertial number", &Groups::inertial},
        {"van der Waals / capillary, CB-CB", &Groups::vdw_capillary_cb_cb},
        {"van der Waals / capillary, NCM-CB", &Groups::vdw_capillary_ncm_cb},
        {"Bond number, largest NCM", &Groups::bond_ncm},
        {"Hertz overlap / r, CB-CB (vdW)", &Groups::overlap_cb_cb},
        {"Hertz overlap / r, NCM on CB (cap.)", &Groups::overlap_ncm_cb},
        {"Hertz overlap / r, NCM on substrate", &Groups::overlap_ncm_substrate},
    };
    for (std::size_t z = 0; z < d.physical.size(); ++z) {
        fmt::print("  zone {} (level {:.4g} um/s)            {:>11} {:>11} {:>10}\n", z + 1,
                   d.level_speeds_physical[z] * 1e6, "physical", "simulated", "ratio");
        for (const auto& [name, member] : rows) {
            const double p = d.physical[z].*member, q = d.simulated[z].*member;
            fmt::print("    {:<37} {:>11.3g} {:>11.3g} {:>10.3g}\n", name, p, q,
                       p > 0.0 ? q / p : 0.0);
        }
    }
    const Groups& worst = d.simulated.back();
    if (worst.push > push_number_warning)
        fmt::print("  warning: the simulated push number {:.3g} passes {:g}: the level cannot "
                   "carry the film, "
                   "which jams at a point set by the time scaling (docs/validation.md)\n",
                   worst.push, push_number_warning);
    fmt::print("\n");
}

} // namespace

/// What sets the quasi-static step (docs/model.md M-9.1).
void print_quasi_static_step(const Config& c, const ScaledParameters& s) {
    const QuasiStaticSettings q = quasi_static_settings(c, s);
    fmt::print("  quasi-static step          set by accuracy, not by the contacts: the level "
               "moves <= {:.3g} um per step (that largest step), no particle more than {:.3g} "
               "um, no gap closes by more than {:.0f} % (counted as >= {:.0f} % of the smaller "
               "radius); linear solve to a relative residual {:.3g} within {} CG "
               "iterations (docs/model.md M-9.1)\n",
               q.max_displacement * 1e6, q.max_displacement * 1e6, 100 * q.approach,
               100 * q.approach_floor, q.tolerance, q.max_iterations);
}

namespace {

/// The solid bonds calendering makes (model.md M-2.10): a CB-CB bond at its contact distance,
/// its normal spring and the stretch at which it breaks in tension alone.
void print_bonds(const Config& c, const FilmRecipe& r) {
    const BondNetwork net = calendering_bond_parameters(c, r);
    const int cb = r.cb_species();
    const SolidBondParams& b = net.pair(cb, cb);
    if (b.youngs_modulus == 0.0)
        return fmt::print("  bonds: none (calendering.bond_youngs_modulus = 0)\n");
    const double r_cb = 0.5 * r.species[std::size_t(cb)].diameter;
    const PairGeometry g =
        make_pair_geometry({2 * r_cb, 0, 0}, 2 * r_cb, r_cb, r_cb, 1.0, 1.0, {}, {}, {}, {});
    const PairResistance k = solid_bond_stiffness(g, b, 2 * r_cb);
    fmt::print("  bonds CB-CB, CB-NCM within {:.3g} nm, p0 {:.3g} x binder profile: E {:.3g} GPa, "
               "r_b/r {:.3g}, strengths {:.3g} / {:.3g} MPa; a CB-CB bond {:.3g} N/m, breaks in "
               "tension at {:.3g} nm stretch\n",
               c.bond_gap * 1e9, c.bond_probability, b.youngs_modulus * 1e-9, b.radius_ratio,
               b.tensile_strength * 1e-6, b.shear_strength * 1e-6, k.normal,
               b.tensile_strength / b.youngs_modulus * 2 * r_cb * 1e9);
}

/// What `drydem calender` will use with this config (docs/calendering.md): the NCM contacts'
/// limiting pressure and yield overlap per partner, the CB spheres' and the plate's moduli.
void print_calendering(const Config& c, const FilmRecipe& r) {
    const ForceField ff = make_calendering_force_field(c, r);
    const int ncm = 0, cb = r.cb_species();
    const double r_ncm = 0.5 * r.species[ncm].diameter,
                 r_cb = 0.5 * r.species[std::size_t(cb)].diameter;
    fmt::print("\nCalendering (drydem calender; docs/calendering.md, model.md M-2.8, M-2.9)\n");
    const std::string target =
        c.calender_mode == "pressure" ? fmt::format("{:.4g} MPa", c.calender_target_pressure * 1e-6)
        : c.calender_mode == "line_load"
            ? fmt::format("line load {:.4g} N/mm, roll radius {:.4g} mm",
                          c.calender_line_load * 1e-3, c.calender_roll_radius * 1e3)
        : c.calender_mode == "unloaded_porosity"
            ? fmt::format("porosity {:.3g} +- {:.3g} after unloading, in at most {} passes",
                          c.calender_target_porosity, c.calender_porosity_tolerance,
                          c.calender_passes)
            : fmt::format("porosity {:.3g} at peak", c.calender_target_porosity);
    fmt::print("  mode {}, plate speed {:.3g} m/s, target {}\n", c.calender_mode,
               c.calender_plate_speed, target);
    // The spheres (NCM and CB envelopes) fill the whole gap at this height (docs/calendering.md);
    // compacting agglomerates lower it to their densest state (model.md M-2.11).
    const AgglomerateCompactionParams cbd = agglomerate_compaction(c);
    const AgglomerateExtrusionParams extrusion = agglomerate_extrusion(c);
    const bool densest = cbd.compacts() || extrusion.on; // the CB solid can fill the pores
    const double spheres = densest ? r.sphere_height(cbd.minimal_porosity) : r.sphere_height();
    if (cbd.compacts())
        fmt::print("  CB agglomerates compact: inner porosity {:.3g} + ({:.3g} - {:.3g}) "
                   "exp(-sigma / {:.4g} MPa), as dried their own height {:.4g} um\n",
                   cbd.minimal_porosity, cbd.initial_porosity, cbd.minimal_porosity,
                   cbd.pressure * 1e-6, r.sphere_height() * 1e6);
    fmt::print("  spheres' own height {:.4g} um{}: they fill the gap at porosity {:.3g} (lower "
               "targets are refused)\n",
               spheres * 1e6, densest ? " (agglomerates at their densest)" : "",
               coating_density(r.dry_mass / r.base_area, spheres, r.solids_density).porosity);
    if (c.cb_density_scaling != 1.0)
        fmt::print(
            "  CB spheres' mass and moment of inertia x {:.3g} (calendering.cb_density_scaling; "
            "gravity keeps the physical mass)\n",
            c.cb_density_scaling);
    auto yield = [](const char* what, const HertzMindlinParams& p, double r_eff) {
        if (p.yield_pressure <= 0.0) return fmt::print("  {:<22} elastic\n", what);
        fmt::print(
            "  {:<22} p_y {:.3g} GPa, yields at {:.3g} nm (F_y {:.3g} mN)\n", what,
            p.yield_pressure * 1e-9, yield_overlap(p.e_star, r_eff, p.yield_pressure) * 1e9,
            hertz_normal(p.e_star, r_eff, yield_overlap(p.e_star, r_eff, p.yield_pressure)).force *
                1e3);
    };
    yield("NCM-NCM", law<HertzMindlinLaw>(ff.pair_params(ncm, ncm)), 0.5 * r_ncm);
    yield("NCM-plate", law<PlateContactLaw>(ff.body_params(ncm)), r_ncm);
    yield("NCM-substrate", law<SubstrateContactLaw>(ff.body_params(ncm)), r_ncm);
    yield("NCM-CB", law<HertzMindlinLaw>(ff.pair_params(ncm, cb)), r_ncm * r_cb / (r_ncm + r_cb));
    yield("CB-CB", law<HertzMindlinLaw>(ff.pair_params(cb, cb)), 0.5 * r_cb);
    yield("CB-plate", law<PlateContactLaw>(ff.body_params(cb)), r_cb);
    if (const HertzMindlinParams& h = law<HertzMindlinLaw>(ff.pair_params(cb, cb));
        agglomerate_hardening(h).hardens())
        fmt::print("  CB contacts harden to p_y {:.3g} GPa as their lens compacts the agglomerate "
                   "from inner porosity {:.3g} to {:.3g} (model.md M-2.12)\n",
                   h.dense_yield_pressure * 1e-9, h.agglomerate_porosity, h.dense_porosity);
    if (extrusion.on)
        fmt::print("  a CB sphere that NCM particles and walls press past its densest state (their "
                   "lenses over {:.3g} of it) flows out: its solid fills the nearest agglomerates' "
                   "pores down to {:.3g} (model.md M-2.13)\n",
                   densest_lens_fraction(extrusion.initial_porosity, extrusion.minimal_porosity),
                   extrusion.minimal_porosity);
    fmt::print(
        "  CB spheres E = {:.3g} GPa, plate E = {:.3g} GPa\n",
        (c.calender_cb_youngs_modulus > 0 ? c.calender_cb_youngs_modulus : c.cb_youngs_modulus) *
            1e-9,
        c.plate_youngs_modulus * 1e-9);
    print_bonds(c, r);
}

} // namespace

/// The scheme's factors and every scaled value (M-7), physical -> as simulated.
void print_scaling(const ScaledParameters& s, const ForceField& ff) {
    fmt::print(
        "Scaling (M-7): scheme \"{}\", k = {:g}, b = {:g}, capillary x {:g}, Hamaker x {:g}, "
        "Young's moduli x {:g}\n",
        s.scheme, s.time_factor, s.viscosity_reduction, s.capillary_factor, s.hamaker_factor,
        s.stiffness_factor);
    if (s.cb_density_scaling != 1.0)
        fmt::print("  CB inertia                mass and moment of inertia x {:g} "
                   "(scaling.cb_density_scaling; gravity and buoyancy physical)\n",
                   s.cb_density_scaling);
    fmt::print("  gravity                   {:g} -> {:g} m/s2\n", s.gravity_physical,
               s.gravity_scaled);
    fmt::print("  Stokes viscosity          {:g} -> {:g} Pa s\n", s.drag_viscosity_physical,
               s.drag_viscosity_scaled);
    fmt::print("  lubrication viscosity     {:g} Pa s\n", s.lubrication_viscosity);
    fmt::print("  Hamaker CB-CB/NCM-CB/NCM-NCM  {:g} / {:g} / {:g} -> {:g} / {:g} / {:g} J\n",
               s.hamaker_cb_cb[0], s.hamaker_ncm_cb[0], s.hamaker_ncm_ncm[0], s.hamaker_cb_cb[1],
               s.hamaker_ncm_cb[1], s.hamaker_ncm_ncm[1]);
    fmt::print("  surface tension x factor  {:g} -> {:g} N/m (capillary stiffness {:.4g} N/m)\n",
               s.surface_tension_physical, s.surface_tension_scaled,
               capillary_stiffness(law<CapillaryFrontLaw>(ff.body_params(0))));
    fmt::print("  dryer zone duration       {:g} s -> {:g} s\n", s.zone_duration_physical,
               s.zone_duration_scaled);
    for (std::size_t z = 0; z < s.level_speeds_scaled.size(); ++z)
        fmt::print("  zone {} shrinkage rate     {:g} um/s -> level speed {:g} m/s\n", z + 1,
                   s.shrinkage_rates_physical[z] * 1e6, s.level_speeds_scaled[z]);
}

/// Cost estimate (M-8.3), from the derived-quantity checks' own estimate and the step the guard
/// allows on the reference clusters.
void print_cost(const Config& c, const FilmRecipe& r, const ScaledParameters& s,
                double guarded_dt) {
    const DerivedQuantities d = derived_quantities(c);
    const double h_final = d.final_thickness, travel = d.level_travel, t_sim = d.sim_time;
    // The guard lowers the step below the cap where contacts set it (the force-ratio scheme):
    // the reference clusters' guarded step bounds the step count from below.
    const double steps = std::max(d.steps, t_sim / guarded_dt);
    fmt::print("\nCost estimate (M-8.3)\n");
    fmt::print("  final thickness (~2.4 g/cm3) {:.4g} um, level travel {:.4g} um\n", h_final * 1e6,
               travel * 1e6);
    fmt::print("  simulated time            {:.3g} s ({:.3g} s process, incl. {:g} s relaxation)\n",
               t_sim, s.process_time(t_sim), c.relaxation);
    fmt::print("  steps                     {:.3g} at the largest step{}\n", d.steps,
               steps > d.steps
                   ? fmt::format("; at least {:.3g} at the reference clusters' guarded step "
                                 "{:.3g} s (the guard's fixed point; a film's own clusters "
                                 "may lower it)",
                                 steps, guarded_dt)
                   : " (the guard may lower it)");
    fmt::print("  particle-steps            {:.3g}\n", steps * r.particle_count());
    const int cores = c.threads > 0 ? c.threads : std::max(1, omp_get_num_procs());
    const double wall = estimated_wall_time({.particles = d.particles,
                                             .steps = steps,
                                             .particle_steps_per_core = d.particle_steps_per_core},
                                            cores);
    fmt::print(
        "  wall time                 ~{:.3g} h on {} cores at {:.3g} particle-steps/s per core{}\n",
        wall / 3600, cores, d.particle_steps_per_core,
        wall > wall_time_warning ? "; warning: more than a day (`drydem run` warns too)" : "");
    const double memory = double(r.particle_count()) * bytes_per_particle + 5e6;
    fmt::print("  memory                    ~{:.0f} MB (particles, neighbor lists, buffers){}\n",
               memory / 1e6,
               memory > 0.8 * physical_memory_bytes()
                   ? fmt::format("; more than 80 % of this machine's {:.3g} GB: "
                                 "`drydem run` refuses it here",
                                 physical_memory_bytes() / 1e9)
                   : "");
    if (c.analysis_at_end && c.analysis_voxel_size > 0.0) {
        const double voxels = voxel_image_voxels(c, r, h_final);
        fmt::print(
            "  analysis at the end       voxel image ~{:.2g} voxels at {:.3g} um, ~{:.1f} GB "
            "(analysis.voxel_size; 0 = none)\n",
            voxels, c.analysis_voxel_size * 1e6, analysis::voxel_analysis_bytes * voxels / 1e9);
    }
}

void print_check(const Config& c) {
    const FilmRecipe r = make_recipe(c);
    const ScaledParameters s = scale_parameters(c);
    const ForceField ff = make_drying_force_field(c, r, s);
    fmt::print("configuration '{}' is valid\n\n", c.name);
    fmt::print("Film (model.md M-1)\n");
    fmt::print("  box                       {:.4g} x {:.4g} um (periodic x, y)\n", c.box_x * 1e6,
               c.box_y * 1e6);
    fmt::print("  areal loading             {:.4g} mg/cm2 nominal, {:.4g} mg/cm2 realised (C-3)\n",
               c.areal_loading * 100, r.realised_dry_mass() / r.base_area * 100);
    fmt::print("  solids density (Eq. 4)    {:.5g} g/cm3\n", r.solids_density * 1e-3);
    fmt::print("  wet film height (Eq. 3)   {:.5g} um\n", r.wet_film_height * 1e6);
    fmt::print(
        "  CB particle density       {:.5g} g/cm3 (porosity {:.3g}, pores filled with solvent)\n",
        r.cb_effective_density * 1e-3, c.cb_porosity);
    fmt::print(
        "  species                   type  diameter_um  count  (unrounded)  density_g_cm3\n");
    int type = 1;
    for (const SizeClass& sc : r.species)
        fmt::print("    {:<22}  {:>4}  {:>11.4g}  {:>5}  ({:>9.2f})  {:>13.5g}\n",
                   sc.is_cb ? "carbon black" : "NCM622", type++, sc.diameter * 1e6, sc.count,
                   sc.count_exact, sc.density * 1e-3);
    fmt::print("  particles                 {}\n\n", r.particle_count());

    print_scaling(s, ff);

    // Time-step limits for the smallest particle (M-9.2).
    const TimeScales ts = time_scales(c, r, s, ff);
    const double cap = largest_time_step(c, s);
    fmt::print("\nTime step, smallest particle d = {:.3g} um, m = {:.4g} kg\n", ts.diameter * 1e6,
               ts.mass);
    fmt::print(
        "  integrator                {} (numerics.integrator), largest step {:.3g} s (scaled)\n",
        c.integrator, cap);
    if (c.integrator == "quasi_static") print_quasi_static_step(c, s);
    if (c.implicit_stiffness_on())
        fmt::print("  implicit self-stiffness   on (numerics.implicit_stiffness): each particle's "
                   "contact and body stiffness is in its kick, so no stiffness bounds the step; "
                   "the step is run.time_step, an accuracy choice to check by halving it "
                   "(docs/model.md M-9.1)\n");
    fmt::print("  Rayleigh time             {:.3g} s (0.2 T_R = {:.3g} s)\n", ts.rayleigh,
               0.2 * ts.rayleigh);
    fmt::print("  Hertz contact time        {:.3g} s at 1 m/s, {:.3g} s at the level speed\n",
               ts.contact_at_1m_s, ts.contact_at_level_speed);
    fmt::print("  Stokes drag (scaled)      2 m/(6 pi eta r) = {:.3g} s\n", ts.drag_relaxation);
    fmt::print("  capillary spring period   {:.3g} s\n", ts.capillary_period);
    const double guarded_dt = print_guard_clusters(c, r);
    fmt::print("\n");
    print_groups(dimensionless_groups(c));
    print_calendering(c, r);

    print_cost(c, r, s, guarded_dt);
}

} // namespace drydem::app
