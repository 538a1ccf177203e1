// SPDX-License-Identifier: MIT
#include "drydem/core/sphere.hpp"
#include "drydem/io/particle_io.hpp"
#include "drydem/core/error.hpp"
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <cctype>

namespace drydem {

namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Reads lines, counting them for error messages and dropping the '\r' of Windows files.
class LineReader {
public:
    explicit LineReader(const fs::path& file) : file_(file), in_(file, std::ios::binary) {
        if (!in_) throw InputError(fmt::format("{}: cannot open particle file", file.string()));
    }
    bool next(std::string& line) {
        if (!std::getline(in_, line)) return false;
        ++line_no_;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        return true;
    }
    [[noreturn]] void fail(std::string_view what) const { fail_at(line_no_, what); }
    [[noreturn]] void fail_at(std::size_t line, std::string_view what) const {
        throw InputError(fmt::format("{}:{}: {}", file_.string(), line, what));
    }
    [[nodiscard]] std::size_t line_no() const { return line_no_; }
    [[nodiscard]] std::streampos tell() { return in_.tellg(); }
    void seek(std::streampos pos, std::size_t line_no) {
        in_.clear();
        in_.seekg(pos);
        line_no_ = line_no;
    }

private:
    fs::path file_;
    std::ifstream in_;
    std::size_t line_no_ = 0;
};

std::string_view trim(std::string_view s) {
    const auto ws = " \t\r\n";
    const auto b = s.find_first_not_of(ws);
    if (b == std::string_view::npos) return {};
    return s.substr(b, s.find_last_not_of(ws) - b + 1);
}

/// Splits at blanks; a '#' starts a comment (LAMMPS data and dump files).
std::vector<std::string_view> words(std::string_view s) {
    s = s.substr(0, s.find('#'));
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (true) {
        i = s.find_first_not_of(" \t", i);
        if (i == std::string_view::npos) return out;
        const auto e = std::min(s.find_first_of(" \t", i), s.size());
        out.push_back(s.substr(i, e - i));
        i = e;
    }
}

std::vector<std::string_view> csv_fields(std::string_view s) {
    std::vector<std::string_view> out;
    for (std::size_t b = 0;;) {
        const auto e = s.find(',', b);
        auto f = trim(s.substr(b, e == std::string_view::npos ? std::string_view::npos : e - b));
        if (f.size() >= 2 && f.front() == '"' && f.back() == '"') f = f.substr(1, f.size() - 2);
        out.push_back(f);
        if (e == std::string_view::npos) return out;
        b = e + 1;
    }
}

template <class T>
bool parse(std::string_view s, T& v) {
    if (s.starts_with('+')) s.remove_prefix(1);
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc{} && p == s.data() + s.size();
}

double number(const LineReader& in, std::string_view s, std::string_view what) {
    double v = 0.0;
    if (!parse(s, v)) in.fail(fmt::format("{} '{}' is not a number", what, s));
    return v;
}

/// Checks one particle and appends it (errors name the reader's current line).
void add(const LineReader& in, ParticleFile& out, std::string_view id_text,
         std::string_view type_text, double radius, double density, const Vec3& x) {
    ParticleRecord r;
    if (!parse(id_text, r.id)) in.fail(fmt::format("id '{}' is not an integer 0..2^32-1", id_text));
    if (!parse(type_text, r.type) || r.type < 1 || r.type > 256)
        in.fail(fmt::format("type '{}' is not an integer 1..256", type_text));
    if (!(radius > 0.0) || !std::isfinite(radius))
        in.fail(fmt::format("radius {} m is not positive", radius));
    if (!std::isnan(density) && !(density > 0.0 && std::isfinite(density)))
        in.fail(fmt::format("density {} kg/m^3 is not positive", density));
    if (!is_finite(x)) in.fail("position is not finite");
    r.radius = radius;
    r.density = density;
    r.position = x;
    r.line = in.line_no();
    out.particles.push_back(r);
}

// ---------------------------------------------------------------- CSV
void read_csv(LineReader& in, const std::string& header, ParticleFile& out) {
    const auto names = csv_fields(header);
    const auto column = [&](std::initializer_list<std::string_view> aliases) -> int {
        for (std::size_t k = 0; k < names.size(); ++k)
            for (const auto a : aliases)
                if (names[k] == a) return static_cast<int>(k);
        return -1;
    };
    const int c_id = column({"id"}), c_type = column({"type"});
    const int c_x = column({"x_m", "x"}), c_y = column({"y_m", "y"}), c_z = column({"z_m", "z"});
    const int c_r = column({"radius_m", "radius"}), c_d = column({"diameter_m", "diameter"});
    const int c_rho = column({"density_kg_m3", "density"});
    if (c_id < 0 || c_type < 0 || c_x < 0 || c_y < 0 || c_z < 0 || (c_r < 0 && c_d < 0))
        in.fail("CSV header must name the columns id, type, radius_m (or diameter_m), x_m, y_m, "
                "z_m and optionally density_kg_m3 (SI units)");
    std::string line;
    while (in.next(line)) {
        if (trim(line).empty() || trim(line).starts_with('#')) continue;
        const auto f = csv_fields(line);
        if (f.size() != names.size())
            in.fail(fmt::format("{} fields, but the header has {}", f.size(), names.size()));
        const auto num = [&](int c) { return number(in, f[c], names[c]); };
        const double r = c_r >= 0 ? num(c_r) : 0.5 * num(c_d);
        add(in, out, f[c_id], f[c_type], r, c_rho >= 0 ? num(c_rho) : kNaN,
            {num(c_x), num(c_y), num(c_z)});
    }
    out.format = "csv";
}

// ---------------------------------------------------------------- LAMMPS data file
bool is_section(std::string_view line) {
    const auto t = trim(line);
    return !t.empty() && std::isalpha(static_cast<unsigned char>(t.front()));
}

void read_data(LineReader& in, ParticleFile& out) {
    // Header: "N atoms", "xlo xhi" etc., up to the first section keyword. Line 1 (title) is
    // already consumed by the format detection.
    std::optional<std::size_t> natoms;
    std::string line;
    bool have_line = false;
    while (in.next(line)) {
        if (is_section(line)) {
            have_line = true;
            break;
        }
        const auto w = words(line);
        if (w.empty()) continue;
        if (w.size() == 2 && w[1] == "atoms") {
            std::size_t n = 0;
            if (!parse(w[0], n)) in.fail("bad atom count");
            natoms = n;
        } else if (w.size() == 4 && (w[2] == "xlo" || w[2] == "ylo")) {
            const double lo = number(in, w[0], w[2]), hi = number(in, w[1], w[3]);
            if (!(hi > lo) || !std::isfinite(hi - lo))
                in.fail(
                    fmt::format("box bounds {} {} are inverted or empty (need lo < hi)", lo, hi));
            (w[2] == "xlo" ? out.xlo : out.ylo) = lo;
            (w[2] == "xlo" ? out.lx : out.ly) = hi - lo;
        } else if (w.size() == 6 && w[3] == "xy") {
            for (int k = 0; k < 3; ++k)
                if (number(in, w[k], "tilt factor") != 0.0)
                    in.fail("triclinic boxes are not supported (the film box is orthogonal)");
        }
    }
    bool atoms_seen = false;
    while (have_line) {
        // One section: keyword line, then body lines up to the next keyword.
        const auto hash = line.find('#');
        const std::string name(trim(std::string_view(line).substr(0, hash)));
        const auto style = hash == std::string::npos
                               ? std::string_view{}
                               : trim(std::string_view(line).substr(hash + 1));
        const bool atoms = name == "Atoms";
        if (atoms && !style.empty() && style != "sphere" && style != "granular")
            in.fail(fmt::format("atom_style '{}' is not supported; write the data file with "
                                "atom_style sphere or granular (id type diameter density x y z)",
                                style));
        if (atoms && atoms_seen) in.fail("second Atoms section");
        atoms_seen = atoms_seen || atoms;
        have_line = false;
        while (in.next(line)) {
            if (is_section(line)) {
                have_line = true;
                break;
            }
            if (!atoms) continue;
            const auto w = words(line);
            if (w.empty()) continue;
            if (w.size() != 7 && w.size() != 10)
                in.fail(fmt::format("{} columns; atom_style sphere expects 7 (id type diameter "
                                    "density x y z) or 10 (with image flags ix iy iz)",
                                    w.size()));
            const double d = number(in, w[2], "diameter");
            add(in, out, w[0], w[1], 0.5 * d, number(in, w[3], "density"),
                {number(in, w[4], "x"), number(in, w[5], "y"), number(in, w[6], "z")});
        }
    }
    if (!atoms_seen) in.fail("no Atoms section: not a LAMMPS data file?");
    if (natoms && *natoms != out.particles.size())
        in.fail(fmt::format("header says {} atoms, Atoms section has {}", *natoms,
                            out.particles.size()));
    out.format = "lammps data";
}

// ---------------------------------------------------------------- LAMMPS dump
/// One frame of a LAMMPS dump: its header items and where its atom lines start.
struct DumpFrame {
    std::int64_t step = -1;
    std::size_t natoms = 0;
    std::array<double, 4> box{}; // xlo xhi ylo yhi
    bool have_box = false;
    std::vector<std::string> columns;
    std::streampos atoms_at{};
    std::size_t atoms_line = 0;
};

/// Reads the items of every frame, skipping the atom lines; returns every complete frame.
std::vector<DumpFrame> dump_frames(LineReader& in, std::string first) {
    DumpFrame cur;
    std::vector<DumpFrame> frames;
    std::string line = std::move(first);
    const auto value_line = [&](std::string_view what) {
        if (!in.next(line)) in.fail(fmt::format("file ends after ITEM: {}", what));
        return words(line);
    };
    do {
        const auto t = trim(line);
        if (!t.starts_with("ITEM:")) continue; // lines of items we do not use (UNITS, TIME...)
        const auto item = trim(t.substr(5));
        if (item == "TIMESTEP") {
            const auto w = value_line(item);
            if (w.size() != 1 || !parse(w[0], cur.step)) in.fail("bad timestep");
        } else if (item == "NUMBER OF ATOMS") {
            const auto w = value_line(item);
            if (w.size() != 1 || !parse(w[0], cur.natoms)) in.fail("bad number of atoms");
        } else if (item.starts_with("BOX BOUNDS")) {
            if (item.find("xy") != std::string_view::npos)
                in.fail("triclinic boxes are not supported (the film box is orthogonal)");
            for (int k = 0; k < 3; ++k) {
                const auto w = value_line(item);
                if (w.size() < 2) in.fail("box bounds need two numbers");
                if (k < 2) {
                    cur.box[2 * k] = number(in, w[0], "lower bound");
                    cur.box[2 * k + 1] = number(in, w[1], "upper bound");
                    // Inverted bounds give a negative volume (density < 0, porosity > 1 downstream).
                    if (!(cur.box[2 * k + 1] > cur.box[2 * k]) ||
                        !std::isfinite(cur.box[2 * k + 1] - cur.box[2 * k]))
                        in.fail(fmt::format(
                            "box bounds {} {} in {} are inverted or empty (need lo < hi)",
                            cur.box[2 * k], cur.box[2 * k + 1], "xy"[k]));
                }
            }
            cur.have_box = true;
        } else if (item.starts_with("ATOMS")) {
            cur.columns.clear();
            for (const auto c : words(item.substr(5))) cur.columns.emplace_back(c);
            cur.atoms_at = in.tell();
            cur.atoms_line = in.line_no();
            // Skip the atom lines of this frame; only the last frame is parsed.
            for (std::size_t k = 0; k < cur.natoms; ++k)
                if (!in.next(line))
                    in.fail_at(cur.atoms_line,
                               fmt::format("last frame (timestep {}) is incomplete: {} of {} atom "
                                           "lines; cut the file before this ITEM: ATOMS line",
                                           cur.step, k, cur.natoms));
            frames.push_back(cur);
        }
    } while (in.next(line));
    if (frames.empty()) in.fail("no ITEM: ATOMS section: not a LAMMPS dump?");
    return frames;
}

/// The particles of one frame found by dump_frames().
void read_dump_frame(LineReader& in, const DumpFrame& last, ParticleFile& out) {
    std::string line;

    const auto col = [&](std::initializer_list<std::string_view> names) -> int {
        for (const auto n : names)
            for (std::size_t k = 0; k < last.columns.size(); ++k)
                if (last.columns[k] == n) return static_cast<int>(k);
        return -1;
    };
    const int c_id = col({"id"}), c_type = col({"type"});
    const int c_r = col({"radius"}), c_d = col({"diameter"});
    const int c_rho = col({"density"}), c_m = col({"mass"});
    std::array<int, 3> c_x{};
    std::array<bool, 3> scaled{};
    for (int k = 0; k < 3; ++k) {
        const std::string a(1, "xyz"[k]);
        c_x[k] = col({a, a + "u"});
        if (c_x[k] < 0) {
            c_x[k] = col({a + "s", a + "su"});
            scaled[k] = true;
        }
    }
    if (c_id < 0 || c_type < 0 || c_x[0] < 0 || c_x[1] < 0 || c_x[2] < 0 || (c_r < 0 && c_d < 0))
        in.fail_at(last.atoms_line, "ITEM: ATOMS must have the columns id, type, x y z (or xu/xs), "
                                    "radius (or diameter)");
    if ((scaled[0] || scaled[1] || scaled[2]) && !last.have_box)
        in.fail_at(last.atoms_line, "scaled coordinates without BOX BOUNDS");
    if (scaled[2]) in.fail_at(last.atoms_line, "scaled z coordinates are not supported; dump z");

    in.seek(last.atoms_at, last.atoms_line);
    out.particles.reserve(last.natoms);
    for (std::size_t k = 0; k < last.natoms; ++k) {
        in.next(line);
        const auto w = words(line);
        if (w.size() != last.columns.size())
            in.fail(fmt::format("{} values, but ITEM: ATOMS names {} columns", w.size(),
                                last.columns.size()));
        const auto num = [&](int c, std::string_view what) { return number(in, w[c], what); };
        const double r = c_r >= 0 ? num(c_r, "radius") : 0.5 * num(c_d, "diameter");
        double rho = kNaN;
        if (c_rho >= 0)
            rho = num(c_rho, "density");
        else if (c_m >= 0)
            rho = num(c_m, "mass") / sphere_volume(r);
        Vec3 x{num(c_x[0], "x"), num(c_x[1], "y"), num(c_x[2], "z")};
        if (scaled[0]) x.x = last.box[0] + x.x * (last.box[1] - last.box[0]);
        if (scaled[1]) x.y = last.box[2] + x.y * (last.box[3] - last.box[2]);
        add(in, out, w[c_id], w[c_type], r, rho, x);
    }
    if (last.have_box) {
        out.xlo = last.box[0];
        out.lx = last.box[1] - last.box[0];
        out.ylo = last.box[2];
        out.ly = last.box[3] - last.box[2];
    }
    out.format = "lammps dump";
}

void read_dump(LineReader& in, std::string first, ParticleFile& out) {
    read_dump_frame(in, dump_frames(in, std::move(first)).back(), out);
}

/// "particle 7 (line 9)"
std::string who(const ParticleRecord& r) {
    return fmt::format("particle {} (line {})", r.id, r.line);
}

/// The first pair of spheres that coincide or overlap by more than the smaller radius, i.e. the
/// smaller one's centre lies inside the larger one: found from the larger one by searching its
/// radius on a hashed cell grid of the median diameter (periodic in x and y).
std::optional<std::pair<std::size_t, std::size_t>> gross_overlap(const ParticleFile& f, double lx,
                                                                 double ly) {
    const auto& p = f.particles;
    std::vector<double> radii(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) radii[i] = p[i].radius;
    std::nth_element(radii.begin(), radii.begin() + std::ptrdiff_t(radii.size() / 2), radii.end());
    const double h = 2.0 * radii[radii.size() / 2];
    constexpr double max_cells = 1 << 20, max_layer = 1 << 22;
    const long nx = std::max(1L, long(std::min(lx / h, max_cells)));
    const long ny = std::max(1L, long(std::min(ly / h, max_cells)));
    auto wrapped = [](double v, double l) { return v - l * std::floor(v / l); };
    auto cell_of = [&](const Vec3& x) {
        const long ix = std::min(nx - 1, long(wrapped(x.x, lx) / lx * double(nx)));
        const long iy = std::min(ny - 1, long(wrapped(x.y, ly) / ly * double(ny)));
        const long iz = long(std::clamp(std::floor(x.z / h), -max_layer, max_layer));
        return std::array<long, 3>{ix, iy, iz};
    };
    auto key = [](long ix, long iy, long iz) {
        return (std::uint64_t(iz + (1L << 22)) << 40) | (std::uint64_t(iy) << 20) |
               std::uint64_t(ix);
    };
    std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const auto c = cell_of(p[i].position);
        cells[key(c[0], c[1], c[2])].push_back(i);
    }
    auto periodic = [](double d, double l) { return d - l * std::nearbyint(d / l); };
    auto gross = [&](std::size_t i, std::size_t j) {
        const double dx = periodic(p[j].position.x - p[i].position.x, lx);
        const double dy = periodic(p[j].position.y - p[i].position.y, ly);
        const double dz = p[j].position.z - p[i].position.z;
        return j != i &&
               std::sqrt(dx * dx + dy * dy + dz * dz) < std::max(p[i].radius, p[j].radius);
    };
    auto ordered = [](std::size_t i, std::size_t j) {
        return std::pair{std::min(i, j), std::max(i, j)};
    };
    for (std::size_t i = 0; i < p.size(); ++i) {
        const auto c = cell_of(p[i].position);
        const long k = long(std::min(std::ceil(p[i].radius / h), max_layer));
        const long wx = std::min(2 * k + 1, nx), wy = std::min(2 * k + 1, ny);
        if (double(wx) * double(wy) * double(2 * k + 1) > double(cells.size())) {
            for (const auto& [unused, members] : cells) // fewer occupied cells than the search box
                for (std::size_t j : members)
                    if (gross(i, j)) return ordered(i, j);
            continue;
        }
        for (long dx = 0; dx < wx; ++dx)
            for (long dy = 0; dy < wy; ++dy)
                for (long iz = c[2] - k; iz <= c[2] + k; ++iz) {
                    const long ix = ((c[0] - k + dx) % nx + nx) % nx,
                               iy = ((c[1] - k + dy) % ny + ny) % ny;
                    const auto it = cells.find(key(ix, iy, iz));
                    if (it == cells.end()) continue;
                    for (std::size_t j : it->second)
                        if (gross(i, j)) return ordered(i, j);
                }
    }
    return std::nullopt;
}

