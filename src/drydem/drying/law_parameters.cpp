// SPDX-License-Identifier: MIT
#include "drydem/drying/law_parameters.hpp"
#include "drydem/core/error.hpp"
#include "drydem/setup/solids.hpp"
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <string>
#include <tuple>
#include <type_traits>

namespace drydem {
namespace {

/// What a mapping reads: the configuration with every law parameter already as simulated
/// (simulated_config) and the scaled values that have no key of their own.
struct LawInputs {
    const Config& c;
    const ScaledParameters& s;
};

template <class L>
using For = std::type_identity<L>;

double youngs_modulus(const Config& c, const SizeClass& s) {
    return s.is_cb ? c.cb_youngs_modulus : c.ncm_youngs_modulus;
}

// ---- pair laws: parameters of the species pair (a, b) ----

/// [materials] and [contact] keys (M-2.1): the two species' materials, one friction for all pairs.
HertzMindlinParams params(For<HertzMindlinLaw>, const LawInputs& in, const SizeClass& a,
                          const SizeClass& b) {
    const Config& c = in.c;
    return mix_hertz_mindlin(youngs_modulus(c, a), c.poisson_ratio, youngs_modulus(c, b),
                             c.poisson_ratio, c.restitution, c.friction, c.rolling_friction);
}

/// [van_der_waals] keys (M-3): Hamaker constant and minimum gap by material pair; cut-off 0 = the
/// pair's r_L = 2R* (C-13, C-15).
VanDerWaalsParams params(For<VanDerWaalsLaw>, const LawInputs& in, const SizeClass& a,
                         const SizeClass& b) {
    const Config& c = in.c;
    VanDerWaalsParams p;
    if (a.is_cb && b.is_cb)
        p = {c.hamaker_cb_cb, c.min_gap_cb_cb, 0.0};
    else if (a.is_cb || b.is_cb)
        p = {c.hamaker_ncm_cb, c.min_gap_ncm_cb, 0.0};
    else
        p = {c.hamaker_ncm_ncm, c.min_gap_ncm_ncm, 0.0};
    p.cutoff_gap =
        c.vdw_cutoff > 0.0 ? c.vdw_cutoff : lubrication_radius(0.5 * a.diameter, 0.5 * b.diameter);
    return p;
}

/// [lubrication] keys (M-4); the viscosity as simulated (η, or η/b, C-17).
LubricationParams params(For<LubricationLaw>, const LawInputs& in, const SizeClass&,
                         const SizeClass&) {
    return {in.c.lubrication ? in.s.lubrication_viscosity : 0.0, in.c.kappa_c};
}

/// [double_layer] keys; cut-off 0 = the pair's lubrication range r_L = 2R*, as for van der Waals
/// (C-13), so that switching it on does not widen the neighbour list.
DoubleLayerParams params(For<DoubleLayerLaw>, const LawInputs& in, const SizeClass& a,
                         const SizeClass& b) {
    const Config& c = in.c;
    if (!c.double_layer) return {};
    return {double_layer_amplitude(c.double_layer_permittivity, c.double_layer_potential, 1.0),
            c.double_layer_debye_length,
            c.double_layer_cutoff > 0.0 ? c.double_layer_cutoff
                                        : lubrication_radius(0.5 * a.diameter, 0.5 * b.diameter)};
}

// ---- body laws: parameters of the species a ----

/// [materials] substrate keys and contact.substrate_friction (M-2.6).
HertzMindlinParams params(For<SubstrateContactLaw>, const LawInputs& in, const SizeClass& a) {
    const Config& c = in.c;
    return mix_hertz_mindlin(youngs_modulus(c, a), c.poisson_ratio, c.substrate_youngs_modulus,
                             c.substrate_poisson_ratio, c.restitution, c.substrate_friction,
                             c.rolling_friction);
}

/// No plate while the film dries: the calendering run (calendering/) sets its own.
HertzMindlinParams params(For<PlateContactLaw>, const LawInputs&, const SizeClass&) { return {}; }

/// lubrication.substrate and lubrication.kappa_c (M-4.4), the lubrication viscosity.
SubstrateLubricationParams params(For<SubstrateLubricationLaw>, const LawInputs& in,
                                  const SizeClass&) {
    return {in.c.substrate_lubrication ? in.s.lubrication_viscosity : 0.0, in.c.kappa_c};
}

/// The Stokes viscosity η/b (M-5), with rotation (C-18).
StokesDragParams params(For<StokesDragLaw>, const LawInputs& in, const SizeClass&) {
    return {in.s.drag_viscosity_scaled, true};
}

/// Scaled gravity and materials.solvent_density (M-5).
GravityBuoyancyParams params(For<GravityBuoyancyLaw>, const LawInputs& in, const SizeClass&) {
    return {in.s.gravity_scaled, in.c.solvent_density, 0.0}; // the film lies flat
}

/// σ s_cap as simulated and materials.contact_angle (M-6).
CapillaryParams params(For<CapillaryFrontLaw>, const LawInputs& in, const SizeClass&) {
    return {in.s.surface_tension_scaled, in.c.contact_angle};
}

/// Every law of a list mapped by its function above (a law without one does not compile).
template <class... Ls>
PairParams pair_params(std::tuple<Ls...>*, const LawInputs& in, const SizeClass& a,
                       const SizeClass& b) {
    PairParams p;
    ((law<Ls>(p) = params(For<Ls>{}, in, a, b)), ...);
    return p;
}
template <class... Ls>
BodyParams body_params(std::tuple<Ls...>*, const LawInputs& in, const SizeClass& a) {
    BodyParams p;
    ((law<Ls>(p) = params(For<Ls>{}, in, a)), ...);
    return p;
}

} // namespace

ForceField make_drying_force_field(const Config& config, const FilmRecipe& recipe,
                                   const ScaledParameters& s) {
    const Config c = simulated_config(config, s); // the laws see simulated values only
    const LawInputs in{c, s};
    ForceField ff;
    const int n = int(recipe.species.size());
    ff.species_count = n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            ff.pair.push_back(pair_params(static_cast<PairLaws::Laws*>(nullptr), in,
                                          recipe.species[std::size_t(i)],
                                          recipe.species[std::size_t(j)]));
    for (int i = 0; i < n; ++i)
        ff.body.push_back(
            body_params(static_cast<BodyLaws::Laws*>(nullptr), in, recipe.species[std::size_t(i)]));
    if (const auto bad = force_field_violations(ff); !bad.empty())
        throw InputError(fmt::format(
            "the laws' parameters as simulated are out of range ({}): {}. Check the keys of the "
            "law's section and the [scaling] factors that multiply them",
            bad.size(), fmt::join(bad, "; ")));
    return ff;
}

double contact_yield_pressure(const Config& c, double e_star, bool with_cb) {
    const double given = with_cb ? c.cb_yield_pressure : c.calender_yield_pressure;
    if (given > 0.0) return given;
    // δ_y = y 2R* in yield_pressure_at(E*, R*, δ_y) = (2E*/π) sqrt(δ_y/R*): R* cancels.
    return yield_pressure_at(e_star, 1.0, 2.0 * c.calender_yield_displacement);
}

namespace {
/// M-2.12: a contact with CB sphere(s) on `sides` hardens from its p_y toward
/// calendering.cb_dense_yield_pressure as its lens compacts the agglomerate(s).
void set_hardening(HertzMindlinParams& p, const Config& c, double cb_modulus,
                   AgglomerateSides sides) {
    if (c.cb_dense_yield_pressure <= 0.0 || sides == AgglomerateSides::none) return;
    if (p.yield_pressure <= 0.0)
        throw InputError(fmt::format(
            "calendering.cb_dense_yield_pressure = {:.4g} MPa, but the CB contacts do not yield "
            "(calendering.cb_yield_pressure = 0 and calendering.yield_displacement = 0): only a "
            "yielding contact hardens; set one of them, or cb_dense_yield_pressure = 0",
            c.cb_dense_yield_pressure * 1e-6));
    if (c.cb_dense_yield_pressure < p.yield_pressure)
        throw InputError(fmt::format(
            "calendering.cb_dense_yield_pressure = {:.4g} MPa is below the CB contacts' limiting "
            "pressure {:.4g} MPa (calendering.cb_yield_pressure, or from "
            "calendering.yield_displacement): the densest agglomerate carries at least what the "
            "loose one does; give a value of at least that, or 0 for no hardening",
            c.cb_dense_yield_pressure * 1e-6, p.yield_pressure * 1e-6));
    const AgglomerateCompactionParams a = agglomerate_compaction(c);
    p.dense_yield_pressure = c.cb_dense_yield_pressure;
    p.agglomerate_porosity = a.initial_porosity;
    p.dense_porosity = a.minimal_porosity;
    p.agglomerates = sides;
    // (1 − ν²)/E_CB over the pair's 1/E*: the agglomerate's share of the contact's compliance,
    // 1/2 between two of them (M-2.12: its modulus hardens with its density).
    p.agglomerate_compliance_share =
        (1.0 - c.poisson_ratio * c.poisson_ratio) / cb_modulus * p.e_star;
}
} // namespace

ForceField make_calendering_force_field(const Config& config, const FilmRecipe& recipe) {
    Config c = config; // physical: the drying run's scaling is not the calendering's
    c.scaling_scheme = "paper";
    c.time_factor = c.viscosity_reduction = c.stiffness_factor = 1.0;
    c.capillary_factor = c.hamaker_factor = 1.0;
    c.lubrication = c.substrate_lubrication = c.double_layer = false;
    if (!c.calender_van_der_waals) c.hamaker_cb_cb = c.hamaker_ncm_cb = c.hamaker_ncm_ncm = 0.0;
    if (c.calender_cb_youngs_modulus > 0.0) c.cb_youngs_modulus = c.calender_cb_youngs_modulus;
    ForceField ff = make_drying_force_field(c, recipe, scale_parameters(c));
    ff.set_body_law<StokesDragLaw>({0.0, false});
    ff.set_body_law<GravityBuoyancyLaw>({c.gravity, 0.0, 0.0});
    ff.set_body_law<CapillaryFrontLaw>({0.0, c.contact_angle});
    const int n = ff.species_count;
    const double cb_modulus = youngs_modulus(c, recipe.species[std::size_t(recipe.cb_species())]);
    for (int i = 0; i < n; ++i) {
        const SizeClass& a = recipe.species[std::size_t(i)];
        HertzMindlinParams plate =
            mix_hertz_mindlin(youngs_modulus(c, a), c.poisson_ratio, c.plate_youngs_modulus,
                              c.plate_poisson_ratio, c.restitution, c.friction, c.rolling_friction);
        HertzMindlinParams& substrate = law<SubstrateContactLaw>(ff.body[std::size_t(i)]);
        const AgglomerateSides on_i = a.is_cb ? AgglomerateSides::i : AgglomerateSides::none;
        plate.yield_pressure = contact_yield_pressure(c, plate.e_star, a.is_cb);
        substrate.yield_pressure = contact_yield_pressure(c, substrate.e_star, a.is_cb);
        set_hardening(plate, c, cb_modulus, on_i);
        set_hardening(substrate, c, cb_modulus, on_i);
        law<PlateContactLaw>(ff.body[std::size_t(i)]) = plate;
        for (int j = 0; j < n; ++j) {
            HertzMindlinParams& hm = law<HertzMindlinLaw>(ff.pair[std::size_t(i * n + j)]);
            const bool j_cb = recipe.species[std::size_t(j)].is_cb;
            hm.yield_pressure = contact_yield_pressure(c, hm.e_star, a.is_cb || j_cb);
            set_hardening(
                hm, c, cb_modulus,
                AgglomerateSides(std::uint8_t(on_i) | std::uint8_t(j_cb ? AgglomerateSides::j
                                                                        : AgglomerateSides::none)));
        }
    }
    if (const auto bad = force_field_violations(ff); !bad.empty())
        throw InputError(fmt::format("the calendering laws' parameters are out of range: {}",
                                     fmt::join(bad, "; ")));
    return ff;
}

namespace {
/// calendering.cb_minimal_porosity (0 = binder-filled); when `used`, InputError for one not
/// below formulation.cb_porosity or below the binder-filled porosity.
double minimal_agglomerate_porosity(const Config& c, bool used) {
    const double filled = agglomerate_binder_porosity(c);
    const double e = c.cb_minimal_porosity > 0.0 ? c.cb_minimal_porosity : filled;
    if (used && e >= c.cb_porosity)
        throw InputError(fmt::format(
            "calendering.cb_minimal_porosity = {:.3g} must be below formulation.cb_porosity = "
            "{:.3g}: the agglomerates compact from their dried inner porosity down to it",
            e, c.cb_porosity));
    if (used && e < filled)
        throw InputError(fmt::format(
            "calendering.cb_minimal_porosity = {:.3g} is below {:.3g}, the share of the "
            "agglomerates' pores that their binder fills (formulation.pvdf_mass_fraction over "
            "formulation.cb_mass_fraction, by volume): no pressure closes those; 0 chooses it",
            e, filled));
    return e;
}
} // namespace

AgglomerateCompactionParams agglomerate_compaction(const Config& c) {
    return {c.cb_porosity, minimal_agglomerate_porosity(c, c.cb_compaction_pressure > 0.0),
            c.cb_compaction_pressure};
}

AgglomerateExtrusionParams agglomerate_extrusion(const Config& c) {
    return {c.cb_porosity, minimal_agglomerate_porosity(c, c.cb_extrusion), c.cb_extrusion};
}

double agglomerate_binder_porosity(const Config& c) {
    return binder_filled_porosity(binder_volume_per_carbon(c.pvdf_mass_fraction, c.pvdf_density,
                                                           c.cb_mass_fraction, c.cb_density));
}

BondNetwork calendering_bond_parameters(const Config& c, const FilmRecipe& recipe) {
    BondNetwork net;
    const int n = int(recipe.species.size());
    net.species_count = n;
    net.params.assign(std::size_t(n * n), {});
    if (c.bond_youngs_modulus == 0.0) return net;
    const SolidBondParams bond{
        c.bond_youngs_modulus, c.bond_youngs_modulus / (2.0 * (1.0 + c.bond_poisson_ratio)),
        c.bond_radius_ratio,   c.bond_tensile_strength,
        c.bond_shear_strength, c.bond_damping_ratio};
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            if (recipe.species[std::size_t(i)].is_cb || recipe.species[std::size_t(j)].is_cb)
                net.params[std::size_t(i * n + j)] = bond;
    if (const auto bad = net.limit_violations(); !bad.empty())
        throw InputError(fmt::format("the calendering bonds' parameters are out of range: {}",
                                     fmt::join(bad, "; ")));
    return net;
}

PairReach widest_pair_reach(const ForceField& ff, const FilmRecipe& recipe) {
    PairReach widest;
    for (int i = 0; i < ff.species_count; ++i)
        for (int j = 0; j < ff.species_count; ++j) {
            const double d_i = recipe.species[std::size_t(i)].diameter,
                         d_j = recipe.species[std::size_t(j)].diameter;
            const double reach =
                0.5 * (d_i + d_j) + interaction_range(ff.pair_params(i, j), 0.5 * d_i, 0.5 * d_j);
            if (reach > widest.reach) widest = {reach, d_i, d_j};
        }
    return widest;
}

} // namespace drydem
