// SPDX-License-Identifier: MIT
// An overdamped, linearly implicit step (issue 30, first piece; not yet wired into the drying run).
// The drying is quasi-static: a particle relaxes in nanoseconds while the level moves ~1 µm/s, so
// inertia is dropped and every force balances at the end of the step:
//   F(x + Δt v) - R v = 0,  F(x + Δt v) ≈ F(x) - Δt K v   =>   (R + Δt K) [v; ω] = [F; T](x)
// R: the resistance of every dissipative law, K: the stiffness of every conservative law, both
// through the laws' contracts (pair_law.hpp, body_law.hpp), in the pair and body forms of
// resistance.hpp; F, T: every force at the present positions, at rest. Solved by conjugate
// gradients, preconditioned with each particle's 6×6 block of R + Δt K. For Δt → ∞ the step is
// Newton's method on F(x) = 0, so the contact stiffness does not limit Δt; what limits it is
// accuracy: the largest displacement Δt |v| of a step is held at `max_displacement` (the
// linearisation's range). The laws' kept states (the tangential springs, Coulomb's cut) advance
// with the solved velocities over Δt. The van der Waals snap-in enters K with |dF/dh| (its true
// stiffness is negative), which keeps R + Δt K positive definite and slows the snap.
#pragma once
#include "drydem/core/box.hpp"
#include "drydem/core/particles.hpp"
#include "drydem/forces/force_field.hpp"
#include "drydem/neighbor/neighbor_list.hpp"
#include <vector>

namespace drydem {

struct QuasiStaticSettings {
    double max_step = 1e-3;         ///< Δt never above this [s]
    double max_displacement = 1e-9; ///< largest |Δt v| of a step [m]
    double tolerance = 1e-10;       ///< CG: relative residual |r| / |F|
    int max_iterations = 1000;      ///< CG iterations per solve
    double skin = 0.1e-6;           ///< neighbour skin [m]
    double liquid_level = 1e30;     ///< z_L [m]
};

struct QuasiStaticReport {
    double dt = 0.0;               ///< the step taken [s]
    double max_displacement = 0.0; ///< largest |Δt v| [m]
    int iterations = 0;            ///< CG iterations of the accepted solve
    double residual = 0.0;         ///< its relative residual
};

class QuasiStaticEngine {
public:
    QuasiStaticEngine(ParticleStore particles, Box box, ForceField forces, QuasiStaticSettings s);
    /// One step: solve, limit the displacement, move, advance the laws' states.
    QuasiStaticReport step();
    [[nodiscard]] const ParticleStore& particles() const { return p_; }
    /// Every force on particle i at rest at the present positions (the residual of equilibrium).
    [[nodiscard]] Vec3 net_force(std::size_t i) const;

private:
    struct PairEntry {
        std::uint32_t i, j, slot;
        PairGeometry g;
        PairResistance r, k; ///< resistance and stiffness, levers set
    };
    struct BodyEntry {
        BodyResistance r, k;
    };
    void assemble();
    /// y = (R + dt K) u.
    void apply(double dt, const std::vector<double>& u, std::vector<double>& y) const;
    /// CG on (R + dt K) u = f; returns iterations and leaves the relative residual in `residual`.
    int solve(double dt, std::vector<double>& u, double& residual) const;

    ParticleStore p_;
    std::vector<BodyState> body_state_;
    Box box_;
    ForceField ff_;
    QuasiStaticSettings s_;
    NeighborList nl_;
    std::vector<PairEntry> pairs_;
    std::vector<BodyEntry> bodies_;
    std::vector<double> force_; ///< [F; T] per particle at rest
};

} // namespace drydem
