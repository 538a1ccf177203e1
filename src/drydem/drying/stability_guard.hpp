// SPDX-License-Identifier: MIT
// The stability guard of a drying run (docs/model.md "Stability guard"). At the start and at every
// neighbour rebuild the rates of what stays explicit are estimated on the laws' own operators
// (Simulation::stability_estimate); numerics.stability_guard then decides:
//   "adapt"  sets Δt to the guarded step (never above the cap run.time_step),
//   "refuse" stops the run where Δt is beyond the stability bound (Δt λ >= 2),
//   "warn"   only warns (and again only when Δt λ keeps rising above 1.5).
// The decision is a pure function (guard_decision), tested directly; StabilityGuard applies it to
// a simulation and keeps what a resumed run needs.
// The quasi-static step (engine/quasi_static.hpp) has no stability bound to estimate: its step is
// set by the displacement per step. There the guard watches the linear solve instead: it counts
// solves and iterations, and where a solve ends above numerics.solver_tolerance "refuse" stops the
// run and the others warn (again only at a residual ten times the last one warned about).
#pragma once
#include "drydem/drying/run_state.hpp"
#include "drydem/engine/simulation.hpp"
#include <cstdint>
#include <string>

namespace spdlog {
class logger;
}

namespace drydem {

enum class GuardPolicy : std::uint8_t { adapt, refuse, warn };
/// numerics.stability_guard ("adapt", "refuse", "warn") as the enum.
GuardPolicy guard_policy_of(const std::string& name);

/// Δt λ above which a non-adapting guard warns, and the rise that warns again.
inline constexpr double kGuardWarnIndicator = 1.5;
inline constexpr double kGuardWarnRise = 0.05;

struct GuardDecision {
    enum class Action : std::uint8_t { none, warn_close, beyond_bound };
    double time_step; ///< Δt for the next steps [s]
    double indicator; ///< Δt λ at that step (stable < 2)
    Action action = Action::none;
};

/// What the guard does with an estimate: the current step dt, the cap run.time_step and the
/// highest indicator warned about so far (warn again only above it + kGuardWarnRise).
GuardDecision guard_decision(GuardPolicy policy, double dt, double cap,
                             const Simulation::StabilityEstimate& e, double warned_indicator);

class StabilityGuard {
public:
    StabilityGuard(GuardPolicy policy, double cap, spdlog::logger& log)
        : policy_(policy), cap_(cap), log_(log) {}

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
    double cap_;
    spdlog::logger& log_;
    double dt_min_ = 0.0, indicator_ = 0.0, warned_ = 0.0, wall_ = 0.0;
    std::uint64_t builds_seen_ = 0;
    SolverTotals solver_;
};

} // namespace drydem
