// SPDX-License-Identifier: MIT
// The calendering driver (docs/calendering.md), top to bottom:
//   1. set-up: the film's recipe and box from the drying run's config, its final.csv.
//   2. settle: in the dry state (elastic-plastic NCM contacts, no liquid), the film relaxes the
//      overlaps the drying left, since the capillary force that made them is gone: FIRE
//      (engine/fire.hpp) to a static state (calendering.settle_*). Then the binder bridges of
//      the dry film become solid bonds (bonding.hpp), and the plate comes down onto the highest
//      particle.
//   3. load: the plate moves down at calendering.plate_speed until the porosity below it is the
//      target (displacement mode) or it carries the target pressure (pressure mode).
//   4. hold: calendering.hold_time at the plate height (pressure mode: a servo on the pressure).
//   5. unload: the plate moves up until it carries nothing and clears the film; it is removed.
//   6. relax: without the plate, FIRE brings the film to rest (the force tolerance of the
//      settling, or its top standing still; at most calendering.relaxation); then it is
//      measured (springback). The roll
//      leaves a real film over milliseconds, so its springback is that of a film at rest: the
//      last plate frames of a dynamic run still see it rising.
//      In unloaded_porosity mode steps 3-6 repeat as passes, each pressed deeper (passes.hpp),
//      until the relaxed film has the target porosity.
//   7. end: final.csv, summary.json with the fitted compaction curve, the structure analysis.
// checkpoint/state.bin every output.checkpoint_every of wall time and when stopped: the engine's
// state, the bonds, and the run's own progress (fields()), so that `drydem calender --resume`
// continues bit for bit.
// From the load on, every kCompactionEvery steps the CB agglomerates compact under their mean
// stress (calendering.cb_compaction_pressure, model.md M-2.11), and those that dense partners
// pressed past their densest state flow out of the gap (calendering.cb_extrusion, M-2.13).
// A row of compaction.csv every calendering.record_every of plate travel.
#include "drydem/calendering/calender_run.hpp"
#include "drydem/analysis/analyze.hpp"
#include "drydem/calendering/bonding.hpp"
#include "drydem/calendering/compaction_fit.hpp"
#include "drydem/calendering/nip.hpp"
#include "drydem/calendering/passes.hpp"
#include "drydem/core/error.hpp"
#include "drydem/core/stop_request.hpp"
#include "drydem/drying/analysis_inputs.hpp"
#include "drydem/drying/derived_checks.hpp"
#include "drydem/drying/film_measures.hpp"
#include "drydem/drying/film_setup.hpp"
#include "drydem/drying/drying_run.hpp"
#include "drydem/drying/law_parameters.hpp"
#include "drydem/drying/run_checkpoint.hpp"
#include "drydem/drying/run_observer.hpp"
#include "drydem/drying/run_summary.hpp"
#include "drydem/drying/stability_guard.hpp"
#include "drydem/engine/fire.hpp"
#include "drydem/git_hash.hpp"
#include "drydem/io/particle_io.hpp"
#include "drydem/io/snapshot_writers.hpp"
#include "drydem/output/analysis_writer.hpp"
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <spdlog/logger.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <unistd.h>

namespace drydem {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

/// The phases in order; their number is compaction.csv's `phase` column.
enum class Phase : int { settle = 0, load = 1, hold = 2, unload = 3, relax = 4, done = 5 };

constexpr const char* phase_name(Phase p) {
    constexpr const char* names[] = {"settle", "load", "hold", "unload", "relax", "done"};
    return names[int(p)];
}

/// Steps between two updates of the agglomerates' compaction: the plate travels a few nm
/// (0.2 m/s × 20 × ~7e-10 s = 3 nm), a ten-thousandth of a film, between them, and the mean
/// stress pass costs about one pair-force evaluation.
constexpr std::int64_t kCompactionEvery = 20;

/// The unloaded film is also at rest when its top moves by less than this share of it over
/// kTopWindow of relaxation: deep plastic contacts with friction can keep a residual force above
/// the settling tolerance on a few particles while the thickness, what is measured, stands still
/// (79.1 MPa on the Sangros film: 0.2 nm in 10 us at 160x the tolerance).
constexpr double kStaticTop = 1e-5;
constexpr double kTopWindow = 0.5e-6; ///< [s]

/// The largest step of the calendering run: calendering.time_step, or 1e-9 s.
double largest_calender_step(const Config& c) {
    return c.calender_time_step > 0.0 ? c.calender_time_step : 1e-9;
}

class CalenderRun {
public:
    CalenderRun(const Config& c, const CalenderOptions& o);
    CalenderResult calender();

private:
    [[nodiscard]] ParticleStore dried_film();
    [[nodiscard]] EngineSettings engine_settings() const;
    /// The engine as the checkpoint left it (its bonds, plate and guard vectors: fields()).
    [[nodiscard]] std::unique_ptr<Simulation> resumed_simulation();
    /// compaction.csv: a new one, or a resumed run's cut back to the checkpoint.
    [[nodiscard]] CsvSeriesWriter compaction_csv();
    void start();
    void resume();
    /// Everything the run keeps beside the engine's state, saved or loaded (run_state.hpp).
    void fields(StateFields& f);
    void write_checkpoint();
    [[nodiscard]] double wall_time() const {
        return wall_before_ + std::chrono::duration<double>(Clock::now() - start_).count();
    }
    void refuse_unreachable_target() const;
    [[nodiscard]] std::unique_ptr<Simulation> make_simulation(ParticleStore particles);
    void start_pressing();
    void step();
    [[nodiscard]] double plate_velocity() const;
    /// The pressure the plate is to carry (pressure mode: calendering.target_pressure; line_load
    /// mode: the nip's mean pressure at the present gap, nip.hpp).
    [[nodiscard]] double target_pressure() const {
        if (c_.calender_mode == "line_load")
            return nip_pressure(c_.calender_line_load, c_.calender_roll_radius, settled_thickness_,
                                sim_->plate_height());
        return c_.calender_target_pressure;
    }
    /// The factor on a sphere's mass and moment of inertia while pressing.
    [[nodiscard]] double mass_scaling(const SizeClass& s) const {
        return s.is_cb ? c_.cb_density_scaling : 1.0;
    }
    /// Displacement-controlled modes: the plate stops at a porosity (peak_target_).
    [[nodiscard]] bool presses_to_porosity() const {
        return c_.calender_mode == "displacement" || c_.calender_mode == "unloaded_porosity";
    }
    [[nodiscard]] bool phase_over() const;
    void next_phase();
    /// After a relaxation: the pass measured; true when another pass is to follow.
    [[nodiscard]] bool another_pass();
    void start_pass();
    /// A pass's load begins: its steps and wall time count from here.
    void mark_pass_start() {
        pass_first_step_ = steps();
        pass_wall_start_ = Clock::now();
    }
    void record();
    void watch_top();
    /// The relaxation's end: the settling's force tolerance reached, or the top standing still.
    [[nodiscard]] bool at_rest() const {
        return relax_fire_.rms_force() <= settle_force_ || top_static_;
    }
    void write_frame();
    [[nodiscard]] double plate_pressure() const {
        return -sim_->body_law_total<PlateContactLaw>().force.z / film_.box.area();
    }
    /// The spheres' share of the cell below height h: the NCM particles and the CB agglomerates'
    /// envelopes (with their inner pores) over A h. Above 1 the spheres cannot fit without
    /// overlapping; a random packing fills ~0.64 of space, a polydisperse one somewhat more.
    [[nodiscard]] double sphere_fraction_at(double h) const {
        double v = 0.0;
        for (double r : sim_->particles().radius) v += sphere_volume(r);
        return v / (film_.box.area() * h);
    }
    /// The lowest height the spheres can fill: the agglomerates at calendering.cb_minimal_porosity
    /// where they compact, as dried where they do not.
    [[nodiscard]] double densest_sphere_height() const {
        return compaction_.compacts() || extrusion_.on
                   ? film_.recipe.sphere_height(compaction_.minimal_porosity)
                   : film_.recipe.sphere_height();
    }
    /// The inner porosity of CB sphere i (M-2.11: from its density, the mass kept).
    [[nodiscard]] double inner_porosity(std::size_t i) const {
        return agglomerate_porosity(film_.recipe.cb_porosity, sim_->particles().density[i],
                                    film_.recipe.cb_effective_density);
    }
    /// The CB agglomerates' inner porosity over all of them: 1 - carbon / envelope volume.
    [[nodiscard]] double cb_inner_porosity() const;
    void compact_agglomerates();
    void extrude_agglomerates();
    /// Extruded agglomerate g's solid and mass to the nearest agglomerates with pore room.
    void pass_on_solid(std::size_t g, const std::vector<char>& leaving);
    [[nodiscard]] bool is_cb(std::size_t i) const {
        return film_.recipe.species[sim_->particles().species[i]].is_cb;
    }
    /// I = (v / h) d sqrt(ρ / p) of the most inert sphere at plate height h and pressure p.
    [[nodiscard]] double inertial_number(double h, double p) const {
        return speed_ / h * inertia_scale_ / std::sqrt(p);
    }
    [[nodiscard]] double porosity_at(double h) const {
        return coating_density(film_.areal_mass, h, film_.recipe.solids_density).porosity;
    }
    /// Simulated time since the settling started [s].
    [[nodiscard]] double now() const { return sim_->time(); }
    [[nodiscard]] std::int64_t steps() const { return sim_->step_count(); }
    /// The film's thickness: the highest top of a particle that touches another one or a wall
    /// (what a plate or a micrometer meets); a particle the unloading threw up is not the film.
    [[nodiscard]] double film_top() const {
        const ParticleStore& p = sim_->particles();
        const std::vector<std::int32_t> z = sim_->coordination();
        double top = 0.0;
        for (std::size_t i = 0; i < p.size(); ++i)
            if (z[i] > 0) top = std::max(top, p.position[i].z + p.radius[i]);
        return top > 0.0 ? top : highest_top();
    }
    [[nodiscard]] double highest_top() const { return top_percentile(sim_->particles(), 1.0); }
    void form_bonds();
    void write_particle_bonds() const;
    void finish();
    [[nodiscard]] json summary() const;
    [[nodiscard]] json bonds_summary() const;
    /// summary.json `passes`: per pass the peak aimed at and reached, the unloaded state, the cost.
    [[nodiscard]] json passes_summary() const;
    void analyse(json& s) const;

