// SPDX-License-Identifier: MIT
// What the pair-law list (pair_law.hpp) and the body-law list (body_law.hpp) share: a list's
// parameters and kept states laid out one law after the other, the K-th law's member, and the
// layout text a checkpoint is checked against. No virtual call: every access is resolved at
// compile time and inlined into the force loops.
#pragma once
#include <cstddef>
#include <string>
#include <type_traits>

namespace drydem {

/// The kept states of a list of laws, one after the other; a law that keeps nothing takes no
/// space ([[no_unique_address]] on its empty State).
template <class... Ls>
struct LawStates {};
template <class L, class... Rest>
struct LawStates<L, Rest...> {
    [[no_unique_address]] typename L::State first{};
    [[no_unique_address]] LawStates<Rest...> rest{};
};

/// The parameters of a list of laws, in list order (the first law's at the start of the entry,
/// where the force loop reads first).
template <class... Ls>
struct LawParams {};
template <class L, class... Rest>
struct LawParams<L, Rest...> {
    typename L::Params first{};
    LawParams<Rest...> rest{};
};

/// The K-th member of a LawStates or LawParams.
template <std::size_t K, class S>
[[gnu::always_inline]] inline auto& law_member(S& s) {
    if constexpr (K == 0)
        return s.first;
    else
        return law_member<K - 1>(s.rest);
}

/// Position of L in the list Ls (a compile error when L is not in it).
template <class L, class... Ls>
constexpr std::size_t law_index = [] {
    constexpr bool same[] = {std::is_same_v<L, Ls>...};
    std::size_t k = 0;
    while (!same[k]) ++k;
    return k;
}();

/// "name:state size;" per law: a checkpoint written with another list is refused.
template <class... Ls>
const std::string& law_layout() {
    static const std::string text = [] {
        std::string t;
        ((t += std::string(Ls::name) + ":" + std::to_string(sizeof(typename Ls::State)) + ";"),
         ...);
        return t;
    }();
    return text;
}

} // namespace drydem
