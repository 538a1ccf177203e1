// SPDX-License-Identifier: MIT
// What one rank holds of the film and how it trades with its neighbours (docs/parallel.md).
//
// A rank's ParticleStore holds its owned particles first, [0, owned()), then ghosts: copies of
// the neighbouring ranks' particles within reach of its subdomain. Positions stay in the global
// cell's wrapped coordinates, so the engine's minimum image finds every pair across a subdomain
// face, the periodic ones included, with one copy per ghost.
//
// Three exchanges, all with the (up to 26) neighbouring ranks only:
//   migrate        at a neighbour-list rebuild: an owned particle whose centre left the subdomain
//                  goes to its new owner with everything the engine keeps for it;
//   make_ghosts    after migrate: the ghost copies, and the lists that update_ghosts reuses;
//   update_ghosts  every step: the ghosts' position, velocity and angular velocity.
// Between rebuilds no particle moves more than half the skin, so ghosts chosen with the skin in
// their reach cover every pair the neighbour list holds.
#pragma once
#include "drydem/core/error.hpp"
#include "drydem/core/particles.hpp"
#include "drydem/parallel/decomposition.hpp"
#include <mpi.h>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace drydem::parallel {

/// Communication counters since construction (docs/parallel.md "Scaling model").
struct HaloCounters {
    std::uint64_t messages = 0;  ///< point-to-point messages sent (sizes and payloads)
    std::uint64_t bytes = 0;     ///< payload bytes sent
    double seconds = 0.0;        ///< wall time spent in exchanges, waiting included
    std::uint64_t migrated = 0;  ///< particles sent to a new owner
    std::uint64_t exchanges = 0; ///< exchange rounds (every step's ghost update is one)
};

/// Everything ParticleStore keeps of one particle, as it travels between ranks.
struct ParticleRecord {
    std::uint32_t id;
    std::uint8_t species;
    double radius, density, mass, inv_mass, inv_inertia;
    Vec3 position, velocity, omega, force, torque;
};
static_assert(std::is_trivially_copyable_v<ParticleRecord>);
[[nodiscard]] ParticleRecord record_of(const ParticleStore& p, std::size_t i);
void append_record(ParticleStore& p, const ParticleRecord& r);

class Halo {
public:
    /// comm's size must equal d.ranks() (InputError otherwise).
    Halo(Decomposition d, MPI_Comm comm);

    [[nodiscard]] const Decomposition& decomposition() const { return d_; }
    [[nodiscard]] int rank() const { return rank_; }
    [[nodiscard]] const std::vector<int>& neighbors() const { return neighbours_; }
    [[nodiscard]] std::size_t owned() const { return owned_; }
    [[nodiscard]] const HaloCounters& counters() const { return counters_; }

    /// From a store that every rank holds whole (the same particles on each, e.g. the seeded
    /// insertion): keeps the particles this rank owns, in their order, and each `extra` array's
    /// elements with them.
    template <class... T>
    void keep_owned(ParticleStore& p, std::vector<T>&... extra);

    /// Moves the cuts of the decomposition so that every rank gets an equal share of the work
    /// (parallel::balanced_cuts), before a migration (call with the ghosts dropped or not: only
    /// the owned particles count). A particle's modelled work is its pairs in the neighbour list
    /// (`pairs[i]` for owned particle i) plus the film's mean pairs per particle (its own
    /// integration); `busy_seconds`, this rank's measured time of work since the last call (0:
    /// none yet), turns it into time, rank by rank. A cut moves at most a quarter of the
    /// narrowest subdomain, and none gets narrower than `min_width`. A collective.
    void rebalance(const ParticleStore& p, const std::vector<double>& pairs, double min_width,
                   double busy_seconds);

    /// Drops the ghosts, sends each owned particle whose centre left this subdomain to its owner
    /// with its element of every `extra` array (one per owned particle, trivially copyable), and
    /// appends the ones that arrive (by sending rank, then in the sender's order). The particles
    /// that stay keep their order. RunError when a particle's new owner is not a neighbour (it
    /// moved more than a subdomain between two rebuilds).
    template <class... T>
    void migrate(ParticleStore& p, std::vector<T>&... extra);

    /// Appends, as ghosts, copies of the neighbours' particles within their reach of this
    /// subdomain: reach[i] for owned particle i is the distance out to which a particle of
    /// another rank can interact with it, skin included. The ghosts arrive by sending rank, in
    /// the sender's order. Call after migrate (the store must hold owned particles only).
    void make_ghosts(ParticleStore& p, const std::vector<double>& reach);

