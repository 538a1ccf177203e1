// SPDX-License-Identifier: MIT
#include "drydem/engine/bond_network.hpp"
#include <algorithm>
#include <fmt/format.h>

namespace drydem {

std::size_t BondNetwork::intact() const {
    return std::size_t(
        std::count_if(bonds.begin(), bonds.end(), [](const Bond& b) { return b.state.intact(); }));
}

std::size_t BondNetwork::broken() const {
    return std::size_t(
        std::count_if(bonds.begin(), bonds.end(), [](const Bond& b) { return b.state.broken; }));
}

std::vector<std::string> BondNetwork::limit_violations() const {
    std::vector<std::string> out;
    if (params.size() != std::size_t(species_count) * std::size_t(species_count))
        return {fmt::format("{} bond parameter sets for {} species", params.size(), species_count)};
    for (int a = 0; a < species_count; ++a)
        for (int b = a; b < species_count; ++b) {
            const SolidBondParams& p = pair(a, b);
            if (p.youngs_modulus == 0.0) continue; // never bonds
            for (const std::string& v : drydem::limit_violations<SolidBondLaw>(p))
                out.push_back(fmt::format("species {}-{}: {}", a, b, v));
        }
    return out;
}

} // namespace drydem
