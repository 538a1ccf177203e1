// SPDX-License-Identifier: MIT
#include "drydem/engine/simulation.hpp"
#include "drydem/core/error.hpp"
#include "drydem/parallel/mpi_world.hpp"
#include <fmt/format.h>
#include <omp.h>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace drydem {

Simulation::Simulation(ParticleStore particles, Box box, ForceField forces, EngineSettings settings)
    : p_(std::move(particles)), body_state_(p_.size()), box_(box), ff_(std::move(forces)),
      settings_(settings), nl_(settings.skin, settings.threads),
      near_(settings.skin, settings.near_list), liquid_level_(settings.initial_liquid_level) {
    threads_ = settings_.threads > 0 ? settings_.threads : omp_get_max_threads();
    substrate_on_ = ff_.substrate_on();
    for (std::size_t i = 0; i < p_.size(); ++i) box_.wrap(p_.position[i]);
    if (settings_.ranks > 1) decompose();
    allocate_integrator();
    stats_.layer_top = p_.size() ? -INFINITY : 0.0;
    for (std::size_t i = 0; i < owned(); ++i)
        stats_.layer_top = std::max(stats_.layer_top, p_.position[i].z + p_.radius[i]);
    if (halo_) stats_.layer_top = halo_->all_max(stats_.layer_top);
    compute_forces();
}

Simulation::Simulation(EngineState state, Box box, ForceField forces, EngineSettings settings)
    : p_(std::move(state.particles)), body_state_(std::move(state.body_state)), box_(box),
      ff_(std::move(forces)), settings_(settings), nl_(settings.skin, settings.threads),
      near_(settings.skin, settings.near_list), step_(state.step), time_(state.time),
      liquid_level_(state.liquid_level), force_rebuild_(state.force_rebuild), stats_(state.stats),
      rebuilds_since_sort_(state.rebuilds_since_sort) {
    settings_.dt = state.dt;
    threads_ = settings_.threads > 0 ? settings_.threads : omp_get_max_threads();
    substrate_on_ = ff_.substrate_on();
    if (body_state_.size() != p_.size())
        throw InputError("checkpoint: the body laws' states do not fit the particles");
    nl_.restore(std::move(state.neighbors));
    if (semi_implicit()) {
        if (state.accel.size() != p_.size() || state.alpha.size() != p_.size())
            throw InputError("checkpoint: the state holds no semi-implicit accelerations (it was "
                             "written by the explicit integrator); resume with the same "
                             "numerics.integrator");
        accel_ = std::move(state.accel);
        alpha_ = std::move(state.alpha);
    }
    if (settings_.ranks > 1) {
        // Every rank holds the whole state: keep what this rank owns, carry the pair states by
        // ids into the first step's rebuild.
        resumed_entries_ = nl_.state_entries(p_);
        decompose();
        force_rebuild_ = true;
    }
    std::vector<Vec3> accel = std::move(accel_), alpha = std::move(alpha_);
    allocate_integrator();
    if (semi_implicit()) {
        accel_ = std::move(accel);
        alpha_ = std::move(alpha);
    }
}

void Simulation::allocate_integrator() {
    const std::size_t n = p_.size();
    const bool semi = semi_implicit();
    buffer_.assign(std::size_t(threads_), {});
    if (threads_ > 1)
        for (ThreadBuffer& b : buffer_) {
            b.force.assign(n, {});
            b.torque.assign(n, {});
            if (semi) b.block.assign(n, {});
            b.marked.assign(n, 0);
            b.touched.reserve(n);
        }
    if (!semi) return;
    body_resistance_.assign(n, {});
    block_.assign(n, {});
    accel_.assign(n, {});
    alpha_.assign(n, {});
}

double owner_range_bound(const ForceField& forces, int species, double radius) {
    // Upper bound of the range an owner can have: partners are never larger than the owner.
    double r = 0.0;
    for (int sj = 0; sj < forces.species_count; ++sj)
        r = std::max(r, interaction_range(forces.pair_params(species, sj), radius, radius));
    return r;
}

parallel::Decomposition plan_decomposition(const Box& box, double r_max, double range_max,
                                           double height, const EngineSettings& settings) {
    // A ghost must be seen as far as a partner's surface reaches: its radius, the largest
    // partner's, that partner's range and the skin (docs/parallel.md "The reach").
    if (settings.integrator == Integrator::quasi_static)
        throw InputError("numerics.integrator = \"quasi_static\" does not run on several MPI "
                         "ranks yet (docs/parallel.md); use \"semi_implicit\" or \"explicit\"");
    const double reach = 2.0 * r_max + range_max + settings.skin;
    return parallel::decompose(box, settings.ranks, reach, height, settings.grid);
}

double Simulation::owner_range_bound(std::size_t i) const {
    return drydem::owner_range_bound(ff_, p_.species[i], p_.radius[i]);
}

void Simulation::decompose() {
    const parallel::World w = parallel::world();
    if (w.size != settings_.ranks)
        throw InputError(fmt::format("the engine was asked for {} MPI ranks; MPI runs {}",
                                     settings_.ranks, w.size));
    // Every rank holds the whole set here: the widest reach needs no reduction.
    double r_max = 0.0, range_max = 0.0, top = 0.0;
    for (std::size_t i = 0; i < p_.size(); ++i) {
        r_max = std::max(r_max, p_.radius[i]);
        range_max = std::max(range_max, owner_range_bound(i));
        top = std::max(top, p_.position[i].z + p_.radius[i]);
    }
    halo_.emplace(plan_decomposition(box_, r_max, range_max, top, settings_), MPI_COMM_WORLD);
    if (!accel_.empty())
        halo_->keep_owned(p_, body_state_, accel_, alpha_); // a resumed semi-implicit state
    else
        halo_->keep_owned(p_, body_state_);
}

std::pair<double, double> Simulation::largest_radius_and_range() const {
    double r_max = 0.0, range_max = 0.0;
    for (std::size_t i = 0; i < owned(); ++i) {
        r_max = std::max(r_max, p_.radius[i]);
        range_max = std::max(range_max, owner_range_bound(i));
    }
    if (halo_) return {halo_->all_max(r_max), halo_->all_max(range_max)};
    return {r_max, range_max};
}

void Simulation::clear_ghost_forces() {
    for (std::size_t g = owned(); g < p_.size(); ++g) {
        p_.force[g] = Vec3{};
        p_.torque[g] = Vec3{};
        if (semi_implicit()) block_[g] = SelfBlock{};
    }
}