    /// Copies each ghost's position, velocity and angular velocity from its owner.
    void update_ghosts(ParticleStore& p);

    /// Copies each ghost's element of a per-particle array (owned and ghosts, store order) from
    /// its owner: what a matrix-vector product over the pairs needs of the ghosts.
    template <class T>
    void update_ghost_values(std::vector<T>& v);

    /// The same for a flat array of `per_particle` doubles per particle (a state vector).
    void update_ghost_values(std::vector<double>& v, std::size_t per_particle);

    /// Removes the ghosts (the store then holds the owned particles only).
    void drop_ghosts(ParticleStore& p) const;

    /// Sends items[k] to neighbors()[k] and returns what each neighbour sent here (same order):
    /// for variable-length data that travels with migrating particles (their pair states).
    template <class T>
    std::vector<std::vector<T>> exchange_items(const std::vector<std::vector<T>>& items);

    /// Every rank's owned particles, on every rank, ordered by id: what the outputs, the
    /// analysis and a checkpoint read of a decomposed film.
    [[nodiscard]] ParticleStore gather(const ParticleStore& p) const;
    /// Every rank's `mine`, on every rank, concatenated in rank order (trivially copyable items).
    template <class T>
    [[nodiscard]] std::vector<T> gather_items(const std::vector<T>& mine) const;

    // Reductions over all ranks of the decomposition (every rank gets the result).
    [[nodiscard]] double all_max(double v) const;
    [[nodiscard]] double all_sum(double v) const;
    [[nodiscard]] std::uint64_t all_sum(std::uint64_t v) const;
    /// The message of the lowest rank whose `local` is not empty, on every rank ("" when none):
    /// a diagnosis found on one rank stops all of them with the same words.
    [[nodiscard]] std::string first_message(const std::string& local) const;
    /// The id of the particle where `value` is largest over all ranks (ties: lowest rank).
    [[nodiscard]] std::uint32_t id_of_max(double value, std::uint32_t id) const;
    /// The message of the rank whose `value` is largest (ties: lowest rank), on every rank.
    [[nodiscard]] std::string message_of_max(double value, const std::string& local) const;

private:
    using Bytes = std::vector<std::byte>;
    /// Sends send[k] to neighbors()[k] and returns what each neighbour sent here, same order;
    /// `expected` (bytes per neighbour) when both sides know the sizes, else they are traded.
    std::vector<Bytes> exchange(const std::vector<Bytes>& send,
                                const std::vector<std::size_t>* expected = nullptr);
    /// The same where both sides know the sizes: into `got`, sized by the caller (kept buffers).
    void exchange_sized(const std::vector<Bytes>& send, std::vector<Bytes>& got);
    /// Every rank's bytes, on every rank, in rank order.
    [[nodiscard]] Bytes gather_bytes(const std::byte* mine, std::size_t size) const;
    /// The index of `rank` in neighbors(), or -1.
    [[nodiscard]] int slot_of(int rank) const;
    [[noreturn]] void throw_not_neighbour(const ParticleStore& p, std::size_t i, int owner) const;

    template <class T>
    static void put(Bytes& b, const T& v) {
        const std::size_t at = b.size();
        b.resize(at + sizeof(T));
        std::memcpy(b.data() + at, &v, sizeof(T));
    }
    template <class T>
    static T take(const Bytes& b, std::size_t& at) {
        T v;
        std::memcpy(&v, b.data() + at, sizeof(T));
        at += sizeof(T);
        return v;
    }
    template <class T>
    static void keep_rows(std::vector<T>& v, const std::vector<std::uint32_t>& rows) {
        std::vector<T> kept;
        kept.reserve(rows.size());
        for (auto r : rows) kept.push_back(v[r]);
        v.swap(kept);
    }
    template <class... T>
    void check_extra_sizes(const ParticleStore& p, const std::vector<T>&... extra) const {
        if (((extra.size() != p.size()) || ...))
            throw RunError("parallel::Halo: a per-particle array does not match the particles");
    }

    Decomposition d_;
    MPI_Comm comm_;
    int rank_ = 0;
    std::vector<int> neighbours_;
    std::size_t owned_ = 0;
    /// Per neighbour: the owned particles it holds as ghosts (indices), and where the ghosts it
    /// sent here start in the store and how many there are.
    std::vector<std::vector<std::uint32_t>> ghost_send_;
    std::vector<std::size_t> ghost_begin_, ghost_count_;
    std::vector<Bytes> motion_out_, motion_in_; ///< update_ghosts' buffers, kept between steps
    std::vector<Bytes> values_out_, values_in_; ///< the same for update_ghost_values (doubles)
    HaloCounters counters_;
};