    const Config& c_;
    const CalenderOptions& o_;
    std::optional<RunCheckpoint> checkpoint_; ///< resuming: what the run continues from
    const Clock::time_point start_ = Clock::now();
    Clock::time_point last_checkpoint_ = start_;
    double wall_before_ = 0.0;                   ///< wall seconds of the sessions before this one
    Clock::time_point pass_wall_start_ = start_; ///< the present pass's load began
    std::int64_t pass_first_step_ = 0;
    StatusLine status_;
    std::shared_ptr<spdlog::logger> log_;
    Film film_;
    std::unique_ptr<Simulation> sim_;
    StabilityGuard guard_;
    FireRelaxation fire_;
    FireRelaxation relax_fire_; ///< the relaxation after the unloading (a fresh FIRE)
    double relax_top_ = NAN, next_top_check_ = 0.0; ///< the film's top at the last check [m]
    bool top_static_ = false; ///< the top moved less than kStaticTop over the last kTopWindow
    double settle_force_;     ///< the settling's force tolerance [N]
    bool settled_ = false;
    double speed_; ///< calendering.plate_speed [m/s]
    AgglomerateCompactionParams compaction_;
    AgglomerateExtrusionParams extrusion_;
    std::size_t extruded_ = 0, extruded_bonds_ = 0; ///< agglomerates, and their intact bonds
    std::size_t extruded_broken_bonds_ = 0; ///< broken bonds that left with them (still counted)
    /// Bonds broken so far, those that left with extruded agglomerates included.
    [[nodiscard]] std::size_t bonds_broken() const {
        return sim_->bonds().broken() + extruded_broken_bonds_;
    }
    double extruded_mass_ = 0.0; ///< [kg]
    double cb_mass_ = 0.0;       ///< the CB agglomerates' mass as dried [kg]
    /// max over the species of d sqrt(ρ), ρ with calendering.cb_density_scaling: the inertial
    /// number I = (v / h) d sqrt(ρ / p) of the most inert sphere is this times v / (h sqrt(p)).
    double inertia_scale_ = 0.0;
    Phase phase_ = Phase::settle;
    double phase_start_ = 0.0, last_record_ = -INFINITY, pressure_ = 0.0;
    CsvSeriesWriter csv_;
    std::ofstream dump_;
    std::uint64_t csv_bytes_ = 0, dump_bytes_ = 0; ///< at the checkpoint: the rest is replayed
    std::size_t rows_ = 0;
    std::vector<double> load_pressure_, load_porosity_, load_inertial_;
    CalenderResult r_;
    double settled_thickness_ = 0.0, settled_overlap_ = 0.0, dried_overlap_ = 0.0;
    double peak_plate_ = 0.0; ///< the plate's height at the end of the hold [m]
    double peak_sphere_fraction_ = 0.0, peak_cb_porosity_ = 0.0; ///< at the end of the hold
    double peak_target_ = c_.calender_target_porosity; ///< this pass presses to it (porosity modes)
    double pass_peak_pressure_ = 0.0;                  ///< [Pa]
    std::vector<CalenderPass> passes_;
    BinderDistribution binder_;
    BondingReport bonding_;
    std::size_t broken_at_peak_ = 0; ///< bonds broken by the end of the hold
};

CalenderRun::CalenderRun(const Config& c, const CalenderOptions& o)
    : c_(c), o_(o),
      checkpoint_(o.resume ? std::optional(read_run_checkpoint(o.output_dir)) : std::nullopt),
      status_(!o.quiet && isatty(STDERR_FILENO)),
      log_(make_run_logger(o.output_dir, o.quiet, o.resume, status_)), film_(describe_film(c)),
      sim_(o.resume ? resumed_simulation() : make_simulation(dried_film())),
      guard_(GuardPolicy::adapt, {largest_calender_step(c), critical_fraction_for(c, "explicit")},
             *log_),
      fire_(1.8 * largest_calender_step(c)), relax_fire_(1.8 * largest_calender_step(c)),
      settle_force_(c.calender_settle_tolerance * film_.box.area() /
                    double(std::max<std::size_t>(sim_->particles().size(), 1))),
      speed_(c.calender_plate_speed), compaction_(agglomerate_compaction(c)),
      extrusion_(agglomerate_extrusion(c)), csv_(compaction_csv()) {
    for (const SizeClass& s : film_.recipe.species)
        inertia_scale_ =
            std::max(inertia_scale_, s.diameter * std::sqrt(s.density * mass_scaling(s)));
    const fs::path dump = o.output_dir / "snapshots" / "dump.lammpstrj";
    if (checkpoint_) {
        checkpoint_->progress("calender.dump_bytes", dump_bytes_);
        truncate_to_checkpoint(dump, dump_bytes_);
        dump_.open(dump, std::ios::app);
        return;
    }
    refuse_unreachable_target();
    std::ofstream(o.output_dir / "config.toml") << to_toml(c);
    fs::create_directories(o.output_dir / "snapshots");
    dump_.open(dump);
}

CsvSeriesWriter CalenderRun::compaction_csv() {
    const fs::path file = o_.output_dir / "compaction.csv";
    if (checkpoint_) {
        checkpoint_->progress("calender.csv_bytes", csv_bytes_);
        truncate_to_checkpoint(file, csv_bytes_);
    }
    return CsvSeriesWriter(file, {"time_s",           "phase",
                                  "plate_height_um",  "pressure_MPa",
                                  "porosity",         "film_top_um",
                                  "contacts",         "max_overlap_rel",
                                  "kinetic_energy_J", "dt_s",
                                  "inertial_number",  "bonds_intact",
                                  "bonds_broken",     "cb_inner_porosity",
                                  "stress_xx_MPa",    "stress_yy_MPa",
                                  "stress_zz_MPa",    "stress_xy_MPa",
                                  "stress_xz_MPa",    "stress_yz_MPa",
                                  "cb_extruded",      "pass"},
                           checkpoint_.has_value());
}

/// The dried film: final.csv of the run, at rest.
ParticleStore CalenderRun::dried_film() {
    const fs::path file = o_.run_dir / "final.csv";
    if (!fs::exists(file))
        throw InputError(fmt::format("{}: no final.csv; calender a drying run that has finished "
                                     "(its folder holds final.csv)",
                                     o_.run_dir.string()));
    // A stopped drying run also leaves final.csv (its film so far): its summary says so.
    if (const fs::path summary = o_.run_dir / "summary.json"; fs::exists(summary)) {
        std::ifstream in(summary);
        const json s = json::parse(in, nullptr, false);
        const std::string status =
            s.is_object() && s.contains("status") && s["status"].is_string() ? s["status"] : "";
        if (status != "completed")
            throw InputError(fmt::format(
                "{}: the drying run did not finish (summary.json status \"{}\"{}); calender a "
                "finished run, or finish this one with drydem run --resume",
                o_.run_dir.string(), status,
                s.is_object() && s.contains("error") ? ": " + s["error"].dump() : ""));
    }
    ParticleStore particles = particles_from_file(file, film_.recipe, film_.box);
    count_species(film_, particles);
    log_->info("DryDEM {} ({}) calendering {}: {} NCM + {} CB particles, box {:.4g} x {:.4g} um, "
               "mode {}, plate speed {:.3g} m/s",
               DRYDEM_VERSION, DRYDEM_GIT_HASH, file.string(), film_.n_ncm, film_.n_cb,
               c_.box_x * 1e6, c_.box_y * 1e6, c_.calender_mode, c_.calender_plate_speed);
    return particles;
}

/// Before the first step (pressure mode): a target pressure that no packing of these contacts
/// carries, or a plate so fast that the film cannot follow it quasi-statically.
void CalenderRun::refuse_unreachable_target() const {
    if (presses_to_porosity()) {
        // The gap at the target porosity must hold the spheres' volume: below it only overlap
        // lenses of the size of whole spheres would make room (docs/calendering.md).
        const double gap =
            film_.areal_mass / ((1.0 - c_.calender_target_porosity) * film_.recipe.solids_density);
        const double spheres = densest_sphere_height();
        if (gap <= spheres)
            throw InputError(fmt::format(
                "calendering.target_porosity = {:.3g}: its gap of {:.4g} um is below the "
                "spheres' own height of {:.4g} um (NCM particles and CB agglomerates with "
                "their inner pores, formulation.cb_porosity, compacted at most to "
                "calendering.cb_minimal_porosity where calendering.cb_compaction_pressure > 0 or "
                "calendering.cb_extrusion), "
                "so no packing of them reaches it; the lowest porosity with the spheres filling "
                "the whole gap is {:.3g}",
                c_.calender_target_porosity, gap * 1e6, spheres * 1e6, porosity_at(spheres)));
        return;
    }
    if (c_.calender_mode != "pressure") return;
    const int ncm = 0;
    const double p_y = law<HertzMindlinLaw>(sim_->forces().pair_params(ncm, ncm)).yield_pressure;
    // Thornton-Ning caps a contact's mean pressure at p_y; the film's pressure is the contacts'
    // force over the whole cell, so it stays below p_y.
    if (p_y > 0.0 && c_.calender_target_pressure >= p_y)
        throw InputError(fmt::format(
            "calendering.target_pressure = {:.4g} MPa: the NCM contacts yield at {:.4g} MPa "
            "(calendering.yield_pressure / yield_displacement), so no packing of them carries "
            "that pressure; choose a lower target",
            c_.calender_target_pressure * 1e-6, p_y * 1e-6));
    // Inertial number at the target, I = (v / h) d sqrt(ρ / p): above 0.1 the film flows (GDR
    // MiDi's dense regime); the plate-speed check found no trend up to I = 0.03.
    const double inertial = inertial_number(film_top(), c_.calender_target_pressure);
    if (inertial > 0.1)
        throw InputError(fmt::format(
            "calendering.plate_speed = {:.3g} m/s is too fast to be quasi-static: the inertial "
            "number at calendering.target_pressure would be {:.2g} (allowed up to 0.1; "
            "docs/calendering.md); lower the speed to {:.3g} m/s or less",
            speed_, inertial, speed_ * 0.1 / inertial));
}

/// The engine on the dried film at rest in the dry state (explicit; the plate not yet there).
std::unique_ptr<Simulation> CalenderRun::make_simulation(ParticleStore particles) {
    for (std::size_t i = 0; i < particles.size(); ++i)
        particles.velocity[i] = particles.omega[i] = Vec3{};
    for (std::size_t k = 0; k < film_.recipe.species.size(); ++k)
        particles.scale_inertia(std::uint8_t(k), mass_scaling(film_.recipe.species[k]));
    return std::make_unique<Simulation>(std::move(particles), film_.box,
                                        make_calendering_force_field(c_, film_.recipe),
                                        engine_settings());
}

EngineSettings CalenderRun::engine_settings() const {
    EngineSettings es;
    es.integrator = Integrator::explicit_verlet;
    es.dt = largest_calender_step(c_);
    es.skin = c_.neighbor_skin(/*for_calendering=*/true);
    es.threads = c_.threads;
    es.sort_every = c_.sort_every;
    es.overlap_limit = c_.overlap_limit;
    es.guard_warm_start = true; // its list is rebuilt often; a checkpoint keeps the vectors
    return es;
}

std::unique_ptr<Simulation> CalenderRun::resumed_simulation() {
    // The checkpoint's particles carry the scaled inertia, compacted agglomerates and the
    // extruded ones' absence already.
    return std::make_unique<Simulation>(std::move(checkpoint_->engine), film_.box,
                                        make_calendering_force_field(c_, film_.recipe),
                                        engine_settings());
}

/// The settled film at rest, the guard's step again, the plate on the highest particle.
void CalenderRun::start_pressing() {
    settled_thickness_ = film_top();
    const double plate = highest_top();
    settled_overlap_ = sim_->stats().max_overlap_rel;
    settled_ = fire_.rms_force() <= settle_force_;
    if (!settled_)
        log_->warn("the film did not settle within calendering.settle_time = {:.3g} s (rms force "
                   "{:.3g} N, tolerance {:.3g} N); pressing it as it is",
                   c_.calender_settle_time, fire_.rms_force(), settle_force_);
    ParticleStore& p = sim_->particles_mut();
    for (std::size_t i = 0; i < p.size(); ++i) p.velocity[i] = p.omega[i] = Vec3{};
    form_bonds();
    guard_.start(*sim_);
    sim_->set_plate_height(plate);
}

/// The binder bridges of the settled film as solid bonds (calendering.bond_*; none when
/// calendering.bond_youngs_modulus = 0).
void CalenderRun::form_bonds() {
    if (c_.bond_youngs_modulus == 0.0) return;
    binder_ = read_binder_distribution(o_.run_dir);
    bonding_ = drydem::form_bonds(*sim_, calendering_bond_parameters(c_, film_.recipe), binder_,
                                  c_.bond_gap, c_.bond_probability, c_.seed);
    log_->info("bonds: {} CB-CB + {} CB-NCM of {} pairs within {:.3g} nm ({} where the binder "
               "profile asks for more than all); binder {}",
               bonding_.cb_cb, bonding_.cb_ncm, bonding_.candidates, c_.bond_gap * 1e9,
               bonding_.saturated, binder_.source);
}

/// The plate's velocity in the present phase (+z up) [m/s]; the pressure servo of the hold.
double CalenderRun::plate_velocity() const {
    switch (phase_) {
    case Phase::load:
        return -speed_;
    case Phase::hold:
        if (presses_to_porosity()) return 0.0;
        // Proportional servo: full speed at a 20 % pressure error, down when below the target.
        return -speed_ *
               std::clamp(5.0 * (target_pressure() - pressure_) / target_pressure(), -1.0, 1.0);
    case Phase::unload:
        return speed_;
    default:
        return 0.0;
    }
}

bool CalenderRun::phase_over() const {
    const double t = now() - phase_start_;
    switch (phase_) {
    case Phase::settle:
        return fire_.rms_force() <= settle_force_ || t >= c_.calender_settle_time;
    case Phase::load:
        return presses_to_porosity() ? porosity_at(sim_->plate_height()) <= peak_target_
                                     : pressure_ >= target_pressure();
    case Phase::hold:
        return t >= c_.calender_hold_time;
    case Phase::unload:
        return pressure_ <= 0.0 && sim_->plate_height() > highest_top();
    case Phase::relax:
        return at_rest() || t >= c_.calender_relaxation;
    default:
        return true;
    }
}

void CalenderRun::next_phase() {
    if (phase_ == Phase::hold) {
        broken_at_peak_ = bonds_broken();
        r_.peak_thickness = peak_plate_ = sim_->plate_height();
        r_.peak_porosity = porosity_at(r_.peak_thickness);
        peak_sphere_fraction_ = sphere_fraction_at(r_.peak_thickness);
        peak_cb_porosity_ = cb_inner_porosity();
    }
    if (phase_ == Phase::unload) sim_->set_plate_height(INFINITY); // the plate is gone
    if (phase_ == Phase::settle) start_pressing();
    write_frame();
    if (phase_ == Phase::relax && another_pass()) {
        start_pass();
        return;
    }
    phase_ = Phase(int(phase_) + 1);
    phase_start_ = now();
    if (phase_ == Phase::load) mark_pass_start();
    log_->info("{} from t = {:.4g} us: plate at {:.4g} um, {:.4g} MPa", phase_name(phase_),
               now() * 1e6, std::min(sim_->plate_height(), 1.0) * 1e6, pressure_ * 1e-6);
}

/// The relaxed film measured as a pass; in unloaded_porosity mode, whether it needs another one
/// (and which peak: passes.hpp), or a RunError when the target is passed or out of reach.
bool CalenderRun::another_pass() {
    const double top = film_top();
    passes_.push_back({peak_target_, porosity_at(peak_plate_), pass_peak_pressure_,
                       porosity_at(top), top, at_rest(), steps() - pass_first_step_,
                       std::chrono::duration<double>(Clock::now() - pass_wall_start_).count()});
    const CalenderPass& last = passes_.back();
    log_->info("pass {}: pressed to porosity {:.4f} ({:.4g} MPa), unloaded {:.4f}", passes_.size(),
               last.peak_porosity, last.peak_pressure * 1e-6, last.unloaded_porosity);
    if (c_.calender_mode != "unloaded_porosity") return false;
    const double target = c_.calender_target_porosity, tol = c_.calender_porosity_tolerance;
    const PassDecision d = decide_next_pass(passes_, target, tol, c_.calender_passes,
                                            porosity_at(densest_sphere_height()));
    switch (d.outcome) {
    case PassOutcome::done:
        return false;
    case PassOutcome::again:
        peak_target_ = d.next_peak;
        return true;
    case PassOutcome::pressed_past:
        throw RunError(fmt::format(
            "pass {} pressed the film past calendering.target_porosity = {:.4g}: it sprang back "
            "only to {:.4f} from {:.4f} (calendering.porosity_tolerance = {:.3g}); a film cannot "
            "be un-pressed: widen the tolerance or aim higher",
            passes_.size(), target, last.unloaded_porosity, last.peak_porosity, tol));
    case PassOutcome::out_of_passes:
        throw RunError(fmt::format(
            "calendering.target_porosity = {:.4g} after unloading not reached in "
            "calendering.passes = {}: the last pass left the film at {:.4f}; allow more passes",
            target, c_.calender_passes, last.unloaded_porosity));
    case PassOutcome::out_of_reach:
        break;
    }
    throw RunError(fmt::format(
        "calendering.target_porosity = {:.4g} after unloading is out of reach: with the "
        "springback of pass {} ({:.4f} -> {:.4f}) the next pass would press to {:.4f}, at or "
        "below {:.4f}, where the spheres fill the whole gap (docs/calendering.md)",
        target, passes_.size(), last.peak_porosity, last.unloaded_porosity, d.next_peak,
        porosity_at(densest_sphere_height())));
}

/// The next pass: the relaxed film at rest, the guard's step again, the plate back on its
/// highest particle.
void CalenderRun::start_pass() {
    ParticleStore& p = sim_->particles_mut();
    for (std::size_t i = 0; i < p.size(); ++i) p.velocity[i] = p.omega[i] = Vec3{};
    guard_.start(*sim_);
    sim_->set_plate_height(highest_top());
    relax_fire_ = FireRelaxation(1.8 * largest_calender_step(c_));
    relax_top_ = NAN;
    next_top_check_ = 0.0;
    top_static_ = false;
    pass_peak_pressure_ = 0.0;
    phase_ = Phase::load;
    phase_start_ = now();
    mark_pass_start();
    log_->info("pass {}: load from t = {:.4g} us to porosity {:.4f}", passes_.size() + 1,
               now() * 1e6, peak_target_);
}

/// One engine step, the guard, the plate's move, the phase, a row when due.
void CalenderRun::step() {
    sim_->step();
    if (phase_ == Phase::settle)
        fire_.after_step(*sim_);
    else if (phase_ == Phase::relax) {
        relax_fire_.after_step(*sim_);
        watch_top();
    } else {
        guard_.after_step(*sim_);
    }
    if (compaction_.compacts() && phase_ != Phase::settle && steps() % kCompactionEvery == 0)
        compact_agglomerates();
    if (extrusion_.on && phase_ != Phase::settle && steps() % kCompactionEvery == 0)
        extrude_agglomerates();
    const bool plate = phase_ == Phase::load || phase_ == Phase::hold || phase_ == Phase::unload;
    if (plate) {
        sim_->set_plate_height(sim_->plate_height() + plate_velocity() * sim_->settings().dt);
        pressure_ = plate_pressure();
        r_.peak_pressure = std::max(r_.peak_pressure, pressure_);
        pass_peak_pressure_ = std::max(pass_peak_pressure_, pressure_);
    } else {
        pressure_ = 0.0;
    }
    // Loading must reach its target before the plate has crossed the film twice over.
    if (phase_ == Phase::load && now() - phase_start_ > 2.0 * settled_thickness_ / speed_)
        throw RunError("the plate crossed the film without reaching the target; lower "
                       "calendering.target_pressure or raise calendering.target_porosity");
    const double every = c_.calender_record_every / speed_;
    if (now() - last_record_ >= every) record();
    if (phase_over()) next_phase();
}

void CalenderRun::record() {
    const double h = sim_->plate_height(), top = film_top();
    const double inertial =
        phase_ == Phase::load && pressure_ > 0.0 ? inertial_number(h, pressure_) : 0.0;
    const StepStats& st = sim_->stats();
    // The film's contact stress over the cell up to the plate (or the film's top without it).
    const Sym3 s = sim_->contact_stress(film_.box.area() * (std::isfinite(h) ? h : top));
    csv_.row({now(),
              double(int(phase_)),
              std::isfinite(h) ? h * 1e6 : NAN,
              pressure_ * 1e-6,
              porosity_at(std::isfinite(h) ? h : top),
              top * 1e6,
              double(st.contacts),
              st.max_overlap_rel,
              sim_->kinetic_energy(),
              sim_->settings().dt,
              inertial,
              double(sim_->bonds().intact()),
              double(bonds_broken()),
              cb_inner_porosity(),
              s.xx * 1e-6,
              s.yy * 1e-6,
              s.zz * 1e-6,
              s.xy * 1e-6,
              s.xz * 1e-6,
              s.yz * 1e-6,
              double(extruded_),
              double(passes_.size() + 1)});
    if (phase_ == Phase::load && passes_.empty()) { // the virgin loading curve
        load_pressure_.push_back(pressure_);
        load_porosity_.push_back(porosity_at(h));
        load_inertial_.push_back(inertial);
    }
    last_record_ = now();
    if (++rows_ % 50 == 0) write_frame();
    if (status_.tty())
        status_.show(fmt::format("{} t = {:.4g} us, plate {:.4g} um, {:.4g} MPa, porosity {:.4f}",
                                 phase_name(phase_), now() * 1e6,
                                 std::isfinite(h) ? h * 1e6 : top * 1e6, pressure_ * 1e-6,
                                 porosity_at(std::isfinite(h) ? h : top)));
}

double CalenderRun::cb_inner_porosity() const {
    const ParticleStore& p = sim_->particles();
    double carbon = 0.0, envelope = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (film_.recipe.species[p.species[i]].is_cb) {
            const double v = sphere_volume(p.radius[i]);
            carbon += (1.0 - inner_porosity(i)) * v;
            envelope += v;
        }
    return envelope > 0.0 ? 1.0 - carbon / envelope : 0.0;
}

/// M-2.11: each agglomerate's inner porosity follows its mean stress down, never up; the
/// envelope shrinks with the solid kept. Shrinking only lowers overlaps, so the neighbour list
/// (built for the larger spheres) stays valid.
void CalenderRun::compact_agglomerates() {
    const std::vector<double> sigma = sim_->particle_mean_stress();
    ParticleStore& p = sim_->particles_mut();
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (!film_.recipe.species[p.species[i]].is_cb) continue;
        const double e = inner_porosity(i);
        const double compacted = compacted_porosity(compaction_, e, sigma[i]);
        if (compacted < e) p.resize_sphere(i, compacted_radius(p.radius[i], e, compacted));
    }
}

