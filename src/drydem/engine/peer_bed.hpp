// SPDX-License-Identifier: MIT
// The peers' granular benchmark bed (../shared/peers, bench/peer_bench.sh, `drydem bench`): a
// settled bed read from a LAMMPS data file, with the benchmark's physics: Hertz-Mindlin with
// tangential history for particles and substrate (E = 1e10 Pa, ν = 0.3, e = 0.5, μ = 0.8),
// gravity 9.81e6 m/s² and per-type Stokes drag 6πηr (η = 0.18 Pa s, translation only, like
// `fix viscous`).
#pragma once
#include "drydem/core/box.hpp"
#include "drydem/core/particles.hpp"
#include "drydem/forces/force_field.hpp"
#include <filesystem>

namespace drydem {

struct PeerBedPhysics {
    double youngs_modulus = 1e10, poisson_ratio = 0.3, restitution = 0.5, friction = 0.8;
    double viscosity = 0.18, gravity = 9.81e6;
};

struct PeerBed {
    ParticleStore particles; ///< positions shifted to the box's origin
    Box box;
    ForceField forces;
};

/// Reads the bed; a file without a periodic box is refused (InputError).
PeerBed read_peer_bed(const std::filesystem::path& data, const PeerBedPhysics& physics = {});

} // namespace drydem
