// SPDX-License-Identifier: MIT
#include "drydem/io/checkpoint.hpp"
#include "drydem/core/error.hpp"
#include "drydem/io/particle_io.hpp"
#include <fmt/format.h>
#include <fstream>
#include <iterator>

namespace drydem {
namespace {

constexpr char kMagic[8] = {'D', 'R', 'Y', 'D', 'E', 'M', 'C', 'K'};
constexpr std::uint32_t kFormatVersion = 1;

std::uint64_t fnv1a(const unsigned char* data, std::size_t n) {
    std::uint64_t h = 14695981039346656037ull;
    for (std::size_t i = 0; i < n; ++i) h = (h ^ data[i]) * 1099511628211ull;
    return h;
}

} // namespace

void BinaryReader::truncated() const {
    throw InputError(fmt::format("{}: the checkpoint data end early (damaged file?)", source_));
}

void write_engine_state(BinaryWriter& w, const EngineState& s) {
    const ParticleStore& p = s.particles;
    w.vec(p.id);
    w.vec(p.species);
    w.vec(p.radius);
    w.vec(p.density);
    w.vec(p.mass);
    w.vec(p.inv_mass);
    w.vec(p.inv_inertia);
    w.vec(p.position);
    w.vec(p.velocity);
    w.vec(p.omega);
    w.vec(p.force);
    w.vec(p.torque);
    w.vec(p.wall_history);
    w.pod(s.neighbors.builds);
    w.vec(s.neighbors.offset);
    w.vec(s.neighbors.partner);
    w.vec(s.neighbors.reach2);
    w.vec(s.neighbors.history);
    w.vec(s.neighbors.x_build);
    w.pod(s.step);
    w.pod(s.time);
    w.pod(s.liquid_level);
    w.pod(s.dt);
    w.pod(std::uint64_t(s.stats.contacts));
    w.pod(std::uint64_t(s.stats.wall_contacts));
    w.pod(s.stats.max_overlap_rel);
    w.pod(s.stats.layer_top);
    w.pod(std::uint8_t(s.force_rebuild));
    w.pod(s.rebuilds_since_sort);
}

EngineState read_engine_state(BinaryReader& r) {
    EngineState s;
    ParticleStore& p = s.particles;
    p.id = r.vec<std::uint32_t>();
    p.species = r.vec<std::uint8_t>();
    p.radius = r.vec<double>();
    p.density = r.vec<double>();
    p.mass = r.vec<double>();
    p.inv_mass = r.vec<double>();
    p.inv_inertia = r.vec<double>();
    p.position = r.vec<Vec3>();
    p.velocity = r.vec<Vec3>();
    p.omega = r.vec<Vec3>();
    p.force = r.vec<Vec3>();
    p.torque = r.vec<Vec3>();
    p.wall_history = r.vec<Vec3>();
    s.neighbors.builds = r.pod<std::uint64_t>();
    s.neighbors.offset = r.vec<std::uint32_t>();
    s.neighbors.partner = r.vec<std::uint32_t>();
    s.neighbors.reach2 = r.vec<double>();
    s.neighbors.history = r.vec<Vec3>();
    s.neighbors.x_build = r.vec<Vec3>();
    s.step = r.pod<std::int64_t>();
    s.time = r.pod<double>();
    s.liquid_level = r.pod<double>();
    s.dt = r.pod<double>();
    s.stats.contacts = std::size_t(r.pod<std::uint64_t>());
    s.stats.wall_contacts = std::size_t(r.pod<std::uint64_t>());
    s.stats.max_overlap_rel = r.pod<double>();
    s.stats.layer_top = r.pod<double>();
    s.force_rebuild = r.pod<std::uint8_t>() != 0;
    s.rebuilds_since_sort = r.pod<std::uint64_t>();
    // Consistency: every per-particle array has one entry per particle, the list fits them.
    const std::size_t n = p.id.size();
    for (std::size_t m : {p.species.size(), p.radius.size(), p.density.size(), p.mass.size(),
                          p.inv_mass.size(), p.inv_inertia.size(), p.position.size(),
                          p.velocity.size(), p.omega.size(), p.force.size(), p.torque.size(),
                          p.wall_history.size()})
        if (m != n) throw InputError("checkpoint: particle arrays of different lengths");
    const auto& nl = s.neighbors;
    const bool list_ok =
        nl.offset.empty() ? nl.partner.empty()
                          : nl.offset.size() == n + 1 && nl.offset.back() == nl.partner.size() &&
                                nl.reach2.size() == nl.partner.size() &&
                                nl.history.size() == nl.partner.size() && nl.x_build.size() == n;
    if (!list_ok) throw InputError("checkpoint: the neighbor list does not fit the particles");
    for (std::uint32_t j : nl.partner)
        if (j >= n) throw InputError("checkpoint: neighbor index out of range");
    return s;
}

void write_checkpoint_file(const std::filesystem::path& file, const BinaryWriter& payload) {
    const auto& b = payload.bytes();
    write_file_atomically(file, [&](std::ostream& os) {
        os.write(kMagic, sizeof kMagic);
        os.write(reinterpret_cast<const char*>(&kFormatVersion), sizeof kFormatVersion);
        os.write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
        const std::uint64_t size = b.size(), sum = fnv1a(b.data(), b.size());
        os.write(reinterpret_cast<const char*>(&size), sizeof size);
        os.write(reinterpret_cast<const char*>(&sum), sizeof sum);
    });
}

std::vector<unsigned char> read_checkpoint_file(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(fmt::format("no checkpoint at {}", file.string()));
    std::vector<unsigned char> all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    constexpr std::size_t head = sizeof kMagic + sizeof kFormatVersion, tail = 16;
    if (all.size() < head + tail || std::memcmp(all.data(), kMagic, sizeof kMagic) != 0)
        throw InputError(fmt::format("{} is not a DryDEM checkpoint", file.string()));
    std::uint32_t version;
    std::memcpy(&version, all.data() + sizeof kMagic, sizeof version);
    if (version != kFormatVersion)
        throw InputError(fmt::format("{}: checkpoint format {} (this build reads format {})",
                                     file.string(), version, kFormatVersion));
    std::uint64_t size, sum;
    std::memcpy(&size, all.data() + all.size() - tail, 8);
    std::memcpy(&sum, all.data() + all.size() - 8, 8);
    if (size != all.size() - head - tail || fnv1a(all.data() + head, size) != sum)
        throw InputError(fmt::format("{}: checkpoint damaged (size or checksum mismatch)", file.string()));
    return {all.begin() + std::ptrdiff_t(head), all.begin() + std::ptrdiff_t(head + size)};
}

} // namespace drydem