/// M-2.13: a CB sphere whose NCM, substrate and plate contacts (their whole lenses) have pressed
/// it past its densest state flows out of the gap: its solid joins the nearest agglomerates with
/// pore room, and it leaves the packing with its bonds.
void CalenderRun::extrude_agglomerates() {
    const ParticleStore& p = sim_->particles();
    std::vector<double> lens(p.size(), 0.0);
    for (const Simulation::ContactOverlap& o : sim_->contact_overlaps()) {
        if (o.j == Simulation::ContactOverlap::kWall) {
            if (is_cb(o.i)) lens[o.i] += dense_lens(p.radius[o.i], 0.0, o.overlap);
        } else if (is_cb(o.i) != is_cb(o.j)) {
            const std::size_t a = is_cb(o.i) ? o.i : o.j, d = is_cb(o.i) ? o.j : o.i;
            lens[a] += dense_lens(p.radius[a], p.radius[d], o.overlap);
        }
    }
    std::vector<std::size_t> out;
    std::vector<char> leaving(p.size(), 0);
    for (std::size_t i = 0; i < p.size(); ++i)
        if (is_cb(i) && extruded(extrusion_, p.radius[i], lens[i])) {
            out.push_back(i);
            leaving[i] = 1;
        }
    if (out.empty()) return;
    for (const std::size_t g : out) pass_on_solid(g, leaving);
    for (const Bond& b : sim_->bonds().bonds)
        if (leaving[b.i] || leaving[b.j])
            ++(b.state.intact() ? extruded_bonds_ : extruded_broken_bonds_);
    sim_->remove_particles(out);
    extruded_ += out.size();
}

