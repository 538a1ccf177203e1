// SPDX-License-Identifier: MIT
// The registration of the force models: the pair laws (pair_law.hpp) and the body laws
// (body_law.hpp) as two compile-time lists, summed in the order of M-9.5 (pair: contact, van der
// Waals, lubrication, then the double layer, which the paper leaves out; body: substrate contact,
// the calendering plate's contact, substrate lubrication, Stokes drag, weight minus buoyancy,
// capillary force of the liquid level).
// Adding a law = one header in forces/ with its struct, one entry in its list below, and its
// parameters from the configuration in drying/law_parameters.cpp (ARCHITECTURE.md "Adding a
// pair law", "Adding a body law").
#pragma once
#include "drydem/forces/body_law.hpp"
#include "drydem/forces/capillary_front.hpp"
#include "drydem/forces/double_layer.hpp"
#include "drydem/forces/gravity_buoyancy.hpp"
#include "drydem/forces/hertz_mindlin.hpp"
#include "drydem/forces/lubrication.hpp"
#include "drydem/forces/pair_geometry.hpp"
#include "drydem/forces/pair_law.hpp"
#include "drydem/forces/plate_contact.hpp"
#include "drydem/forces/stokes_drag.hpp"
#include "drydem/forces/substrate_contact.hpp"
#include "drydem/forces/substrate_lubrication.hpp"
#include "drydem/forces/van_der_waals.hpp"
#include <algorithm>
#include <vector>

namespace drydem {

/// The pair laws, in the order their forces are summed.
using PairLaws = PairLawList<HertzMindlinLaw, VanDerWaalsLaw, LubricationLaw, DoubleLayerLaw>;

/// The body laws, in the order their forces are summed.
using BodyLaws = BodyLawList<SubstrateContactLaw, PlateContactLaw, SubstrateLubricationLaw,
                             StokesDragLaw, GravityBuoyancyLaw, CapillaryFrontLaw>;

/// Pre-mixed parameters of one species pair (all values as simulated, i.e. scaled), one entry
/// per law: `law<VanDerWaalsLaw>(pp)`.
using PairParams = PairLaws::Params;
/// The body laws' parameters of one species, one entry per law: `law<StokesDragLaw>(bp)`.
using BodyParams = BodyLaws::Params;

/// Law L's parameters in a species pair's (or a species') entry.
template <class L>
auto& law(PairParams& p) {
    return PairLaws::params<L>(p);
}
template <class L>
const auto& law(const PairParams& p) {
    return PairLaws::params<L>(p);
}
template <class L>
auto& law(BodyParams& p) {
    return BodyLaws::params<L>(p);
}
template <class L>
const auto& law(const BodyParams& p) {
    return BodyLaws::params<L>(p);
}

/// What the laws keep per pair (the neighbour list holds one per slot) and per particle (the
/// engine holds one per particle, in storage order).
using PairState = PairLaws::State;
using BodyState = BodyLaws::State;

/// Interaction range beyond contact of a pair [m] (M-9.4): the largest of the laws' ranges.
inline double interaction_range(const PairParams& p, double r_i, double r_j) {
    return PairLaws::range(p, r_i, r_j);
}

/// Pair forces of every law (PairLaws::force), and with `tangent` their stiffness after the step.
/// Always inlined into the pair loop (where the resistance and tangent pointers are constants):
/// out of line, with the tangent, it costs the loop ~10 %.
[[gnu::always_inline]] inline PairForce pair_interaction(const PairGeometry& g, const PairParams& p,
                                                         PairState& state, double dt,
                                                         PairResistance* resistance = nullptr,
                                                         PairResistance* tangent = nullptr) {
    return PairLaws::force(g, p, state, dt, resistance, tangent);
}

/// Every force acting on the particles: per species pair and per species.
struct ForceField {
    int species_count = 0;
    std::vector<PairParams> pair; ///< species_count², symmetric
    std::vector<BodyParams> body; ///< species_count

    [[nodiscard]] const PairParams& pair_params(int si, int sj) const {
        return pair[std::size_t(si) * species_count + sj];
    }
    [[nodiscard]] const BodyParams& body_params(int s) const { return body[std::size_t(s)]; }

    /// Body law L's parameters for every species.
    template <class L>
    void set_body_law(const typename L::Params& p) {
        for (BodyParams& b : body) law<L>(b) = p;
    }
    /// Takes the substrate away (contact and lubrication): a free cell in z, for tests.
    void remove_substrate() {
        set_body_law<SubstrateContactLaw>({});
        set_body_law<SubstrateLubricationLaw>({});
    }
    /// Whether a particle of any species touches the substrate when it reaches z < r.
    [[nodiscard]] bool substrate_on() const {
        return std::any_of(body.begin(), body.end(), [](const BodyParams& b) {
            return law<SubstrateContactLaw>(b).e_star > 0.0;
        });
    }
};

/// Every parameter of every law outside its declared interval (law_limits.hpp), as
/// "law (species i-j): name = value, allowed I"; empty when the field is valid.
std::vector<std::string> force_field_violations(const ForceField& ff);

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
    law<HertzMindlinLaw>(pp) = hm;
    ff.pair.assign(std::size_t(species_count) * species_count, pp);
    BodyParams bp{};
    law<SubstrateContactLaw>(bp) = hm;
    ff.body.assign(std::size_t(species_count), bp);
    return ff;
}

} // namespace drydem
