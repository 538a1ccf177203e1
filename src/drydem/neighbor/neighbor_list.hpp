// SPDX-License-Identifier: MIT
// Half Verlet list (CSR) with skin, built on a cell grid, with per-pair cut-offs and the pair
// laws' per-pair state (PairState: the contact's tangential spring, and whatever a law keeps; see
// forces/pair_law.hpp) that survives rebuilds, re-sorting and periodic wrapping (model.md M-2.5,
// M-9.4).
//
// Size-aware search for a 1:8 size ratio: every pair is owned by its larger particle (ordering key
// (radius, id)), so a particle only searches for partners no larger than itself. The grid is sized
// for the smallest particles (CB-CB, 2.25 µm + skin); a CB then scans 27 cells, and only the few
// large NCM spheres scan the wide stencil their 17 µm reach needs. No global 17 µm cut-off.
#pragma once
#include "drydem/core/box.hpp"
#include "drydem/core/particles.hpp"
#include "drydem/core/vec3.hpp"
#include "drydem/forces/force_field.hpp"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>
#include <omp.h>

namespace drydem {

class NeighborList {
public:
    /// skin: extra distance beyond every pair's interaction range; rebuild when some particle moved
    /// more than skin/2 since the last build.
    explicit NeighborList(double skin = 0.1e-6, int threads = 0)
        : skin_(skin), threads_(threads > 0 ? threads : omp_get_max_threads()) {}

    [[nodiscard]] double skin() const { return skin_; }
    [[nodiscard]] std::size_t owners() const { return offset_.empty() ? 0 : offset_.size() - 1; }
    [[nodiscard]] std::size_t pairs() const { return partner_.size(); }
    [[nodiscard]] std::uint32_t begin(std::size_t i) const { return offset_[i]; }
    [[nodiscard]] std::uint32_t end(std::size_t i) const { return offset_[i + 1]; }
    [[nodiscard]] std::uint32_t partner(std::uint32_t slot) const { return partner_[slot]; }
    /// Squared interaction reach (r_i + r_j + range)² of the pair in this slot, without skin.
    [[nodiscard]] double reach2(std::uint32_t slot) const { return reach2_[slot]; }
    /// What the pair laws keep for the pair in this slot (PairState{} when nothing).
    [[nodiscard]] PairState& state(std::uint32_t slot) { return state_[slot]; }
    [[nodiscard]] const PairState& state(std::uint32_t slot) const { return state_[slot]; }
    [[nodiscard]] std::uint64_t builds() const { return builds_; }

    /// True when the pair (i, j) is owned by i: i is larger, ties broken by id (stable under
    /// re-sorting, so a pair's state always lives in the same owner's row).
    static bool owns(double r_i, std::uint32_t id_i, double r_j, std::uint32_t id_j) {
        return r_j < r_i || (r_j == r_i && id_j < id_i);
    }

    /// Largest displacement (squared) since the last build decides the rebuild (skin/2).
    [[nodiscard]] bool needs_rebuild(double max_displacement2) const {
        return offset_.empty() || max_displacement2 > 0.25 * skin_ * skin_;
    }
    [[nodiscard]] const std::vector<Vec3>& positions_at_build() const { return x_build_; }

    /// Rebuilds the list. `range(i, j)` returns the pair's interaction range beyond contact [m];
    /// `owner_range(i)` an upper bound of range(i, j) over every j that i can own. When `sort` is
    /// set, particles are first reordered by cell for memory locality. Pair states are carried
    /// over by particle id. Under a domain decomposition (docs/parallel.md) the particles from
    /// `owned` on are ghosts: a pair of two ghosts is left out (another rank computes it).
    template <class RangeFn, class OwnerRangeFn>
    void build(ParticleStore& p, const Box& box, RangeFn&& range, OwnerRangeFn&& owner_range,
               bool sort, std::size_t owned = SIZE_MAX);

    /// The order build(sort = true) gives the particles (by cell of the search grid), as
    /// indices into `p`: for a store that sorts itself before it is built (a decomposed rank sorts
    /// its owned particles before the ghosts are appended).
    template <class OwnerRangeFn>
    [[nodiscard]] std::vector<std::uint32_t> spatial_order(const ParticleStore& p, const Box& box,
                                                           OwnerRangeFn&& owner_range);

    /// After particles left the store: `new_index[i]` is old particle i's new index, UINT32_MAX
    /// for one that left. Its rows and every pair with it go; the rest keep their states.
    void keep_rows(const std::vector<std::uint32_t>& new_index);