void CalenderRun::pass_on_solid(std::size_t g, const std::vector<char>& leaving) {
    ParticleStore& p = sim_->particles_mut();
    const double v = sphere_volume(p.radius[g]);
    const double solid = (1.0 - inner_porosity(g)) * v, mass = p.density[g] * v;
    struct Candidate {
        double distance2, room;
        std::size_t index;
    };
    std::vector<Candidate> near; // nearest first, ties by storage index
    for (std::size_t k = 0; k < p.size(); ++k)
        if (is_cb(k) && !leaving[k])
            if (const double room = pore_room(extrusion_, p.radius[k], inner_porosity(k)); room > 0)
                near.push_back(
                    {norm2(film_.box.minimum_image(p.position[g], p.position[k])), room, k});
    std::sort(near.begin(), near.end(), [](const Candidate& a, const Candidate& b) {
        return a.distance2 != b.distance2 ? a.distance2 < b.distance2 : a.index < b.index;
    });
    std::vector<double> room;
    for (const Candidate& c : near) room.push_back(c.room);
    const ExtrusionShares share = share_extruded_solid(solid, room);
    if (share.left > 1e-9 * solid)
        throw RunError(fmt::format(
            "agglomerate {} was pressed past its densest state (calendering.cb_extrusion), but "
            "the other agglomerates have no pore room left for its solid: the film is at its "
            "densest ({:.3g} um of solid volume without a place)",
            p.id[g], std::cbrt(share.left) * 1e6));
    for (std::size_t n = 0; n < near.size() && share.taken[n] > 0.0; ++n) {
        const std::size_t k = near[n].index;
        p.set_density(k, p.density[k] + mass * share.taken[n] / solid / sphere_volume(p.radius[k]));
    }
    extruded_mass_ += mass;
}

