// SPDX-License-Identifier: MIT
// `drydem bench DATA`: the peers' granular benchmark (bench/peer_bench.sh, README "Performance") in
// DryDEM: the settled bed from rest with the benchmark's physics (engine/peer_bed.hpp), dt = 2e-10
// s, skin 0.3 um; `warmup` untimed then `steps` timed steps.
#include "drydem/app/commands.hpp"
#include "drydem/core/error.hpp"
#include "drydem/engine/simulation.hpp"
#include "drydem/engine/peer_bed.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <chrono>
#include <cmath>

namespace drydem::app {

int run_bench(const BenchOptions& o) {
    PeerBed bed = read_peer_bed(o.data, o.physics);
    EngineSettings es;
    es.dt = o.dt;
    es.skin = o.skin;
    es.threads = o.threads;
    es.near_list = !o.whole_list;
    es.overlap_limit = 1.0;
    Simulation sim(std::move(bed.particles), bed.box, bed.forces, es);
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