    /// Kept pair states keyed by (owner id, partner id): for tests, and for the pair states that
    /// travel between ranks.
    struct Entry {
        std::uint32_t owner_id, partner_id;
        PairState state;
    };
    [[nodiscard]] std::vector<Entry> state_entries(const ParticleStore& p) const;
    /// The next build carries the pair states over from these entries instead of from the
    /// present list: when particles were traded between ranks, the present list's slots no
    /// longer name the stored particles. A key given twice keeps the first entry.
    void carry_from(std::vector<Entry> entries);

    /// Everything the next steps depend on (checkpoints): the list itself in its slot order, the
    /// pair states and the positions of the last build (which decide the next rebuild). The cell
    /// grid and the carry-over arrays are rebuilt from scratch at every build, so they are not
    /// state.
    struct State {
        std::uint64_t builds = 0;
        std::vector<std::uint32_t> offset, partner;
        std::vector<double> reach2;
        std::vector<PairState> pair_state;
        std::vector<Vec3> x_build;
    };
    [[nodiscard]] State state() const {
        return {builds_, offset_, partner_, reach2_, state_, x_build_};
    }
    void restore(State s) {
        builds_ = s.builds;
        offset_ = std::move(s.offset);
        partner_ = std::move(s.partner);
        reach2_ = std::move(s.reach2);
        state_ = std::move(s.pair_state);
        x_build_ = std::move(s.x_build);
    }

private:
    struct Grid {
        int nx = 1, ny = 1, nz = 1;
        double cx = 1, cy = 1, cz = 1, zlo = 0;
        bool wrapped = true; ///< every particle inside [0, lx) x [0, ly): inside its cell's box
        std::vector<std::uint32_t> cell_start, cell_items, cell_of;
        [[nodiscard]] int index(int ix, int iy, int iz) const { return (iz * ny + iy) * nx + ix; }
    };
    void bin(const ParticleStore& p, const Box& box, double cell_size);
    /// The grid's cell: the smallest search radius of an owner, its own reach to partners no
    /// larger than itself.
    template <class OwnerRangeFn>
    [[nodiscard]] double search_cell(const ParticleStore& p, OwnerRangeFn&& owner_range) const {
        double smallest = INFINITY;
        for (std::size_t i = 0; i < p.size(); ++i)
            smallest = std::min(smallest, 2.0 * p.radius[i] + owner_range(i));
        return std::isfinite(smallest) ? smallest + skin_ : 1e-6;
    }
    void sort_by_cell(ParticleStore& p);
    /// Keeps the present list, keyed by ids, for carry_states (unless carry_from() set it up).
    void keep_previous_list(const ParticleStore& p);
    void carry_states(const ParticleStore& p);

    /// Rows per block of the build's search; each block's pairs, kept between builds.
    static constexpr std::size_t kBuildBlock = 256;
    struct BuiltPair {
        std::uint32_t partner;
        double reach2;
    };
    std::vector<std::vector<BuiltPair>> block_pairs_;

