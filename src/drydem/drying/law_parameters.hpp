// SPDX-License-Identifier: MIT
// The laws' parameters from the configuration, in one place beside the lists that register the
// laws (forces/force_field.hpp). The law headers know nothing of Config or the recipe: each law
// gets one mapping function here, from the simulated values (drying/scaling.cpp: the factors are
// applied before, never in a law). The whole field is then checked against the intervals every
// law declares (forces/law_limits.hpp).
#pragma once
#include "drydem/drying/scaling.hpp"
#include "drydem/engine/bond_network.hpp"
#include "drydem/forces/agglomerate_compaction.hpp"
#include "drydem/forces/agglomerate_extrusion.hpp"
#include "drydem/forces/force_field.hpp"
#include "drydem/io/config.hpp"
#include "drydem/setup/formulation.hpp"

namespace drydem {

/// Species pair table and body-law parameters of the drying simulation, from the recipe's species
/// (NCM classes, then CB) and the scaled parameters. InputError, naming the law, the parameter,
/// its value and the configuration keys behind it, when a value leaves its law's interval.
ForceField make_drying_force_field(const Config& c, const FilmRecipe& recipe,
                                   const ScaledParameters& s);

/// The dry film under the calendering plate (docs/calendering.md): the [materials], [contact] and
/// [van_der_waals] keys as they are, physical (no time scaling; calendering.van_der_waals: off
/// sets the Hamaker constants to 0), the CB spheres with calendering.cb_youngs_modulus; no liquid (no lubrication, drag, buoyancy, capillary force or
/// double layer); physical gravity; the plate (calendering.plate_*); every contact of an NCM
/// particle (with NCM, the substrate, the plate) elastic-plastic, Thornton-Ning with
/// calendering.yield_pressure, or the p_y at which a pair yields at calendering.yield_displacement
/// × 2R* (model.md M-2.8, M-2.9); CB contacts yield at calendering.cb_yield_pressure (or the
/// same yield displacement): the carbon-binder agglomerates crush, and with
/// calendering.cb_dense_yield_pressure their contacts harden as the lens compacts them (M-2.12).
/// InputError for a dense yield pressure below the contacts' own or without yielding contacts.
ForceField make_calendering_force_field(const Config& c, const FilmRecipe& recipe);

/// The solid bonds' parameters in the dry film (calendering.bond_*, model.md M-2.10): CB-CB and
/// CB-NCM pairs bond, NCM-NCM pairs do not; no bonds at all with calendering.bond_youngs_modulus
/// = 0. The network comes without bonds: calendering/bonding.hpp makes them.
BondNetwork calendering_bond_parameters(const Config& c, const FilmRecipe& recipe);

/// The carbon-binder agglomerates' compaction in the dry film (calendering.cb_compaction_pressure,
/// calendering.cb_minimal_porosity, 0 = binder-filled, b / (1 + b); ε_0 = formulation.cb_porosity;
/// model.md M-2.11). InputError for an ε_min not below ε_0 or below the binder-filled porosity.
AgglomerateCompactionParams agglomerate_compaction(const Config& c);
/// The extrusion of agglomerates pressed past their densest state (calendering.cb_extrusion,
/// ε_min and ε_0 as for the compaction, model.md M-2.13); the same InputError for ε_min.
AgglomerateExtrusionParams agglomerate_extrusion(const Config& c);
/// The inner porosity of an agglomerate whose pores hold only the recipe's binder (M-2.11).
double agglomerate_binder_porosity(const Config& c);

/// The limiting contact pressure of a contact of effective modulus E*: calendering.cb_yield_pressure
/// for a contact with a CB sphere, calendering.yield_pressure for NCM with NCM or a wall, or else
/// the p_y at which the pair yields at calendering.yield_displacement × 2R*; 0 = elastic.
double contact_yield_pressure(const Config& c, double e_star, bool with_cb);

/// The widest pair of the film's species: the largest centre distance r_i + r_j + the pair laws'
/// range (interaction_range, as the neighbour list reaches) over every species pair [m], and the
/// two diameters of that pair.
struct PairReach {
    double reach = 0.0, diameter_i = 0.0, diameter_j = 0.0;
};
PairReach widest_pair_reach(const ForceField& ff, const FilmRecipe& recipe);

} // namespace drydem
