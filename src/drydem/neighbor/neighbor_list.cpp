// SPDX-License-Identifier: MIT
#include "drydem/neighbor/neighbor_list.hpp"
#include "drydem/core/error.hpp"
#include <algorithm>

namespace drydem {

void NeighborList::bin(const ParticleStore& p, const Box& box, double cell_size) {
    Grid& g = grid_;
    const std::size_t n = p.size();
    g.nx = std::max(1, int(box.lx / cell_size));
    g.ny = std::max(1, int(box.ly / cell_size));
    g.cx = box.lx / g.nx;
    g.cy = box.ly / g.ny;
    double zlo = INFINITY, zhi = -INFINITY;
    for (std::size_t i = 0; i < n; ++i) {
        zlo = std::min(zlo, p.position[i].z);
        zhi = std::max(zhi, p.position[i].z);
    }
    if (n == 0) zlo = zhi = 0.0;
    if (!std::isfinite(zlo) || !std::isfinite(zhi))
        throw RunError("neighbor search: a particle position is not finite");
    // Cap the number of z layers so that one stray particle cannot exhaust memory; wider cells
    // stay correct because the stencil is computed from the actual cell size.
    const double max_layers = std::max(16.0, 4.0e6 / (double(g.nx) * g.ny));
    g.nz = int(std::min(max_layers, std::floor((zhi - zlo) / cell_size) + 1.0));
    g.cz = std::max(cell_size, (zhi - zlo) / g.nz * (1.0 + 1e-12));
    g.zlo = zlo;
    const std::size_t ncell = std::size_t(g.nx) * g.ny * g.nz;
    g.cell_start.assign(ncell + 1, 0);
    g.cell_of.resize(n);
    g.wrapped = true;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& x = p.position[i];
        if (!(x.x >= 0.0 && x.x < box.lx && x.y >= 0.0 && x.y < box.ly)) g.wrapped = false;
        const int ix = std::min(g.nx - 1, std::max(0, int(x.x / g.cx)));
        const int iy = std::min(g.ny - 1, std::max(0, int(x.y / g.cy)));
        const int iz = std::min(g.nz - 1, std::max(0, int((x.z - zlo) / g.cz)));
        g.cell_of[i] = std::uint32_t(g.index(ix, iy, iz));
        ++g.cell_start[g.cell_of[i] + 1];
    }
    for (std::size_t c = 0; c < ncell; ++c) g.cell_start[c + 1] += g.cell_start[c];
    g.cell_items.resize(n);
    std::vector<std::uint32_t>& fill = order_;
    fill.assign(g.cell_start.begin(), g.cell_start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) g.cell_items[fill[g.cell_of[i]]++] = std::uint32_t(i);
}

void NeighborList::keep_previous_list(const ParticleStore& p) {
    if (carry_pending_) {
        carry_pending_ = false; // carry_from() has set the old list up
        return;
    }
    const std::size_t n = p.size();
    old_offset_.swap(offset_);
    old_state_.swap(state_);
    old_partner_id_.resize(partner_.size());
    for (std::size_t s = 0; s < partner_.size(); ++s) old_partner_id_[s] = p.id[partner_[s]];
    std::uint32_t max_id = 0;
    for (std::size_t i = 0; i < n; ++i) max_id = std::max(max_id, p.id[i]);
    old_row_of_id_.assign(std::size_t(max_id) + 1, UINT32_MAX);
    if (!old_offset_.empty())
        for (std::size_t i = 0; i < n; ++i) old_row_of_id_[p.id[i]] = std::uint32_t(i);
}

void NeighborList::sort_by_cell(ParticleStore& p) {
    // cell_items is a counting sort of the particles by cell: use it as the new storage order.
    std::vector<std::uint32_t> order(grid_.cell_items.begin(), grid_.cell_items.end());
    p.permute(order);
}

void NeighborList::carry_from(std::vector<Entry> entries) {
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
        return a.owner_id != b.owner_id ? a.owner_id < b.owner_id : a.partner_id < b.partner_id;
    });
    std::uint32_t max_id = 0;
    for (const Entry& e : entries) max_id = std::max(max_id, e.owner_id);
    old_row_of_id_.assign(entries.empty() ? 0 : std::size_t(max_id) + 1, UINT32_MAX);
    old_offset_.assign(1, 0);
    old_partner_id_.clear();
    old_state_.clear();
    for (std::size_t k = 0; k < entries.size(); ++k) {
        const Entry& e = entries[k];
        if (k > 0 && e.owner_id == entries[k - 1].owner_id &&
            e.partner_id == entries[k - 1].partner_id)
            continue; // the same pair from two ranks: both computed it alike
        if (old_row_of_id_[e.owner_id] == UINT32_MAX) {
            old_row_of_id_[e.owner_id] = std::uint32_t(old_offset_.size() - 1);
            old_offset_.push_back(old_offset_.back());
        }
        old_partner_id_.push_back(e.partner_id);
        old_state_.push_back(e.state);
        ++old_offset_.back();
    }
    if (entries.empty()) old_offset_.clear(); // nothing to carry
    carry_pending_ = true;
}

void NeighborList::carry_states(const ParticleStore& p) {
    if (old_offset_.empty()) return;
    const std::size_t n = p.size();
#pragma omp parallel for schedule(dynamic, 512) num_threads(threads_)
    for (std::size_t i = 0; i < n; ++i) {
        if (p.id[i] >= old_row_of_id_.size()) continue;
        const std::uint32_t orow = old_row_of_id_[p.id[i]];
        if (orow == UINT32_MAX) continue;
        const std::uint32_t ob = old_offset_[orow], oe = old_offset_[orow + 1];
        bool any = false;
        for (std::uint32_t s = ob; s < oe && !any; ++s) any = PairLaws::keeps(old_state_[s]);
        if (!any) continue;
        for (std::uint32_t s = offset_[i]; s < offset_[i + 1]; ++s) {
            const std::uint32_t pid = p.id[partner_[s]];
            for (std::uint32_t o = ob; o < oe; ++o)
                if (old_partner_id_[o] == pid) {
                    state_[s] = old_state_[o];
                    break;
                }
        }
    }
}

void NeighborList::keep_rows(const std::vector<std::uint32_t>& new_index) {
    if (offset_.empty()) return;
    std::vector<std::uint32_t> offset{0}, partner;
    std::vector<double> reach2;
    std::vector<PairState> state;
    std::vector<Vec3> x_build;
    for (std::size_t i = 0; i + 1 < offset_.size(); ++i) {
        if (new_index[i] == UINT32_MAX) continue;
        for (std::uint32_t s = offset_[i]; s < offset_[i + 1]; ++s) {
            const std::uint32_t j = new_index[partner_[s]];
            if (j == UINT32_MAX) continue;
            partner.push_back(j);
            reach2.push_back(reach2_[s]);
            state.push_back(state_[s]);
        }
        offset.push_back(std::uint32_t(partner.size()));
        x_build.push_back(x_build_[i]);
    }
    offset_.swap(offset);
    partner_.swap(partner);
    reach2_.swap(reach2);
    state_.swap(state);
    x_build_.swap(x_build);
}

std::vector<NeighborList::Entry> NeighborList::state_entries(const ParticleStore& p) const {
    std::vector<Entry> out;
    for (std::size_t i = 0; i + 1 < offset_.size(); ++i)
        for (std::uint32_t s = offset_[i]; s < offset_[i + 1]; ++s)
            if (PairLaws::keeps(state_[s])) out.push_back({p.id[i], p.id[partner_[s]], state_[s]});
    return out;
}

} // namespace drydem
