// SPDX-License-Identifier: MIT
// Electrostatic double-layer repulsion between two charged spheres in the solvent (the "EL" part
// of DLVO theory; paper Sec. 3, which discusses it and leaves it out because van der Waals
// dominates in cathode slurries). Hogg, Healy & Fuerstenau (1966) for equal, constant surface
// potentials ψ₀ in the Derjaguin approximation (h ≪ R*, weak overlap of the diffuse layers):
//   V(h)    = 4π ε_r ε_0 R* ψ₀² ln(1 + e^{-h/λ_D})
//   F_el,i  = -4π ε_r ε_0 R* ψ₀² (1/λ_D) e^{-h_e/λ_D} / (1 + e^{-h_e/λ_D}) n,   h_e = max(h, 0)
//   for h ≤ h_cut, else 0 (i is pushed away from j; n from i to j as in M-0)
// λ_D is the Debye length of the liquid (set by its ion content), ε_r its relative permittivity
// (NMP: 32.2). In overlap the force stays at its contact value; Hertz takes over there. Scaled
// like van der Waals (drying/scaling.cpp hands the law ε_r × the Hamaker factor) so that the
// balance of the two surface forces stays the physical one. Conservative and central: no torque,
// no state.
// Off by default; docs/model.md "Double-layer repulsion".
#pragma once
#include "drydem/forces/pair_geometry.hpp"
#include "drydem/forces/law_limits.hpp"
#include <array>
#include "drydem/forces/resistance.hpp"
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string_view>

namespace drydem {

/// Vacuum permittivity ε_0 [F/m] (CODATA 2018).
inline constexpr double vacuum_permittivity = 8.8541878128e-12;

struct DoubleLayerParams {
    double amplitude =
        0.0; ///< 4π ε_r ε_0 ψ₀² × scale [J/m]: V(h) = amplitude R* ln(1 + e^{-h/λ_D}); 0 = off
    double debye_length = 0.0; ///< λ_D [m]
    double cutoff_gap = 0.0;   ///< h_cut [m]
};

/// 4π ε_r ε_0 ψ₀² · scale, the prefactor of V(h) per unit R* [J/m].
inline double double_layer_amplitude(double relative_permittivity, double surface_potential,
                                     double scale) {
    return 4.0 * std::numbers::pi * relative_permittivity * vacuum_permittivity *
           surface_potential * surface_potential * scale;
}

/// Magnitude of the repulsion at gap h (> 0 pushes the spheres apart) [N].
inline double double_layer_magnitude(double gap, double r_eff, const DoubleLayerParams& p) {
    const double e = std::exp(-std::max(gap, 0.0) / p.debye_length);
    return p.amplitude * r_eff / p.debye_length * e / (1.0 + e);
}

inline PairForce double_layer(const PairGeometry& g, const DoubleLayerParams& p) {
    if (p.amplitude == 0.0 || g.gap > p.cutoff_gap) return {};
    return {(-double_layer_magnitude(g.gap, g.r_eff, p)) * g.n, {}, {}};
}

/// -dF/dh = F(h) / (λ_D (1 + e^{-h/λ_D})) for 0 ≤ h ≤ h_cut: positive, a spring that stiffens as
/// the gap closes (0 in overlap, where the force is constant).
inline double double_layer_stiffness(const PairGeometry& g, const DoubleLayerParams& p) {
    if (p.amplitude == 0.0 || g.gap < 0.0 || g.gap > p.cutoff_gap) return 0.0;
    const double e = std::exp(-g.gap / p.debye_length);
    return double_layer_magnitude(g.gap, g.r_eff, p) / (p.debye_length * (1.0 + e));
}

/// The law as a pair law (pair_law.hpp): conservative, keeps nothing.
struct DoubleLayerLaw {
    using Params = DoubleLayerParams;
    struct State {};
    static constexpr std::string_view name = "double_layer";
    static constexpr std::array limits{ParamLimit<Params>{"amplitude", &Params::amplitude},
                                       ParamLimit<Params>{"debye_length", &Params::debye_length},
                                       ParamLimit<Params>{"cutoff_gap", &Params::cutoff_gap}};
    static double range(const Params& p, double, double) {
        return p.amplitude != 0.0 ? p.cutoff_gap : 0.0;
    }
    /// Central: only the force, no torques to add.
    [[gnu::always_inline]] static inline void add_force(const PairGeometry& g, const Params& p,
                                                        State&, double, PairForce& f,
                                                        PairResistance*) {
        if (p.amplitude == 0.0 || g.gap > p.cutoff_gap) return;
        f.force_i += double_layer(g, p).force_i;
    }
    static PairResistance resistance(const PairGeometry&, const Params&) { return {}; }
    /// At the closest approach before the next rebuild (the repulsion stiffens as the gap closes;
    /// clamped at contact).
    static PairResistance stiffness(const PairGeometry& closest, const PairGeometry&,
                                    const Params& p) {
        PairGeometry at = closest;
        at.gap = std::max(at.gap, 0.0);
        return {double_layer_stiffness(at, p), 0.0, 0.0, 0.0, 0.0, 0.0};
    }
    static bool keeps(const State&) { return false; }
};

} // namespace drydem
