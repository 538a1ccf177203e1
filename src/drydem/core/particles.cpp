// SPDX-License-Identifier: MIT
#include "drydem/core/particles.hpp"

namespace drydem {

namespace {
template <class T>
void apply(std::vector<T>& v, const std::vector<std::uint32_t>& order, std::vector<T>& scratch) {
    scratch.resize(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) scratch[k] = v[order[k]];
    v.swap(scratch);
}
} // namespace

void ParticleStore::permute(const std::vector<std::uint32_t>& order) {
    std::vector<std::uint32_t> su;
    std::vector<std::uint8_t> s8;
    std::vector<double> sd;
    std::vector<Vec3> sv;
    apply(id, order, su);
    apply(species, order, s8);
    apply(radius, order, sd);
    apply(density, order, sd);
    apply(mass, order, sd);
    apply(inv_mass, order, sd);
    apply(inv_inertia, order, sd);
    apply(position, order, sv);
    apply(velocity, order, sv);
    apply(omega, order, sv);
    apply(force, order, sv);
    apply(torque, order, sv);
}

} // namespace drydem
