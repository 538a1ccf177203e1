// SPDX-License-Identifier: MIT
// The contract of a pair law, and the composition of a compile-time list of laws (issue 12,
// ARCHITECTURE.md "Adding a pair law"). The pair loop, the stability guard, `drydem check`, the
// neighbour list and the checkpoint reach every law only through PairLawList below: no virtual
// call, and a law nobody switched on costs one early return.
//
// A pair law is a struct L with
//   Params                  its parameters for one species pair, as simulated (scaled SI units)
//   State                   what it keeps per pair from step to step (trivially copyable, a value
//                           State{} means "nothing kept"); an empty struct when it keeps nothing
//   name                    a short name (checkpoint layout, messages)
//   range(p, r_i, r_j)      the largest surface gap h at which it acts [m]; 0 when it is off
//   add_force(g, p, s, dt, f, R)  adds its force and torques for the geometry g
//                           (pair_geometry.hpp) to f; it advances its state s by dt, and when R is
//                           given adds the resistance of its dissipative part (resistance.hpp pair
//                           form) to *R. A law that does not act adds nothing (not zeros: the
//                           pair loop pays for every addition)
//   resistance(g, p)        the resistance of its dissipative part at g (zero if conservative):
//                           the linear map velocities -> forces the force applies
//   stiffness(closest, now, p)  |dF/dx| of its conservative part for the stability guard, in the
//                           pair form (normal, sliding); `closest` is the pair brought together by
//                           the neighbour skin (the worst case before the next rebuild), `now` the
//                           present pair: the law picks the one that bounds its rate
//   keeps(s)                whether s holds something (carried over list rebuilds, checkpointed)
//   limits                  the valid interval of each parameter (law_limits.hpp)
// and optionally, for the quasi-static step (engine/quasi_static.hpp) and the kick's implicit
// self-stiffness (M-9.1), the linearisation given what the law keeps (a contact whose spring sits
// at the Coulomb limit slides: it has no tangential stiffness and no tangential damping):
//   tangent(g, p, s)        -dF/dx at g; without it, stiffness(g, g, p)
//   resistance(g, p, s)     the resistance at g; without it, resistance(g, p)
//   add_force(g, p, s, dt, f, R, K)  add_force that also adds tangent(g, p, s) of the state it
//                           leaves to *K when K is given, from what it computed for the force
//                           (the pair loop then evaluates a law once, not twice); without it,
//                           the list calls add_force and then tangent
// A law knows nothing of the application's configuration: its parameters are mapped from the
// configuration in one place, drying/law_parameters.cpp, beside the list's registration.
// Every law of the list sees the same PairGeometry, computed once per pair. A law's state lives
// in the neighbour list beside the pair; it survives rebuilds, re-sorts and periodic wraps while
// the pair stays within reach (the largest range of the list plus the skin) and is cleared once
// the pair has left it, so a law whose state must outlive a gap includes that gap in its range.
#pragma once
#include "drydem/forces/law_limits.hpp"
#include "drydem/forces/law_list.hpp"
#include "drydem/forces/pair_geometry.hpp"
#include "drydem/forces/resistance.hpp"
#include <algorithm>
#include <concepts>
#include <cstdint>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

namespace drydem {

template <class L>
concept PairLaw = requires(const typename L::Params& p, typename L::State& s,
                           const typename L::State& cs, const PairGeometry& g, double r, double dt,
                           PairForce& f, PairResistance* res) {
    { L::name } -> std::convertible_to<std::string_view>;
    { L::range(p, r, r) } -> std::same_as<double>;
    { L::add_force(g, p, s, dt, f, res) } -> std::same_as<void>;
    { L::resistance(g, p) } -> std::same_as<PairResistance>;
    { L::stiffness(g, g, p) } -> std::same_as<PairResistance>;
    { L::keeps(cs) } -> std::same_as<bool>;
    { limit_violations<L>(p) } -> std::same_as<std::vector<std::string>>;
    requires std::is_trivially_copyable_v<typename L::State>;
    requires std::is_default_constructible_v<typename L::Params>;
};

/// A compile-time list of pair laws, summed in list order.
template <PairLaw... Ls>
struct PairLawList {
    using Params = LawParams<Ls...>; ///< one species pair's parameters
    using State = LawStates<Ls...>;  ///< one pair's kept state
    using Laws = std::tuple<Ls...>;  ///< the laws themselves (for walking the list)

