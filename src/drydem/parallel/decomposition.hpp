// SPDX-License-Identifier: MIT
// Spatial domain decomposition of the periodic cell in x and y (the film is thin in z): a grid of
// px × py subdomains, one per MPI rank (docs/parallel.md), cut by px + 1 planes along x and py + 1
// along y. The cuts start equal; a film of a few thousand spheres, with NCM spheres of ~200 CB
// neighbours each, is not homogeneous on the scale of a subdomain, so the engine moves the cuts
// to balance the measured work (`balanced_cuts`, the "shift" balancing of LAMMPS); z is never cut.
//
// A particle is owned by the rank whose subdomain holds its (wrapped) centre. A rank also keeps
// ghost copies of the particles of its neighbours that lie within their reach of its subdomain;
// with subdomains at least one reach wide, those come only from the eight neighbouring
// subdomains (periodic), which is what `neighbors` lists.
#pragma once
#include "drydem/core/box.hpp"
#include "drydem/core/vec3.hpp"
#include <vector>

namespace drydem::parallel {

struct Decomposition {
    Box box{};
    int px = 1, py = 1; ///< subdomains along x and y

    /// Cut positions along x (px + 1, from 0 to box.lx) and y; empty: equal subdomains.
    std::vector<double> cut_x{}, cut_y{};

    [[nodiscard]] int ranks() const { return px * py; }
    /// Where column ix starts and ends along x, row iy along y [m].
    [[nodiscard]] double x_lo(int ix) const { return cut_x.empty() ? ix * box.lx / px : cut_x[ix]; }
    [[nodiscard]] double x_hi(int ix) const { return x_lo(ix + 1); }
    [[nodiscard]] double y_lo(int iy) const { return cut_y.empty() ? iy * box.ly / py : cut_y[iy]; }
    [[nodiscard]] double y_hi(int iy) const { return y_lo(iy + 1); }
    /// The narrowest column and row [m].
    [[nodiscard]] double width_x() const;
    [[nodiscard]] double width_y() const;
    /// Rank of the subdomain in column ix, row iy (both taken periodically).
    [[nodiscard]] int rank_at(int ix, int iy) const;
    /// The rank that owns a point (x and y wrapped into the box or not).
    [[nodiscard]] int owner(const Vec3& x) const;
    /// The other ranks of the (up to eight) neighbouring subdomains, ascending, each once: with two
    /// subdomains along x the left and the right neighbour are the same rank.
    [[nodiscard]] std::vector<int> neighbors(int rank) const;
    /// Squared x-y distance from a point to the subdomain of `rank`, through the periodic images
    /// (0 inside it) [m²].
    [[nodiscard]] double distance2(int rank, const Vec3& x) const;
};

/// The px × py grid for `ranks` subdomains of the box with the least ghost area per rank (its
/// rectangle grown by `reach` across each cut face, less itself: the ghosts it holds and
/// receives every step), with every cut dimension at least `reach` wide (the
/// largest distance at which a particle must be seen by a neighbouring rank: interaction range
/// plus skin, docs/parallel.md). Ties go to more cuts along x. InputError when no grid leaves
/// subdomains that wide, naming the rank count, the widths and the reach.
Decomposition decompose(const Box& box, int ranks, double reach);

/// Cuts that split `weight` (a histogram of the work along one periodic axis of length `length`,
/// in equal bins) into `parts` equal shares, from the present cuts `now` (parts + 1 values, 0 to
/// length): each cut moves at most `max_shift`, and no part becomes narrower than `min_width`
/// (the reach). The same inputs give the same cuts on every rank.
std::vector<double> balanced_cuts(const std::vector<double>& weight, double length,
                                  const std::vector<double>& now, double min_width,
                                  double max_shift);

} // namespace drydem::parallel
