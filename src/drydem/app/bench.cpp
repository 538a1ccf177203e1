// SPDX-License-Identifier: MIT
// `drydem bench DATA`: the peers' granular benchmark (bench/peer_bench.sh, README "Performance") in DryDEM: the
// settled bed from rest, Hertz-Mindlin with tangential history (E = 1e10 Pa, ν = 0.3, e = 0.5,
// μ = 0.8, particles and wall), gravity 9.81e6 m/s², per-type Stokes drag 6πηr (translation only,
// like `fix viscous`), dt = 2e-10 s, skin 0.3 um; `warmup` untimed then `steps` timed steps.
#include "drydem/app/commands.hpp"
#include "drydem/core/error.hpp"
#include "drydem/engine/simulation.hpp"
#include "drydem/io/particle_io.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <chrono>
#include <cmath>

namespace drydem::app {

int run_bench(const BenchOptions& o) {
    const ParticleFile in = read_particles(o.data);
    if (!in.lx || !in.ly)
        throw InputError(fmt::format("bench: {} has no box (need a LAMMPS data file)", o.data));
    const Box box{*in.lx, *in.ly};
    ParticleStore p;
    int types = 0;
    for (const ParticleRecord& r : in.particles) {
        Vec3 x = r.position;
        x.x -= in.xlo.value_or(0.0);
        x.y -= in.ylo.value_or(0.0);
        p.add(r.id, std::uint8_t(r.type - 1), r.radius, r.density, x);
        types = std::max(types, r.type);
    }
    ForceField ff = uniform_contact_force_field(types, o.youngs_modulus, o.poisson_ratio,
                                                o.restitution, o.friction);
    ff.set_body_law<GravityBuoyancyLaw>({o.gravity, 0.0});
    ff.set_body_law<StokesDragLaw>({o.viscosity, false});
    EngineSettings es;
    es.dt = o.dt;
    es.skin = o.skin;
    es.threads = o.threads;
    es.near_list = !o.whole_list;
    es.overlap_limit = 1.0;
    Simulation sim(std::move(p), box, ff, es);
    const std::size_t n = sim.particles().size();
    sim.run(o.warmup);
    const auto builds0 = sim.neighbors().builds(), near_builds0 = sim.near_pairs().builds();
    const PhaseTimes before = sim.phase_times();
    const auto t0 = std::chrono::steady_clock::now();
    sim.run(o.steps);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double rate = double(n) * double(o.steps) / wall;
    const PhaseTimes& after = sim.phase_times();
    // Contacts per particle as the peers count them: each contact at both particles, no wall.
    fmt::print(
        "{{\"code\": \"drydem\", \"threads\": {}, \"particles\": {}, \"steps\": {}, "
        "\"seconds\": {:.4f}, \"ms_per_step\": {:.4f}, \"particle_steps_per_s\": {:.5g}, "
        "\"contacts_per_particle\": {:.4f}, \"neighbor_builds\": {}, \"pairs_in_list\": {}, "
        "\"near_builds\": {}, \"pairs_near\": {}, "
        "\"seconds_pair\": {:.4f}, \"seconds_neighbor\": {:.4f}, \"seconds_integrate\": {:.4f}}}\n",
        sim.threads(), n, o.steps, wall, 1e3 * wall / double(o.steps), rate,
        2.0 * double(sim.stats().contacts) / double(n), sim.neighbors().builds() - builds0,
        sim.neighbors().pairs(), sim.near_pairs().builds() - near_builds0, sim.near_pairs().pairs(),
        after.pair - before.pair, after.neighbor - before.neighbor,
        after.integrate - before.integrate);
    return 0;
}

} // namespace drydem::app