    /// The parameters (or state) of law L.
    template <class L>
    static constexpr std::size_t index_of = law_index<L, Ls...>;
    template <class L>
    static auto& params(Params& p) {
        return member_at<index_of<L>>(p);
    }
    template <class L>
    static const auto& params(const Params& p) {
        return member_at<index_of<L>>(p);
    }
    template <class L>
    static auto& state(State& s) {
        return state_at<index_of<L>>(s);
    }

    /// Interaction range of the pair beyond contact [m]: the largest of the laws' ranges.
    static double range(const Params& p, double r_i, double r_j) {
        return range_of(all{}, p, r_i, r_j);
    }

    /// Force and torques of all laws, in list order. With `resistance`, it receives the sum of the
    /// dissipative parts, with the lever arms r + h/2 that every dissipative pair law shares
    /// (centres to the mid-plane of the gap; r - δ/2 in overlap). Always inlined into the pair
    /// loop, like the laws were before they had a list: an out-of-line call here costs 10-20 %.
    /// With `tangent`, it also receives the sum of the laws' tangents (`tangent` below) at the
    /// state the step leaves, without levers.
    [[gnu::always_inline]] static inline PairForce force(const PairGeometry& g, const Params& p,
                                                         State& s, double dt,
                                                         PairResistance* resistance = nullptr,
                                                         PairResistance* tangent = nullptr) {
        PairForce f = force_of(all{}, g, p, s, dt, resistance, tangent);
        if (resistance) set_levers(*resistance, g);
        return f;
    }

    /// Resistance of the dissipative parts at g (stability guard, `drydem check`).
    static PairResistance resistance(const PairGeometry& g, const Params& p) {
        PairResistance r = resistance_of(all{}, g, p);
        set_levers(r, g);
        return r;
    }

    /// Stiffness of the conservative parts (stability guard), levers at `closest`.
    static PairResistance stiffness(const PairGeometry& closest, const PairGeometry& now,
                                    const Params& p) {
        PairResistance k = stiffness_of(all{}, closest, now, p);
        set_levers(k, closest);
        return k;
    }

    /// The resistance at g given the kept state s (quasi-static step).
    static PairResistance resistance(const PairGeometry& g, const Params& p, const State& s) {
        PairResistance r = resistance_kept_of(all{}, g, p, s);
        set_levers(r, g);
        return r;
    }
    /// The stiffness at g given the kept state s (quasi-static step), levers at g.
    static PairResistance tangent(const PairGeometry& g, const Params& p, const State& s) {
        PairResistance k = tangent_of(all{}, g, p, s);
        set_levers(k, g);
        return k;
    }

    /// Whether any law keeps something for this pair.
    [[gnu::always_inline]] static inline bool keeps(const State& s) { return keeps_of(all{}, s); }

    /// The laws' names and state sizes: a checkpoint written with another list is refused.
    static std::string_view layout() { return law_layout<Ls...>(); }

private:
    using all = std::index_sequence_for<Ls...>;
    template <std::size_t K>
    using at = std::tuple_element_t<K, std::tuple<Ls...>>;

    template <std::size_t K, class S>
    [[gnu::always_inline]] static inline auto& member_at(S& s) {
        return law_member<K>(s);
    }
    template <std::size_t K, class S>
    [[gnu::always_inline]] static inline auto& state_at(S& s) {
        return law_member<K>(s);
    }