std::vector<std::int32_t> Simulation::coordination() const {
    std::vector<std::int32_t> z(p_.size(), 0);
    for (std::size_t i = 0; i < p_.size(); ++i) {
        if (p_.position[i].z < p_.radius[i]) ++z[i];
        if (nl_.owners() != p_.size()) continue;
        for (std::uint32_t s = nl_.begin(i); s < nl_.end(i); ++s) {
            const std::uint32_t j = nl_.partner(s);
            const double reach = p_.radius[i] + p_.radius[j];
            if (norm2(box_.minimum_image(p_.position[i], p_.position[j])) < reach * reach) {
                ++z[i];
                ++z[j];
            }
        }
    }
    return z;
}

template <class PairFn, class WallFn>
void Simulation::visit_contact_forces(PairFn&& pair, WallFn&& wall) const {
    // Thread t visits the rows of row_split and its share of the bonds; what it adds goes to its
    // own accumulator (the callbacks' first argument), summed by the caller in thread order, so
    // the result is the same run to run for a given thread count.
    const std::size_t threads = std::size_t(threads_), n = p_.size(), nb = bonds_.bonds.size();
#pragma omp parallel for schedule(static, 1) num_threads(threads_)
    for (std::size_t t = 0; t < threads; ++t) {
        for (std::size_t i = row_split(t, threads); i < row_split(t + 1, threads); ++i) {
            if (nl_.owners() == n)
                for (std::uint32_t k = nl_.begin(i); k < nl_.end(i); ++k) {
                    const std::uint32_t j = nl_.partner(k);
                    const Vec3 d = box_.minimum_image(p_.position[i], p_.position[j]);
                    const double dist2 = norm2(d);
                    if (dist2 >= nl_.reach2(k) || dist2 == 0.0) continue;
                    const PairGeometry g = make_pair_geometry(
                        d, std::sqrt(dist2), p_.radius[i], p_.radius[j], p_.mass[i], p_.mass[j],
                        p_.velocity[i], p_.velocity[j], p_.omega[i], p_.omega[j]);
                    PairState kept = nl_.state(k);
                    pair(t, i, j,
                         pair_interaction(g, ff_.pair_params(p_.species[i], p_.species[j]), kept,
                                          0.0)
                             .force_i,
                         d);
                }
            // The walls: their contact point lies on the plane, straight below or above the
            // centre.
            const BodyGeometry g = body_geometry(i, p_.velocity[i], p_.omega[i], 0.0);
            const BodyParams& bp = ff_.body_params(p_.species[i]);
            BodyState kept = body_state_[i];
            BodyForce sub{}, plate{};
            SubstrateContactLaw::add_force(g, law<SubstrateContactLaw>(bp),
                                           BodyLaws::state<SubstrateContactLaw>(kept), 0.0, sub,
                                           nullptr);
            PlateContactLaw::add_force(g, law<PlateContactLaw>(bp),
                                       BodyLaws::state<PlateContactLaw>(kept), 0.0, plate, nullptr);
            wall(t, i, sub.force, Vec3{0.0, 0.0, -p_.position[i].z});
            if (std::isfinite(plate_height_))
                wall(t, i, plate.force, Vec3{0.0, 0.0, plate_height_ - p_.position[i].z});
        }
        for (std::size_t k = nb * t / threads; k < nb * (t + 1) / threads; ++k)
            if (const Bond& b = bonds_.bonds[k]; b.state.intact())
                pair(t, std::size_t(b.i), std::size_t(b.j), bond_force(b).force_i,
                     box_.minimum_image(p_.position[b.i], p_.position[b.j]));
    }
}

Sym3 Simulation::contact_stress(double volume) const {
    std::vector<Sym3> part(static_cast<std::size_t>(threads_));       // per thread, summed in order
    auto add = [&part](std::size_t t, const Vec3& f, const Vec3& d) { // -= f ⊗ d, symmetrised
        Sym3& s = part[t];
        s.xx -= f.x * d.x, s.yy -= f.y * d.y, s.zz -= f.z * d.z;
        s.xy -= 0.5 * (f.x * d.y + f.y * d.x);
        s.xz -= 0.5 * (f.x * d.z + f.z * d.x);
        s.yz -= 0.5 * (f.y * d.z + f.z * d.y);
    };
    visit_contact_forces(
        [&](std::size_t t, std::size_t, std::size_t, const Vec3& f, const Vec3& d) {
            add(t, f, d);
        },
        [&](std::size_t t, std::size_t, const Vec3& f, const Vec3& lever) { add(t, f, lever); });
    Sym3 s;
    for (const Sym3& q : part)
        s.xx += q.xx, s.yy += q.yy, s.zz += q.zz, s.xy += q.xy, s.xz += q.xz, s.yz += q.yz;
    const double inv = 1.0 / volume;
    s.xx *= inv, s.yy *= inv, s.zz *= inv, s.xy *= inv, s.xz *= inv, s.yz *= inv;
    return s;
}

std::vector<double> Simulation::particle_mean_stress() const {
    // -Σ f · (x_c - x), then / 3V; one array per thread (a pair adds to both of its particles),
    // summed in thread order.
    std::vector<std::vector<double>> part(std::size_t(threads_),
                                          std::vector<double>(p_.size(), 0.0));
    visit_contact_forces(
        [&](std::size_t th, std::size_t i, std::size_t j, const Vec3& f, const Vec3& d) {
            std::vector<double>& t = part[th];
            const double dist = norm(d), ri = p_.radius[i], rj = p_.radius[j];
            // The contact plane of two overlapping spheres (their intersection circle), a_i
            // from i's centre; for a gap, the same formula splits it by the radii.
            const double ai =
                std::clamp((dist * dist + ri * ri - rj * rj) / (2.0 * dist), 0.0, dist);
            const double fn = dot(f, d) / dist; // f on i along i -> j: < 0 in compression
            t[i] -= fn * ai;
            t[j] -= fn * (dist - ai); // j feels -f, its lever is -(dist - a_i) n
        },
        [&](std::size_t th, std::size_t i, const Vec3& f, const Vec3& lever) {
            part[th][i] -= dot(f, lever);
        });
    std::vector<double> t = std::move(part[0]);
    for (std::size_t k = 1; k < part.size(); ++k)
        for (std::size_t i = 0; i < t.size(); ++i) t[i] += part[k][i];
    for (std::size_t i = 0; i < p_.size(); ++i) t[i] /= 3.0 * sphere_volume(p_.radius[i]);
    return t;
}

