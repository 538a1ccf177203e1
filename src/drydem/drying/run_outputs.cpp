// SPDX-License-Identifier: MIT
// The outputs of a drying run that follow it step by step: diagnostics, time series, frames,
// LAMMPS dump, checkpoint and progress line. Each owns its trigger and its resume state. The
// outputs of the end (final particles, analysis, summary, plots) are in run_summary.cpp.
#include "drydem/setup/solids.hpp"
#include "drydem/core/error.hpp"
#include "drydem/drying/dimensionless_groups.hpp"
#include "drydem/drying/eta.hpp"
#include "drydem/drying/film_measures.hpp"
#include "drydem/drying/run_checkpoint.hpp"
#include "drydem/drying/run_observer.hpp"
#include "drydem/drying/run_summary.hpp"
#include "drydem/io/config.hpp"
#include "drydem/io/snapshot_writers.hpp"
#include <fmt/format.h>
#include <spdlog/logger.h>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>

namespace drydem {
namespace {
namespace fs = std::filesystem;
constexpr double kNever = std::numeric_limits<double>::infinity();

/// Overlaps beyond this fraction of the smaller radius are warned about once (model.md C-9).
constexpr double kOverlapWarning = 0.25;

/// A trigger every `every` seconds of simulated time; never where `every` is infinite.
struct Every {
    double every;
    double next = 0.0;
    /// Due at t (the caller then advances it).
    [[nodiscard]] bool due(double t) const { return t >= next; }
    void advance() { next += every; }
};

/// Warnings that are given once per run: overlaps beyond kOverlapWarning (C-9), and a film still
/// shrinking after the last dryer zone (C-21).
class Diagnostics final : public RunObserver {
public:
    explicit Diagnostics(const RunContext& ctx) : ctx_(ctx) {}
    const char* name() const override { return "diagnostics"; }
    void after_step(const StepView& s) override {
        const ScaledParameters& sc = ctx_.film.scaled;
        const double t = s.sim.time();
        if (!overlap_ && s.sim.stats().max_overlap_rel > kOverlapWarning) {
            overlap_ = true;
            ctx_.log.warn("overlaps exceed {:.0f} % of the smaller radius at process time {:.3f} s "
                          "(max {:.3f}): the scaled capillary and van der Waals forces press the "
                          "particles harder than their contact stiffness resists (model.md C-9)",
                          kOverlapWarning * 100, sc.process_time(t), s.sim.stats().max_overlap_rel);
        }
        if (!last_zone_ && int(t / sc.zone_duration_scaled) >= int(sc.level_speeds_scaled.size())) {
            last_zone_ = true;
            ctx_.log.warn("the film is still shrinking after the last dryer zone ({:.4g} s); its "
                          "rate is kept (model.md C-21)",
                          sc.process_time(t));
        }
    }
    void fields(StateFields& f) override {
        f("diagnostics.warned_overlap", overlap_);
        f("diagnostics.warned_last_zone", last_zone_);
    }

private:
    const RunContext& ctx_;
    bool overlap_ = false, last_zone_ = false;
};

/// timeseries.csv: a row every output.timeseries_every of process time, at t = 0 and at the end.
class TimeSeries final : public RunObserver {
public:
    explicit TimeSeries(const RunContext& ctx)
        : ctx_(ctx),
          file_(ctx.options.output_dir / "timeseries.csv"), trigger_{ctx.film.scaled.sim_time(
                                                                ctx.config.timeseries_every)} {}
    const char* name() const override { return "time series"; }
    void open(const StepView& s, bool resumed) override {
        if (resumed) truncate_to_checkpoint(file_, bytes_);
        writer_.emplace(file_,
                        std::vector<std::string>{
                            "process_time_s", "sim_time_s", "step", "liquid_level_um",
                            "film_thickness_um", "film_top_p99_um", "kinetic_energy_J", "contacts",
                            "wall_contacts", "max_overlap_rel", "particles_at_level", "dt_lambda",
                            "time_step_s", "zone", "push_number", "inertial_number",
                            "overlap_p99_rel", "solver_solves", "solver_iterations"},
                        resumed);
        if (resumed) return;
        row(s);
        trigger_.next = trigger_.every;
    }
    void after_step(const StepView& s) override {
        if (trigger_.due(s.sim.time()) || s.end.done() || s.timeout) {
            row(s);
            trigger_.advance();
        }
    }
    void fields(StateFields& f) override {
        if (!f.loading()) bytes_ = fs::file_size(file_); // every row is flushed
        f("series.next", trigger_.next);
        f("series.bytes", bytes_);
        f("series.warned_overlap_p99", warned_overlap_);
        f("series.warned_push_number", warned_push_);
    }

private:
    void row(const StepView& s) {
        const Simulation& sim = s.sim;
        const auto& st = sim.stats();
        const Film& film = ctx_.film;
        const int zone = film.schedule.zone(sim.time());
        const LevelLoad load = level_load(s.whole.particles(), sim.forces(), sim.liquid_level(),
                                          film.schedule.speeds[std::size_t(zone)], film.box.area());
        // The pairs the structure analysis' census counts (particles and substrate), taken from
        // the engine's neighbour list rather than a pair search of its own (a census every row
        // was ~3 % of a dense film's steps, on one core); with several ranks, gathered.
        const double p99 = s.whole.overlap_p99();
        const double values[] = {
            ctx_.film.scaled.process_time(sim.time()),
            sim.time(),
            double(sim.step_count()),
            sim.liquid_level() * 1e6,
            st.layer_top * 1e6,
            top_percentile(s.whole.particles(), 0.99) * 1e6,
            s.whole.kinetic_energy(),
            double(st.contacts),
            double(st.wall_contacts),
            st.max_overlap_rel,
            double(particles_cutting_level(s.whole.particles(), sim.liquid_level())),
            s.guard.indicator(),
            sim.settings().dt,
            double(zone + 1),
            load.push_number,
            load.inertial_number,
            p99,
            double(s.guard.solver_totals().solves),
            double(s.guard.solver_totals().iterations)};
        writer_->row(values);
        warn_once(
            warned_overlap_, p99 > overlap_p99_warning,
            "the 99th-percentile overlap is {:.1f} % of the smaller radius at process time {:.3f} "
            "s "
            "(DEM practice ~1 %, warning above {:.0f} %): the contacts are soft for the forces "
            "that press "
            "them; raise scaling.stiffness_factor or lower the force scaling (docs/validation.md)",
            p99 * 100, values[0], overlap_p99_warning * 100);
        warn_once(warned_push_, load.push_number > push_number_warning,
                  "the push number is {:.3g} at process time {:.3f} s (warning above {:g}): the "
                  "level cannot carry "
                  "the film, which then jams where the time scaling puts it; scaling.scheme = "
                  "\"force_ratio\" "
                  "keeps the process's value (docs/validation.md)",
                  load.push_number, values[0], push_number_warning);
    }
    template <class... Args>
    void warn_once(bool& warned, bool condition, fmt::format_string<Args...> text, Args&&... args) {
        if (warned || !condition) return;
        warned = true;
        ctx_.log.warn(text, std::forward<Args>(args)...);
    }

