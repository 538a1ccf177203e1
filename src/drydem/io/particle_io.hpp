// SPDX-License-Identifier: MIT
// Particle files in and out: our CSV (final.csv, `--particles`), LAMMPS/LIGGGHTS data files
// (atom_style sphere/granular) and LAMMPS text dumps (last frame), so beds settled in LIGGGHTS or
// LAMMPS can be dried here and our results analysed by the same reader. All values SI.
#pragma once
#include "drydem/core/particles.hpp"
#include "drydem/core/vec3.hpp"
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace drydem {

struct ParticleRecord {
    std::uint32_t id = 0;
    int type = 1;         ///< as in the file: 1-based (type = species + 1)
    double radius = 0.0;  ///< [m]
    double density = 0.0; ///< [kg/m^3]; NaN when the file has none (caller fills it per species)
    Vec3 position;        ///< [m], as in the file (not wrapped into the box)
    std::size_t line = 0; ///< line of the file it was read from (error messages)
};

struct ParticleFile {
    std::vector<ParticleRecord> particles; ///< in file order
    std::optional<double> lx, ly;          ///< periodic lengths [m] where the file has a box
    std::optional<double> xlo, ylo;        ///< box origin [m]
    std::string format;                    ///< "csv", "lammps data" or "lammps dump"
};

/// Reads a particle file, detecting the format from its content:
///  - CSV with a header naming the columns: id, type, x_m, y_m, z_m, radius_m (or diameter_m),
///    optional density_kg_m3; any order, further columns ignored;
///  - LAMMPS/LIGGGHTS data file, atom_style sphere or granular
///    (Atoms: `id type diameter density x y z [ix iy iz]`; image flags are ignored);
///  - LAMMPS text dump: the last frame, columns by name (id type x|xu|xs y.. z.. radius|diameter
///    [density|mass]).
/// Ids must be unique. Throws InputError naming the file and line for anything else (also for
/// gzip files: gunzip them first).
[[nodiscard]] ParticleFile read_particles(const std::filesystem::path& file);

/// One frame of a LAMMPS text dump.
struct DumpSnapshot {
    std::int64_t step = -1; ///< ITEM: TIMESTEP
    ParticleFile particles;
};

/// Hands every complete frame of a LAMMPS text dump (a run's snapshots/dump.lammpstrj) to `use`,
/// in file order, one at a time (a long run's dump need not fit in memory), each read and checked
/// as read_particles() reads the last one.
void for_each_dump_frame(const std::filesystem::path& file,
                         const std::function<void(DumpSnapshot&&)>& use);

/// Refuses a particle file no film can be: a box that is not finite and positive, a sphere wider
/// than half the periodic box, a centre below the substrate (z < 0) or a sphere sunk into it by
/// more than half its radius, a position more than 10 box lengths outside the box or 1 cm above the substrate, two particles
/// that coincide or overlap by more than the smaller radius (minimum image in x and y). The
/// InputError names the file, the line(s) and the reason; `lx`, `ly` are the periodic box [m]
/// (the file's where it has one, else the config's).
void check_particle_geometry(const ParticleFile& file, double lx, double ly,
                             const std::filesystem::path& name);

/// Writes `id,type,radius_m,density_kg_m3,x_m,y_m,z_m` sorted by id, type = species + 1, with the
/// shortest digits that read back bit-exact. Atomic (temporary file + rename). RunError on failure.
void write_particles_csv(const std::filesystem::path& file, const ParticleStore& particles);

/// Writes `file` through `write` into `file`.tmp and renames it over `file`, so readers (ParaView,
/// a user's script, a restart) never see a half-written file. RunError on I/O failure.
void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& write);

} // namespace drydem
