// SPDX-License-Identifier: MIT
// Micro-benchmarks of the pair laws (per-pair cost of the composition used in the force loop).
#include "drydem/forces/force_field.hpp"
#include <benchmark/benchmark.h>

using namespace drydem;

namespace {
PairParams drying_pair() {
    PairParams p;
    p.contact = mix_hertz_mindlin(142e9, 0.3, 142e9, 0.3, 0.5, 0.8, 0.0);
    p.van_der_waals = {4.64e-13, 5e-9, 0.75e-6};
    p.lubrication = {1.801, 0.1};
    return p;
}

void pair_interaction_bench(benchmark::State& state, double gap) {
    const PairParams p = drying_pair();
    const double r = 0.75e-6;
    const Vec3 d{2 * r + gap, 1e-8, 2e-8};
    Vec3 hist{};
    for (auto _ : state) {
        const PairGeometry g = make_pair_geometry(d, norm(d), r, r, 2e-15, 2e-15, {1, 0, 0},
                                                  {0, 0.1, 0}, {0, 0, 1e3}, {1e3, 0, 0});
        benchmark::DoNotOptimize(pair_interaction(g, p, hist, 1e-11));
    }
}
} // namespace

BENCHMARK_CAPTURE(pair_interaction_bench, contact, -5e-9);
BENCHMARK_CAPTURE(pair_interaction_bench, near_field, 0.2e-6);
BENCHMARK_MAIN();