bool looks_like_csv_header(std::string_view line) {
    const auto f = csv_fields(line);
    return f.size() >= 5 && std::find(f.begin(), f.end(), "id") != f.end();
}

} // namespace

namespace {

void refuse_gzip(const fs::path& file) {
    std::ifstream probe(file, std::ios::binary);
    if (!probe) throw InputError(fmt::format("{}: cannot open particle file", file.string()));
    std::array<char, 2> magic{};
    probe.read(magic.data(), 2);
    if (file.extension() == ".gz" || (magic[0] == '\x1f' && magic[1] == '\x8b'))
        throw InputError(fmt::format("{}: gzip-compressed files are not read directly; "
                                     "run `gunzip -k {}` and pass the unzipped file",
                                     file.string(), file.string()));
}

/// A file without particles or with a duplicate id is refused: ids key contact history and
/// output, and a duplicate would silently merge two particles.
void check_ids(const ParticleFile& out, const fs::path& file) {
    if (out.particles.empty())
        throw InputError(fmt::format("{}: no particles in the file", file.string()));
    std::vector<std::uint32_t> ids(out.particles.size());
    std::transform(out.particles.begin(), out.particles.end(), ids.begin(),
                   [](const ParticleRecord& r) { return r.id; });
    std::sort(ids.begin(), ids.end());
    if (const auto dup = std::adjacent_find(ids.begin(), ids.end()); dup != ids.end())
        throw InputError(
            fmt::format("{}: particle id {} occurs more than once", file.string(), *dup));
}

} // namespace