std::vector<Simulation::ContactOverlap> Simulation::contact_overlaps() const {
    std::vector<ContactOverlap> out;
    for (std::size_t i = 0; i < p_.size(); ++i) {
        const double r = p_.radius[i], z = p_.position[i].z;
        if (nl_.owners() == p_.size())
            for (std::uint32_t k = nl_.begin(i); k < nl_.end(i); ++k) {
                const std::uint32_t j = nl_.partner(k);
                const double d = norm(box_.minimum_image(p_.position[i], p_.position[j]));
                if (const double overlap = r + p_.radius[j] - d; overlap > 0.0)
                    out.push_back({std::uint32_t(i), j, overlap});
            }
        if (substrate_on_ && z < r) out.push_back({std::uint32_t(i), ContactOverlap::kWall, r - z});
        if (std::isfinite(plate_height_) && z + r > plate_height_)
            out.push_back({std::uint32_t(i), ContactOverlap::kWall, z + r - plate_height_});
    }
    return out;
}

std::vector<double> Simulation::relative_overlaps() const {
    std::vector<double> out;
    for (const ContactOverlap& c : contact_overlaps()) {
        if (c.i >= owned()) continue; // a ghost's row: its owner counts the pair
        const double r = p_.radius[c.i];
        out.push_back(c.overlap / (c.j == ContactOverlap::kWall ? r : std::min(r, p_.radius[c.j])));
    }
    return out;
}

void Simulation::remove_particles(const std::vector<std::size_t>& which) {
    if (which.empty()) return;
    if (settings_.integrator != Integrator::explicit_verlet)
        throw RunError("particles can leave the packing only with the explicit integrator");
    if (halo_) throw RunError("particles cannot leave the packing on several MPI ranks yet");
    const std::size_t n = p_.size();
    std::vector<std::uint32_t> new_index(n, 0);
    for (const std::size_t i : which) new_index.at(i) = UINT32_MAX;
    std::vector<std::uint32_t> order;
    for (std::size_t i = 0; i < n; ++i)
        if (new_index[i] != UINT32_MAX) {
            new_index[i] = std::uint32_t(order.size());
            order.push_back(std::uint32_t(i));
        }
    nl_.keep_rows(new_index);
    std::vector<Bond> kept;
    for (Bond b : bonds_.bonds)
        if (new_index[b.i] != UINT32_MAX && new_index[b.j] != UINT32_MAX) {
            b.i = new_index[b.i], b.j = new_index[b.j];
            kept.push_back(b);
        }
    bonds_.bonds.swap(kept);
    bond_force_.assign(bonds_.bonds.size(), {});
    p_.permute(order);
    std::vector<BodyState> body(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) body[k] = body_state_[order[k]];
    body_state_.swap(body);
    allocate_integrator();
    invalidate_neighbors();
}

EngineState Simulation::state() const {
    if (halo_) return gathered_state();
    return {p_,           body_state_, nl_.state(), step_,  time_,          liquid_level_,
            settings_.dt, stats_,      accel_,      alpha_, force_rebuild_, rebuilds_since_sort_};
}

ParticleStore Simulation::whole_particles() const { return halo_ ? halo_->gather(p_) : p_; }

namespace {
/// What a decomposed state gathers per owned particle besides its record.
struct KeptRow {
    std::uint32_t id;
    std::int32_t coordination;
    BodyState body;
    Vec3 accel, alpha, x_build;
};
/// One slot of a rank's neighbour list, keyed by ids.
struct ListSlot {
    std::uint32_t owner_id, partner_id;
    double reach2;
    PairState state;
};
/// Rows ordered by id, for a store ordered by id.
std::vector<KeptRow> by_id(std::vector<KeptRow> rows) {
    std::sort(rows.begin(), rows.end(),
              [](const KeptRow& a, const KeptRow& b) { return a.id < b.id; });
    return rows;
}
} // namespace

std::vector<std::int32_t> Simulation::whole_coordination() const {
    std::vector<std::int32_t> z = coordination();
    if (!halo_) return z;
    std::vector<KeptRow> mine(owned());
    for (std::size_t i = 0; i < mine.size(); ++i) mine[i] = {p_.id[i], z[i], {}, {}, {}, {}};
    const std::vector<KeptRow> all = by_id(halo_->gather_items(mine));
    z.resize(all.size());
    for (std::size_t k = 0; k < all.size(); ++k) z[k] = all[k].coordination;
    return z;
}

// Each pair sits in the row of one particle on every rank that holds it (the larger one, ties by
// id): the rows of owned particles hold every pair once over the ranks.
EngineState Simulation::gathered_state() const {
    const parallel::Halo& halo = *halo_;
    const NeighborList::State list = nl_.state();
    std::vector<KeptRow> mine(owned());
    std::vector<ListSlot> slots;
    for (std::size_t i = 0; i < mine.size(); ++i) {
        mine[i] = {p_.id[i],
                   0,
                   body_state_[i],
                   semi_implicit() ? accel_[i] : Vec3{},
                   semi_implicit() ? alpha_[i] : Vec3{},
                   i < list.x_build.size() ? list.x_build[i] : p_.position[i]};
        if (i + 1 < list.offset.size())
            for (std::uint32_t s = list.offset[i]; s < list.offset[i + 1]; ++s)
                slots.push_back(
                    {p_.id[i], p_.id[list.partner[s]], list.reach2[s], list.pair_state[s]});
    }
    EngineState st;
    st.particles = halo.gather(p_);
    const std::vector<KeptRow> rows = by_id(halo.gather_items(mine));
    std::vector<ListSlot> all = halo.gather_items(slots);
    std::sort(all.begin(), all.end(), [](const ListSlot& a, const ListSlot& b) {
        return a.owner_id != b.owner_id ? a.owner_id < b.owner_id : a.partner_id < b.partner_id;
    });
    const std::size_t n = rows.size();
    std::unordered_map<std::uint32_t, std::uint32_t> index;
    for (std::size_t k = 0; k < n; ++k) {
        index.emplace(rows[k].id, std::uint32_t(k));
        st.body_state.push_back(rows[k].body);
        st.neighbors.x_build.push_back(rows[k].x_build);
        if (semi_implicit()) {
            st.accel.push_back(rows[k].accel);
            st.alpha.push_back(rows[k].alpha);
        }
    }
    NeighborList::State& nl = st.neighbors;
    nl.builds = nl_.builds();
    nl.offset.assign(n + 1, 0);
    for (const ListSlot& e : all) ++nl.offset[index.at(e.owner_id) + 1];
    for (std::size_t k = 0; k < n; ++k) nl.offset[k + 1] += nl.offset[k];
    for (const ListSlot& e : all) { // sorted by owner id: the rows fill in order
        nl.partner.push_back(index.at(e.partner_id));
        nl.reach2.push_back(e.reach2);
        nl.pair_state.push_back(e.state);
    }
    st.step = step_;
    st.time = time_;
    st.liquid_level = liquid_level_;
    st.dt = settings_.dt;
    st.stats = stats_;
    st.force_rebuild = true; // the list is over the id order, not a build's
    st.rebuilds_since_sort = rebuilds_since_sort_;
    return st;
}