/// While relaxing: every kTopWindow, whether the film's top stood still since the last look.
void CalenderRun::watch_top() {
    const double t = now() - phase_start_;
    if (t < next_top_check_) return;
    const double top = film_top();
    top_static_ = std::isfinite(relax_top_) && std::abs(top - relax_top_) < kStaticTop * top;
    relax_top_ = top;
    next_top_check_ = t + kTopWindow;
}

void CalenderRun::write_frame() {
    append_lammps_dump(dump_, sim_->particles(), film_.box, steps(),
                       std::isfinite(sim_->plate_height()) ? sim_->plate_height() : highest_top());
}

/// A fresh run: the dried film measured, the guard's first estimate, the first row.
void CalenderRun::start() {
    r_.dried_thickness = film_top();
    r_.dried_porosity = porosity_at(r_.dried_thickness);
    dried_overlap_ = sim_->stats().max_overlap_rel;
    const ParticleStore& p = sim_->particles();
    for (std::size_t i = 0; i < p.size(); ++i)
        if (is_cb(i)) cb_mass_ += p.density[i] * sphere_volume(p.radius[i]);
    guard_.start(*sim_);
    fire_ = FireRelaxation(1.8 * sim_->settings().dt); // within the guard's stable range
    record();
    if (c_.checkpoint_every > 0) write_checkpoint(); // a run killed early can still resume
}