    double skin_;
    int threads_; ///< OpenMP threads of the build (the engine's)
    std::uint64_t builds_ = 0;
    Grid grid_;
    std::vector<std::uint32_t> offset_, partner_;
    std::vector<double> reach2_;
    std::vector<PairState> state_;
    std::vector<Vec3> x_build_;
    // Previous list, keyed by ids, for carrying pair states over.
    std::vector<std::uint32_t> old_offset_, old_partner_id_, old_row_of_id_;
    std::vector<PairState> old_state_;
    bool carry_pending_ = false; ///< carry_from() filled the old list for the next build
    std::vector<std::uint32_t> order_;
};

template <class OwnerRangeFn>
std::vector<std::uint32_t> NeighborList::spatial_order(const ParticleStore& p, const Box& box,
                                                       OwnerRangeFn&& owner_range) {
    bin(p, box, search_cell(p, owner_range));
    return {grid_.cell_items.begin(), grid_.cell_items.end()};
}

template <class RangeFn, class OwnerRangeFn>
void NeighborList::build(ParticleStore& p, const Box& box, RangeFn&& range,
                         OwnerRangeFn&& owner_range, bool sort, std::size_t owned) {
    const std::size_t n = p.size();
    keep_previous_list(p);

    const double cell = search_cell(p, owner_range);
    bin(p, box, cell);
    if (sort) {
        sort_by_cell(p);
        bin(p, box, cell);
    }

    offset_.assign(n + 1, 0);
    const Grid& g = grid_;
    auto visit = [&](std::size_t i, auto&& on_pair) {
        const Vec3 xi = p.position[i];
        const double ri = p.radius[i];
        const std::uint32_t idi = p.id[i];
        const double search = 2.0 * ri + owner_range(i) + skin_;
        const int wx = int(std::ceil(search / g.cx)), wy = int(std::ceil(search / g.cy)),
                  wz = int(std::ceil(search / g.cz));
        const std::uint32_t c = g.cell_of[i];
        const int ix = int(c % g.nx), iy = int((c / g.nx) % g.ny), iz = int(c / (g.nx * g.ny));
        // A stencil wider than the periodic grid visits every column once.
        const int x0 = 2 * wx + 1 >= g.nx ? 0 : ix - wx,
                  x1 = 2 * wx + 1 >= g.nx ? g.nx - 1 : ix + wx;
        const int y0 = 2 * wy + 1 >= g.ny ? 0 : iy - wy,
                  y1 = 2 * wy + 1 >= g.ny ? g.ny - 1 : iy + wy;
        const int z0 = std::max(0, iz - wz), z1 = std::min(g.nz - 1, iz + wz);
        // Cells whose nearest point lies beyond the search radius hold no partner: skipped (a
        // large particle's cubic stencil is ~2.5x its sphere). Along a periodic axis whose
        // stencil is narrower than the grid, the unwrapped offset is a minimum image (|dx| <=
        // (w + 1) c <= L/2), so the bound holds; a stencil as wide as the grid is not pruned.
        // The margin covers the rounding of the binning; the list is the same, pair for pair.
        // Positions outside the period (clamped into an edge cell) turn the pruning off.
        const double s2 = search * search * (1.0 + 1e-9);
        const bool prune_x = g.wrapped && 2 * wx + 1 < g.nx,
                   prune_y = g.wrapped && 2 * wy + 1 < g.ny;
        const auto outside = [](double u, int k, double width) {
            const double lo = k * width, hi = lo + width;
            return u < lo ? lo - u : (u > hi ? u - hi : 0.0);
        };
        for (int kz = z0; kz <= z1; ++kz) {
            const double gz = g.wrapped ? outside(xi.z - g.zlo, kz, g.cz) : 0.0, gz2 = gz * gz;
            if (gz2 > s2) continue;
            for (int ky = y0; ky <= y1; ++ky) {
                const double gy = prune_y ? outside(xi.y, ky, g.cy) : 0.0, gzy2 = gz2 + gy * gy;
                if (gzy2 > s2) continue;
                const int cy = ((ky % g.ny) + g.ny) % g.ny;
                for (int kx = x0; kx <= x1; ++kx) {
                    const double gx = prune_x ? outside(xi.x, kx, g.cx) : 0.0;
                    if (gzy2 + gx * gx > s2) continue;
                    const int cx = ((kx % g.nx) + g.nx) % g.nx;
                    const int cc = g.index(cx, cy, kz);
                    for (std::uint32_t k = g.cell_start[cc]; k < g.cell_start[cc + 1]; ++k) {
                        const std::uint32_t j = g.cell_items[k];
                        if (!owns(ri, idi, p.radius[j], p.id[j])) continue;
                        if (i >= owned && j >= owned) continue; // two ghosts
                        const Vec3 d = box.minimum_image(xi, p.position[j]);
                        const double reach = ri + p.radius[j] + range(i, j);
                        if (norm2(d) < (reach + skin_) * (reach + skin_)) on_pair(j, reach * reach);
                    }
                }
            }
        }
    };
    // One search per row into fixed blocks of rows, then the blocks copied in row order: the
    // build stays parallel and the slot order deterministic. (A count pass and a fill pass, each
    // searching every row, cost twice the search: with the self-stiffness the list is rebuilt
    // every ~8 steps and the second search was ~15 % of the run.)
    const std::size_t blocks = (n + kBuildBlock - 1) / kBuildBlock;
    if (block_pairs_.size() < blocks) block_pairs_.resize(blocks);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads_)
    for (std::size_t b = 0; b < blocks; ++b) {
        std::vector<BuiltPair>& out = block_pairs_[b];
        out.clear();
        for (std::size_t i = b * kBuildBlock; i < std::min(n, (b + 1) * kBuildBlock); ++i) {
            const std::size_t before = out.size();
            visit(i, [&](std::uint32_t j, double reach2) { out.push_back({j, reach2}); });
            offset_[i + 1] = std::uint32_t(out.size() - before);
        }
    }
    for (std::size_t i = 0; i < n; ++i) offset_[i + 1] += offset_[i];
    partner_.resize(offset_[n]);
    reach2_.resize(offset_[n]);
    state_.assign(offset_[n], PairState{});
#pragma omp parallel for schedule(static) num_threads(threads_)
    for (std::size_t b = 0; b < blocks; ++b) {
        std::uint32_t s = offset_[b * kBuildBlock];
        for (const BuiltPair& e : block_pairs_[b]) {
            partner_[s] = e.partner;
            reach2_[s++] = e.reach2;
        }
    }
    carry_states(p);
    x_build_ = p.position;
    ++builds_;
}

} // namespace drydem
