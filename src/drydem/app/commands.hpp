// SPDX-License-Identifier: MIT
#pragma once
#include "drydem/io/config.hpp"
#include <cstdint>
#include <string>

namespace drydem::app {

/// `drydem check`: prints every derived quantity of the configuration; runs nothing.
void print_check(const Config& c);

/// `drydem bench`: the peers' granular benchmark (../shared/peers) in DryDEM.
struct BenchOptions {
    std::string data;
    std::int64_t warmup = 200, steps = 2000;
    int threads = 1;
    double youngs_modulus = 1e10, poisson_ratio = 0.3, restitution = 0.5, friction = 0.8;
    double viscosity = 0.18, gravity = 9.81e6, dt = 2e-10, skin = 0.3e-6;
};
int run_bench(const BenchOptions& o);

} // namespace drydem::app
