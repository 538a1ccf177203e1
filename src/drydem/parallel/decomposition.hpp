// SPDX-License-Identifier: MIT
// Spatial domain decomposition of the periodic cell in x and y (the film is thin in z): a grid of
// px × py equal subdomains, one per MPI rank (docs/parallel.md). The film is homogeneous in x and
// y, so equal subdomains carry equal work; z is never cut.
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

    [[nodiscard]] int ranks() const { return px * py; }
    [[nodiscard]] double width_x() const { return box.lx / px; }
    [[nodiscard]] double width_y() const { return box.ly / py; }
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

} // namespace drydem::parallel