    const RunContext& ctx_;
    fs::path file_;
    Every trigger_;
    std::uint64_t bytes_ = 0;
    std::optional<CsvSeriesWriter> writer_;
    bool warned_overlap_ = false, warned_push_ = false;
};

/// Snapshot times: every output.snapshot_every of process time (0 = none between the first and
/// the last frame).
Every snapshot_trigger(const RunContext& ctx) {
    const double every = ctx.config.snapshot_every;
    return {every > 0 ? ctx.film.scaled.sim_time(every) : kNever};
}

/// An output written at every snapshot time and at the end: `frame` writes one.
class SnapshotObserver : public RunObserver {
public:
    explicit SnapshotObserver(const RunContext& ctx) : trigger_(snapshot_trigger(ctx)) {}
    void after_step(const StepView& s) override {
        if (!trigger_.due(s.sim.time())) return;
        frame(s.sim, s.whole);
        trigger_.advance();
    }
    void finish(const RunEnd& e) override { frame(e.sim, e.whole); }

protected:
    virtual void frame(const Simulation& sim, const WholeFilm& whole) = 0;
    /// The first frame of a fresh run, at t = 0.
    void first_frame(const StepView& s) {
        frame(s.sim, s.whole);
        trigger_.next = trigger_.every;
    }
    Every trigger_;
};

/// snapshots/frame_*.vtp + particles.pvd, and the liquid level as level_*.vtp + liquid_level.pvd.
class Frames final : public SnapshotObserver {
public:
    explicit Frames(const RunContext& ctx)
        : SnapshotObserver(ctx), ctx_(ctx), dir_(ctx.options.output_dir / "snapshots"),
          particles_pvd_(dir_ / "particles.pvd"), level_pvd_(dir_ / "liquid_level.pvd") {}
    const char* name() const override { return "frames"; }
    void open(const StepView& s, bool resumed) override {
        if (resumed) {
            for (PvdWriter* w : {&particles_pvd_, &level_pvd_}) {
                w->load_existing();
                w->truncate(std::size_t(count_));
            }
            return;
        }
        first_frame(s);
    }
    void fields(StateFields& f) override {
        f("frames.next", trigger_.next);
        f("frames.count", count_);
    }

private:
    void frame(const Simulation& sim, const WholeFilm& whole) override {
        const int k = count_++;
        const double tp = ctx_.film.scaled.process_time(sim.time());
        const std::string name = fmt::format("frame_{:05d}.vtp", k);
        write_vtp(dir_ / name, whole.particles(), sim.time(), tp, whole.coordination());
        particles_pvd_.add(tp, name);
        const std::string level_name = fmt::format("level_{:05d}.vtp", k);
        write_level_vtp(dir_ / level_name, ctx_.film.box, sim.liquid_level(), tp);
        level_pvd_.add(tp, level_name);
    }

