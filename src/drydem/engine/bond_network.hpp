// SPDX-License-Identifier: MIT
// The solid bonds of a packing (forces/solid_bond.hpp, model.md M-2.10): which pairs are bonded,
// each bond's state, and the bond law's parameters per species pair. The engine adds the bonds'
// forces after the pair laws' (Simulation::set_bonds); it keeps the particle indices right when it
// re-sorts the particles. Bonds are made once, by whoever sets up the run (calendering: when the
// film is dry, calendering/bonding.hpp), and only ever break.
#pragma once
#include "drydem/core/box.hpp"
#include "drydem/core/particles.hpp"
#include "drydem/forces/solid_bond.hpp"
#include <cstdint>
#include <string>
#include <vector>

namespace drydem {

struct Bond {
    std::uint32_t i = 0, j = 0; ///< the particles' storage indices (i ≠ j)
    SolidBondState state;
};

/// The bonded pair's geometry (minimum image i -> j); with `moving`, its velocities and spins,
/// else at rest (the stability estimate's operators).
inline PairGeometry bond_geometry(const Bond& b, const ParticleStore& p, const Box& box,
                                  bool moving = true) {
    const Vec3 d = box.minimum_image(p.position[b.i], p.position[b.j]);
    if (!moving)
        return make_pair_geometry(d, norm(d), p.radius[b.i], p.radius[b.j], p.mass[b.i],
                                  p.mass[b.j], {}, {}, {}, {});
    return make_pair_geometry(d, norm(d), p.radius[b.i], p.radius[b.j], p.mass[b.i], p.mass[b.j],
                              p.velocity[b.i], p.velocity[b.j], p.omega[b.i], p.omega[b.j]);
}

struct BondNetwork {
    int species_count = 0;
    std::vector<SolidBondParams> params; ///< species_count², symmetric; E_b = 0: never bonds
    std::vector<Bond> bonds;             ///< intact and broken, in the order they were made

    [[nodiscard]] const SolidBondParams& pair(int si, int sj) const {
        return params[std::size_t(si) * std::size_t(species_count) + std::size_t(sj)];
    }
    [[nodiscard]] std::size_t intact() const;
    [[nodiscard]] std::size_t broken() const;
    /// Every bonded species pair's parameter outside the bond law's limits, naming the pair;
    /// empty when all are valid.
    [[nodiscard]] std::vector<std::string> limit_violations() const;
};

} // namespace drydem
