// SPDX-License-Identifier: MIT
// Spatial domain decomposition of the film: a grid of px × py × pz subdomains, one per MPI rank
// (docs/parallel.md), cut by planes along x and y (periodic) and along z (open: the lowest layer
// reaches down through the substrate, the highest up without bound). A wide film is cut in x and
// y; the paper's 75 µm cell holds a film 90-130 µm thick, which one cut in z splits with a third
// of the ghosts of a cut in x (`decompose` weighs every grid by its ghost volume). The cuts start
// equal; a film of a few thousand spheres, with NCM spheres of ~200 CB neighbours each, is not
// homogeneous on the scale of a subdomain, and it settles while it dries, so the engine moves the
// cuts to balance the measured work (`balanced_cuts`, the "shift" balancing of LAMMPS).
//
// A particle is owned by the rank whose subdomain holds its (wrapped) centre. A rank also keeps
// ghost copies of the particles of its neighbours that lie within their reach of its subdomain;
// with subdomains at least one reach wide (in z: the inner layers), those come only from the
// (up to 26) neighbouring subdomains, which is what `neighbors` lists.
#pragma once
#include "drydem/core/box.hpp"
#include "drydem/core/vec3.hpp"
#include <array>
#include <cmath>
#include <vector>

namespace drydem::parallel {

struct Decomposition {
    Box box{};
    int px = 1, py = 1; ///< subdomains along x and y
    /// Cut positions along x (px + 1, from 0 to box.lx) and y; empty: equal subdomains.
    std::vector<double> cut_x{}, cut_y{};
    int pz = 1; ///< layers along z
    /// Cut positions along z (pz + 1, from 0 to the film's top when they were last set; the
    /// lowest layer owns everything below cut_z[1], the highest everything above cut_z[pz - 1]).
    std::vector<double> cut_z{};

    [[nodiscard]] int ranks() const { return px * py * pz; }
    /// Where column ix starts and ends along x, row iy along y [m].
    [[nodiscard]] double x_lo(int ix) const { return cut_x.empty() ? ix * box.lx / px : cut_x[ix]; }
    [[nodiscard]] double x_hi(int ix) const { return x_lo(ix + 1); }
    [[nodiscard]] double y_lo(int iy) const { return cut_y.empty() ? iy * box.ly / py : cut_y[iy]; }
    [[nodiscard]] double y_hi(int iy) const { return y_lo(iy + 1); }
    /// Where layer iz starts and ends along z [m]: open below the first, above the last.
    [[nodiscard]] double z_lo(int iz) const;
    [[nodiscard]] double z_hi(int iz) const { return iz + 1 >= pz ? INFINITY : z_lo(iz + 1); }
    /// The narrowest column and row [m]; in z the thinnest layer between its cuts (0 to the top
    /// for the outer ones), infinite without a cut.
    [[nodiscard]] double width_x() const;
    [[nodiscard]] double width_y() const;
    [[nodiscard]] double width_z() const;
    /// Rank of the subdomain in column ix, row iy (both taken periodically), layer iz.
    [[nodiscard]] int rank_at(int ix, int iy, int iz = 0) const;
    /// The rank that owns a point (x and y wrapped into the box or not).
    [[nodiscard]] int owner(const Vec3& x) const;
    /// The other ranks of the (up to 26) neighbouring subdomains, ascending, each once: with two
    /// subdomains along x the left and the right neighbour are the same rank. z is not periodic.
    [[nodiscard]] std::vector<int> neighbors(int rank) const;
    /// Squared distance from a point to the subdomain of `rank`, through the periodic images in
    /// x and y (0 inside it) [m²].
    [[nodiscard]] double distance2(int rank, const Vec3& x) const;
};

/// The px × py × pz grid for `ranks` subdomains of a film `height` thick on the box with the
/// least ghost volume per rank (its subdomain grown by `reach` across each cut face, less itself:
/// the ghosts it holds and receives every step), with every cut dimension at least `reach` wide
/// (the largest distance at which a particle must be seen by a neighbouring rank: interaction
/// range plus skin, docs/parallel.md); in z the layers are `height` / pz thick. Ties go to more
/// cuts along x, then y. `grid` fixes the subdomains along x, y or z where it is not 0.
/// InputError when no grid leaves subdomains that wide, naming the rank count, the widths and
/// the reach.
Decomposition decompose(const Box& box, int ranks, double reach, double height,
                        std::array<int, 3> grid = {0, 0, 0});

/// Cuts that split `weight` (a histogram of the work along one axis of length `length`, in equal
/// bins) into `parts` equal shares, from the present cuts `now` (parts + 1 values, 0 to
/// length): each cut moves at most `max_shift`, and no part becomes narrower than `min_width`
/// (the reach). The same inputs give the same cuts on every rank.
std::vector<double> balanced_cuts(const std::vector<double>& weight, double length,
                                  const std::vector<double>& now, double min_width,
                                  double max_shift);

} // namespace drydem::parallel
