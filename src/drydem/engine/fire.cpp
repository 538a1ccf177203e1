// SPDX-License-Identifier: MIT
#include "drydem/engine/fire.hpp"
#include <algorithm>
#include <cmath>

namespace drydem {

void FireRelaxation::after_step(Simulation& sim) {
    ParticleStore& p = sim.particles_mut();
    const std::size_t n = p.size();
    double power = 0.0, f2 = 0.0, v2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        power += dot(p.force[i], p.velocity[i]) + dot(p.torque[i], p.omega[i]);
        f2 += norm2(p.force[i]);
        v2 += norm2(p.velocity[i]);
    }
    rms_force_ = n > 0 ? std::sqrt(f2 / double(n)) : 0.0;
    double dt = sim.settings().dt;
    if (power > 0.0) {
        const double mix = f2 > 0.0 ? alpha_ * std::sqrt(v2 / f2) : 0.0;
        for (std::size_t i = 0; i < n; ++i)
            p.velocity[i] = (1.0 - alpha_) * p.velocity[i] + mix * p.force[i];
        if (++positive_ > p_.n_min) {
            dt = std::min(dt * p_.f_inc, dt_max_);
            alpha_ *= p_.f_alpha;
        }
    } else {
        for (std::size_t i = 0; i < n; ++i) p.velocity[i] = p.omega[i] = Vec3{};
        dt *= p_.f_dec;
        alpha_ = p_.alpha_start;
        positive_ = 0;
        ++stops_;
    }
    sim.set_time_step(dt);
}

} // namespace drydem
