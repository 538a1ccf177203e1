// SPDX-License-Identifier: MIT
#include "drydem/parallel/halo.hpp"
#include "drydem/parallel/mpi_world.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <climits>
#include <cmath>

namespace drydem::parallel {

namespace {
constexpr int kSizeTag = 7101, kDataTag = 7102;

/// What update_ghosts sends per ghost: position, velocity, angular velocity.
struct Motion {
    Vec3 position, velocity, omega;
};
} // namespace

ParticleRecord record_of(const ParticleStore& p, std::size_t i) {
    return {p.id[i],          p.species[i],  p.radius[i],   p.density[i], p.mass[i],  p.inv_mass[i],
            p.inv_inertia[i], p.position[i], p.velocity[i], p.omega[i],   p.force[i], p.torque[i]};
}

void append_record(ParticleStore& p, const ParticleRecord& r) {
    p.id.push_back(r.id);
    p.species.push_back(r.species);
    p.radius.push_back(r.radius);
    p.density.push_back(r.density);
    p.mass.push_back(r.mass);
    p.inv_mass.push_back(r.inv_mass);
    p.inv_inertia.push_back(r.inv_inertia);
    p.position.push_back(r.position);
    p.velocity.push_back(r.velocity);
    p.omega.push_back(r.omega);
    p.force.push_back(r.force);
    p.torque.push_back(r.torque);
}

Halo::Halo(Decomposition d, MPI_Comm comm) : d_(d), comm_(comm) {
    int size = 0;
    MPI_Comm_rank(comm_, &rank_);
    MPI_Comm_size(comm_, &size);
    if (size != d_.ranks())
        throw InputError(fmt::format("parallel::Halo: {} ranks run a decomposition into {} x {} "
                                     "x {} subdomains",
                                     size, d_.px, d_.py, d_.pz));
    if (d_.pz > 1 && d_.cut_z.size() != std::size_t(d_.pz) + 1)
        throw InputError(fmt::format("parallel::Halo: {} layers need {} cuts along z, not {}",
                                     d_.pz, d_.pz + 1, d_.cut_z.size()));
    neighbours_ = d_.neighbors(rank_);
}

int Halo::slot_of(int rank) const {
    const auto it = std::lower_bound(neighbours_.begin(), neighbours_.end(), rank);
    return (it != neighbours_.end() && *it == rank) ? int(it - neighbours_.begin()) : -1;
}

void Halo::throw_not_neighbour(const ParticleStore& p, std::size_t i, int owner) const {
    throw RunError(
        fmt::format(
            "particle {} at ({:.4g}, {:.4g}, {:.4g}) um moved from the subdomain of rank {} into "
            "that of rank {}, which is not a neighbour: it travelled more than a subdomain ({:.4g} "
            "x {:.4g} x {:.4g} um) between two neighbour-list rebuilds. Likely cause: a blow-up "
            "(see the time step)",
            p.id[i], p.position[i].x * 1e6, p.position[i].y * 1e6, p.position[i].z * 1e6, rank_,
            owner, d_.width_x() * 1e6, d_.width_y() * 1e6, d_.width_z() * 1e6),
        "blow_up");
}

void Halo::drop_ghosts(ParticleStore& p) const {
    if (p.size() == owned_) return;
    std::vector<std::uint32_t> owned(owned_);
    for (std::size_t i = 0; i < owned_; ++i) owned[i] = std::uint32_t(i);
    p.permute(owned);
}

void Halo::make_ghosts(ParticleStore& p, const std::vector<double>& reach) {
    if (p.size() != owned_ || reach.size() != owned_)
        throw RunError("parallel::Halo::make_ghosts: the store must hold the owned particles "
                       "only, with one reach each");
    std::vector<Bytes> send(neighbours_.size());
    ghost_send_.assign(neighbours_.size(), {});
    for (std::size_t i = 0; i < owned_; ++i) {
        const double r2 = reach[i] * reach[i];
        for (std::size_t k = 0; k < neighbours_.size(); ++k)
            if (d_.distance2(neighbours_[k], p.position[i]) < r2) {
                ghost_send_[k].push_back(std::uint32_t(i));
                put(send[k], record_of(p, i));
            }
    }
    const std::vector<Bytes> got = exchange(send);
    ghost_begin_.assign(neighbours_.size(), 0);
    ghost_count_.assign(neighbours_.size(), 0);
    for (std::size_t k = 0; k < got.size(); ++k) {
        if (got[k].size() % sizeof(ParticleRecord) != 0)
            throw RunError("parallel::Halo: a ghost message is not a whole number of particles");
        ghost_begin_[k] = p.size();
        ghost_count_[k] = got[k].size() / sizeof(ParticleRecord);
        for (std::size_t at = 0; at < got[k].size();) {
            ParticleRecord r = take<ParticleRecord>(got[k], at);
            r.force = r.torque = Vec3{}; // a ghost's forces are its owner's business
            append_record(p, r);
        }
    }
}

void Halo::rebalance(const ParticleStore& p, const std::vector<double>& pairs, double min_width,
                     double busy_seconds) {
    constexpr std::size_t kBins = 512;
    // The modelled work of this rank, to turn its measured time into a time per unit of work.
    double mean_local = 0.0;
    for (std::size_t i = 0; i < owned_; ++i) mean_local += pairs[i];
    const double shift = 0.25 * std::min({d_.width_x(), d_.width_y(), d_.width_z()});
    // Along z (open) the bins span the film, from the substrate to its highest centre.
    double top = 0.0;
    if (d_.pz > 1) {
        for (std::size_t i = 0; i < owned_; ++i) top = std::max(top, p.position[i].z);
        top = all_max(top);
    }
    auto balance = [&](int parts, double length, bool periodic, auto coordinate,
                       std::vector<double>& cuts) {
        if (parts < 2 || !(length >= parts * min_width)) return;
        // Two histograms in one reduction: pair incidences, then particle counts.
        std::vector<double> h(2 * kBins, 0.0), all(2 * kBins, 0.0);
        for (std::size_t i = 0; i < owned_; ++i) {
            double u = coordinate(p.position[i]);
            if (periodic) {
                u = std::fmod(u, length);
                if (u < 0.0) u += length;
            }
            const auto b =
                std::min(kBins - 1, std::size_t(std::max(0.0, u / length * double(kBins))));
            h[b] += pairs[i];
            h[kBins + b] += 1.0;
        }
        MPI_Allreduce(h.data(), all.data(), int(h.size()), MPI_DOUBLE, MPI_SUM, comm_);
        double incidences = 0.0, count = 0.0;
        for (std::size_t b = 0; b < kBins; ++b) incidences += all[b], count += all[kBins + b];
        const double mean = count > 0.0 ? incidences / count : 0.0;
        // Modelled work: pairs plus the mean pairs per particle. With a measured time, each rank
        // weighs its own particles' work by its seconds per unit of modelled work, so the cuts
        // balance time (the pair laws differ in cost, the root writes the outputs).
        const double modelled = mean_local + (mean + 1.0) * double(owned_);
        const double scale = busy_seconds > 0.0 && modelled > 0.0 ? busy_seconds / modelled : 0.0;
        std::vector<double> w(kBins, 0.0), total(kBins, 0.0);
        for (std::size_t b = 0; b < kBins; ++b) w[b] = h[b] + (mean + 1.0) * h[kBins + b];
        if (scale > 0.0)
            for (double& x : w) x *= scale;
        // Every rank weighs alike: all measured, or (the first rebalance) none.
        int measured = scale > 0.0 ? 1 : 0, everywhere = 0;
        MPI_Allreduce(&measured, &everywhere, 1, MPI_INT, MPI_MIN, comm_);
        if (!everywhere)
            for (std::size_t b = 0; b < kBins; ++b) w[b] = h[b] + (mean + 1.0) * h[kBins + b];
        MPI_Allreduce(w.data(), total.data(), int(kBins), MPI_DOUBLE, MPI_SUM, comm_);
        std::vector<double>& work = total;
        std::vector<double> now = cuts;
        if (now.empty())
            for (int k = 0; k <= parts; ++k) now.push_back(length * k / parts);
        // An open axis: the film's extent now, the inner cuts inside it.
        now.front() = 0.0;
        now.back() = length;
        for (int k = 1; k < parts; ++k)
            now[std::size_t(k)] = std::clamp(now[std::size_t(k)], 0.0, length);
        cuts = balanced_cuts(work, length, now, min_width, shift);
    };
    balance(
        d_.px, d_.box.lx, true, [](const Vec3& x) { return x.x; }, d_.cut_x);
    balance(
        d_.py, d_.box.ly, true, [](const Vec3& x) { return x.y; }, d_.cut_y);
    balance(
        d_.pz, top, false, [](const Vec3& x) { return x.z; }, d_.cut_z);
}

void Halo::update_ghosts(ParticleStore& p) {
    // Every step: the buffers are kept (sized at the rebuild), packed and unpacked with memcpy.
    const std::size_t n = neighbours_.size();
    motion_out_.resize(n);
    motion_in_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        motion_out_[k].resize(ghost_send_[k].size() * sizeof(Motion));
        motion_in_[k].resize(ghost_count_[k] * sizeof(Motion));
        std::byte* out = motion_out_[k].data();
        for (std::uint32_t i : ghost_send_[k]) {
            const Motion m{p.position[i], p.velocity[i], p.omega[i]};
            std::memcpy(out, &m, sizeof m);
            out += sizeof m;
        }
    }
    exchange_sized(motion_out_, motion_in_);
    for (std::size_t k = 0; k < n; ++k) {
        const std::byte* in = motion_in_[k].data();
        for (std::size_t g = ghost_begin_[k]; g < ghost_begin_[k] + ghost_count_[k]; ++g) {
            Motion m;
            std::memcpy(&m, in, sizeof m);
            in += sizeof m;
            p.position[g] = m.position;
            p.velocity[g] = m.velocity;
            p.omega[g] = m.omega;
        }
    }
}

