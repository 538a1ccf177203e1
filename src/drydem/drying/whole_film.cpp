// SPDX-License-Identifier: MIT
#include "drydem/drying/whole_film.hpp"
#include "drydem/analysis/overlap_census.hpp"
#include "drydem/core/error.hpp"
#include "drydem/parallel/mpi_world.hpp"
#include <cstdio>

namespace drydem {

WholeFilm::WholeFilm(const Simulation& sim) : sim_(sim) {
    decomposed_ = sim.halo() != nullptr;
    root_ = !decomposed_ || sim.halo()->rank() == 0;
    size_ = decomposed_ ? std::size_t(sim.halo()->all_sum(std::uint64_t(sim.owned())))
                        : sim.particles().size();
}

void WholeFilm::ask(Request r) const {
    if (decomposed_) (void)parallel::broadcast(int(r));
}

const ParticleStore& WholeFilm::particles() const {
    if (!decomposed_) return sim_.particles();
    if (particles_step_ != sim_.step_count()) {
        ask(kParticles);
        particles_ = sim_.whole_particles();
        particles_step_ = sim_.step_count();
    }
    return particles_;
}

const std::vector<std::int32_t>& WholeFilm::coordination() const {
    if (coordination_step_ != sim_.step_count()) {
        ask(kCoordination);
        coordination_ = sim_.whole_coordination();
        coordination_step_ = sim_.step_count();
    }
    return coordination_;
}

double WholeFilm::kinetic_energy() const {
    ask(kKineticEnergy);
    return sim_.kinetic_energy();
}

double WholeFilm::overlap_p99() const {
    ask(kOverlaps); // nothing to ask on one rank
    std::vector<double> all = sim_.relative_overlaps();
    if (decomposed_) all = sim_.halo()->gather_items(all);
    return analysis::summarise(all).p99;
}

EngineState WholeFilm::state() const {
    ask(kState);
    return sim_.state();
}

RankLoad WholeFilm::own_load() const {
    return {sim_.owned(), sim_.particles().size() - sim_.owned(), parallel::waited_seconds()};
}

std::vector<RankLoad> WholeFilm::rank_loads() const {
    if (!decomposed_) return {own_load()};
    ask(kRankLoads);
    return sim_.halo()->gather_items(std::vector<RankLoad>{own_load()});
}

void WholeFilm::release() const { ask(kRelease); }

void WholeFilm::fail(const std::string& why) const {
    if (!decomposed_) return;
    ask(kFail);
    (void)parallel::broadcast(why);
}

void WholeFilm::serve() const {
    for (;;) {
        const int request = parallel::broadcast(0);
        switch (request) {
        case kRelease:
            return;
        case kParticles:
            (void)sim_.whole_particles();
            break;
        case kCoordination:
            (void)sim_.whole_coordination();
            break;
        case kState:
            (void)sim_.state();
            break;
        case kKineticEnergy:
            (void)sim_.kinetic_energy();
            break;
        case kOverlaps:
            (void)sim_.halo()->gather_items(sim_.relative_overlaps());
            break;
        case kRankLoads:
            (void)sim_.halo()->gather_items(std::vector<RankLoad>{own_load()});
            break;
        case kFail:
            throw RunError(parallel::broadcast(std::string()), "output_failed");
        default: // a request this rank cannot answer: rank 0 waits in it, so end the launch
            std::fprintf(stderr, "error: rank %d: unknown request %d from rank 0\n",
                         sim_.halo()->rank(), request);
            parallel::abort_all(1);
        }
    }
}

} // namespace drydem