ParticleFile read_particles(const fs::path& file) {
    refuse_gzip(file);
    LineReader in(file);
    ParticleFile out;
    std::string first;
    while (in.next(first) && trim(first).empty()) {
    }
    const auto head = trim(first);
    if (head.empty()) in.fail("empty particle file");
    if (head.starts_with("ITEM:"))
        read_dump(in, first, out);
    else if (looks_like_csv_header(head))
        read_csv(in, first, out);
    else
        read_data(in, out); // line 1 of a data file is a free title
    check_ids(out, file);
    return out;
}

void for_each_dump_frame(const fs::path& file, const std::function<void(DumpSnapshot&&)>& use) {
    refuse_gzip(file);
    LineReader in(file);
    std::string first;
    while (in.next(first) && trim(first).empty()) {
    }
    if (!trim(first).starts_with("ITEM:")) in.fail("not a LAMMPS text dump (no ITEM: line)");
    for (const DumpFrame& f : dump_frames(in, first)) {
        DumpSnapshot d;
        d.step = f.step;
        read_dump_frame(in, f, d.particles);
        check_ids(d.particles, file);
        use(std::move(d));
    }
}

void check_particle_geometry(const ParticleFile& f, double lx, double ly, const fs::path& name) {
    const std::string file = name.string();
    if (!(lx > 0.0 && ly > 0.0 && std::isfinite(lx) && std::isfinite(ly)))
        throw InputError(fmt::format(
            "{}: the periodic box {:g} x {:g} m is not finite and positive", file, lx, ly));
    const double xlo = f.xlo.value_or(0.0), ylo = f.ylo.value_or(0.0);
    for (const ParticleRecord& r : f.particles) {
        if (2.0 * r.radius > 0.5 * std::min(lx, ly))
            throw InputError(fmt::format(
                "{}: {} has radius {:.4g} um, too large for the {:.4g} x {:.4g} um periodic box "
                "(its diameter "
                "must be below half the smaller side); wrong units in the file or the wrong box?",
                file, who(r), r.radius * 1e6, lx * 1e6, ly * 1e6));
        const double out_x = std::max(xlo - r.position.x, r.position.x - (xlo + lx)) / lx;
        const double out_y = std::max(ylo - r.position.y, r.position.y - (ylo + ly)) / ly;
        if (out_x > 10.0 || out_y > 10.0)
            throw InputError(fmt::format("{}: {} at x = {:.4g} um, y = {:.4g} um lies more than 10 "
                                         "box lengths outside the {:.4g} x {:.4g} um "
                                         "box; wrong units in the file or the wrong box?",
                                         file, who(r), r.position.x * 1e6, r.position.y * 1e6,
                                         lx * 1e6, ly * 1e6));
        // A wet electrode film is below 1 mm; 1 cm above the substrate is a typo ("1.8" for 1.8e-5).
        if (r.position.z - r.radius > 0.01)
            throw InputError(fmt::format(
                "{}: {} at z = {:.4g} m lies more than 1 cm above the substrate; no film "
                "is that thick (wrong units or a damaged number?)",
                file, who(r), r.position.z));
        if (r.position.z < 0.0)
            throw InputError(
                fmt::format("{}: {} has its centre below the substrate (z = {:.4g} um < 0)", file,
                            who(r), r.position.z * 1e6));
        // Soft CB agglomerates under the NCM of a 20.1 mg/cm² film end up to 81 % of their radius
        // in the substrate (our own final.csv, z/r = 0.19): deep, but a packing; 90 % is not.
        if (r.position.z < 0.1 * r.radius)
            throw InputError(fmt::format("{}: {} (radius {:.4g} um, z = {:.4g} um) is sunk into "
                                         "the substrate by more than 90 % of its radius",
                                         file, who(r), r.radius * 1e6, r.position.z * 1e6));
    }
    if (const auto pair = gross_overlap(f, lx, ly)) {
        const ParticleRecord &a = f.particles[pair->first], &b = f.particles[pair->second];
        const double dist = std::sqrt(std::pow(std::remainder(b.position.x - a.position.x, lx), 2) +
                                      std::pow(std::remainder(b.position.y - a.position.y, ly), 2) +
                                      std::pow(b.position.z - a.position.z, 2));
        throw InputError(
            fmt::format("{}: {} and {} {} (centres {:.4g} um apart, radii {:.4g} and {:.4g} um): "
                        "an overlap larger than the "
                        "smaller radius is no packing",
                        file, who(a), who(b),
                        dist < 1e-6 * std::min(a.radius, b.radius) ? "coincide" : "overlap grossly",
                        dist * 1e6, a.radius * 1e6, b.radius * 1e6));
    }
}