/// A resumed run: everything as the checkpoint left it.
void CalenderRun::resume() {
    fields(checkpoint_->progress);
    checkpoint_->progress.check_all_loaded();
    checkpoint_.reset();
    log_->info("DryDEM {} ({}) resuming the calendering of {} at step {} (t = {:.4g} us, {}), "
               "{} threads",
               DRYDEM_VERSION, DRYDEM_GIT_HASH, o_.run_dir.string(), steps(), now() * 1e6,
               phase_name(phase_), sim_->threads());
}

void CalenderRun::write_checkpoint() {
    dump_.flush();
    csv_bytes_ = fs::file_size(o_.output_dir / "compaction.csv");
    dump_bytes_ = fs::file_size(o_.output_dir / "snapshots" / "dump.lammpstrj");
    write_run_checkpoint(
        o_.output_dir, to_toml(c_), [this](StateFields& f) { fields(f); }, sim_->state());
    last_checkpoint_ = Clock::now();
    r_.resumable = true;
}

void CalenderRun::fields(StateFields& f) {
    // What read_calender_resume needs before the run is made again.
    std::string run_dir = fs::absolute(o_.run_dir).string();
    f("calender.run_dir", run_dir);
    std::int32_t threads = sim_->threads();
    f("run.threads", threads);
    // The phases' progress.
    int phase = int(phase_);
    f("calender.phase", phase);
    phase_ = Phase(phase);
    f("calender.phase_start", phase_start_);
    f("calender.last_record", last_record_);
    f("calender.pressure", pressure_);
    f("calender.rows", rows_);
    f("calender.csv_bytes", csv_bytes_);
    f("calender.dump_bytes", dump_bytes_);
    f("calender.settle_fire", fire_);
    f("calender.relax_fire", relax_fire_);
    f("calender.relax_top", relax_top_);
    f("calender.next_top_check", next_top_check_);
    f("calender.top_static", top_static_);
    f("calender.settled", settled_);
    f("calender.settle_force", settle_force_); // per particle of the film as dried
    // The film as dried and settled, the peak, the passes, the virgin loading curve.
    f("calender.ncm", film_.n_ncm);
    f("calender.cb", film_.n_cb);
    f("calender.dried_thickness", r_.dried_thickness);
    f("calender.dried_porosity", r_.dried_porosity);
    f("calender.dried_overlap", dried_overlap_);
    f("calender.settled_thickness", settled_thickness_);
    f("calender.settled_overlap", settled_overlap_);
    f("calender.peak_pressure", r_.peak_pressure);
    f("calender.peak_thickness", r_.peak_thickness);
    f("calender.peak_porosity", r_.peak_porosity);
    f("calender.peak_plate", peak_plate_);
    f("calender.peak_sphere_fraction", peak_sphere_fraction_);
    f("calender.peak_cb_porosity", peak_cb_porosity_);
    f("calender.peak_target", peak_target_);
    f("calender.pass_peak_pressure", pass_peak_pressure_);
    f("calender.pass_first_step", pass_first_step_);
    f("calender.passes", passes_);
    f("calender.load_pressure", load_pressure_);
    f("calender.load_porosity", load_porosity_);
    f("calender.load_inertial", load_inertial_);
    // The agglomerates and the bonds.
    f("calender.cb_mass", cb_mass_);
    f("calender.extruded", extruded_);
    f("calender.extruded_bonds", extruded_bonds_);
    f("calender.extruded_broken_bonds", extruded_broken_bonds_);
    f("calender.extruded_mass", extruded_mass_);
    f("calender.bonding", bonding_);
    f("calender.binder_source", binder_.source);
    f("calender.broken_at_peak", broken_at_peak_);
    // Wall time: the sessions so far, and the present pass's share of them.
    double wall = wall_time(),
           pass_wall = std::chrono::duration<double>(Clock::now() - pass_wall_start_).count();
    f("calender.wall_time", wall);
    f("calender.pass_wall_time", pass_wall);
    guard_.fields(f);
    // The engine's parts that its state does not hold.
    double plate = sim_->plate_height();
    f("calender.plate_height", plate);
    std::vector<Bond> bonds = sim_->bonds().bonds;
    f("calender.bonds", bonds);
    std::array<std::vector<double>, 2> warm = sim_->guard_warm_start();
    f("calender.guard_warm_start_0", warm[0]);
    f("calender.guard_warm_start_1", warm[1]);
    if (!f.loading()) return;
    wall_before_ = wall;
    pass_wall_start_ = Clock::now() - std::chrono::duration_cast<Clock::duration>(
                                          std::chrono::duration<double>(pass_wall));
    sim_->set_plate_height(plate);
    if (!bonds.empty()) {
        BondNetwork network = calendering_bond_parameters(c_, film_.recipe);
        network.bonds = std::move(bonds);
        sim_->set_bonds(std::move(network), /*from_checkpoint=*/true);
    }
    sim_->set_guard_warm_start(std::move(warm));
}

