// SPDX-License-Identifier: MIT
// What the parts of a drying run share: the film being dried (recipe, scaling, level schedule),
// the run's context, and the interface of its outputs. Each output (time series, frames, dump,
// checkpoint, progress line, summary, plots, ...) is a RunObserver: it owns its trigger and its
// part of the resume state, and the driver calls every observer of one fixed list at the start,
// after each step and at the end (drying_run.cpp).
#pragma once
#include "drydem/core/box.hpp"
#include "drydem/drying/drying_run.hpp"
#include "drydem/drying/end_criterion.hpp"
#include "drydem/drying/liquid_level.hpp"
#include "drydem/drying/run_state.hpp"
#include "drydem/drying/scaling.hpp"
#include "drydem/drying/stability_guard.hpp"
#include "drydem/drying/whole_film.hpp"
#include "drydem/engine/simulation.hpp"
#include "drydem/setup/formulation.hpp"
#include <nlohmann/json.hpp>
#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace spdlog {
class logger;
}

namespace drydem {

using RunClock = std::chrono::steady_clock;

/// The film being dried: the formulation's recipe (M-1), the scaled parameters (M-7) and the
/// descending liquid level (M-8.1).
struct Film {
    FilmRecipe recipe;
    ScaledParameters scaled;
    Box box;
    LiquidLevelSchedule schedule;
    std::size_t n_ncm = 0, n_cb = 0;
    double areal_mass = 0.0; ///< realised dry mass per area [kg/m^2]
};

/// A progress line that updates in place on a terminal. Every console message of the run's
/// logger clears it first (make_run_logger), so messages never land in the middle of it.
class StatusLine {
public:
    explicit StatusLine(bool tty) : tty_(tty) {}
    [[nodiscard]] bool tty() const { return tty_; }
    void show(const std::string& line);
    void clear();

private:
    bool tty_;
    bool shown_ = false;
};

/// The run's logger: console (warnings only when quiet; clears the status line first) and
/// log.txt (everything, appended to on resume).
std::shared_ptr<spdlog::logger> make_run_logger(const std::filesystem::path& dir, bool quiet,
                                                bool append, StatusLine& status);

/// A logger that writes nothing: the other ranks of a decomposed run (rank 0 writes).
std::shared_ptr<spdlog::logger> silent_logger();

/// What every part of the run sees, fixed for the run.
struct RunContext {
    const Config& config;
    const RunOptions& options;
    const Film& film;
    spdlog::logger& log;
    StatusLine& status;
    RunClock::time_point session_start; ///< this session's start (a resumed run starts anew)
};

/// The run after one step, as the outputs see it.
struct StepView {
    const Simulation& sim;  ///< time, level, reduced statistics (the same on every rank)
    const WholeFilm& whole; ///< the particles of the whole film
    const EndCriterion& end;
    const StabilityGuard& guard;
    bool timeout = false; ///< run.max_process_time reached without an end
    int stop = 0;         ///< nonzero: the run stops after this step (signal number)
    RunClock::time_point now;
    /// The run goes on after this step.
    [[nodiscard]] bool continues() const { return !end.done() && stop == 0 && !timeout; }
};

/// The run at its end (completed or not).
struct RunEnd {
    const Simulation& sim;
    const WholeFilm& whole;
    const EndCriterion& end;
    const StabilityGuard& guard;
    const DryingResult& result;
    nlohmann::json& summary; ///< filled by the observers, written by the summary observer
};

class RunObserver {
public:
    virtual ~RunObserver() = default;
    /// Name in messages.
    [[nodiscard]] virtual const char* name() const = 0;
    /// Before the first step: the outputs at t = 0 of a fresh run, or, resumed, the outputs cut
    /// back to the checkpoint (the resume state is loaded before).
    virtual void open(const StepView& /*at*/, bool /*resumed*/) {}
    /// After every step (also the last, and a step after which the run stops).
    virtual void after_step(const StepView& /*step*/) {}
    /// At the end, completed or failed: what the run reached.
    virtual void finish(const RunEnd& /*end*/) {}
    /// Its part of the resume state (saved at each checkpoint, loaded on resume).
    virtual void fields(StateFields& /*f*/) {}
    /// Whether a failure at the end fails the run (the summary); the others are logged only.
    [[nodiscard]] virtual bool required() const { return false; }
};

/// Visits the resume state of every part of the run: the driver's, the end criterion's, the
/// guard's and every observer's.
using StateVisitor = std::function<void(StateFields&)>;

/// The run's outputs, in the order they are called: diagnostics, time series, frames, dump,
/// checkpoint, progress line, final particles, structure analysis, summary, plots.
/// `visit_state` gives the checkpoint every part's resume state.
std::vector<std::unique_ptr<RunObserver>> make_run_outputs(const RunContext& ctx,
                                                           StateVisitor visit_state);

} // namespace drydem