// Under a decomposition (docs/parallel.md): the pair states of this rank's list, keyed by ids,
// with those of every particle that changes rank sent along to its new owner (a pair is computed
// by the owners of its two particles, so the new owner may never have seen it); then migration,
// the ghosts, and the list over owned particles and ghosts, carrying the states over by ids. No
// re-sort: it would mix ghosts into the owned particles.
template <class RangeFn, class OwnerRangeFn>
void Simulation::rebuild_decomposed(RangeFn&& range, OwnerRangeFn&& owner_range, bool sort) {
    parallel::Halo& halo = *halo_;
    const parallel::Decomposition& d = halo.decomposition();
    const std::size_t own = halo.owned();
    const auto [r_max, range_max] = largest_radius_and_range();
    // This rank's own work since the last rebalance: the elapsed time less its waits in MPI.
    const double now = omp_get_wtime(), waited = parallel::waited_seconds();
    const double busy =
        balance_clock_ > 0.0 ? (now - balance_clock_) - (waited - balance_waited_) : 0.0;
    halo.rebalance(p_, pairs_per_owned(), 2.0 * r_max + range_max + settings_.skin, busy);
    balance_clock_ = omp_get_wtime();
    balance_waited_ = parallel::waited_seconds();
    std::vector<NeighborList::Entry> entries;
    if (nl_.owners() == p_.size())
        entries = nl_.state_entries(p_);
    else // the first rebuild of a resumed state: the whole film's list, read from the checkpoint
        entries = std::move(resumed_entries_);
    resumed_entries_.clear();
    const std::vector<int>& nb = halo.neighbors();
    std::unordered_map<std::uint32_t, std::size_t> leaving; // id -> neighbour slot
    for (std::size_t i = 0; i < own; ++i) {
        const int r = d.owner(p_.position[i]);
        const auto k = std::size_t(std::lower_bound(nb.begin(), nb.end(), r) - nb.begin());
        if (r != halo.rank() && k < nb.size() && nb[k] == r) leaving.emplace(p_.id[i], k);
    }
    std::vector<std::vector<NeighborList::Entry>> travel(nb.size());
    if (!leaving.empty())
        for (const NeighborList::Entry& e : entries)
            for (const std::uint32_t id : {e.owner_id, e.partner_id})
                if (const auto it = leaving.find(id); it != leaving.end())
                    travel[it->second].push_back(e);
    for (const auto& got : halo.exchange_items(travel))
        entries.insert(entries.end(), got.begin(), got.end());
    // Migration with everything the next steps read of a particle.
    body_state_.resize(own);
    if (semi_implicit()) {
        body_resistance_.resize(own);
        accel_.resize(own);
        alpha_.resize(own);
        halo.migrate(p_, body_state_, body_resistance_, accel_, alpha_);
    } else {
        halo.migrate(p_, body_state_);
    }
    if (sort) sort_owned(owner_range);
    std::vector<double> reach(halo.owned());
    for (std::size_t i = 0; i < reach.size(); ++i)
        reach[i] = p_.radius[i] + r_max + range_max + settings_.skin;
    halo.make_ghosts(p_, reach);
    const std::size_t n = p_.size();
    body_state_.resize(n);
    if (semi_implicit()) {
        body_resistance_.resize(n);
        accel_.resize(n);
        alpha_.resize(n);
        block_.assign(n, SelfBlock{});
    }
    if (threads_ > 1)
        for (ThreadBuffer& b : buffer_) {
            b.force.assign(n, {});
            b.torque.assign(n, {});
            if (semi_implicit()) b.block.assign(n, {});
            b.marked.assign(n, 0);
            b.touched.clear();
            b.touched.reserve(n);
        }
    nl_.carry_from(std::move(entries));
    nl_.build(p_, box_, range, owner_range, false, halo.owned());
}

std::vector<double> Simulation::pairs_per_owned() const {
    const std::size_t own = owned();
    std::vector<double> pairs(own, 0.0);
    if (nl_.owners() != p_.size()) return pairs; // no list over this store yet (a resumed state)
    for (std::size_t i = 0; i < p_.size(); ++i)
        for (std::uint32_t s = nl_.begin(i); s < nl_.end(i); ++s) {
            if (i < own) pairs[i] += 1.0;
            if (const std::uint32_t j = nl_.partner(s); j < own) pairs[j] += 1.0;
        }
    return pairs;
}

template <class OwnerRangeFn>
void Simulation::sort_owned(OwnerRangeFn&& owner_range) {
    const std::vector<std::uint32_t> order = nl_.spatial_order(p_, box_, owner_range);
    p_.permute(order);
    auto follow = [&](auto& v) {
        std::remove_reference_t<decltype(v)> moved(order.size());
        for (std::size_t k = 0; k < order.size(); ++k) moved[k] = v[order[k]];
        v.swap(moved);
    };
    follow(body_state_);
    if (semi_implicit()) {
        follow(body_resistance_);
        follow(accel_);
        follow(alpha_);
    }
}

void Simulation::rebuild_neighbors() {
    const bool sort =
        settings_.sort_every > 0 &&
        (nl_.builds() == 0 || ++rebuilds_since_sort_ >= std::uint64_t(settings_.sort_every));
    if (sort) rebuilds_since_sort_ = 0;
    auto owner_range = [&](std::size_t i) { return owner_range_bound(i); };
    auto range = [&](std::size_t i, std::size_t j) {
        return interaction_range(ff_.pair_params(p_.species[i], p_.species[j]), p_.radius[i],
                                 p_.radius[j]);
    };
    const double t0 = omp_get_wtime();
    if (halo_) {
        rebuild_decomposed(range, owner_range, sort);
    } else if (sort) {
        // The body laws' states and (semi-implicit) resistances are kept in storage order: carry
        // them to the new order by id.
        std::vector<std::uint32_t> ids = p_.id;
        nl_.build(p_, box_, range, owner_range, sort);
        std::uint32_t max_id = 0;
        for (std::uint32_t id : ids) max_id = std::max(max_id, id);
        std::vector<std::uint32_t> old_index(std::size_t(max_id) + 1);
        for (std::size_t k = 0; k < ids.size(); ++k) old_index[ids[k]] = std::uint32_t(k);
        auto carry = [&](auto& v) {
            std::remove_reference_t<decltype(v)> moved(p_.size());
            for (std::size_t k = 0; k < p_.size(); ++k) moved[k] = v[old_index[p_.id[k]]];
            v.swap(moved);
        };
        carry(body_state_);
        if (semi_implicit()) carry(body_resistance_);
        if (!bonds_.bonds.empty()) {
            std::vector<std::uint32_t> new_index(p_.size());
            for (std::size_t k = 0; k < p_.size(); ++k)
                new_index[old_index[p_.id[k]]] = std::uint32_t(k);
            for (Bond& b : bonds_.bonds) b.i = new_index[b.i], b.j = new_index[b.j];
        }
    } else {
        nl_.build(p_, box_, range, owner_range, sort);
    }
    force_rebuild_ = false;
    near_.neighbors_rebuilt(step_);
    times_.neighbor += omp_get_wtime() - t0;
}