template <class T>
void Halo::update_ghost_values(std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    std::vector<Bytes> send(neighbours_.size());
    std::vector<std::size_t> expected(neighbours_.size());
    for (std::size_t k = 0; k < neighbours_.size(); ++k) {
        send[k].reserve(ghost_send_[k].size() * sizeof(T));
        for (std::uint32_t i : ghost_send_[k]) put(send[k], v[i]);
        expected[k] = ghost_count_[k] * sizeof(T);
    }
    const std::vector<Bytes> got = exchange(send, &expected);
    for (std::size_t k = 0; k < got.size(); ++k) {
        std::size_t at = 0;
        for (std::size_t g = ghost_begin_[k]; g < ghost_begin_[k] + ghost_count_[k]; ++g)
            v[g] = take<T>(got[k], at);
    }
}

template <class T>
std::vector<std::vector<T>> Halo::exchange_items(const std::vector<std::vector<T>>& items) {
    static_assert(std::is_trivially_copyable_v<T>);
    std::vector<Bytes> send(neighbours_.size());
    for (std::size_t k = 0; k < neighbours_.size(); ++k) {
        send[k].resize(items[k].size() * sizeof(T));
        if (!items[k].empty()) std::memcpy(send[k].data(), items[k].data(), send[k].size());
    }
    const std::vector<Bytes> got = exchange(send);
    std::vector<std::vector<T>> out(got.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
        if (got[k].size() % sizeof(T) != 0)
            throw RunError("parallel::Halo: a message is not a whole number of items");
        out[k].resize(got[k].size() / sizeof(T));
        if (!got[k].empty()) std::memcpy(out[k].data(), got[k].data(), got[k].size());
    }
    return out;
}

template <class... T>
void Halo::keep_owned(ParticleStore& p, std::vector<T>&... extra) {
    static_assert((std::is_trivially_copyable_v<T> && ...));
    check_extra_sizes(p, extra...);
    std::vector<std::uint32_t> mine;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (d_.owner(p.position[i]) == rank_) mine.push_back(std::uint32_t(i));
    p.permute(mine);
    (keep_rows(extra, mine), ...);
    owned_ = p.size();
    ghost_send_.assign(neighbours_.size(), {});
    ghost_begin_.assign(neighbours_.size(), owned_);
    ghost_count_.assign(neighbours_.size(), 0);
}

template <class... T>
void Halo::migrate(ParticleStore& p, std::vector<T>&... extra) {
    static_assert((std::is_trivially_copyable_v<T> && ...));
    drop_ghosts(p);
    check_extra_sizes(p, extra...);
    std::vector<Bytes> send(neighbours_.size());
    std::vector<std::uint32_t> stay;
    stay.reserve(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        const int owner = d_.owner(p.position[i]);
        if (owner == rank_) {
            stay.push_back(std::uint32_t(i));
            continue;
        }
        const int k = slot_of(owner);
        if (k < 0) throw_not_neighbour(p, i, owner);
        put(send[k], record_of(p, i));
        (put(send[k], extra[i]), ...);
        ++counters_.migrated;
    }
    p.permute(stay);
    (keep_rows(extra, stay), ...);
    const std::vector<Bytes> got = exchange(send);
    constexpr std::size_t size = sizeof(ParticleRecord) + (sizeof(T) + ... + 0);
    for (const Bytes& b : got) {
        if (b.size() % size != 0)
            throw RunError("parallel::Halo: a migration message is not a whole number of "
                           "particles (the ranks run different builds?)");
        for (std::size_t at = 0; at < b.size();) {
            append_record(p, take<ParticleRecord>(b, at));
            (extra.push_back(take<T>(b, at)), ...);
        }
    }
    owned_ = p.size();
    ghost_send_.assign(neighbours_.size(), {});
    ghost_begin_.assign(neighbours_.size(), owned_);
    ghost_count_.assign(neighbours_.size(), 0);
}

template <class T>
std::vector<T> Halo::gather_items(const std::vector<T>& mine) const {
    static_assert(std::is_trivially_copyable_v<T>);
    const Bytes all =
        gather_bytes(reinterpret_cast<const std::byte*>(mine.data()), mine.size() * sizeof(T));
    std::vector<T> out(all.size() / sizeof(T));
    if (!out.empty()) std::memcpy(out.data(), all.data(), out.size() * sizeof(T));
    return out;
}

} // namespace drydem::parallel