void write_file_atomically(const fs::path& file, const std::function<void(std::ostream&)>& write) {
    auto tmp = file;
    tmp += ".tmp";
    {
        std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
        if (!os) throw RunError(fmt::format("cannot write {}", tmp.string()));
        write(os);
        os.flush();
        if (!os) {
            std::error_code ec;
            fs::remove(tmp, ec);
            throw RunError(fmt::format("writing {} failed (disk full?)", tmp.string()));
        }
    }
    std::error_code ec;
    fs::rename(tmp, file, ec);
    if (ec)
        throw RunError(
            fmt::format("cannot rename {} to {}: {}", tmp.string(), file.string(), ec.message()));
}

void write_particles_csv(const fs::path& file, const ParticleStore& p) {
    std::vector<std::uint32_t> order(p.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return p.id[a] < p.id[b]; });
    // fmt's "{}" is the shortest text that reads back to the same double (bit-exact round trip,
    // like %.17g but without the noise digits: 6.5e-06 rather than 6.5000000000000004e-06).
    fmt::memory_buffer buf;
    fmt::format_to(std::back_inserter(buf), "id,type,radius_m,density_kg_m3,x_m,y_m,z_m\n");
    for (const auto i : order) {
        const auto& x = p.position[i];
        fmt::format_to(std::back_inserter(buf), "{},{},{},{},{},{},{}\n", p.id[i],
                       int(p.species[i]) + 1, p.radius[i], p.density[i], x.x, x.y, x.z);
    }
    write_file_atomically(file, [&](std::ostream& os) {
        os.write(buf.data(), static_cast<std::streamsize>(buf.size()));
    });
}

} // namespace drydem