void Simulation::compute_forces() {
    near_.invalidate(); // the particles may have been moved outside step()
    if (force_rebuild_) rebuild_neighbors();
    if (quasi_static()) return assemble_quasi_static();
    std::size_t wall_contacts = 0;
    double wall_overlap = 0.0;
    const std::size_t own = owned();
#pragma omp parallel for schedule(static) num_threads(threads_) reduction(+ : wall_contacts) reduction(max : wall_overlap)
    for (std::size_t i = 0; i < own; ++i) body_forces(i, wall_contacts, wall_overlap);
    clear_ghost_forces();
    pair_forces(wall_contacts, wall_overlap);
    if (semi_implicit()) {
#pragma omp parallel for schedule(static) num_threads(threads_)
        for (std::size_t i = 0; i < own; ++i) implicit_acceleration(i);
    }
}

void Simulation::set_bonds(BondNetwork bonds, bool from_checkpoint) {
    if (halo_ && !bonds.bonds.empty())
        throw InputError("solid bonds do not run on several MPI ranks yet (docs/parallel.md)");
    if (!bonds.bonds.empty() && settings_.integrator != Integrator::explicit_verlet)
        throw InputError("solid bonds need the explicit integrator (numerics.integrator = "
                         "\"explicit\"): their damping is not part of the implicit steps");
    if (bonds.species_count != ff_.species_count)
        throw InputError(fmt::format("bonds: parameters for {} species, the force field has {}",
                                     bonds.species_count, ff_.species_count));
    if (const auto bad = bonds.limit_violations(); !bad.empty())
        throw InputError(fmt::format("solid bond parameter out of range: {}", bad.front()));
    for (const Bond& b : bonds.bonds)
        if (b.i >= p_.size() || b.j >= p_.size() || b.i == b.j)
            throw InputError(
                fmt::format("bond between particles {} and {} of {}", b.i, b.j, p_.size()));
    bonds_ = std::move(bonds);
    bond_force_.assign(bonds_.bonds.size(), {});
    if (!from_checkpoint) force_rebuild_ = true;
}

PairForce Simulation::bond_force(const Bond& b) const {
    SolidBondState kept = b.state;
    return solid_bond(bond_geometry(b, p_, box_), bonds_.pair(p_.species[b.i], p_.species[b.j]),
                      kept, 0.0);
}

// Each bond's force in parallel (its own slot), then added to the particles in bond order: the
// result does not depend on the thread count. Bonds are few beside the pairs (the carbon-binder
// pairs within a gap), so the serial sum costs little.
void Simulation::bond_forces() {
    const double dt = settings_.dt;
    const std::size_t nb = bonds_.bonds.size();
    bond_force_.resize(nb);
#pragma omp parallel for schedule(static) num_threads(threads_)
    for (std::size_t k = 0; k < nb; ++k) {
        Bond& b = bonds_.bonds[k];
        if (!b.state.intact()) {
            bond_force_[k] = {};
            continue;
        }
        bond_force_[k] = solid_bond(bond_geometry(b, p_, box_),
                                    bonds_.pair(p_.species[b.i], p_.species[b.j]), b.state, dt);
    }
    for (std::size_t k = 0; k < nb; ++k) {
        const Bond& b = bonds_.bonds[k];
        const PairForce& f = bond_force_[k];
        p_.force[b.i] += f.force_i;
        p_.force[b.j] -= f.force_i;
        p_.torque[b.i] += f.torque_i;
        p_.torque[b.j] += f.torque_j;
    }
}

void Simulation::implicit_acceleration(std::size_t i) {
    ParticleStore& p = p_;
    SelfBlock d = block_[i];
    block_[i] = SelfBlock{};
    add_self_block(d, body_resistance_[i]);
    solve_self_block(d, settings_.dt, p.mass[i], 1.0 / p.inv_inertia[i], p.force[i], p.torque[i],
                     accel_[i], alpha_[i]);
}

void Simulation::pair_forces(std::size_t wall_contacts, double wall_overlap) {
    if (force_rebuild_) rebuild_neighbors();
    if (near_.on() && !near_.valid()) {
        const double t_near = omp_get_wtime();
        near_.build(nl_, p_, box_, threads_, step_);
        times_.neighbor += omp_get_wtime() - t_near;
    }
    const double t0 = omp_get_wtime();
    std::size_t contacts = 0;
    double max_overlap = wall_overlap;
    if (semi_implicit())
        near_.on() ? pair_loop<true, NearList>(near_, contacts, max_overlap)
                   : pair_loop<true, NeighborList>(nl_, contacts, max_overlap);
    else
        near_.on() ? pair_loop<false, NearList>(near_, contacts, max_overlap)
                   : pair_loop<false, NeighborList>(nl_, contacts, max_overlap);
    if (halo_) {
        contacts = halo_->all_sum(std::uint64_t(contacts));
        wall_contacts = halo_->all_sum(std::uint64_t(wall_contacts));
        max_overlap = halo_->all_max(max_overlap);
    }
    stats_.contacts = contacts;
    stats_.wall_contacts = wall_contacts;
    stats_.max_overlap_rel = max_overlap;
    if (!bonds_.bonds.empty()) bond_forces();
    times_.pair += omp_get_wtime() - t0;
}