CalenderResult CalenderRun::calender() {
    try {
        if (checkpoint_)
            resume();
        else
            start();
        while (phase_ != Phase::done) {
            if (const int sig = stop_requested()) {
                write_checkpoint();
                throw RunError(fmt::format("stopped by signal {} before the end", sig));
            }
            if (o_.stop_after_steps && steps() >= *o_.stop_after_steps) {
                write_checkpoint();
                throw RunError(fmt::format("stopped after step {} (--stop-after-steps)", steps()));
            }
            step();
            if (c_.checkpoint_every > 0 &&
                std::chrono::duration<double>(Clock::now() - last_checkpoint_).count() >=
                    c_.checkpoint_every)
                write_checkpoint();
        }
        r_.completed = true;
        r_.resumable = false;
    } catch (const RunError& e) {
        r_.error = e.what();
        // The engine's diagnosis speaks of the drying's scaled forces; here the plate presses.
        if (r_.error.find("runaway overlap") != std::string::npos)
            r_.error += ". In calendering the plate presses the pair together: the film cannot "
                        "reach this target as spheres (docs/calendering.md); raise "
                        "calendering.target_porosity or lower calendering.target_pressure. A CB "
                        "sphere's contact that flattens at a constant limiting pressure lets the "
                        "sphere be pressed through: let it harden as the agglomerate compacts "
                        "(calendering.cb_dense_yield_pressure, docs/model.md M-2.12), and let "
                        "one pressed past its densest state flow out of the gap "
                        "(calendering.cb_extrusion, M-2.13)";
        log_->error("calendering stopped: {}", r_.error);
    }
    finish();
    return r_;
}

void CalenderRun::finish() {
    status_.clear();
    r_.steps = steps();
    r_.passes = int(passes_.size());
    r_.wall_time = wall_time();
    if (r_.completed) {
        r_.unloaded_thickness = film_top();
        r_.unloaded_porosity = porosity_at(r_.unloaded_thickness);
        r_.springback = (r_.unloaded_thickness - r_.peak_thickness) / r_.peak_thickness;
        r_.unloaded_at_rest = at_rest();
        if (!r_.unloaded_at_rest)
            log_->warn("the unloaded film did not come to rest within calendering.relaxation = "
                       "{:.3g} s (rms force {:.3g} N, tolerance {:.3g} N, and its top still "
                       "moved): its springback is that of a film still moving",
                       c_.calender_relaxation, relax_fire_.rms_force(), settle_force_);
    }
    for (std::size_t k = 0; k < load_pressure_.size(); ++k)
        if (load_pressure_[k] >= 0.01 * r_.peak_pressure)
            r_.max_inertial_number = std::max(r_.max_inertial_number, load_inertial_[k]);
    write_particles_csv(o_.output_dir / "final.csv", sim_->particles());
    write_particle_bonds();
    write_frame();
    json s = summary();
    if (r_.completed && c_.analysis_at_end) {
        try {
            analyse(s);
        } catch (const std::exception& e) {
            log_->warn("structure analysis failed: {}", e.what());
        }
    }
    write_file_atomically(o_.output_dir / "summary.json",
                          [&](std::ostream& os) { os << s.dump(2) << "\n"; });
    if (r_.completed)
        log_->info("completed: peak {:.4g} MPa at {:.4g} um (porosity {:.4f}); unloaded {:.4g} um "
                   "(porosity {:.4f}, springback {:.2f} %); {} steps in {:.1f} s",
                   r_.peak_pressure * 1e-6, r_.peak_thickness * 1e6, r_.peak_porosity,
                   r_.unloaded_thickness * 1e6, r_.unloaded_porosity, 100.0 * r_.springback,
                   r_.steps, r_.wall_time);
    else
        log_->info("stopped before the end, at most {:.4g} MPa reached; {} steps in {:.1f} s",
                   r_.peak_pressure * 1e-6, r_.steps, r_.wall_time);
}

json CalenderRun::summary() const {
    // The curve of the film under load: the rows before the plate carries 1 % of the peak are
    // the plate's approach (porosity falls at no pressure) and would fit a vertical drop.
    std::vector<double> p, e;
    for (std::size_t k = 0; k < load_pressure_.size(); ++k)
        if (load_pressure_[k] >= 0.01 * r_.peak_pressure) {
            p.push_back(load_pressure_[k]);
            e.push_back(load_porosity_[k]);
        }
    const CompactionFit fit = fit_compaction(p, e);
    json s;
    s["status"] = r_.completed ? "completed" : "failed";
    if (!r_.completed) s["error"] = r_.error;
    s["dried_film"] = {{"run", fs::absolute(o_.run_dir).string()},
                       {"thickness_um", r_.dried_thickness * 1e6},
                       {"porosity", r_.dried_porosity},
                       {"max_overlap_rel", dried_overlap_},
                       {"sphere_height_um", film_.recipe.sphere_height() * 1e6},
                       {"porosity_at_sphere_height", porosity_at(film_.recipe.sphere_height())}};
    s["settled_film"] = {{"settled", settled_},
                         {"thickness_um", settled_thickness_ * 1e6},
                         {"porosity", porosity_at(settled_thickness_)},
                         {"max_overlap_rel", settled_overlap_},
                         {"rms_force_N", fire_.rms_force()},
                         {"tolerance_N", settle_force_},
                         {"fire_stops", fire_.stops()}};
    s["mode"] = c_.calender_mode;
    if (c_.calender_mode == "line_load")
        s["line_load"] = {
            {"line_load_N_mm", c_.calender_line_load * 1e-3},
            {"roll_radius_mm", c_.calender_roll_radius * 1e3},
            {"nip_length_um",
             std::sqrt(2.0 * c_.calender_roll_radius * (settled_thickness_ - peak_plate_)) * 1e6},
            {"convention", "mean nip pressure q / sqrt(2 R (h0 - h)), h0 the settled film"}};
    s["plate_speed_m_s"] = speed_;
    s["cb_density_scaling"] = c_.cb_density_scaling;
    s["cb_compaction"] = {
        {"pressure_MPa", compaction_.pressure * 1e-6},
        {"initial_porosity", compaction_.initial_porosity},
        {"minimal_porosity",
         compaction_.compacts() ? compaction_.minimal_porosity : compaction_.initial_porosity},
        {"inner_porosity_end", cb_inner_porosity()},
        {"densest_sphere_height_um", densest_sphere_height() * 1e6},
        {"porosity_at_densest_sphere_height", porosity_at(densest_sphere_height())}};
    s["passes"] = passes_summary();
    if (c_.calender_mode == "unloaded_porosity")
        s["target"] = {{"unloaded_porosity", c_.calender_target_porosity},
                       {"tolerance", c_.calender_porosity_tolerance},
                       {"max_passes", c_.calender_passes}};
    s["cb_extrusion"] = {{"on", extrusion_.on},
                         {"agglomerates", extruded_},
                         {"mass_share_of_cb", cb_mass_ > 0.0 ? extruded_mass_ / cb_mass_ : 0.0},
                         {"intact_bonds_removed", extruded_bonds_}};
    s["peak"] = {{"pressure_MPa", r_.peak_pressure * 1e-6},
                 {"thickness_um", r_.peak_thickness * 1e6},
                 {"porosity", r_.peak_porosity},
                 {"plate_height_um", peak_plate_ * 1e6},
                 {"porosity_below_plate", porosity_at(peak_plate_)},
                 {"sphere_fraction", peak_sphere_fraction_},
                 {"cb_inner_porosity", peak_cb_porosity_}};
    s["unloaded"] = {{"thickness_um", r_.unloaded_thickness * 1e6},
                     {"porosity", r_.unloaded_porosity},
                     {"springback_percent", 100.0 * r_.springback},
                     {"at_rest", r_.unloaded_at_rest},
                     {"rms_force_N", relax_fire_.rms_force()},
                     {"tolerance_N", settle_force_},
                     {"top_static", top_static_}};
    s["compaction_fit"] = {{"ok", fit.ok},
                           {"model", "porosity = porosity_min + (porosity_0 - porosity_min) "
                                     "exp(-pressure / resistance)"},
                           {"porosity_min", fit.porosity_min},
                           {"porosity_0", fit.porosity_zero},
                           {"resistance_MPa", fit.resistance * 1e-6},
                           {"rms", fit.rms},
                           {"points", fit.points}};
    s["bonds"] = bonds_summary();
    s["max_inertial_number"] = r_.max_inertial_number;
    s["areal_loading_mg_cm2"] = film_.areal_mass * 100.0;
    s["particles"] = {{"ncm", film_.n_ncm}, {"cb", film_.n_cb}};
    s["steps"] = r_.steps;
    s["time_simulated_s"] = now();
    s["wall_time_s"] = r_.wall_time;
    // The rest of the wall time: settling and relaxation (FIRE), agglomerate compaction and
    // extrusion, the rows (stress tensor), the structure analysis.
    s["wall_time_phases_s"] = wall_time_phases(*sim_, guard_);
    s["neighbor_builds"] = sim_->neighbors().builds();
    s["particle_steps_per_s"] =
        double(r_.steps) * double(sim_->particles().size()) / std::max(r_.wall_time, 1e-9);
    s["threads"] = sim_->threads();
    s["version"] = DRYDEM_VERSION;
    s["git"] = DRYDEM_GIT_HASH;
    return s;
}

