// SPDX-License-Identifier: MIT
// The quasi-static step (docs/model.md M-9.1, "Quasi-static step"): a linearly implicit Euler step
// whose step the contact stiffness does not limit. With every force split into what the laws give
// at rest, F(x), and the dissipative part -R v, and linearised over the step, F(x + Δt v) ≈
// F(x) - Δt K v, backward Euler M (v - v₀)/Δt = F(x + Δt v) - R v becomes one linear system
//     (M/Δt + R + Δt K) [v; ω] = [F; T](x) + M [v₀; ω₀]/Δt
// R: the resistance of every dissipative law, K: the stiffness of every conservative law, both
// through the laws' contracts (pair_law.hpp, body_law.hpp) in the pair and body forms of
// resistance.hpp. In the drying film M/Δt is tiny beside R (a particle relaxes in nanoseconds,
// the step is microseconds), so the step is overdamped and quasi-static: every force balances at
// its end; M/Δt keeps the system definite for a particle that nothing resists (one above the
// liquid, out of contact: it falls as it would). For Δt → ∞ the step is Newton's method on
// F(x) = 0. Solved by conjugate gradients, preconditioned with each particle's 6×6 block, warm
// started from the last velocities. What limits Δt is accuracy, the range over which the
// linearisation holds: no particle moves more than `max_displacement` (the capillary and drag
// forces vary over a radius), and no pair (or particle and substrate) closes by more than
// `approach` of its gap, a gap counted as at least `approach_floor` of the smaller radius (the
// lubrication and van der Waals forces vary over the gap itself; once in contact, K holds the
// pair). The driver also caps Δt so that the liquid level moves no further than
// `max_displacement` per step. The laws' kept states (tangential springs,
// Coulomb's cut) advance with the solved velocities. The van der Waals snap-in enters K with
// |dF/dh| (its true stiffness is negative), which keeps the system definite and slows the snap.
#pragma once
#include "drydem/engine/linear_operator.hpp"
#include <cstdint>
#include <vector>

namespace drydem {

struct QuasiStaticSettings {
    double max_step = 1e-3;         ///< Δt never above this [s]
    double max_displacement = 1e-9; ///< largest |Δt v| of a step [m]
    double approach = 0.5;          ///< a pair closes by at most this fraction of its gap
    double approach_floor = 0.01;   ///< ... the gap counted as at least this fraction of r_min
    double tolerance = 1e-8;        ///< CG: relative residual |r| / |b|
    int max_iterations = 2000;      ///< CG iterations per solve
};

/// What the last quasi-static step did.
struct QuasiStaticReport {
    double dt = 0.0;               ///< the step taken [s]
    double max_displacement = 0.0; ///< largest |Δt v| [m]
    int solves = 0;                ///< linear solves (1 + the retries at a smaller Δt)
    int iterations = 0;            ///< CG iterations, all solves
    double residual = 0.0;         ///< relative residual of the accepted solve
};

/// The linearised system of one step, per thread (its rows' pairs and particles).
struct QuasiStaticSystem {
    struct Pair {
        std::uint32_t i, j, slot;
        PairGeometry g;
        PairResistance r, k; ///< resistance and stiffness, lever arms set
    };
    struct Body {
        BodyResistance r, k;
    };
    std::vector<std::vector<Pair>> pairs; ///< per thread
    std::vector<Body> bodies;             ///< per particle
    std::vector<double> force;            ///< [F; T] at rest, 6 per particle
    std::vector<Operator> a;              ///< M/Δt + R + Δt K, per thread
    std::vector<SelfBlockInverse> block;  ///< its 6×6 self-blocks, inverted
    std::vector<std::vector<double>> share, force_share;
    std::vector<std::vector<SelfBlock>> block_share;
    std::vector<double> b, u, r, z, d, q, partial; ///< CG work vectors
};

} // namespace drydem