namespace {
// The partners' data lie in L2/L3: ask for the lines of the partners two and one slots ahead
// (their geometry first, then what the pair writes) before they are needed. Always inlined: as
// an ordinary function GCC's interprocedural analysis finds it free of side effects (a prefetch
// changes nothing it can see) and deletes the call. That happened when this was split out of the
// pair loop (2cd0e8a): no prefetch was left in the binary and the pair loop of a dense 20.1
// mg/cm2 film took 18 % longer (docs/performance.md, "Cost of the pair-law contract").
template <bool SelfBlocks, class List>
[[gnu::always_inline]] inline void prefetch_partners(const List& nl, const ParticleStore& p,
                                                     const SelfBlock* block, std::uint32_t s,
                                                     std::uint32_t row_end) {
    if (s + 2 < row_end) {
        const std::uint32_t jf = nl.partner(s + 2);
        __builtin_prefetch(&p.position[jf]);
        __builtin_prefetch(&p.radius[jf]);
        __builtin_prefetch(&p.mass[jf]);
    }
    if (s + 1 < row_end) {
        const std::uint32_t jn = nl.partner(s + 1);
        __builtin_prefetch(&p.velocity[jn]);
        __builtin_prefetch(&p.omega[jn]);
        __builtin_prefetch(&p.force[jn], 1);
        __builtin_prefetch(&p.torque[jn], 1);
        if constexpr (SelfBlocks) { // 120 bytes: two cache lines
            __builtin_prefetch(&block[jn], 1);
            __builtin_prefetch(reinterpret_cast<const char*>(&block[jn]) + 64, 1);
        }
    }
}

// Implicit self-stiffness (model.md M-9.1): Δt K of a pair or a body law joins the resistance
// that the semi-implicit kick's self-blocks are made of, so its inertia is M + Δt D + Δt² K_ii.
void add_self_stiffness(PairResistance& r, const PairResistance& k, double dt) {
    r.normal += dt * k.normal;
    r.sliding += dt * k.sliding;
    r.rolling += dt * k.rolling;
    r.twisting += dt * k.twisting;
}
void add_self_stiffness(BodyResistance& r, const BodyResistance& k, double dt) {
    r.normal += dt * k.normal;
    r.tangential += dt * k.tangential;
    r.coupling += dt * k.coupling;
    r.rotation_t += dt * k.rotation_t;
    r.rotation_n += dt * k.rotation_n;
}

// The pair's force, its resistance r and, added to r, Δt times its laws' stiffness (M-9.1),
// from one evaluation of the laws. Inlined with the tangent pointer a constant: a pointer chosen
// at run time costs the pair loop ~5 %.
[[gnu::always_inline]] inline PairForce stiff_interaction(const PairGeometry& g,
                                                          const PairParams& pp, PairState& state,
                                                          double dt, PairResistance& r) {
    PairResistance tangent;
    const PairForce f = pair_interaction(g, pp, state, dt, &r, &tangent);
    add_self_stiffness(r, tangent, dt);
    return f;
}

// The slot of the neighbour list that entry k of the walked list names.
std::uint32_t slot_of(const NearList& l, std::uint32_t k) { return l.slot(k); }
std::uint32_t slot_of(const NeighborList&, std::uint32_t k) { return k; }
} // namespace

// The rows [lo, hi) of thread t hold an equal share of the list's slots (plus one per row), not
// of the particles: pairs are owned by the larger particle and the film is denser at the bottom,
// so equal particle counts left one thread waiting for the other at the barrier (18 % of the time
// on the peers' bed with two threads).
std::size_t Simulation::row_split(std::size_t t, std::size_t parts) const {
    const std::size_t n = p_.size();
    if (t >= parts) return n;
    const std::uint32_t slots = n ? nl_.end(n - 1) : 0;
    const double target = double(slots + n) * double(t) / double(parts);
    std::size_t a = 0, b = n; // first row whose cumulative cost reaches the target
    while (a < b) {
        const std::size_t m = (a + b) / 2;
        if (double(nl_.begin(m)) + double(m) < target)
            a = m + 1;
        else
            b = m;
    }
    return a;
}

// Fixed-order reduction: every thread adds, for its own particles, what the other threads wrote
// across, thread 0 first; it leaves those buffer entries zeroed.
template <bool SelfBlocks>
void Simulation::add_cross_range(std::size_t t, std::size_t lo, std::size_t hi) {
    for (std::size_t k = 0; k < std::size_t(threads_); ++k) {
        if (k == t) continue;
        ThreadBuffer& other = buffer_[k];
        for (const std::uint32_t j : other.touched) {
            if (j - lo >= hi - lo) continue;
            p_.force[j] += other.force[j];
            p_.torque[j] += other.torque[j];
            other.force[j] = Vec3{};
            other.torque[j] = Vec3{};
            if constexpr (SelfBlocks) {
                block_[j] += other.block[j];
                other.block[j] = SelfBlock{};
            }
            other.marked[j] = 0;
        }
    }
}

template <bool SelfBlocks, class List>
void Simulation::pair_loop(const List& list, std::size_t& contacts_out, double& max_overlap_out) {
    const double dt = settings_.dt;
    std::size_t contacts = 0;
    double max_overlap = max_overlap_out;
    ParticleStore& p = p_;
    const std::size_t species_count = std::size_t(ff_.species_count);
    const PairParams* pair_table = ff_.pair.data();
    const std::size_t threads = std::size_t(threads_);
    const std::size_t owned_rows = owned(); // a ghost's row is counted by the ghost's owner

    // Pair loop over the half list. Thread t owns the rows [lo, hi) and writes the forces,
    // torques and self-blocks of its own particles straight into the store (which holds the
    // particle forces already). A partner j owned by another thread goes to t's buffer and its
    // index to t's `touched` list; after the loop every thread adds the other threads' buffers
    // for its own particles, in thread order, so results are identical run to run for a given
    // thread count. The spatial sort keeps partners near in storage order, so only the rows at
    // a range's edge write across it: the reduction touches a few percent of the particles, not
    // all of them (it used to stream three full buffers per extra thread every step). (A variant
    // that evaluated batches of 64 pairs in one `omp simd` loop was measured 20 % slower: the
    // gathers and masked branches cost more than the overlapped divisions save.) With
    // SelfBlocks, each pair's dissipative resistance is also added to both particles'
    // self-blocks (semi-implicit kick).
#pragma omp parallel num_threads(threads_) reduction(+ : contacts) reduction(max : max_overlap)
    {
        const std::size_t t = std::size_t(omp_get_thread_num());
        const std::size_t lo = row_split(t, threads), hi = row_split(t + 1, threads);
        ThreadBuffer& own = buffer_[t];
        Vec3* force = p.force.data();
        Vec3* torque = p.torque.data();
        SelfBlock* block = block_.data();
        auto remote = [&](std::uint32_t j) {
            if (!own.marked[j]) {
                own.marked[j] = 1;
                own.touched.push_back(j); // capacity n reserved: never reallocates
            }
        };
        for (std::size_t i = lo; i < hi; ++i) {
            const Vec3 xi = p.position[i];
            const double ri = p.radius[i];
            const PairParams* row = pair_table + std::size_t(p.species[i]) * species_count;
            Vec3 fi{}, ti{};
            SelfBlock di{};
            const std::uint32_t row_end = list.end(i);
            for (std::uint32_t k = list.begin(i); k < row_end; ++k) {
                const std::uint32_t j = list.partner(k), s = slot_of(list, k);
                prefetch_partners<SelfBlocks>(list, p, block, k, row_end);
                const Vec3 d = box_.minimum_image(xi, p.position[j]);
                const double dist2 = norm2(d);
                PairState& state = nl_.state(s);
                if (dist2 >= nl_.reach2(s)) { // beyond every law's range: nothing is kept
                    if (PairLaws::keeps(state)) state = PairState{};
                    continue;
                }
                const double rj = p.radius[j];
                const PairGeometry g =
                    make_pair_geometry(d, std::sqrt(dist2), ri, rj, p.mass[i], p.mass[j],
                                       p.velocity[i], p.velocity[j], p.omega[i], p.omega[j]);
                if (g.gap < 0.0) {
                    contacts += i < owned_rows;
                    max_overlap = std::max(max_overlap, -g.gap / std::min(ri, rj));
                }
                const bool local = j - lo < hi - lo; // j in [lo, hi)
                if (!local) remote(j);
                Vec3& fj = local ? force[j] : own.force[j];
                Vec3& tj = local ? torque[j] : own.torque[j];
                PairForce f;
                if constexpr (SelfBlocks) {
                    PairResistance r;
                    const PairParams& pp = row[p.species[j]];
                    f = settings_.implicit_stiffness ? stiff_interaction(g, pp, state, dt, r)
                                                     : pair_interaction(g, pp, state, dt, &r);
                    if (r.normal > 0.0 || r.sliding > 0.0 || r.rolling > 0.0) {
                        add_self_block(di, r, g.n, r.lever_i, 1.0);
                        add_self_block(local ? block[j] : own.block[j], r, g.n, r.lever_j, -1.0);
                    }
                } else {
                    f = pair_interaction(g, row[p.species[j]], state, dt);
                }
                fi += f.force_i;
                ti += f.torque_i;
                fj -= f.force_i;
                tj += f.torque_j;
            }
            force[i] += fi;
            torque[i] += ti;
            if constexpr (SelfBlocks) block[i] += di;
        }
        if (threads > 1) {
#pragma omp barrier
            add_cross_range<SelfBlocks>(t, lo, hi);
#pragma omp barrier
            own.touched.clear();
        }
    }
    contacts_out = contacts;
    max_overlap_out = max_overlap;
}

