// SPDX-License-Identifier: MIT
// Composition of the force models (architecture.md "Principles"): the pair loop and the particle
// loop call these two inline functions, which sum the laws in the order of model.md M-9.5. Adding a
// model = one file in forces/ plus one line here (and its parameters in ForceField).
#pragma once
#include "drydem/forces/capillary_front.hpp"
#include "drydem/forces/gravity_buoyancy.hpp"
#include "drydem/forces/hertz_mindlin.hpp"
#include "drydem/forces/lubrication.hpp"
#include "drydem/forces/pair_geometry.hpp"
#include "drydem/forces/stokes_drag.hpp"
#include "drydem/forces/substrate.hpp"
#include "drydem/forces/van_der_waals.hpp"
#include <algorithm>
#include <vector>

namespace drydem {

/// Pre-mixed parameters of one species pair (all values as used in the simulation, i.e. scaled).
struct PairParams {
    HertzMindlinParams contact;
    VanDerWaalsParams van_der_waals;
    LubricationParams lubrication;
};

/// Interaction range beyond contact of a pair [m] (M-9.4): the largest of the laws' ranges.
inline double interaction_range(const PairParams& p, double r_i, double r_j) {
    return std::max(van_der_waals_range(p.van_der_waals, r_i, r_j),
                    lubrication_range(p.lubrication, r_i, r_j));
}

/// Pair forces in the order of M-9.5: contact (δ > 0), van der Waals, lubrication. When
/// `resistance` is given, it receives the sum of the dissipative laws' resistances (contact
/// damping and lubrication share the lever arms r + h/2, resistance.hpp).
inline PairForce pair_interaction(const PairGeometry& g, const PairParams& p, Vec3& tangential,
                                  double dt, PairResistance* resistance = nullptr) {
    PairForce f{};
    if (g.gap < 0.0) f += hertz_mindlin(g, p.contact, tangential, dt, resistance);
    else tangential = Vec3{}; // contact opened: history erased (M-2.3)
    f += van_der_waals(g, p.van_der_waals);
    const PairResistance lub = lubrication_resistance(g, p.lubrication);
    f += resistance_force(lub, g.n, g.v_rel, g.omega_i, g.omega_j);
    if (resistance) {
        *resistance += lub;
        resistance->lever_i = g.r_i + 0.5 * g.gap;
        resistance->lever_j = g.r_j + 0.5 * g.gap;
    }
    return f;
}

/// Every force acting on the particles, per species (pair table) and per particle.
struct ForceField {
    int species_count = 0;
    std::vector<PairParams> pair;                 ///< species_count², symmetric
    std::vector<HertzMindlinParams> substrate;    ///< per species, particle-substrate contact
    bool substrate_on = true;                     ///< rigid plane at z = 0
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
    const HertzMindlinParams hm = mix_hertz_mindlin(youngs_modulus, poisson_ratio, youngs_modulus,
                                                    poisson_ratio, restitution, friction,
                                                    rolling_friction);
    ff.pair.assign(std::size_t(species_count) * species_count, PairParams{hm, {}, {}});
    ff.substrate.assign(std::size_t(species_count), hm);
    return ff;
}

} // namespace drydem