    const RunContext& ctx_;
    fs::path dir_;
    std::int32_t count_ = 0;
    PvdWriter particles_pvd_, level_pvd_;
};

/// snapshots/dump.lammpstrj (OVITO, LAMMPS read_dump): a frame at every snapshot time.
class Dump final : public SnapshotObserver {
public:
    explicit Dump(const RunContext& ctx)
        : SnapshotObserver(ctx), ctx_(ctx),
          file_(ctx.options.output_dir / "snapshots" / "dump.lammpstrj") {}
    const char* name() const override { return "dump"; }
    void open(const StepView& s, bool resumed) override {
        if (resumed) truncate_to_checkpoint(file_, bytes_);
        os_.open(file_, resumed ? std::ios::app : std::ios::trunc);
        if (resumed) return;
        first_frame(s);
    }
    void fields(StateFields& f) override {
        if (!f.loading()) {
            os_.flush();
            bytes_ = fs::file_size(file_);
        }
        f("dump.next", trigger_.next);
        f("dump.bytes", bytes_);
    }

private:
    void frame(const Simulation& sim, const WholeFilm& whole) override {
        if (!os_.is_open()) os_.open(file_, std::ios::trunc); // a run that failed before open()
        append_lammps_dump(os_, whole.particles(), ctx_.film.box, sim.step_count(),
                           sim.stats().layer_top);
        os_.flush();
    }

    const RunContext& ctx_;
    fs::path file_;
    std::uint64_t bytes_ = 0;
    std::ofstream os_;
};

/// checkpoint/state.bin: at the start, every output.checkpoint_every of wall time, and when the
/// run is stopped (a stopped run can resume).
class Checkpointer final : public RunObserver {
public:
    Checkpointer(const RunContext& ctx, StateVisitor visit_state)
        : ctx_(ctx), visit_state_(std::move(visit_state)), last_(RunClock::now()) {}
    const char* name() const override { return "checkpoint"; }
    void open(const StepView& s, bool resumed) override {
        // A first checkpoint at once: a run killed before the first checkpoint_every (10 min by
        // default) can still be resumed.
        if (!resumed && ctx_.config.checkpoint_every > 0) write(s);
    }
    void after_step(const StepView& s) override {
        if (s.end.done()) return;
        if (s.stop) {
            write(s);
            return;
        }
        if (s.timeout || ctx_.config.checkpoint_every <= 0) return;
        if (std::chrono::duration<double>(s.now - last_).count() >= ctx_.config.checkpoint_every) {
            last_ = s.now;
            write(s);
        }
    }

private:
    void write(const StepView& s) {
        const Simulation& sim = s.sim;
        write_run_checkpoint(ctx_.options.output_dir, to_toml(ctx_.config), visit_state_,
                             s.whole.state());
        ctx_.log.debug("checkpoint at step {} (process time {:.4f} s)", sim.step_count(),
                       ctx_.film.scaled.process_time(sim.time()));
    }