void Simulation::body_forces(std::size_t i, std::size_t& wall_contacts, double& wall_overlap) {
    ParticleStore& p = p_;
    BodyResistance* resistance = nullptr;
    if (semi_implicit()) {
        body_resistance_[i] = BodyResistance{};
        resistance = &body_resistance_[i];
    }
    const BodyGeometry g = body_geometry(i, p.velocity[i], p.omega[i], 0.0);
    const BodyForce b =
        BodyLaws::force(g, ff_.body_params(p.species[i]), body_state_[i], settings_.dt, resistance);
    p.force[i] = b.force;
    p.torque[i] = b.torque;
    if (resistance && settings_.implicit_stiffness)
        add_self_stiffness(*resistance,
                           BodyLaws::tangent(g, ff_.body_params(p.species[i]), body_state_[i]),
                           settings_.dt);
    if (substrate_on_ && p.position[i].z < p.radius[i]) {
        ++wall_contacts;
        wall_overlap = std::max(wall_overlap, 1.0 - p.position[i].z / p.radius[i]);
    }
}

void Simulation::step() {
    if (quasi_static()) return step_quasi_static();
    const std::size_t n = owned();
    const double dt = settings_.dt, half = 0.5 * dt;
    const bool semi = semi_implicit();
    ParticleStore& p = p_;
    const auto& x_build = nl_.positions_at_build();
    // Displacements since the near list's build (near_list.hpp), when it has one.
    const Vec3* x_near = near_.valid() && near_.positions_at_build().size() == p.size()
                             ? near_.positions_at_build().data()
                             : nullptr;
    double t_start = omp_get_wtime();
    double max_disp2 = 0.0, max_near2 = 0.0, wall_overlap = 0.0;
    std::size_t wall_contacts = 0;
    // Step 3 (level part): the liquid level at the new time, needed by the particle forces.
    if (level_at_) liquid_level_ = level_at_(time_ + dt);
        // M-9.1 steps 1-2: half kick, drift, wrap; track the largest displacement since the build.
        // The particle forces (substrate, drag, weight, capillary) need only this particle's new
        // state, so they are computed in the same pass (step 4, first half).
#pragma omp parallel for schedule(static) num_threads(threads_) reduction(max : max_disp2, max_near2, wall_overlap) reduction(+ : wall_contacts)
    for (std::size_t i = 0; i < n; ++i) {
        if (semi) {
            p.velocity[i] += half * accel_[i];
            p.omega[i] += half * alpha_[i];
        } else {
            p.velocity[i] += (half * p.inv_mass[i]) * p.force[i];
            p.omega[i] += (half * p.inv_inertia[i]) * p.torque[i];
        }
        p.position[i] += dt * p.velocity[i];
        box_.wrap(p.position[i]);
        max_disp2 = std::max(max_disp2, norm2(box_.minimum_image(x_build[i], p.position[i])));
        if (x_near)
            max_near2 = std::max(max_near2, norm2(box_.minimum_image(x_near[i], p.position[i])));
        body_forces(i, wall_contacts, wall_overlap);
    }
    time_ += dt;
    ++step_;
    // Step 3: neighbor list check (a rebuild may re-sort the particles, forces included). Under a
    // decomposition every rank rebuilds when one must; otherwise the ghosts follow their owners.
    if (halo_) {
        max_disp2 = halo_->all_max(max_disp2);
        max_near2 = halo_->all_max(max_near2);
    }
    if (!std::isfinite(max_disp2)) non_finite_ = true;
    if (non_finite_) check_health();
    if (nl_.needs_rebuild(max_disp2)) force_rebuild_ = true;
    if (x_near) near_.moved(max_near2, step_);
    if (halo_) {
        clear_ghost_forces();
        if (!force_rebuild_) halo_->update_ghosts(p_);
    }
    times_.integrate += omp_get_wtime() - t_start;
    // Step 4: pair forces at the new positions with the half-step velocities.
    pair_forces(wall_contacts, wall_overlap);
    t_start = omp_get_wtime();
    // Step 5: second half kick; layer top for the end criterion (M-8.2). A rebuild may have
    // traded particles between ranks: the owned count is the present one.
    double top = -INFINITY;
    bool finite = true;
    const std::size_t n_now = owned();
#pragma omp parallel for schedule(static) num_threads(threads_) reduction(max : top) reduction(&& : finite)
    for (std::size_t i = 0; i < n_now; ++i) {
        if (semi) {
            implicit_acceleration(i);
            p.velocity[i] += half * accel_[i];
            p.omega[i] += half * alpha_[i];
        } else {
            p.velocity[i] += (half * p.inv_mass[i]) * p.force[i];
            p.omega[i] += (half * p.inv_inertia[i]) * p.torque[i];
        }
        top = std::max(top, p.position[i].z + p.radius[i]);
        finite = finite && is_finite(p.velocity[i]) && is_finite(p.omega[i]);
    }
    if (halo_) {
        top = halo_->all_max(top);
        finite = halo_->all_max(finite ? 0.0 : 1.0) == 0.0;
    }
    stats_.layer_top = top;
    non_finite_ = !finite;
    times_.integrate += omp_get_wtime() - t_start;
    if (non_finite_ || stats_.max_overlap_rel > settings_.overlap_limit) check_health();
}

