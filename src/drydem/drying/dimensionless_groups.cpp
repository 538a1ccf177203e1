// SPDX-License-Identifier: MIT
#include "drydem/drying/law_parameters.hpp"
#include "drydem/drying/dimensionless_groups.hpp"
#include "drydem/core/sphere.hpp"
#include "drydem/drying/derived_checks.hpp"
#include <nlohmann/json.hpp>
#include <algorithm>
#include <cmath>

namespace drydem {
namespace {

/// Two spheres at surface gap h along x, at rest.
PairGeometry at_gap(double r_i, double r_j, double gap, double m_i, double m_j) {
    const double d = r_i + r_j + gap;
    return make_pair_geometry({d, 0.0, 0.0}, d, r_i, r_j, m_i, m_j, {}, {}, {}, {});
}

double mass_of(const SizeClass& s) { return s.density * sphere_volume(0.5 * s.diameter); }

/// The configuration of the process itself: the force_ratio scheme with no scaling at all.
Config physical_config(const Config& c) {
    Config p = c;
    p.scaling_scheme = "force_ratio";
    p.time_factor = p.viscosity_reduction = p.stiffness_factor = 1.0;
    p.drying_cb_density_scaling = 1.0;
    p.capillary_factor = p.hamaker_factor = 0.0;
    return p;
}

} // namespace

double push_length(const FilmRecipe& recipe) {
    double r1 = 0.0, r2 = 0.0;
    for (const SizeClass& s : recipe.species) {
        const double r = 0.5 * s.diameter;
        r1 += double(s.count) * r;
        r2 += double(s.count) * r * r;
    }
    return r1 > 0.0 ? 2.0 * r2 / r1 : 0.0;
}

Groups groups_of(const ForceField& ff, const FilmRecipe& recipe, double level_speed,
                 double thickness, double cb_inertia) {
    const int cb = recipe.cb_species();
    int ncm = 0; // the largest NCM class
    for (int s = 0; s < cb; ++s)
        if (recipe.species[std::size_t(s)].diameter > recipe.species[std::size_t(ncm)].diameter)
            ncm = s;
    const SizeClass &n = recipe.species[std::size_t(ncm)], &c = recipe.species[std::size_t(cb)];
    const double r_n = 0.5 * n.diameter, r_c = 0.5 * c.diameter, m_n = mass_of(n),
                 m_c = mass_of(c) * cb_inertia;
    const double U = level_speed, H = thickness;
    const BodyParams &body_n = ff.body_params(ncm), &body_c = ff.body_params(cb);
    const CapillaryParams& capillary = law<CapillaryFrontLaw>(body_c);
    auto cap = [&](double r) { return capillary_max_force(r, capillary); };
    Groups g;
    g.capillary_drag = stokes_drag_coefficient(r_c, law<StokesDragLaw>(body_c)) * U / cap(r_c);
    // Lubrication at the gap where its resistance freezes (κ_c r_L), CB-CB.
    const LubricationParams& lub = law<LubricationLaw>(ff.pair_params(cb, cb));
    const double r_l = lubrication_radius(r_c, r_c);
    g.capillary_lubrication =
        lubrication_resistance(at_gap(r_c, r_c, lub.kappa_c * r_l, m_c, m_c), lub).normal * U /
        cap(r_c);
    // Push number and the level's push per area at the film's thickness.
    double push_per_area = 0.0;
    for (const SizeClass& s : recipe.species)
        push_per_area += 2.0 * double(s.count) * 0.5 * s.diameter * cap(0.5 * s.diameter);
    push_per_area /= recipe.base_area * H;
    g.push = g.capillary_drag * H / push_length(recipe);
    g.stokes_ncm = stokes_relaxation_time(m_n, r_n, law<StokesDragLaw>(body_n)) * U / r_n;
    g.stokes_cb = stokes_relaxation_time(m_c, r_c, law<StokesDragLaw>(body_c)) * U / r_c;
    g.inertial = (U / H) * n.diameter * std::sqrt(n.density / push_per_area);
    // Surface forces at contact (the law holds them at h_min).
    const PairGeometry cc = at_gap(r_c, r_c, 0.0, m_c, m_c), nc = at_gap(r_n, r_c, 0.0, m_n, m_c);
    const double vdw_cc =
        norm(van_der_waals(cc, law<VanDerWaalsLaw>(ff.pair_params(cb, cb))).force_i);
    const double vdw_nc =
        norm(van_der_waals(nc, law<VanDerWaalsLaw>(ff.pair_params(ncm, cb))).force_i);
    g.vdw_capillary_cb_cb = vdw_cc / cap(r_c);
    g.vdw_capillary_ncm_cb = vdw_nc / cap(r_c);
    g.bond_ncm =
        std::abs(gravity_buoyancy(r_n, n.density, law<GravityBuoyancyLaw>(body_n)).z) / cap(r_n);
    // Expected Hertz overlaps under the forces that press these contacts.
    g.overlap_cb_cb =
        hertz_overlap(vdw_cc, cc.r_eff, law<HertzMindlinLaw>(ff.pair_params(cb, cb)).e_star) / r_c;
    g.overlap_ncm_cb =
        hertz_overlap(cap(r_n), nc.r_eff, law<HertzMindlinLaw>(ff.pair_params(ncm, cb)).e_star) /
        r_c;
    const double e_substrate = law<SubstrateContactLaw>(body_n).e_star;
    g.overlap_ncm_substrate =
        e_substrate > 0.0 ? hertz_overlap(cap(r_n), r_n, e_substrate) / r_n : 0.0;
    return g;
}

DimensionlessGroups dimensionless_groups(const Config& c) {
    DimensionlessGroups d;
    const FilmRecipe recipe = make_recipe(c);
    const Config pc = physical_config(c);
    const ScaledParameters sim = scale_parameters(c), phys = scale_parameters(pc);
    const ForceField ff_sim = make_drying_force_field(c, recipe, sim),
                     ff_phys = make_drying_force_field(pc, recipe, phys);
    d.push_length = push_length(recipe);
    d.film_thickness = derived_quantities(c).final_thickness;
    for (std::size_t z = 0; z < sim.level_speeds_scaled.size(); ++z) {
        d.level_speeds_physical.push_back(phys.level_speeds_scaled[z]);
        d.physical.push_back(
            groups_of(ff_phys, recipe, phys.level_speeds_scaled[z], d.film_thickness, 1.0));
        d.simulated.push_back(groups_of(ff_sim, recipe, sim.level_speeds_scaled[z],
                                        d.film_thickness, sim.cb_density_scaling));
    }
    return d;
}

nlohmann::json to_json(const DimensionlessGroups& d) {
    using nlohmann::json;
    auto set = [](const Groups& g) {
        return json{{"capillary_number_drag", g.capillary_drag},
                    {"capillary_number_lubrication_cb_cb", g.capillary_lubrication},
                    {"push_number", g.push},
                    {"stokes_number_largest_ncm", g.stokes_ncm},
                    {"stokes_number_cb", g.stokes_cb},
                    {"inertial_number", g.inertial},
                    {"vdw_over_capillary_cb_cb", g.vdw_capillary_cb_cb},
                    {"vdw_over_capillary_ncm_cb", g.vdw_capillary_ncm_cb},
                    {"bond_number_largest_ncm", g.bond_ncm},
                    {"hertz_overlap_cb_cb_vdw", g.overlap_cb_cb},
                    {"hertz_overlap_ncm_cb_capillary", g.overlap_ncm_cb},
                    {"hertz_overlap_ncm_substrate_capillary", g.overlap_ncm_substrate}};
    };
    json zones = json::array();
    for (std::size_t z = 0; z < d.physical.size(); ++z)
        zones.push_back({{"zone", z + 1},
                         {"level_speed_physical_m_s", d.level_speeds_physical[z]},
                         {"physical", set(d.physical[z])},
                         {"simulated", set(d.simulated[z])}});
    return json{
        {"film_thickness_m", d.film_thickness}, {"push_length_m", d.push_length}, {"zones", zones}};
}

} // namespace drydem
