// SPDX-License-Identifier: MIT
// Output frames and series: VTK XML PolyData (.vtp) + .pvd collection for ParaView, LAMMPS text
// dump for OVITO, CSV time series. Hand-written (libvtk9-dev would drag in Java, GDAL, Qt...).
#pragma once
#include "drydem/core/box.hpp"
#include "drydem/core/particles.hpp"
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <ostream>
#include <span>
#include <string>
#include <vector>

namespace drydem {

/// One particle frame as VTK XML PolyData: one vertex per particle (storage order), point data id,
/// type (= species + 1), radius, diameter, velocity, omega, force, and coordination (contacts per
/// particle, substrate included) when given; field data TimeValue (= process time, what
/// ParaView's time readout shows), process_time_s and sim_time_s. ASCII. Written atomically;
/// RunError on failure.
void write_vtp(const std::filesystem::path& file, const ParticleStore& particles, double sim_time,
               double process_time, std::span<const std::int32_t> coordination = {});

/// The liquid level as its own surface: one quad over the periodic base at height z_L, with field
/// data TimeValue and liquid_level_um (shown beside the particles in ParaView).
void write_level_vtp(const std::filesystem::path& file, const Box& box, double liquid_level,
                     double process_time);

/// ParaView time collection (.pvd) listing frames with their process time [s]. Rewritten
/// (atomically) on every add, so the file is valid whenever a run stops.
class PvdWriter {
public:
    explicit PvdWriter(std::filesystem::path file) : file_(std::move(file)) {}

    /// Appends a frame; `relative_file` is relative to the .pvd's folder, e.g. "frames/p_0001.vtp".
    void add(double time, std::string relative_file);
    void write() const;
    /// For a resumed run: takes over the entries of an existing .pvd (none if there is no file),
    /// so frames from before the restart stay in the collection. Returns how many were read.
    std::size_t load_existing();
    /// Keeps the first n entries (a resumed run drops frames written after its checkpoint).
    void truncate(std::size_t n) {
        if (n < entries_.size()) entries_.resize(n);
    }
    [[nodiscard]] std::size_t size() const { return entries_.size(); }

private:
    struct Entry {
        double time;
        std::string file;
    };
    std::filesystem::path file_;
    std::vector<Entry> entries_;
};

/// Appends one LAMMPS text-dump frame (ITEM: TIMESTEP / NUMBER OF ATOMS / BOX BOUNDS pp pp fm /
/// ATOMS id type x y z radius vx vy vz), sorted by id, type = species + 1, SI units. The z bounds
/// are [0, z_top]. Flushes, so complete frames reach the disk; RunError if the stream failed.
void append_lammps_dump(std::ostream& os, const ParticleStore& particles, const Box& box,
                        std::int64_t step, double z_top);

/// CSV time series: a header line of column names (units in the names, e.g. "process_time_s"),
/// then one row per call with %.10g numbers. Every row is flushed: a run that dies keeps what it
/// wrote.
class CsvSeriesWriter {
public:
    /// append = true continues an existing file (resumed run) without repeating the header.
    CsvSeriesWriter(const std::filesystem::path& file, std::vector<std::string> columns,
                    bool append = false);

    /// One row; must have as many values as there are columns (RunError otherwise).
    void row(std::span<const double> values);
    void row(std::initializer_list<double> values) {
        row(std::span(values.begin(), values.size()));
    }
    [[nodiscard]] const std::vector<std::string>& columns() const { return columns_; }

private:
    std::filesystem::path file_;
    std::vector<std::string> columns_;
    std::ofstream os_;
};

} // namespace drydem
