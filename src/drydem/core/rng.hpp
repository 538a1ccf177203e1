// SPDX-License-Identifier: MIT
// Reproducible random numbers: std::mt19937_64 is exactly specified by the standard; the uniform
// transform is our own because std::uniform_real_distribution is not portable across libraries.
#pragma once
#include <cstdint>
#include <random>

namespace drydem {

class Rng {
public:
    explicit Rng(std::uint64_t seed) : engine_(seed) {}
    /// Uniform in [0, 1) with 53 random bits.
    double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

private:
    std::mt19937_64 engine_;
};

} // namespace drydem
