// SPDX-License-Identifier: MIT
// The contract of a body law, a law acting on one particle alone (the substrate, the suspending
// liquid, gravity, the liquid level; a calendering plate later), and the composition of a
// compile-time list of them (ARCHITECTURE.md "Adding a body law"). The particle loop, the
// stability guard, `drydem check` and the checkpoint reach every body law only through
// BodyLawList: no virtual call, no law named outside its own header and the list.
//
// A body law is a struct L with
//   Params                  its parameters for one species, as simulated (scaled SI units)
//   State                   what it keeps per particle from step to step (trivially copyable,
//                           State{} = nothing kept); an empty struct when it keeps nothing
//   name                    a short name (checkpoint layout, messages)
//   add_force(g, p, s, dt, f, R)  adds its force and torque on the particle g (BodyGeometry) to f;
//                           advances its state s by dt; with R, adds the resistance of its
//                           dissipative part (resistance.hpp body form) to *R
//   resistance(g, p)        the resistance of its dissipative part, the largest the particle can
//                           meet within g.reach of where it is (the guard passes the neighbour
//                           skin, the kick 0: the present state)
//   stiffness(g, p)         |dF/dx| of its conservative part, as an upper bound within g.reach
//                           (body form, spring constants in place of resistances)
//   keeps(s)                whether s holds something
//   limits                  the valid interval of each parameter (law_limits.hpp)
// and optionally, for the quasi-static step, the linearisation given what the law keeps (as for
// a pair law, pair_law.hpp):
//   tangent(g, p, s)        -dF/dx at g; without it, stiffness(g, p) (g.reach = 0: the present)
//   resistance(g, p, s)     the resistance at g; without it, resistance(g, p)
// Like a pair law, it knows nothing of the application's configuration
// (drying/law_parameters.cpp maps the configuration to its parameters).
#pragma once
#include "drydem/forces/law_limits.hpp"
#include "drydem/forces/law_list.hpp"
#include "drydem/forces/pair_geometry.hpp"
#include "drydem/forces/resistance.hpp"
#include <cmath>
#include <concepts>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

namespace drydem {

/// What a body law sees of its particle, built once per particle and step.
struct BodyGeometry {
    Vec3 x;                    ///< centre [m]; the substrate is the plane z = 0
    Vec3 v, omega;             ///< velocity [m/s], angular velocity [rad/s]
    double r = 0.0;            ///< radius [m]
    double mass = 0.0;         ///< [kg]
    double density = 0.0;      ///< particle density [kg/m³]
    double liquid_level = 0.0; ///< z_L [m]
    double reach = 0.0;        ///< how far the particle may move before it is looked at again [m]
    double plate = INFINITY;   ///< height of the calendering plate z_p [m] (+inf: none)
};

template <class L>
concept BodyLaw = requires(const typename L::Params& p, typename L::State& s,
                           const typename L::State& cs, const BodyGeometry& g, double dt,
                           BodyForce& f, BodyResistance* res) {
    { L::name } -> std::convertible_to<std::string_view>;
    { L::add_force(g, p, s, dt, f, res) } -> std::same_as<void>;
    { L::resistance(g, p) } -> std::same_as<BodyResistance>;
    { L::stiffness(g, p) } -> std::same_as<BodyResistance>;
    { L::keeps(cs) } -> std::same_as<bool>;
    { limit_violations<L>(p) } -> std::same_as<std::vector<std::string>>;
    requires std::is_trivially_copyable_v<typename L::State>;
    requires std::is_default_constructible_v<typename L::Params>;
};

/// A compile-time list of body laws, summed in list order.
template <BodyLaw... Ls>
struct BodyLawList {
    using Params = LawParams<Ls...>; ///< one species' parameters
    using State = LawStates<Ls...>;  ///< one particle's kept state
    using Laws = std::tuple<Ls...>;

    template <class L>
    static auto& params(Params& p) {
        return law_member<law_index<L, Ls...>>(p);
    }
    template <class L>
    static const auto& params(const Params& p) {
        return law_member<law_index<L, Ls...>>(p);
    }
    template <class L>
    static auto& state(State& s) {
        return law_member<law_index<L, Ls...>>(s);
    }
    template <class L>
    static const auto& state(const State& s) {
        return law_member<law_index<L, Ls...>>(s);
    }

