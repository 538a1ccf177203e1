// SPDX-License-Identifier: MIT
#include "drydem/io/snapshot_writers.hpp"
#include "drydem/core/error.hpp"
#include "drydem/io/particle_io.hpp"
#include <algorithm>
#include <charconv>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <iterator>
#include <numeric>
#include <optional>
#include <string_view>
#include <utility>

namespace drydem {

namespace {

namespace fs = std::filesystem;
using Out = std::back_insert_iterator<fmt::memory_buffer>;

std::string xml_escape(std::string_view s) {
    std::string out;
    for (const char c : s) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        case '\'':
            out += "&apos;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string xml_unescape(std::string_view s) {
    static constexpr std::pair<std::string_view, char> entities[]{
        {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
    std::string out;
    for (std::size_t i = 0; i < s.size();) {
        bool replaced = false;
        for (const auto& [e, c] : entities)
            if (s.substr(i).starts_with(e)) {
                out += c;
                i += e.size();
                replaced = true;
                break;
            }
        if (!replaced) out += s[i++];
    }
    return out;
}

/// Value of attribute `name="..."` in an XML tag, or nothing.
std::optional<std::string> attribute(std::string_view tag, std::string_view name) {
    const auto key = fmt::format(" {}=\"", name);
    const auto b = tag.find(key);
    if (b == std::string_view::npos) return std::nullopt;
    const auto v = b + key.size();
    const auto e = tag.find('"', v);
    if (e == std::string_view::npos) return std::nullopt;
    return xml_unescape(tag.substr(v, e - v));
}

// 9 significant digits: finer than any length in the model (1e-13 m at 100 um) and half the size
// of full precision; frames are for looking at, final.csv and checkpoints carry exact values.
// `put(out, i)` writes the components of tuple i.
template <class Put>
void vtp_array(Out out, std::string_view type, std::string_view name, int components, std::size_t n,
               Put put) {
    fmt::format_to(out,
                   "        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" "
                   "format=\"ascii\">\n",
                   type, name, components);
    for (std::size_t i = 0; i < n; ++i) {
        put(out, i);
        fmt::format_to(out, "\n");
    }
    fmt::format_to(out, "        </DataArray>\n");
}

auto scalar(const std::vector<double>& v, double scale = 1.0) {
    return [&v, scale](Out out, std::size_t i) { fmt::format_to(out, "{:.9g}", scale * v[i]); };
}
auto vec3s(const std::vector<Vec3>& v) {
    return [&v](Out out, std::size_t i) {
        fmt::format_to(out, "{:.9g} {:.9g} {:.9g}", v[i].x, v[i].y, v[i].z);
    };
}

} // namespace

void write_vtp(const fs::path& file, const ParticleStore& p, double sim_time, double process_time,
               std::span<const std::int32_t> coordination) {
    const std::size_t n = p.size();
    fmt::memory_buffer buf;
    const Out out(buf);
    fmt::format_to(out, "<?xml version=\"1.0\"?>\n"
                        "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
                        "header_type=\"UInt64\">\n"
                        "  <PolyData>\n"
                        "    <FieldData>\n");
    // TimeValue is the name ParaView looks for; process time is what the user compares with the
    // dryer, the scaled simulation time is kept next to it.
    using Field = std::pair<std::string_view, double>;
    for (const auto& [name, value] :
         {Field{"TimeValue", process_time}, Field{"process_time_s", process_time},
          Field{"sim_time_s", sim_time}})
        fmt::format_to(out,
                       "      <DataArray type=\"Float64\" Name=\"{}\" NumberOfTuples=\"1\" "
                       "format=\"ascii\">{}</DataArray>\n",
                       name, value);
    fmt::format_to(out,
                   "    </FieldData>\n"
                   "    <Piece NumberOfPoints=\"{0}\" NumberOfVerts=\"{0}\" "
                   "NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
                   "      <PointData Scalars=\"radius\" Vectors=\"velocity\">\n",
                   n);
    vtp_array(out, "UInt32", "id", 1, n, [&](Out o, auto i) { fmt::format_to(o, "{}", p.id[i]); });
    vtp_array(out, "Int32", "type", 1, n,
              [&](Out o, auto i) { fmt::format_to(o, "{}", int(p.species[i]) + 1); });
    vtp_array(out, "Float64", "radius", 1, n, scalar(p.radius));
    vtp_array(out, "Float64", "diameter", 1, n, scalar(p.radius, 2.0));
    vtp_array(out, "Float64", "velocity", 3, n, vec3s(p.velocity));
    vtp_array(out, "Float64", "omega", 3, n, vec3s(p.omega));
    vtp_array(out, "Float64", "force", 3, n, vec3s(p.force));
    if (coordination.size() == n)
        vtp_array(out, "Int32", "coordination", 1, n,
                  [&](Out o, auto i) { fmt::format_to(o, "{}", coordination[i]); });
    fmt::format_to(out, "      </PointData>\n      <Points>\n");
    vtp_array(out, "Float64", "Points", 3, n, vec3s(p.position));
    fmt::format_to(out, "      </Points>\n      <Verts>\n");
    vtp_array(out, "Int64", "connectivity", 1, n,
              [](Out o, auto i) { fmt::format_to(o, "{}", i); });
    vtp_array(out, "Int64", "offsets", 1, n, [](Out o, auto i) { fmt::format_to(o, "{}", i + 1); });
    fmt::format_to(out, "      </Verts>\n    </Piece>\n  </PolyData>\n</VTKFile>\n");
    write_file_atomically(file, [&](std::ostream& os) {
        os.write(buf.data(), static_cast<std::streamsize>(buf.size()));
    });
}

void write_level_vtp(const fs::path& file, const Box& box, double level, double process_time) {
    fmt::memory_buffer buf;
    const Out out(buf);
    fmt::format_to(
        out,
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
        "header_type=\"UInt64\">\n"
        "  <PolyData>\n"
        "    <FieldData>\n"
        "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
        "format=\"ascii\">{0}</DataArray>\n"
        "      <DataArray type=\"Float64\" Name=\"liquid_level_um\" NumberOfTuples=\"1\" "
        "format=\"ascii\">{1}</DataArray>\n"
        "    </FieldData>\n"
        "    <Piece NumberOfPoints=\"4\" NumberOfVerts=\"0\" NumberOfLines=\"0\" "
        "NumberOfStrips=\"0\" NumberOfPolys=\"1\">\n"
        "      <Points>\n"
        "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" "
        "format=\"ascii\">0 0 {2:.9g} {3:.9g} 0 {2:.9g} {3:.9g} {4:.9g} {2:.9g} 0 {4:.9g} {2:.9g}"
        "</DataArray>\n"
        "      </Points>\n"
        "      <Polys>\n"
        "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3"
        "</DataArray>\n"
        "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4</DataArray>\n"
        "      </Polys>\n"
        "    </Piece>\n"
        "  </PolyData>\n"
        "</VTKFile>\n",
        process_time, level * 1e6, level, box.lx, box.ly);
    write_file_atomically(file, [&](std::ostream& os) {
        os.write(buf.data(), static_cast<std::streamsize>(buf.size()));
    });
}

void PvdWriter::add(double time, std::string relative_file) {
    entries_.push_back({time, std::move(relative_file)});
    write();
}

void PvdWriter::write() const {
    fmt::memory_buffer buf;
    const Out out(buf);
    fmt::format_to(out, "<?xml version=\"1.0\"?>\n"
                        "<VTKFile type=\"Collection\" version=\"0.1\" "
                        "byte_order=\"LittleEndian\">\n"
                        "  <Collection>\n");
    for (const auto& e : entries_)
        fmt::format_to(out, "    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n",
                       e.time, xml_escape(e.file));
    fmt::format_to(out, "  </Collection>\n</VTKFile>\n");
    write_file_atomically(file_, [&](std::ostream& os) {
        os.write(buf.data(), static_cast<std::streamsize>(buf.size()));
    });
}

std::size_t PvdWriter::load_existing() {
    entries_.clear();
    std::ifstream in(file_);
    if (!in) return 0;
    std::string line;
    while (std::getline(in, line)) {
        if (line.find("<DataSet") == std::string::npos) continue;
        const auto t = attribute(line, "timestep");
        const auto f = attribute(line, "file");
        double time = 0.0;
        if (!t || !f || std::from_chars(t->data(), t->data() + t->size(), time).ec != std::errc{})
            throw InputError(
                fmt::format("{}: cannot read the DataSet entry '{}'", file_.string(), line));
        entries_.push_back({time, *f});
    }
    return entries_.size();
}

void append_lammps_dump(std::ostream& os, const ParticleStore& p, const Box& box, std::int64_t step,
                        double z_top) {
    // Sorted by id so frames diff cleanly and tools that index by line see a stable order.
    std::vector<std::uint32_t> order(p.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return p.id[a] < p.id[b]; });
    fmt::memory_buffer buf;
    const Out out(buf);
    fmt::format_to(out,
                   "ITEM: TIMESTEP\n{}\nITEM: NUMBER OF ATOMS\n{}\nITEM: BOX BOUNDS pp pp fm\n"
                   "0 {:.10g}\n0 {:.10g}\n0 {:.10g}\nITEM: ATOMS id type x y z radius vx vy vz\n",
                   step, p.size(), box.lx, box.ly, z_top);
    for (const auto i : order) {
        const auto &x = p.position[i], &v = p.velocity[i];
        fmt::format_to(out, "{} {} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g}\n",
                       p.id[i], int(p.species[i]) + 1, x.x, x.y, x.z, p.radius[i], v.x, v.y, v.z);
    }
    os.write(buf.data(), static_cast<std::streamsize>(buf.size()));
    os.flush();
    if (!os) throw RunError(fmt::format("writing the LAMMPS dump frame of step {} failed", step));
}

CsvSeriesWriter::CsvSeriesWriter(const fs::path& file, std::vector<std::string> columns,
                                 bool append)
    : file_(file), columns_(std::move(columns)) {
    std::string header;
    for (const auto& c : columns_) header += (header.empty() ? "" : ",") + c;
    std::error_code ec;
    const bool continuing = append && fs::exists(file_, ec) && fs::file_size(file_, ec) > 0;
    if (continuing) {
        // A resumed run must not mix column layouts in one file.
        std::ifstream in(file_);
        std::string first;
        std::getline(in, first);
        if (first != header)
            throw RunError(fmt::format("{}: cannot append, its header '{}' differs from '{}'",
                                       file_.string(), first, header));
    }
    os_.open(file_, continuing ? std::ios::app : std::ios::trunc);
    if (!os_) throw RunError(fmt::format("cannot open {} for writing", file_.string()));
    if (!continuing) os_ << header << '\n' << std::flush;
    if (!os_) throw RunError(fmt::format("writing {} failed", file_.string()));
}

void CsvSeriesWriter::row(std::span<const double> values) {
    if (values.size() != columns_.size())
        throw RunError(fmt::format("{}: row with {} values for {} columns", file_.string(),
                                   values.size(), columns_.size()));
    fmt::memory_buffer buf;
    fmt::format_to(std::back_inserter(buf), "{:.10g}\n", fmt::join(values, ","));
    os_.write(buf.data(), static_cast<std::streamsize>(buf.size()));
    os_.flush();
    if (!os_) throw RunError(fmt::format("writing {} failed (disk full?)", file_.string()));
}

} // namespace drydem
