// SPDX-License-Identifier: MIT
#include "drydem/engine/peer_bed.hpp"
#include "drydem/core/error.hpp"
#include "drydem/io/particle_io.hpp"
#include <fmt/format.h>
#include <algorithm>

namespace drydem {

PeerBed read_peer_bed(const std::filesystem::path& data, const PeerBedPhysics& physics) {
    const ParticleFile in = read_particles(data);
    if (!in.lx || !in.ly)
        throw InputError(
            fmt::format("bench: {} has no box (need a LAMMPS data file)", data.string()));
    PeerBed bed{{}, Box{*in.lx, *in.ly}, {}};
    int types = 0;
    for (const ParticleRecord& r : in.particles) {
        Vec3 x = r.position;
        x.x -= in.xlo.value_or(0.0);
        x.y -= in.ylo.value_or(0.0);
        bed.particles.add(r.id, std::uint8_t(r.type - 1), r.radius, r.density, x);
        types = std::max(types, r.type);
    }
    bed.forces = uniform_contact_force_field(types, physics.youngs_modulus, physics.poisson_ratio,
                                             physics.restitution, physics.friction);
    bed.forces.set_body_law<GravityBuoyancyLaw>({physics.gravity, 0.0});
    bed.forces.set_body_law<StokesDragLaw>({physics.viscosity, false});
    return bed;
}

} // namespace drydem