    /// Force and torque of all laws on one particle, in list order; with `resistance`, it
    /// receives the sum of the dissipative parts.
    [[gnu::always_inline]] static inline BodyForce force(const BodyGeometry& g, const Params& p,
                                                         State& s, double dt,
                                                         BodyResistance* resistance = nullptr) {
        return force_of(all{}, g, p, s, dt, resistance);
    }
    static BodyResistance resistance(const BodyGeometry& g, const Params& p) {
        return resistance_of(all{}, g, p);
    }
    static BodyResistance stiffness(const BodyGeometry& g, const Params& p) {
        return stiffness_of(all{}, g, p);
    }
    /// The resistance at g given the kept state s (quasi-static step).
    static BodyResistance resistance(const BodyGeometry& g, const Params& p, const State& s) {
        return resistance_kept_of(all{}, g, p, s);
    }
    /// The stiffness at g given the kept state s (quasi-static step).
    static BodyResistance tangent(const BodyGeometry& g, const Params& p, const State& s) {
        return tangent_of(all{}, g, p, s);
    }
    static bool keeps(const State& s) { return keeps_of(all{}, s); }
    static std::string_view layout() { return law_layout<Ls...>(); }

private:
    using all = std::index_sequence_for<Ls...>;
    template <std::size_t K>
    using at = std::tuple_element_t<K, Laws>;

    template <std::size_t... K>
    [[gnu::always_inline]] static inline BodyForce
    force_of(std::index_sequence<K...>, const BodyGeometry& g, const Params& p, State& s, double dt,
             BodyResistance* resistance) {
        BodyForce f{};
        (at<K>::add_force(g, law_member<K>(p), law_member<K>(s), dt, f, resistance), ...);
        return f;
    }
    template <std::size_t... K>
    static BodyResistance resistance_of(std::index_sequence<K...>, const BodyGeometry& g,
                                        const Params& p) {
        BodyResistance r;
        ((r += at<K>::resistance(g, law_member<K>(p))), ...);
        return r;
    }
    template <std::size_t... K>
    static BodyResistance stiffness_of(std::index_sequence<K...>, const BodyGeometry& g,
                                       const Params& p) {
        BodyResistance k;
        ((k += at<K>::stiffness(g, law_member<K>(p))), ...);
        return k;
    }
    template <std::size_t K>
    static BodyResistance resistance_kept_at(const BodyGeometry& g, const Params& p,
                                             const State& s) {
        if constexpr (requires { at<K>::resistance(g, law_member<K>(p), law_member<K>(s)); })
            return at<K>::resistance(g, law_member<K>(p), law_member<K>(s));
        else
            return at<K>::resistance(g, law_member<K>(p));
    }
    template <std::size_t... K>
    static BodyResistance resistance_kept_of(std::index_sequence<K...>, const BodyGeometry& g,
                                             const Params& p, const State& s) {
        BodyResistance r;
        ((r += resistance_kept_at<K>(g, p, s)), ...);
        return r;
    }
    template <std::size_t K>
    static BodyResistance tangent_at(const BodyGeometry& g, const Params& p, const State& s) {
        if constexpr (requires { at<K>::tangent(g, law_member<K>(p), law_member<K>(s)); })
            return at<K>::tangent(g, law_member<K>(p), law_member<K>(s));
        else
            return at<K>::stiffness(g, law_member<K>(p));
    }
    template <std::size_t... K>
    static BodyResistance tangent_of(std::index_sequence<K...>, const BodyGeometry& g,
                                     const Params& p, const State& s) {
        BodyResistance k;
        ((k += tangent_at<K>(g, p, s)), ...);
        return k;
    }
    template <std::size_t... K>
    static bool keeps_of(std::index_sequence<K...>, const State& s) {
        return (at<K>::keeps(law_member<K>(s)) || ...);
    }
};

} // namespace drydem