void Halo::update_ghost_values(std::vector<double>& v, std::size_t per_particle) {
    // Every power iteration of the guard: the buffers are kept, as update_ghosts' are.
    const std::size_t row = per_particle * sizeof(double), n = neighbours_.size();
    values_out_.resize(n);
    values_in_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        values_out_[k].resize(ghost_send_[k].size() * row);
        values_in_[k].resize(ghost_count_[k] * row);
        std::byte* out = values_out_[k].data();
        for (std::uint32_t i : ghost_send_[k]) {
            std::memcpy(out, v.data() + std::size_t(i) * per_particle, row);
            out += row;
        }
    }
    exchange_sized(values_out_, values_in_);
    for (std::size_t k = 0; k < n; ++k)
        if (!values_in_[k].empty())
            std::memcpy(v.data() + ghost_begin_[k] * per_particle, values_in_[k].data(),
                        values_in_[k].size());
}

ParticleStore Halo::gather(const ParticleStore& p) const {
    std::vector<ParticleRecord> mine(owned_);
    for (std::size_t i = 0; i < owned_; ++i) mine[i] = record_of(p, i);
    std::vector<ParticleRecord> all = gather_items(mine);
    std::sort(all.begin(), all.end(),
              [](const ParticleRecord& a, const ParticleRecord& b) { return a.id < b.id; });
    ParticleStore out;
    for (const ParticleRecord& r : all) append_record(out, r);
    return out;
}

