// SPDX-License-Identifier: MIT
#include "drydem/drying/stability_guard.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
#include <spdlog/logger.h>
#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace drydem {

GuardPolicy guard_policy_of(const std::string& name) {
    if (name == "adapt") return GuardPolicy::adapt;
    if (name == "refuse") return GuardPolicy::refuse;
    if (name == "warn") return GuardPolicy::warn;
    throw InputError(fmt::format(
        "numerics.stability_guard = \"{}\": allowed \"adapt\", \"refuse\", \"warn\"", name));
}

GuardDecision guard_decision(GuardPolicy policy, double dt, const GuardLimits& limits,
                             const Simulation::StabilityEstimate& e, double warned_indicator) {
    if (policy == GuardPolicy::adapt) {
        const double target = guarded_time_step(limits.cap, e, limits.critical_fraction);
        return {target, stability_indicator(target, e)};
    }
    const double indicator = stability_indicator(dt, e);
    if (indicator >= limits.bound) return {dt, indicator, GuardDecision::Action::beyond_bound};
    if (indicator > kGuardWarnFraction * limits.bound &&
        indicator > warned_indicator + kGuardWarnRise)
        return {dt, indicator, GuardDecision::Action::warn_close};
    return {dt, indicator};
}

void StabilityGuard::start(Simulation& sim) {
    dt_min_ = sim.settings().dt;
    if (sim.settings().integrator == Integrator::quasi_static) return;
    const std::string refused = check(sim);
    builds_seen_ = sim.neighbors().builds();
    if (!refused.empty()) throw RunError(refused, "stability_guard");
}

void StabilityGuard::after_step(Simulation& sim) {
    if (sim.settings().integrator == Integrator::quasi_static) {
        const std::string refused = check_solver(sim);
        if (!refused.empty()) throw RunError(refused, "stability_guard");
        return;
    }
    if (sim.neighbors().builds() == builds_seen_) return;
    builds_seen_ = sim.neighbors().builds();
    const std::string refused = check(sim);
    if (!refused.empty()) throw RunError(refused, "stability_guard");
}

std::string StabilityGuard::check(Simulation& sim) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    const Simulation::StabilityEstimate e = sim.stability_estimate();
    wall_ += std::chrono::duration<double>(Clock::now() - t0).count();
    const double dt = sim.settings().dt;
    const GuardDecision d = guard_decision(policy_, dt, limits_, e, warned_);
    indicator_ = d.indicator;
    if (policy_ == GuardPolicy::adapt) {
        if (d.time_step != dt)
            log_.debug(
                "step {}: dt {:.3g} -> {:.3g} s (damping {:.3g} /s, stiffness {:.3g} rad/s, at "
                "particle {}; {} power iterations)",
                sim.step_count(), dt, d.time_step, e.damping_rate, e.stiffness_rate, e.particle_id,
                e.iterations);
        sim.set_time_step(d.time_step);
        dt_min_ = std::min(dt_min_, d.time_step);
        return {};
    }
    if (d.action == GuardDecision::Action::beyond_bound) {
        const std::string msg = fmt::format(
            "time step {:.3g} s is beyond the stability bound: max(dt*lambda, dt*omega) = {:.3g} "
            ">= {:.3g} at particle {} (damping rate {:.3g} /s, stiffness rate {:.3g} rad/s; "
            "docs/model.md \"Stability guard\"); lower run.time_step or use "
            "numerics.stability_guard = \"adapt\"",
            dt, d.indicator, limits_.bound, e.particle_id, e.damping_rate, e.stiffness_rate);
        if (policy_ == GuardPolicy::refuse) return msg;
        log_.warn("{}", msg);
    } else if (d.action == GuardDecision::Action::warn_close) {
        warned_ = d.indicator; // warn again only when it keeps rising
        log_.warn(
            "time step {:.3g} s is close to the stability bound {:.3g}: max(dt*lambda, dt*omega) = "
            "{:.3g} at particle {}",
            dt, limits_.bound, d.indicator, e.particle_id);
    }
    return {};
}

std::string StabilityGuard::check_solver(const Simulation& sim) {
    const QuasiStaticReport& r = sim.quasi_static_report();
    const double tolerance = sim.settings().quasi_static.tolerance;
    dt_min_ = std::min(dt_min_, r.dt);
    ++solver_.steps;
    solver_.solves += std::uint64_t(r.solves);
    solver_.iterations += std::uint64_t(r.iterations);
    solver_.residual_max = std::max(solver_.residual_max, r.residual);
    if (!(r.residual > tolerance) || r.residual <= 10.0 * warned_) return {};
    const std::string msg = fmt::format(
        "quasi-static step {}: the linear solve ended at a relative residual {:.3g} above "
        "numerics.solver_tolerance = {:.3g} after {} iterations (numerics.solver_max_iterations = "
        "{}); the step's forces do not balance to that accuracy",
        sim.step_count(), r.residual, tolerance, r.iterations,
        sim.settings().quasi_static.max_iterations);
    if (policy_ == GuardPolicy::refuse) return msg;
    warned_ = r.residual;
    log_.warn("{}", msg);
    return {};
}

} // namespace drydem
