// SPDX-License-Identifier: MIT
// Composition of the force models: the pair laws as a compile-time list (pair_law.hpp), summed in
// the order of M-9.5 (contact, van der Waals, lubrication, then the double layer, which the
// paper leaves out); the body laws in particle_forces below. Adding a pair law = one file in
// forces/ with its struct (pair_law.hpp's contract) and one entry in PairLaws; its config keys
// go into io/ (ARCHITECTURE.md "Adding a pair law").
#pragma once
#include "drydem/forces/capillary_front.hpp"
#include "drydem/forces/double_layer.hpp"
#include "drydem/forces/gravity_buoyancy.hpp"
#include "drydem/forces/hertz_mindlin.hpp"
#include "drydem/forces/lubrication.hpp"
#include "drydem/forces/pair_geometry.hpp"
#include "drydem/forces/pair_law.hpp"
#include "drydem/forces/stokes_drag.hpp"
#include "drydem/forces/substrate.hpp"
#include "drydem/forces/van_der_waals.hpp"
#include <algorithm>
#include <vector>

namespace drydem {

/// The pair laws, in the order their forces are summed.
using PairLaws = PairLawList<HertzMindlinLaw, VanDerWaalsLaw, LubricationLaw, DoubleLayerLaw>;

/// Pre-mixed parameters of one species pair (all values as simulated, i.e. scaled), one entry
/// per law: `PairLaws::params<VanDerWaalsLaw>(pp)`.
using PairParams = PairLaws::Params;

/// Law L's parameters in a species pair's entry: `law<VanDerWaalsLaw>(pp).hamaker`.
template <class L>
auto& law(PairParams& p) {
    return PairLaws::params<L>(p);
}
template <class L>
const auto& law(const PairParams& p) {
    return PairLaws::params<L>(p);
}

/// What the laws keep per pair (the neighbour list holds one per slot).
using PairState = PairLaws::State;

/// Interaction range beyond contact of a pair [m] (M-9.4): the largest of the laws' ranges.
inline double interaction_range(const PairParams& p, double r_i, double r_j) {
    return PairLaws::range(p, r_i, r_j);
}

/// Pair forces of every law (PairLaws::force).
inline PairForce pair_interaction(const PairGeometry& g, const PairParams& p, PairState& state,
                                  double dt, PairResistance* resistance = nullptr) {
    return PairLaws::force(g, p, state, dt, resistance);
}

/// Every force acting on the particles, per species (pair table) and per particle.
struct ForceField {
    int species_count = 0;
    std::vector<PairParams> pair;              ///< species_count², symmetric
    std::vector<HertzMindlinParams> substrate; ///< per species, particle-substrate contact
    bool substrate_on = true;                  ///< rigid plane at z = 0
    SubstrateLubricationParams substrate_lubrication;
    StokesDragParams drag;
    GravityBuoyancyParams gravity;
    CapillaryParams capillary;

    [[nodiscard]] const PairParams& pair_params(int si, int sj) const {
        return pair[std::size_t(si) * species_count + sj];
    }
};

/// Particle forces in the order of M-9.5: substrate contact and lubrication, Stokes drag,
/// weight minus buoyancy, capillary force of the liquid level. When `resistance` is given, it
/// receives the sum of the dissipative laws' resistances (resistance.hpp body form).
inline BodyForce particle_forces(const ForceField& ff, int species, double r, double density,
                                 double mass, const Vec3& x, const Vec3& v, const Vec3& omega,
                                 double liquid_level, Vec3& wall_history, double dt,
                                 BodyResistance* resistance = nullptr) {
    BodyForce f{};
    BodyResistance fluid = stokes_drag_resistance(r, ff.drag);
    if (ff.substrate_on) {
        f += substrate_contact(x.z, r, mass, v, omega, ff.substrate[species], wall_history, dt,
                               resistance);
        fluid += substrate_lubrication_resistance(x.z, r, ff.substrate_lubrication);
    }
    f += resistance_force(fluid, v, omega);
    f.force += gravity_buoyancy(r, density, ff.gravity);
    f.force += capillary_front(x.z, r, liquid_level, ff.capillary);
    if (resistance) *resistance += fluid;
    return f;
}

} // namespace drydem

namespace drydem {

/// A force field with only Hertz-Mindlin contact, the same material for every species and the
/// substrate (the peers' benchmark, contact tests); other laws off until set.
inline ForceField uniform_contact_force_field(int species_count, double youngs_modulus,
                                              double poisson_ratio, double restitution,
                                              double friction, double rolling_friction = 0.0) {
    ForceField ff;
    ff.species_count = species_count;
    const HertzMindlinParams hm =
        mix_hertz_mindlin(youngs_modulus, poisson_ratio, youngs_modulus, poisson_ratio, restitution,
                          friction, rolling_friction);
    PairParams pp{};
    PairLaws::params<HertzMindlinLaw>(pp) = hm;
    ff.pair.assign(std::size_t(species_count) * species_count, pp);
    ff.substrate.assign(std::size_t(species_count), hm);
    return ff;
}

} // namespace drydem
