// SPDX-License-Identifier: MIT
// Micro-benchmarks of the pair laws (per-pair cost of the composition used in the force loop).
#include "drydem/forces/force_field.hpp"
#include <benchmark/benchmark.h>
#include <vector>

using namespace drydem;

namespace {
PairParams drying_pair() {
    PairParams p;
    law<HertzMindlinLaw>(p) = mix_hertz_mindlin(142e9, 0.3, 142e9, 0.3, 0.5, 0.8, 0.0);
    law<VanDerWaalsLaw>(p) = {4.64e-13, 5e-9, 0.75e-6};
    law<LubricationLaw>(p) = {1.801, 0.1};
    return p;
}

void pair_interaction_bench(benchmark::State& state, double gap) {
    const PairParams p = drying_pair();
    const double r = 0.75e-6;
    const Vec3 d{2 * r + gap, 1e-8, 2e-8};
    PairState hist{};
    for (auto _ : state) {
        const PairGeometry g = make_pair_geometry(d, norm(d), r, r, 2e-15, 2e-15, {1, 0, 0},
                                                  {0, 0.1, 0}, {0, 0, 1e3}, {1e3, 0, 0});
        benchmark::DoNotOptimize(pair_interaction(g, p, hist, 1e-11));
    }
}
/// Throughput of the contact law alone over many independent contacts (as in a pair loop).
void hertz_mindlin_throughput(benchmark::State& state) {
    const HertzMindlinParams p = mix_hertz_mindlin(1e10, 0.3, 1e10, 0.3, 0.5, 0.8, 0.0);
    const double r = 0.75e-6;
    constexpr int n = 1024;
    std::vector<Vec3> hist(n), d(n);
    for (int k = 0; k < n; ++k) {
        d[k] = {2 * r - 1e-9 * (1 + k % 7), 1e-8 * (k % 5), 2e-8 * (k % 3)};
        hist[k] = {0, 1e-10 * (k % 4), 1e-11};
    }
    for (auto _ : state) {
        for (int k = 0; k < n; ++k) {
            const PairGeometry g =
                make_pair_geometry(d[k], norm(d[k]), r, r, 2e-15, 2e-15, {1e-3, 0, 0}, {0, 1e-3, 0},
                                   {0, 0, 1e2}, {1e2, 0, 0});
            benchmark::DoNotOptimize(hertz_mindlin(g, p, hist[k], 2e-10));
        }
    }
    state.SetItemsProcessed(state.iterations() * n);
}
} // namespace

BENCHMARK(hertz_mindlin_throughput);
BENCHMARK_CAPTURE(pair_interaction_bench, contact, -5e-9);
BENCHMARK_CAPTURE(pair_interaction_bench, near_field, 0.2e-6);
BENCHMARK_MAIN();
