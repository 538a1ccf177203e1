// SPDX-License-Identifier: MIT
// Relaxation to a static equilibrium by FIRE (Bitzek, Koskinen, Gähler, Moseler, Gumbsch, Phys.
// Rev. Lett. 97 (2006) 170201), on top of the explicit integrator's velocity-Verlet steps: after
// each step the velocities are turned toward the forces,
//   v <- (1 - α) v + α |v| F/|F|       (global norms over the translational degrees of freedom)
// while the power P = Σ F·v + T·ω stays positive, and every velocity is set to zero the moment it
// turns negative (the descent overshot). The step grows by f_inc after N_min positive steps (never
// above dt_max) and α decays by f_α; a stop halves the step and restarts α. It reaches the static
// state far sooner than damped dynamics, without a made-up viscosity: calendering uses it to let
// the dried film relax once the capillary force that pressed it is gone.
#pragma once
#include "drydem/engine/simulation.hpp"
#include <cstdint>

namespace drydem {

struct FireParameters { // Bitzek et al.'s recommended values
    int n_min = 5;
    double f_inc = 1.1, f_dec = 0.5, alpha_start = 0.1, f_alpha = 0.99;
};

class FireRelaxation {
public:
    /// dt_max: the largest step it may take (the caller's stability bound).
    FireRelaxation(double dt_max, FireParameters p = {})
        : p_(p), dt_max_(dt_max), alpha_(p.alpha_start) {}
    /// After each Simulation::step(): mixes or stops the velocities and sets the next step.
    void after_step(Simulation& sim);
    /// Root mean square of the particles' force magnitudes at the last step [N].
    [[nodiscard]] double rms_force() const { return rms_force_; }
    [[nodiscard]] std::int64_t stops() const { return stops_; }

private:
    FireParameters p_;
    double dt_max_, alpha_;
    int positive_ = 0;
    std::int64_t stops_ = 0;
    double rms_force_ = INFINITY;
};

} // namespace drydem