json CalenderRun::passes_summary() const {
    json passes = json::array();
    for (const CalenderPass& q : passes_)
        passes.push_back({{"peak_target_porosity", q.peak_target},
                          {"peak_porosity", q.peak_porosity},
                          {"peak_pressure_MPa", q.peak_pressure * 1e-6},
                          {"unloaded_porosity", q.unloaded_porosity},
                          {"unloaded_thickness_um", q.unloaded_thickness * 1e6},
                          {"at_rest", q.at_rest},
                          {"steps", q.steps},
                          {"wall_time_s", q.wall_time}});
    return passes;
}

json CalenderRun::bonds_summary() const {
    if (c_.bond_youngs_modulus == 0.0)
        return {{"made", 0}, {"note", "no bonds (calendering.bond_youngs_modulus = 0)"}};
    // Made when drying ended; extruded agglomerates took theirs out of the network.
    const std::size_t made = bonding_.cb_cb + bonding_.cb_ncm, broken = bonds_broken();
    return {
        {"made", made},
        {"cb_cb", bonding_.cb_cb},
        {"cb_ncm", bonding_.cb_ncm},
        {"candidates", bonding_.candidates},
        {"saturated_candidates", bonding_.saturated},
        {"binder_profile", binder_.source},
        {"broken", broken},
        {"broken_by_peak", broken_at_peak_},
        {"broken_fraction", made ? double(broken) / double(made) : 0.0},
        {"left_with_extruded", {{"intact", extruded_bonds_}, {"broken", extruded_broken_bonds_}}},
        {"per_particle", "particle_bonds.csv"}};
}

/// particle_bonds.csv: each particle's intact and broken bonds and its contacts at the end.
void CalenderRun::write_particle_bonds() const {
    const ParticleStore& p = sim_->particles();
    const BondCounts b = bond_counts(*sim_);
    const std::vector<std::int32_t> z = sim_->coordination();
    write_file_atomically(o_.output_dir / "particle_bonds.csv", [&](std::ostream& os) {
        os << "id,type,z_um,bonds_intact,bonds_broken,contacts\n";
        for (std::size_t i = 0; i < p.size(); ++i)
            os << fmt::format("{},{},{:.6g},{},{},{}\n", p.id[i], p.species[i] + 1,
                              p.position[i].z * 1e6, b.intact[i], b.broken[i], z[i]);
    });
}

/// The structure analysis of the calendered film into analysis/, as a drying run's.
void CalenderRun::analyse(json& s) const {
    analysis::AnalysisOptions ao = end_of_run_analysis_options(c_);
    ao.log = [this](const std::string& m) { log_->info("analysis: {}", m); };
    const analysis::Structure st = analysis::structure_from_file(
        read_particles(o_.output_dir / "final.csv"), file_defaults(c_));
    const analysis::AnalysisResult ar = analysis::analyze_structure(st, ao);
    write_analysis(o_.output_dir / "analysis", ar, ao, "final.csv");
    json add;
    add["analysis"] = "analysis/analysis.json";
    add["coordination_mean"] = ar.coordination.mean();
    const analysis::Coordination& co = ar.coordination;
    add["coordination"] = {
        {"ncm_with_ncm", co.ncm_with_ncm()},    {"ncm_with_cb", co.ncm_with_cb()},
        {"cb_with_ncm", co.cb_with_ncm()},      {"cb_with_cb", co.cb_with_cb()},
        {"ncm_on_substrate", co.ncm_substrate}, {"cb_on_substrate", co.cb_substrate}};
    if (ar.transport && ar.transport->solved()) {
        const analysis::TransportLevel& L = ar.transport->reported();
        add["tortuosity_factor_z"] = L.tau_z;
        add["electronic_conductivity_S_m"] = L.electronic_z.sigma_eff;
    }
    s.update(add);
}

} // namespace

CalenderResume read_calender_resume(const std::filesystem::path& output_dir) {
    RunCheckpoint ck = read_run_checkpoint(output_dir);
    if (!ck.progress.has("calender.run_dir"))
        throw InputError(fmt::format("{}: holds a drying run's checkpoint, not a calendering's; "
                                     "continue it with drydem run --resume {}",
                                     output_dir.string(), output_dir.string()));
    CalenderResume r{load_config(ck.config_toml, checkpoint_file(output_dir).string()), {}};
    std::int32_t threads = 0;
    ck.progress("run.threads", threads);
    r.config.threads = threads;
    std::string run_dir;
    ck.progress("calender.run_dir", run_dir);
    r.run_dir = run_dir;
    return r;
}

CalenderResult run_calendering(const Config& c, const CalenderOptions& options) {
    CalenderRun run(c, options);
    return run.calender();
}

} // namespace drydem