    const RunContext& ctx_;
    StateVisitor visit_state_;
    RunClock::time_point last_;
};

/// The progress line every output.progress_every of wall time: step, process time, level, top,
/// contacts, pace and ETA.
class Progress final : public RunObserver {
public:
    explicit Progress(const RunContext& ctx) : ctx_(ctx), last_(RunClock::now()) {}
    const char* name() const override { return "progress"; }
    void open(const StepView& s, bool /*resumed*/) override {
        pace_.add(0.0, s.sim.time());
        first_step_ = s.sim.step_count();
    }
    void after_step(const StepView& s) override {
        if (!s.continues()) return;
        if (std::chrono::duration<double>(s.now - last_).count() < ctx_.config.progress_every)
            return;
        last_ = s.now;
        const Simulation& sim = s.sim;
        const double t = sim.time();
        const double elapsed = std::chrono::duration<double>(s.now - ctx_.session_start).count();
        pace_.add(elapsed, t);
        const double eta = pace_.eta(remaining(s));
        const std::string line = fmt::format(
            "step {:>9}  t = {:8.3f} s ({:.4g} us sim)  level {:7.3f} um  top {:7.3f} um  "
            "contacts {:>7}  {:.3g} particle-steps/s  ETA {:.0f} s",
            sim.step_count(), ctx_.film.scaled.process_time(t), t * 1e6, sim.liquid_level() * 1e6,
            sim.stats().layer_top * 1e6, sim.stats().contacts,
            double(s.whole.size()) * double(sim.step_count() - first_step_) / elapsed, eta);
        if (ctx_.status.tty()) {
            ctx_.log.debug("{}", line); // log.txt only
            ctx_.status.show(line);
        } else {
            ctx_.log.info("{}", line);
        }
    }
    void finish(const RunEnd& /*end*/) override { ctx_.status.clear(); }

private:
    /// Simulated time still to run: until the level is final_gap below the expected final top (the
    /// current top, or at most the thickness of an uncalendered film of uncalendered_density,
    /// M-8.3), plus the relaxation window.
    [[nodiscard]] double remaining(const StepView& s) const {
        const double t = s.sim.time(), top = s.sim.stats().layer_top;
        if (s.end.final_found()) return s.end.time_end() - t;
        const double expected_top =
            std::min(top, std::max(ctx_.film.areal_mass / uncalendered_density, 0.5 * top));
        const double level_end = std::max(0.0, expected_top - s.end.final_gap());
        return std::max(0.0, ctx_.film.schedule.time_at_level(level_end) - t) + s.end.relaxation();
    }

    const RunContext& ctx_;
    RunClock::time_point last_;
    RecentPace pace_;
    std::int64_t first_step_ = 0;
};

} // namespace

std::vector<std::unique_ptr<RunObserver>> make_run_outputs(const RunContext& ctx,
                                                           StateVisitor visit_state) {
    std::vector<std::unique_ptr<RunObserver>> list;
    list.push_back(std::make_unique<Diagnostics>(ctx));
    list.push_back(std::make_unique<TimeSeries>(ctx));
    list.push_back(std::make_unique<Frames>(ctx));
    list.push_back(std::make_unique<Dump>(ctx));
    list.push_back(std::make_unique<Checkpointer>(ctx, std::move(visit_state)));
    list.push_back(std::make_unique<Progress>(ctx));
    append_end_outputs(ctx, list);
    return list;
}

} // namespace drydem
