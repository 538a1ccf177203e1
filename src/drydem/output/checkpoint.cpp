// SPDX-License-Identifier: MIT
#include "drydem/output/checkpoint.hpp"
#include "drydem/core/error.hpp"
#include "drydem/forces/force_field.hpp"
#include "drydem/io/particle_io.hpp"
#include <fmt/format.h>
#include <fstream>
#include <iterator>

namespace drydem {
namespace {

constexpr char kMagic[8] = {'D', 'R', 'Y', 'D', 'E', 'M', 'C', 'K'};
// Format 3: the drying run's progress is a versioned list of named fields (drying/run_state.hpp),
// no longer the raw bytes of a struct. Format 4: the neighbour list holds the pair laws' state
// (PairState), preceded by the list's layout (law names and state sizes). Format 5: the body
// laws' states (BodyState) in place of the substrate's spring, and the layout of both lists.
constexpr std::uint32_t kFormatVersion = 5;

std::uint64_t fnv1a(const unsigned char* data, std::size_t n) {
    std::uint64_t h = 14695981039346656037ull;
    for (std::size_t i = 0; i < n; ++i) h = (h ^ data[i]) * 1099511628211ull;
    return h;
}

} // namespace

std::string law_layout_text() {
    return "pair " + std::string(PairLaws::layout()) + " body " + std::string(BodyLaws::layout());
}

void BinaryReader::truncated() const {
    throw InputError(fmt::format("{}: the checkpoint data end early (damaged file?)", source_));
}

namespace {
/// Every field of the engine state, in file order: one list for writing and reading, so the two
/// cannot drift apart.
template <class State, class F> // State: EngineState or const EngineState
void each_field(State& s, F&& field) {
    auto& p = s.particles;
    field(p.id), field(p.species), field(p.radius), field(p.density), field(p.mass);
    field(p.inv_mass), field(p.inv_inertia), field(p.position), field(p.velocity), field(p.omega);
    field(p.force), field(p.torque), field(s.body_state);
    auto& nl = s.neighbors;
    field(nl.builds), field(nl.offset), field(nl.partner), field(nl.reach2), field(nl.pair_state);
    field(nl.x_build);
    field(s.step), field(s.time), field(s.liquid_level), field(s.dt);
    field(s.stats.contacts), field(s.stats.wall_contacts), field(s.stats.max_overlap_rel);
    field(s.stats.layer_top), field(s.force_rebuild), field(s.rebuilds_since_sort);
    field(s.accel), field(s.alpha); // format 2: the semi-implicit kick's accelerations
}
template <class T>
struct is_vector : std::false_type {};
template <class T>
struct is_vector<std::vector<T>> : std::true_type {};
} // namespace

void write_engine_state(BinaryWriter& w, const EngineState& s) {
    const std::string layout = law_layout_text();
    w.vec(std::vector<char>(layout.begin(), layout.end()));
    each_field(s, [&](const auto& v) {
        if constexpr (is_vector<std::remove_cvref_t<decltype(v)>>::value)
            w.vec(v);
        else
            w.pod(v);
    });
}

EngineState read_engine_state(BinaryReader& r) {
    const std::vector<char> layout = r.vec<char>();
    if (std::string_view(layout.data(), layout.size()) != law_layout_text())
        throw InputError(fmt::format("checkpoint: written with the laws '{}', this build has '{}'; "
                                     "it cannot be continued by this build",
                                     std::string(layout.begin(), layout.end()), law_layout_text()));
    EngineState s;
    each_field(s, [&](auto& v) {
        using T = std::remove_cvref_t<decltype(v)>;
        if constexpr (is_vector<T>::value)
            v = r.vec<typename T::value_type>();
        else
            v = r.pod<T>();
    });
    const ParticleStore& p = s.particles;
    // Consistency: every per-particle array has one entry per particle, the list fits them.
    const std::size_t n = p.id.size();
    for (std::size_t m :
         {p.species.size(), p.radius.size(), p.density.size(), p.mass.size(), p.inv_mass.size(),
          p.inv_inertia.size(), p.position.size(), p.velocity.size(), p.omega.size(),
          p.force.size(), p.torque.size(), s.body_state.size()})
        if (m != n) throw InputError("checkpoint: particle arrays of different lengths");
    const auto& nl = s.neighbors;
    const bool list_ok =
        nl.offset.empty() ? nl.partner.empty()
                          : nl.offset.size() == n + 1 && nl.offset.back() == nl.partner.size() &&
                                nl.reach2.size() == nl.partner.size() &&
                                nl.pair_state.size() == nl.partner.size() && nl.x_build.size() == n;
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
    std::vector<unsigned char> all((std::istreambuf_iterator<char>(in)),
                                   std::istreambuf_iterator<char>());
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
        throw InputError(
            fmt::format("{}: checkpoint damaged (size or checksum mismatch)", file.string()));
    return {all.begin() + std::ptrdiff_t(head), all.begin() + std::ptrdiff_t(head + size)};
}

} // namespace drydem
