// SPDX-License-Identifier: MIT
#include "drydem/forces/force_field.hpp"
#include <string>
#include <tuple>
#include <utility>

namespace drydem {
namespace {

template <class L>
void collect(std::vector<std::string>& out, const typename L::Params& p, const std::string& who) {
    for (const std::string& v : limit_violations<L>(p))
        out.push_back(std::string(L::name) + " (" + who + "): " + v);
}

template <class... Ls>
void pair_violations(std::tuple<Ls...>*, std::vector<std::string>& out, const PairParams& p,
                     const std::string& who) {
    (collect<Ls>(out, PairLaws::params<Ls>(p), who), ...);
}
template <class... Ls>
void body_violations(std::tuple<Ls...>*, std::vector<std::string>& out, const BodyParams& p,
                     const std::string& who) {
    (collect<Ls>(out, BodyLaws::params<Ls>(p), who), ...);
}

} // namespace

std::vector<std::string> force_field_violations(const ForceField& ff) {
    std::vector<std::string> out;
    for (int i = 0; i < ff.species_count; ++i) {
        for (int j = 0; j < ff.species_count; ++j)
            pair_violations(static_cast<PairLaws::Laws*>(nullptr), out, ff.pair_params(i, j),
                            "species " + std::to_string(i) + "-" + std::to_string(j));
        body_violations(static_cast<BodyLaws::Laws*>(nullptr), out, ff.body_params(i),
                        "species " + std::to_string(i));
    }
    return out;
}

} // namespace drydem