    // The folds over the list, one per operation (index sequences, no lambdas: every layer
    // between the pair loop and a law is one the inliner might refuse).
    template <std::size_t... K>
    static double range_of(std::index_sequence<K...>, const Params& p, double r_i, double r_j) {
        double h = 0.0;
        ((h = std::max(h, at<K>::range(member_at<K>(p), r_i, r_j))), ...);
        return h;
    }
    template <std::size_t K>
    [[gnu::always_inline]] static inline void
    add_force_at(const PairGeometry& g, const Params& p, State& s, double dt, PairForce& f,
                 PairResistance* resistance, PairResistance* tangent) {
        if constexpr (requires {
                          at<K>::add_force(g, member_at<K>(p), state_at<K>(s), dt, f, resistance,
                                           tangent);
                      }) {
            at<K>::add_force(g, member_at<K>(p), state_at<K>(s), dt, f, resistance, tangent);
        } else {
            at<K>::add_force(g, member_at<K>(p), state_at<K>(s), dt, f, resistance);
            if (tangent) *tangent += tangent_at<K>(g, p, s);
        }
    }
    template <std::size_t... K>
    [[gnu::always_inline]] static inline PairForce
    force_of(std::index_sequence<K...>, const PairGeometry& g, const Params& p, State& s, double dt,
             PairResistance* resistance, PairResistance* tangent) {
        PairForce f{};
        (add_force_at<K>(g, p, s, dt, f, resistance, tangent), ...);
        return f;
    }
    template <std::size_t... K>
    static PairResistance resistance_of(std::index_sequence<K...>, const PairGeometry& g,
                                        const Params& p) {
        PairResistance r;
        ((r += at<K>::resistance(g, member_at<K>(p))), ...);
        return r;
    }
    template <std::size_t... K>
    static PairResistance stiffness_of(std::index_sequence<K...>, const PairGeometry& closest,
                                       const PairGeometry& now, const Params& p) {
        PairResistance k;
        ((k += at<K>::stiffness(closest, now, member_at<K>(p))), ...);
        return k;
    }
    template <std::size_t K>
    static PairResistance resistance_kept_at(const PairGeometry& g, const Params& p,
                                             const State& s) {
        if constexpr (requires { at<K>::resistance(g, member_at<K>(p), law_member<K>(s)); })
            return at<K>::resistance(g, member_at<K>(p), law_member<K>(s));
        else
            return at<K>::resistance(g, member_at<K>(p));
    }
    template <std::size_t... K>
    static PairResistance resistance_kept_of(std::index_sequence<K...>, const PairGeometry& g,
                                             const Params& p, const State& s) {
        PairResistance r;
        ((r += resistance_kept_at<K>(g, p, s)), ...);
        return r;
    }
    template <std::size_t K>
    [[gnu::always_inline]] static inline PairResistance
    tangent_at(const PairGeometry& g, const Params& p, const State& s) {
        if constexpr (requires { at<K>::tangent(g, member_at<K>(p), law_member<K>(s)); })
            return at<K>::tangent(g, member_at<K>(p), law_member<K>(s));
        else
            return at<K>::stiffness(g, g, member_at<K>(p));
    }
    template <std::size_t... K>
    static PairResistance tangent_of(std::index_sequence<K...>, const PairGeometry& g,
                                     const Params& p, const State& s) {
        PairResistance k;
        ((k += tangent_at<K>(g, p, s)), ...);
        return k;
    }
    template <std::size_t... K>
    [[gnu::always_inline]] static inline bool keeps_of(std::index_sequence<K...>, const State& s) {
        return (at<K>::keeps(state_at<K>(s)) || ...);
    }

    static void set_levers(PairResistance& r, const PairGeometry& g) {
        r.lever_i = g.r_i + 0.5 * g.gap;
        r.lever_j = g.r_j + 0.5 * g.gap;
    }
};

} // namespace drydem