void Simulation::check_health() {
    std::string blow_up = non_finite_report();
    if (halo_) blow_up = halo_->first_message(blow_up);
    if (!blow_up.empty()) throw RunError(blow_up, "blow_up");
    if (stats_.max_overlap_rel <= settings_.overlap_limit) return;
    auto [worst, report] = worst_overlap_report();
    if (halo_) report = halo_->message_of_max(worst, report);
    throw RunError(report, "runaway_overlap");
}

std::string Simulation::non_finite_report() const {
    const ParticleStore& p = p_;
    for (std::size_t i = 0; i < owned(); ++i) {
        if (!is_finite(p.position[i]) || !is_finite(p.velocity[i]) || !is_finite(p.omega[i]) ||
            !is_finite(p.force[i]))
            return fmt::format("blow-up at step {} (t = {:.6g} s): particle {} (species "
                               "{}, r = {:.4g} um) has a "
                               "non-finite state: position ({:.4g}, {:.4g}, {:.4g}) um, "
                               "velocity ({:.4g}, {:.4g}, "
                               "{:.4g}) m/s, force ({:.4g}, {:.4g}, {:.4g}) N. Likely "
                               "cause: time step {:.3g} s "
                               "too large for the stiffest force (see `drydem check`)",
                               step_, time_, p.id[i], int(p.species[i]), p.radius[i] * 1e6,
                               p.position[i].x * 1e6, p.position[i].y * 1e6, p.position[i].z * 1e6,
                               p.velocity[i].x, p.velocity[i].y, p.velocity[i].z, p.force[i].x,
                               p.force[i].y, p.force[i].z, settings_.dt);
    }
    return {};
}

// Runaway overlap: the worst pair (or wall contact) of this rank's list, named, with a steady
// load told from a blow-up by how fast it is closing.
std::pair<double, std::string> Simulation::worst_overlap_report() const {
    const ParticleStore& p = p_;
    double worst = 0.0, closing = 0.0, r_min = 0.0;
    std::string what;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (substrate_on_ && i < owned() && p.position[i].z < p.radius[i]) {
            const double rel = 1.0 - p.position[i].z / p.radius[i];
            if (rel > worst) {
                worst = rel;
                closing = -p.velocity[i].z;
                r_min = p.radius[i];
                what = fmt::format("particle {} (r = {:.4g} um) with the substrate", p.id[i],
                                   p.radius[i] * 1e6);
            }
        }
        for (std::uint32_t s = nl_.begin(i); s < nl_.end(i); ++s) {
            const std::uint32_t j = nl_.partner(s);
            const Vec3 d = box_.minimum_image(p.position[i], p.position[j]);
            const double dist = norm(d);
            const double rel =
                -(dist - p.radius[i] - p.radius[j]) / std::min(p.radius[i], p.radius[j]);
            if (rel > worst) {
                worst = rel;
                closing = dot(p.velocity[i] - p.velocity[j], d) / dist; // normal relative speed
                r_min = std::min(p.radius[i], p.radius[j]);
                what = fmt::format("particles {} (r = {:.4g} um) and {} (r = {:.4g} um)", p.id[i],
                                   p.radius[i] * 1e6, p.id[j], p.radius[j] * 1e6);
            }
        }
    }
    if (what.empty()) return {0.0, {}};
    return {worst, fmt::format("runaway overlap at step {} (t = {:.6g} s): {} overlap by {:.3g} "
                               "of the smaller radius (limit {:.3g}). {}",
                               step_, time_, what, worst, settings_.overlap_limit,
                               overlap_cause(closing * settings_.dt / r_min))};
}

std::string Simulation::overlap_cause(double closing_per_step) {
    // A blow-up moves a pair by a sizeable part of a radius per step (closing or bouncing back); a
    // pair pressed by a steady load creeps, its overlap growing over thousands of steps (docs/
    // model.md C-9, departure 4; a 40 um film at friction 0.3 crept 0.005 % per step). The
    // boundary, 0.1 % of the smaller radius per step, lies far from both.
    const double per_step =
        100.0 * std::abs(closing_per_step); // % of the smaller radius, either way
    if (per_step < 0.1)
        return fmt::format("The pair moves by only {:.2g} % of the smaller radius per step: a "
                           "steady load presses it, "
                           "not an instability. The scaled capillary and van der Waals forces "
                           "(scaling.capillary_factor, "
                           "scaling.hamaker_factor) exceed what the contact stiffness holds at "
                           "this overlap (docs/model.md "
                           "C-9); raise numerics.overlap_limit (up to 2) to let the run finish, or "
                           "stiffen the contact "
                           "(materials.cb_youngs_modulus)",
                           per_step);
    return fmt::format(
        "The pair moves by {:.2g} % of the smaller radius per step: the contact could not stop "
        "it. Likely causes: a time step too large for the stiffest force (see `drydem check`), "
        "or attractive or capillary forces too strong for the contact stiffness",
        per_step);
}

double Simulation::kinetic_energy() const {
    double e = 0.0;
    for (std::size_t i = 0; i < owned(); ++i)
        e +=
            0.5 * p_.mass[i] * norm2(p_.velocity[i]) + 0.5 / p_.inv_inertia[i] * norm2(p_.omega[i]);
    return halo_ ? halo_->all_sum(e) : e;
}

Vec3 Simulation::momentum() const {
    Vec3 m{};
    for (std::size_t i = 0; i < owned(); ++i) m += p_.mass[i] * p_.velocity[i];
    if (halo_) m = {halo_->all_sum(m.x), halo_->all_sum(m.y), halo_->all_sum(m.z)};
    return m;
}

} // namespace drydem

namespace drydem {} // namespace drydem