Halo::Bytes Halo::gather_bytes(const std::byte* mine, std::size_t size) const {
    if (size > std::size_t(INT_MAX))
        throw RunError("parallel::Halo: one rank's share exceeds one MPI message (2 GB)");
    const int bytes = int(size);
    std::vector<int> counts(std::size_t(d_.ranks())), offsets(std::size_t(d_.ranks()));
    MPI_Allgather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_);
    long total = 0;
    for (std::size_t r = 0; r < counts.size(); ++r) {
        offsets[r] = int(total);
        total += counts[r];
    }
    if (total > long(INT_MAX))
        throw RunError("parallel::Halo: the gathered film exceeds one MPI message (2 GB)");
    Bytes all(static_cast<std::size_t>(total));
    MPI_Allgatherv(mine, bytes, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE,
                   comm_);
    return all;
}

double Halo::all_max(double v) const {
    const double t0 = MPI_Wtime();
    double out = v;
    MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, MPI_MAX, comm_);
    add_waited(MPI_Wtime() - t0);
    return out;
}

double Halo::all_sum(double v) const {
    const double t0 = MPI_Wtime();
    double out = v;
    MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, MPI_SUM, comm_);
    add_waited(MPI_Wtime() - t0);
    return out;
}

std::uint64_t Halo::all_sum(std::uint64_t v) const {
    const double t0 = MPI_Wtime();
    std::uint64_t out = v;
    MPI_Allreduce(&v, &out, 1, MPI_UINT64_T, MPI_SUM, comm_);
    add_waited(MPI_Wtime() - t0);
    return out;
}

