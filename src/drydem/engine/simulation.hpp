// SPDX-License-Identifier: MIT
// The DEM engine: owns particles, box, force field and neighbor list, and advances them with
// velocity Verlet (model.md M-9.1). No global state: several simulations can live in one process.
#pragma once
#include "drydem/core/box.hpp"
#include "drydem/core/particles.hpp"
#include "drydem/engine/bond_network.hpp"
#include "drydem/engine/quasi_static.hpp"
#include "drydem/forces/force_field.hpp"
#include "drydem/neighbor/near_list.hpp"
#include "drydem/neighbor/neighbor_list.hpp"
#include "drydem/parallel/halo.hpp"
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace drydem {

/// Time integration (docs/model.md "Resistance and time integration").
enum class Integrator {
    explicit_verlet, ///< velocity Verlet, every force explicit (the reference; Δt < 2/λ_max of M⁻¹R)
    semi_implicit, ///< v += Δt (M_i + Δt D_i)⁻¹ F_i: the dissipative forces do not limit Δt
    quasi_static, ///< (M/Δt + R + Δt K) v = F + M v₀/Δt (quasi_static.hpp): nor do the contacts
};

struct EngineSettings {
    double dt = 1.0e-11;  ///< time step [s] (C-23)
    double skin = 0.1e-6; ///< neighbor skin [m] (M-9.4)
    int threads = 0;      ///< OpenMP threads; 0 = runtime default
    int sort_every = 10;  ///< spatial re-sort every this many rebuilds (0 = never)
    double overlap_limit =
        1.0; ///< stop when an overlap exceeds this fraction of the smaller radius
    double initial_liquid_level = 1.0e30; ///< z_L at t = 0 [m] (far above: no capillary force)
    Integrator integrator = Integrator::explicit_verlet;
    QuasiStaticSettings quasi_static{}; ///< the quasi-static step's accuracy and solver
    /// MPI ranks of a domain decomposition (docs/parallel.md): 1 = none, else the size of
    /// MPI_COMM_WORLD. Explicit and semi-implicit integrators only, without bonds.
    int ranks = 1;
    /// Subdomains along x, y and z; 0 = whichever gives the fewest ghosts (parallel::decompose).
    std::array<int, 3> grid{0, 0, 0};
    /// The stability estimate's power iteration starts from the last estimate's vector (carried
    /// by particle id, with a random part) instead of a fresh random one: far fewer iterations
    /// where it runs every few dozen steps (calendering, whose extrusion rebuilds the list). The
    /// vector is not in the engine state: a run that resumes bit for bit keeps it itself
    /// (guard_warm_start(), as the calendering checkpoint does).
    bool guard_warm_start = false;
    /// Semi-implicit only: each particle's own stiffness blocks (contacts, body laws; the laws'
    /// `tangent`) join the kick's, v += Δt (M + Δt D + Δt² K_ii)⁻¹ F (model.md M-9.1), so that
    /// the stiffness no longer bounds the step: the stability estimate leaves it out and the
    /// step is settings.dt.
    bool implicit_stiffness = false;
    /// The pair loop walks a near list where that pays (near_list.hpp); false: always the whole
    /// neighbour list (the same forces to the bit; tests and A/B timings).
    bool near_list = true;
};

/// Wall-clock seconds spent per phase since construction (the summary's timing breakdown).
struct PhaseTimes {
    double integrate = 0.0; ///< kick, drift, particle forces, second kick
    double neighbor = 0.0;  ///< neighbor-list rebuilds (incl. re-sorting)
    double pair = 0.0;      ///< pair forces
};

/// Per-step diagnostics of the last force evaluation and kick.
struct StepStats {
    std::size_t contacts = 0;      ///< particle-particle contacts (δ > 0)
    std::size_t wall_contacts = 0; ///< particle-substrate contacts
    double max_overlap_rel = 0.0;  ///< max δ / min(r_i, r_j) over all contacts
    double layer_top = 0.0;        ///< max_i (z_i + r_i) [m] (M-8.2)
};

/// The complete dynamic state of a simulation, for checkpoints: restoring it continues the run
/// bit for bit as if it had not stopped (same build, same thread count). Forces and torques are
/// part of it: velocity Verlet's first half kick uses the forces of the previous evaluation, which
/// saw the half-step velocities, so they cannot be recomputed from the full-step state.
struct EngineState {
    ParticleStore particles;           ///< in storage order
    std::vector<BodyState> body_state; ///< what the body laws keep, per particle in storage order
    NeighborList::State neighbors;
    std::int64_t step = 0;
    double time = 0.0;         ///< simulated time [s]
    double liquid_level = 0.0; ///< [m]
    double dt = 0.0;           ///< current Δt (the stability guard may have lowered it)
    StepStats stats;
    /// Semi-implicit only: (M_i + Δt D_i)⁻¹ [F_i; T_i] of the last evaluation, which the next
    /// step's first half kick uses (empty for the explicit integrator).
    std::vector<Vec3> accel, alpha;
    bool force_rebuild = false;
    std::uint64_t rebuilds_since_sort = 0;
};

/// How far beyond its surface a sphere of `species` and `radius` interacts with any partner no
/// larger than itself (the neighbour list's owner bound).
[[nodiscard]] double owner_range_bound(const ForceField& forces, int species, double radius);

/// The decomposition `settings.ranks` MPI ranks make of a film on `box` whose spheres are at most
/// `r_max` large, interact at most `range_max` beyond their surfaces (owner_range_bound) and reach
/// no higher than `height` (docs/parallel.md "The reach"): what the engine builds, and what
/// a run checks before it makes its output folder. InputError when no grid fits.
[[nodiscard]] parallel::Decomposition plan_decomposition(const Box& box, double r_max,
                                                         double range_max, double height,
                                                         const EngineSettings& settings);

class Simulation {
public:
    Simulation(ParticleStore particles, Box box, ForceField forces, EngineSettings settings);
    /// Continues from a checkpointed state; computes nothing (the state carries its forces).
    /// settings.dt is replaced by the state's Δt.
    /// On several ranks (settings.ranks > 1) every rank is given the whole state and keeps what
    /// it owns; the pair states are carried over by ids at the first step's rebuild.
    Simulation(EngineState state, Box box, ForceField forces, EngineSettings settings);
    /// On one rank, the engine's own state. On several (a collective: every rank calls it), the
    /// whole film's, on every rank: particles ordered by id, the neighbour list as the union of
    /// the ranks' lists over that order, and a rebuild due at the next step, so it continues on
    /// any rank count (round-off apart: the summation order changes).
    [[nodiscard]] EngineState state() const;
    /// Every particle of the film, ordered by id on several ranks (a collective), in storage
    /// order on one.
    [[nodiscard]] ParticleStore whole_particles() const;
    /// coordination() of every particle, in whole_particles() order (a collective on several
    /// ranks).
    [[nodiscard]] std::vector<std::int32_t> whole_coordination() const;

    /// One velocity-Verlet step with rotation (M-9.1). Throws RunError on a blow-up (non-finite
    /// state or runaway overlap), naming the particle(s) and the cause; the state is then the one
    /// at which the problem was found.
    void step();
    void run(std::int64_t steps) {
        for (std::int64_t s = 0; s < steps; ++s) step();
    }
    /// The cause a runaway-overlap stop names, from the worst pair's closing speed × Δt in units
    /// of its smaller radius: a steady load (creep) below 0.1 % per step, a blow-up above.
    [[nodiscard]] static std::string overlap_cause(double closing_per_step);

    /// The liquid level z_L(t) [m] as a function of simulated time; evaluated once per step after
    /// the drift (M-9.1 step 3). Without it the level stays where set_liquid_level put it.
    void set_liquid_level_schedule(std::function<double(double)> level) {
        level_at_ = std::move(level);
    }
    void set_liquid_level(double z) { liquid_level_ = z; }
    [[nodiscard]] double liquid_level() const { return liquid_level_; }
    /// The calendering plate's height z_p [m] (PlateContactLaw; +inf: no plate), set between steps.
    void set_plate_height(double z) { plate_height_ = z; }
    [[nodiscard]] double plate_height() const { return plate_height_; }
    /// The sum over the particles of what body law L applies at the present state (its history
    /// not advanced): e.g. the plate's load on the film is -plate_total().force.
    template <class L>
    [[nodiscard]] BodyForce body_law_total() const {
        BodyForce sum{};
        for (std::size_t i = 0; i < owned(); ++i) {
            auto kept = BodyLaws::state<L>(body_state_[i]);
            L::add_force(body_geometry(i, p_.velocity[i], p_.omega[i], 0.0),
                         law<L>(ff_.body_params(p_.species[i])), kept, 0.0, sum, nullptr);
        }
        if (halo_)
            for (Vec3* v : {&sum.force, &sum.torque})
                *v = {halo_->all_sum(v->x), halo_->all_sum(v->y), halo_->all_sum(v->z)};
        return sum;
    }
    /// What the body laws see of particle i at velocities v, omega (reach: see BodyGeometry).
    [[nodiscard]] BodyGeometry body_geometry(std::size_t i, const Vec3& v, const Vec3& omega,
                                             double reach) const {
        return {p_.position[i], v,     omega,        p_.radius[i], p_.mass[i], p_.density[i],
                liquid_level_,  reach, plate_height_};
    }

    /// The solid bonds (bond_network.hpp), acting from the next force evaluation on: their
    /// indices refer to the present storage order. Explicit integrator only (their damping is not
    /// in the semi-implicit self-blocks nor in the quasi-static system); InputError otherwise,
    /// or for a parameter outside the bond law's limits or an index out of range. The neighbour
    /// list is rebuilt to hold them, except `from_checkpoint`: a state whose list was built with
    /// them continues as it was (bit for bit).
    void set_bonds(BondNetwork bonds, bool from_checkpoint = false);
    [[nodiscard]] const BondNetwork& bonds() const { return bonds_; }
    /// guard_warm_start: the last stability estimate's vectors by particle id, which the next
    /// estimate starts from; a checkpoint keeps them so that the resumed guard sets the same step.
    [[nodiscard]] std::array<std::vector<double>, 2> guard_warm_start() const {
        return {guard_by_id_[0], guard_by_id_[1]};
    }
    void set_guard_warm_start(std::array<std::vector<double>, 2> v) {
        guard_by_id_[0] = std::move(v[0]);
        guard_by_id_[1] = std::move(v[1]);
    }
    /// The force on i and the torques of bond b at the present state (its history not advanced).
    [[nodiscard]] PairForce bond_force(const Bond& b) const;

    /// The particles this rank owns: the first owned() of the store; the rest are ghosts, copies
    /// of other ranks' particles (docs/parallel.md). All of them without a decomposition.
    [[nodiscard]] std::size_t owned() const { return halo_ ? halo_->owned() : p_.size(); }
    /// The domain decomposition's exchanges, or nullptr without one.
    [[nodiscard]] const parallel::Halo* halo() const { return halo_ ? &*halo_ : nullptr; }
    [[nodiscard]] const ParticleStore& particles() const { return p_; }
    /// What the body laws keep per particle (storage order): `BodyLaws::state<L>(s[i])`.
    [[nodiscard]] const std::vector<BodyState>& body_states() const { return body_state_; }
    /// Mutable access for set-up and tests; call invalidate_neighbors() after moving particles.
    [[nodiscard]] ParticleStore& particles_mut() { return p_; }
    void invalidate_neighbors() {
        force_rebuild_ = true;
        near_.invalidate();
    }
    [[nodiscard]] const Box& box() const { return box_; }
    [[nodiscard]] const ForceField& forces() const { return ff_; }
    [[nodiscard]] const EngineSettings& settings() const { return settings_; }
    [[nodiscard]] const NeighborList& neighbors() const { return nl_; }
    /// The slots the pair loop walks (near_list.hpp).
    [[nodiscard]] const NearList& near_pairs() const { return near_; }
    [[nodiscard]] double time() const { return time_; }
    [[nodiscard]] std::int64_t step_count() const { return step_; }
    /// Changes Δt between steps (the stability guard lowers it in dense packings, M-9.2).
    void set_time_step(double dt) { settings_.dt = dt; }
    [[nodiscard]] const StepStats& stats() const { return stats_; }
    /// The last quasi-static step (zero for the other integrators).
    [[nodiscard]] const QuasiStaticReport& quasi_static_report() const { return qs_report_; }
    [[nodiscard]] const PhaseTimes& phase_times() const { return times_; }
    [[nodiscard]] int threads() const { return threads_; }

    /// Contacts (overlap > 0) per particle in storage order, the substrate counted as a partner.
    [[nodiscard]] std::vector<std::int32_t> coordination() const;
    /// The packing's stress from its contacts (Love-Weber), compression positive [Pa]:
    ///   s = -(1/V) [ Σ_pairs f_i ⊗ (x_j - x_i) + Σ_wall contacts f ⊗ (x_c - x) ]
    /// f_i the pair laws' force on i (velocities as they are, nothing advanced), x_c the contact
    /// point on the substrate or the plate. Over a film between the substrate and a plate in
    /// equilibrium, s_zz is the plate's pressure; V is the caller's (cell area × height).
    [[nodiscard]] Sym3 contact_stress(double volume) const;
    /// Each particle's mean stress from its contacts and bonds (Love-Weber over its own volume,
    /// compression positive) [Pa], storage order:
    ///   σ_i = -(1 / 3V_i) Σ_c f_c · (x_c - x_i)
    /// x_c on the pair's contact plane (the spheres' intersection circle) or on the wall. The
    /// same forces as contact_stress: Σ_i 3 σ_i V_i = tr(s) V.
    [[nodiscard]] std::vector<double> particle_mean_stress() const;
    /// An overlap of the present state: particles i and j (storage order), or i with a wall
    /// (j = kWall: the substrate or the plate, sphere on a plane) [m].
    struct ContactOverlap {
        static constexpr std::uint32_t kWall = UINT32_MAX;
        std::uint32_t i = 0, j = kWall;
        double overlap = 0.0;
    };
    /// Every listed pair that overlaps, and every sphere pressed into the substrate or the plate.
    [[nodiscard]] std::vector<ContactOverlap> contact_overlaps() const;
    /// Takes the particles `which` (storage order) out of the packing: the calendering's
    /// extruded agglomerates (model.md M-2.13). Their pair states and bonds go with them; the
    /// others keep theirs and their order. Explicit integrator only (RunError otherwise).
    /// δ / min(r_i, r_j) of every overlapping pair in the rows of the owned particles (on
    /// several ranks each pair is in one rank's rows) and δ / r of every owned particle on the
    /// substrate or the plate: the time series' overlap percentile without a pair search.
    [[nodiscard]] std::vector<double> relative_overlaps() const;
    void remove_particles(const std::vector<std::size_t>& which);
    /// Translational + rotational kinetic energy [J].
    [[nodiscard]] double kinetic_energy() const;
    /// Total linear momentum [kg m/s].
    [[nodiscard]] Vec3 momentum() const;
    /// Rates that limit the step of what stays explicit (docs/model.md "Stability guard"),
    /// estimated on the laws' own linear operators by power iteration from a random start
    /// (seeded by the step: a resumed run repeats it), gaps reduced by the skin:
    /// damping_rate: λ_max of M⁻¹R (R: the resistance of every dissipative law; explicit
    /// integrator only, 0 otherwise), stable for Δt λ < 2;
    /// stiffness_rate: sqrt(λ_max) of M_eff⁻¹K (K: contact springs, van der Waals, capillary
    /// spring; M_eff = M, or M + Δt D for the semi-implicit kick), stable for Δt ω < 2 (explicit,
    /// undamped) or sqrt(2) to 2 (semi-implicit: docs/model.md "What the bound is").
    struct StabilityEstimate {
        double damping_rate = 0.0;     ///< [1/s]
        double stiffness_rate = 0.0;   ///< [rad/s]
        std::uint32_t particle_id = 0; ///< where the limiting mode is largest
        int iterations = 0;            ///< power iterations spent
    };
    [[nodiscard]] StabilityEstimate stability_estimate() const;

    /// Computes forces at the current state (also done by the constructor).
    void compute_forces();

private:
    /// Calls pair(t, i, j, f_i, x_j - x_i) for each listed pair and intact bond with the force on
    /// i at the present state (nothing advanced), and wall(t, i, f, x_c - x_i) for the substrate
    /// and the plate, on the engine's threads: t is the calling thread, whose accumulator the
    /// callback adds to (each thread its own, summed in thread order by the caller).
    template <class PairFn, class WallFn>
    void visit_contact_forces(PairFn&& pair, WallFn&& wall) const;
    void rebuild_neighbors();
    /// Under a decomposition: pair states that change rank, migration, ghosts, then the list.
    template <class RangeFn, class OwnerRangeFn>
    void rebuild_decomposed(RangeFn&& range, OwnerRangeFn&& owner_range, bool sort);
    /// Pairs in the neighbour list per owned particle (the work the rebalancing weighs).
    [[nodiscard]] std::vector<double> pairs_per_owned() const;
    /// Reorders the owned particles (no ghosts in the store) by cell, with what the engine keeps
    /// per particle.
    template <class OwnerRangeFn>
    void sort_owned(OwnerRangeFn&& owner_range);
    /// Sets the decomposition up from settings_.ranks (constructor).
    void decompose();
    /// state() on several ranks.
    [[nodiscard]] EngineState gathered_state() const;
    /// Upper bound of the interaction range of the pairs particle i owns (partners are never
    /// larger than their owner, neighbor_list.hpp).
    [[nodiscard]] double owner_range_bound(std::size_t i) const;
    /// Largest radius and largest owner range over all ranks (the ghosts' reach).
    [[nodiscard]] std::pair<double, double> largest_radius_and_range() const;
    /// Zeroes what the ghosts accumulate in a force evaluation (their owners have theirs).
    void clear_ghost_forces();
    /// Particle forces of particle i into the store (M-9.5), counting substrate contacts.
    void body_forces(std::size_t i, std::size_t& wall_contacts, double& wall_overlap);
    /// Pair forces (and the bonds') added to the store; completes the step statistics.
    void pair_forces(std::size_t wall_contacts, double wall_overlap);
    /// The bonds' forces added to the store (after the pair forces); breaks the bonds that fail.
    void bond_forces();
    /// The pair loop over `list`: the near list or the neighbour list itself (near_list.hpp).
    template <bool SelfBlocks, class List>
    void pair_loop(const List& list, std::size_t& contacts, double& max_overlap);
    /// First row of thread t's share of the list (rows weighted by their slots + 1), t < parts.
    [[nodiscard]] std::size_t row_split(std::size_t t, std::size_t parts) const;
    /// Thread t adds, for its rows [lo, hi), what the other threads wrote across (thread order).
    template <bool SelfBlocks>
    void add_cross_range(std::size_t t, std::size_t lo, std::size_t hi);
    /// Semi-implicit: the accelerations (M_i + Δt D_i)⁻¹ [F_i; T_i] of particle i, its pair
    /// self-block reset for the next evaluation.
    void implicit_acceleration(std::size_t i);
    [[nodiscard]] bool semi_implicit() const {
        return settings_.integrator == Integrator::semi_implicit;
    }
    [[nodiscard]] bool quasi_static() const {
        return settings_.integrator == Integrator::quasi_static;
    }
    // The quasi-static step (quasi_static.cpp): the linearised system at rest at the present
    // positions (forces into the store, step statistics), its solve at a step Δt (CG iterations
    // and relative residual into the report), and the step itself.
    void assemble_quasi_static();
    void solve_quasi_static(double dt, QuasiStaticReport& report);
    /// The largest Δt the solved velocities allow (quasi_static.hpp: displacement, approach).
    [[nodiscard]] double quasi_static_step_limit() const;
    void step_quasi_static();
    /// Stops the run (RunError, the same on every rank) on a non-finite state or an overlap
    /// beyond the limit.
    void check_health();
    /// The first owned particle with a non-finite state, described ("" when none).
    [[nodiscard]] std::string non_finite_report() const;
    /// The largest relative overlap of this rank's list and its description.
    [[nodiscard]] std::pair<double, std::string> worst_overlap_report() const;
    void allocate_integrator();

    ParticleStore p_;
    std::vector<BodyState> body_state_; ///< per particle, permuted with it on a re-sort
    BondNetwork bonds_;                 ///< indices renumbered on a re-sort
    std::vector<PairForce> bond_force_; ///< per bond, the last evaluation (scratch)
    Box box_;
    ForceField ff_;
    EngineSettings settings_;
    NeighborList nl_;
    NearList near_; ///< the slots of nl_ within reach + its skin: what the pair loop walks
    int threads_ = 1;
    std::int64_t step_ = 0;
    double time_ = 0.0;
    double liquid_level_;
    double plate_height_ = INFINITY;
    std::function<double(double)> level_at_;
    bool force_rebuild_ = true;
    bool non_finite_ = false;
    StepStats stats_;
    PhaseTimes times_;
    std::uint64_t rebuilds_since_sort_ = 0;
    // Semi-implicit integrator: body resistance of each particle (written with the particle
    // forces, permuted with the particles on a re-sort), pair self-blocks, and the resulting
    // accelerations.
    std::vector<BodyResistance> body_resistance_;
    QuasiStaticSystem qs_;
    QuasiStaticReport qs_report_;
    std::vector<SelfBlock> block_;
    std::vector<Vec3> accel_, alpha_;
    mutable std::vector<double> guard_vector_[2]; ///< the estimate's work vectors, reused
    /// guard_warm_start: the last estimate's vectors by particle id (6 entries each; NaN: none)
    mutable std::vector<double> guard_by_id_[2];
    // What a pair-loop thread writes for partners outside its own rows (see pair_loop): a fixed
    // reduction order makes results identical run to run for a given thread count. Allocated
    // only with more than one thread.
    struct ThreadBuffer {
        std::vector<Vec3> force, torque;
        std::vector<SelfBlock> block;       ///< semi-implicit only
        std::vector<std::uint8_t> marked;   ///< 1 while the particle is in `touched`
        std::vector<std::uint32_t> touched; ///< particles written this step (capacity n)
    };
    std::vector<ThreadBuffer> buffer_;
    bool substrate_on_ = false; ///< ForceField::substrate_on, for the wall-contact statistics
    /// The domain decomposition (settings_.ranks > 1). Mutable: the const estimates trade
    /// ghost values and count what they sent.
    mutable std::optional<parallel::Halo> halo_;
    /// A state resumed on several ranks: the pair states of the whole film's list, keyed by ids,
    /// for the first rebuild to carry over.
    std::vector<NeighborList::Entry> resumed_entries_;
    /// When the cuts were last balanced, and this process's MPI waits then (omp_get_wtime,
    /// parallel::waited_seconds): the measured work of the next balancing.
    double balance_clock_ = 0.0, balance_waited_ = 0.0;
};

/// Stability indicator of a step: max(Δt λ_damping, Δt ω_stiffness); stable below the
/// integrator's bound (GuardLimits::bound: 2 explicit, sqrt(2) semi-implicit).
double stability_indicator(double dt, const Simulation::StabilityEstimate& e);

/// The guard's policy (docs/model.md "Stability guard"): the largest step with Δt λ_damping ≤ 1.5
/// and Δt ≤ critical_fraction × 2/ω_stiffness (numerics.critical_step_fraction; at 0.5, Δt ω ≤ 1:
/// the first-order overdamped update stays monotone, an undamped contact gets ~6 steps per
/// period), never above `cap`.
double guarded_time_step(double cap, const Simulation::StabilityEstimate& e,
                         double critical_fraction);

} // namespace drydem
