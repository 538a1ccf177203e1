// SPDX-License-Identifier: MIT
// The stability guard of a drying run (docs/model.md "Stability guard"). At the start and at every
// neighbour rebuild the rates of what stays explicit are estimated on the laws' own operators
// (Simulation::stability_estimate); numerics.stability_guard then decides:
//   "adapt"  sets Δt to the guarded step (never above the cap run.time_step),
//   "refuse" stops the run where Δt is beyond the stability bound (max(Δt λ, Δt ω) >= 2, or
//            sqrt(2) for the semi-implicit kick),
//   "warn"   only warns (and again only when the indicator keeps rising above 3/4 of the bound).
// The decision is a pure function (guard_decision), tested directly; StabilityGuard applies it to
// a simulation and keeps what a resumed run needs.
// The quasi-static step (engine/quasi_static.hpp) has no stability bound to estimate: its step is
// set by the displacement per step. There the guard watches the linear solve instead: it counts
// solves and iterations, and where a solve ends above numerics.solver_tolerance "refuse" stops the
// run and the others warn (again only at a residual ten times the last one warned about).
#pragma once
#include "drydem/drying/run_state.hpp"
#include "drydem/io/config.hpp"
#include "drydem/engine/simulation.hpp"
#include <algorithm>
#include <cstdint>
#include <numbers>
#include <string>
#include <string_view>

namespace spdlog {
class logger;
}

namespace drydem {

enum class GuardPolicy : std::uint8_t { adapt, refuse, warn };
/// numerics.stability_guard ("adapt", "refuse", "warn") as the enum.
GuardPolicy guard_policy_of(const std::string& name);

/// The fraction of the stability bound above which a non-adapting guard warns (1.5 of the
/// explicit bound 2), and the rise of the indicator that warns again.
inline constexpr double kGuardWarnFraction = 0.75;
inline constexpr double kGuardWarnRise = 0.05;

struct GuardDecision {
    enum class Action : std::uint8_t { none, warn_close, beyond_bound };
    double time_step; ///< Δt for the next steps [s]
    double indicator; ///< max(Δt λ, Δt ω) at that step (stable below GuardLimits::bound)
    Action action = Action::none;
};

/// The guard's bounds: the cap run.time_step [s], numerics.critical_step_fraction (adapt) and the
/// integrator's stability bound on max(Δt λ, Δt ω) (refuse, warn): 2 for the explicit one;
/// sqrt(2) for the semi-implicit kick, whose spring bound falls from 2 to sqrt(2) as a mode
/// becomes overdamped (docs/model.md "Stability guard").
struct GuardLimits {
    double cap;
    double critical_fraction;
    double bound = 2.0;
};

/// The explicit integrator's largest critical-step fraction: its damping and stiffness bounds
/// combine, (Δt ω)² + 2 Δt λ < 4 for a mode with both, and the guard lets Δt λ reach 1.5.
inline constexpr double kExplicitCriticalFraction = 0.5;

/// numerics.critical_step_fraction as the guard of `integrator` ("explicit", "semi_implicit") uses
/// it: the explicit one (a drying run refuses more, a calendering run is always explicit) takes
/// at most kExplicitCriticalFraction.
inline double critical_fraction_for(const Config& c, std::string_view integrator) {
    return integrator == "semi_implicit"
               ? c.critical_step_fraction_value()
               : std::min(c.critical_step_fraction_value(), kExplicitCriticalFraction);
}
/// The stability bound of GuardLimits for `integrator`.
inline double stability_bound_for(std::string_view integrator) {
    return integrator == "semi_implicit" ? std::numbers::sqrt2 : 2.0;
}

/// What the guard does with an estimate: the current step dt, the limits and the highest
/// indicator warned about so far (warn again only above it + kGuardWarnRise).
GuardDecision guard_decision(GuardPolicy policy, double dt, const GuardLimits& limits,
                             const Simulation::StabilityEstimate& e, double warned_indicator);

class StabilityGuard {
public:
    StabilityGuard(GuardPolicy policy, const GuardLimits& limits, spdlog::logger& log)
        : policy_(policy), limits_(limits), log_(log) {}

    /// At the start of a fresh run: the first estimate. RunError where "refuse" refuses the step
    /// (the run fails like a refusal later on: summary.json says why).
    void start(Simulation& sim);
    /// After each step: a new estimate where the neighbour list was rebuilt. RunError where
    /// "refuse" refuses the step.
    void after_step(Simulation& sim);

    /// Δt λ of the latest estimate.
    [[nodiscard]] double indicator() const { return indicator_; }
    /// The smallest step the guard set [s].
    [[nodiscard]] double min_time_step() const { return dt_min_; }
    /// Wall time this session spent in the estimates [s].
    [[nodiscard]] double wall_time() const { return wall_; }
    /// Quasi-static step: linear solves, CG iterations and the largest residual so far.
    struct SolverTotals {
        std::uint64_t solves = 0, iterations = 0, steps = 0;
        double residual_max = 0.0;
    };
    [[nodiscard]] const SolverTotals& solver_totals() const { return solver_; }

    void fields(StateFields& f) {
        f("guard.dt_min", dt_min_);
        f("guard.indicator", indicator_);
        f("guard.warned_indicator", warned_);
        f("guard.builds_seen", builds_seen_);
        f("guard.solver_solves", solver_.solves);
        f("guard.solver_iterations", solver_.iterations);
        f("guard.solver_steps", solver_.steps);
        f("guard.solver_residual_max", solver_.residual_max);
    }

private:
    /// Estimates, decides, applies; the message of a refusal is returned (empty: none).
    std::string check(Simulation& sim);
    /// The quasi-static step's solve, after each step; the message of a refusal (empty: none).
    std::string check_solver(const Simulation& sim);

    GuardPolicy policy_;
    GuardLimits limits_;
    spdlog::logger& log_;
    double dt_min_ = 0.0, indicator_ = 0.0, warned_ = 0.0, wall_ = 0.0;
    std::uint64_t builds_seen_ = 0;
    SolverTotals solver_;
};

} // namespace drydem