std::string Halo::first_message(const std::string& local) const {
    const int mine = local.empty() ? d_.ranks() : rank_;
    int first = mine;
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm_);
    if (first == d_.ranks()) return {};
    std::uint64_t length = local.size();
    MPI_Bcast(&length, 1, MPI_UINT64_T, first, comm_);
    std::string out = rank_ == first ? local : std::string(length, ' ');
    MPI_Bcast(out.data(), int(length), MPI_CHAR, first, comm_);
    return out;
}

namespace {
/// The rank with the largest value (MPI_MAXLOC: ties go to the lowest rank).
int rank_of_max(double value, int rank, MPI_Comm comm) {
    struct {
        double value;
        int rank;
    } mine{value, rank}, best{};
    MPI_Allreduce(&mine, &best, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm);
    return best.rank;
}
} // namespace

std::string Halo::message_of_max(double value, const std::string& local) const {
    const int from = rank_of_max(value, rank_, comm_);
    std::uint64_t length = local.size();
    MPI_Bcast(&length, 1, MPI_UINT64_T, from, comm_);
    std::string out = rank_ == from ? local : std::string(length, ' ');
    if (length > 0) MPI_Bcast(out.data(), int(length), MPI_CHAR, from, comm_);
    return out;
}

std::uint32_t Halo::id_of_max(double value, std::uint32_t id) const {
    std::uint32_t out = id;
    MPI_Bcast(&out, 1, MPI_UINT32_T, rank_of_max(value, rank_, comm_), comm_);
    return out;
}

void Halo::exchange_sized(const std::vector<Bytes>& send, std::vector<Bytes>& got) {
    const double t0 = MPI_Wtime();
    const std::size_t n = neighbours_.size();
    std::vector<MPI_Request> req;
    req.reserve(2 * n);
    for (std::size_t k = 0; k < n; ++k) {
        if (got[k].empty()) continue;
        req.emplace_back();
        MPI_Irecv(got[k].data(), int(got[k].size()), MPI_BYTE, neighbours_[k], kDataTag, comm_,
                  &req.back());
    }
    for (std::size_t k = 0; k < n; ++k) {
        if (send[k].empty()) continue;
        if (send[k].size() > std::size_t(INT_MAX))
            throw RunError(fmt::format("parallel::Halo: {} bytes for rank {} exceed one MPI "
                                       "message; use more ranks",
                                       send[k].size(), neighbours_[k]));
        req.emplace_back();
        MPI_Isend(send[k].data(), int(send[k].size()), MPI_BYTE, neighbours_[k], kDataTag, comm_,
                  &req.back());
        ++counters_.messages;
        counters_.bytes += send[k].size();
    }
    MPI_Waitall(int(req.size()), req.data(), MPI_STATUSES_IGNORE);
    ++counters_.exchanges;
    counters_.seconds += MPI_Wtime() - t0;
    add_waited(MPI_Wtime() - t0);
}

std::vector<Halo::Bytes> Halo::exchange(const std::vector<Bytes>& send,
                                        const std::vector<std::size_t>* expected) {
    const std::size_t n = neighbours_.size();
    std::vector<Bytes> got(n);
    if (expected) {
        // Sizes both sides know (the ghost update): no size round.
        for (std::size_t k = 0; k < n; ++k) got[k].resize((*expected)[k]);
    } else {
        const double t0 = MPI_Wtime();
        std::vector<std::uint64_t> out_size(n), in_size(n);
        std::vector<MPI_Request> req(2 * n);
        for (std::size_t k = 0; k < n; ++k) {
            out_size[k] = send[k].size();
            MPI_Irecv(&in_size[k], 1, MPI_UINT64_T, neighbours_[k], kSizeTag, comm_, &req[k]);
        }
        for (std::size_t k = 0; k < n; ++k)
            MPI_Isend(&out_size[k], 1, MPI_UINT64_T, neighbours_[k], kSizeTag, comm_, &req[n + k]);
        MPI_Waitall(int(req.size()), req.data(), MPI_STATUSES_IGNORE);
        counters_.messages += n;
        counters_.bytes += n * sizeof(std::uint64_t);
        counters_.seconds += MPI_Wtime() - t0;
        add_waited(MPI_Wtime() - t0);
        for (std::size_t k = 0; k < n; ++k) got[k].resize(in_size[k]);
    }
    exchange_sized(send, got);
    return got;
}

} // namespace drydem::parallel
