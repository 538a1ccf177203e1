// SPDX-License-Identifier: MIT
// VTP frames, PVD collection, LAMMPS dump frames and CSV series (io/snapshot_writers.hpp).
#include "drydem/core/error.hpp"
#include "drydem/core/particles.hpp"
#include "drydem/io/snapshot_writers.hpp"
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include "test_dirs.hpp"
#include <sstream>
#include <string>
#include <vector>

using namespace drydem;
namespace fs = std::filesystem;

namespace {

using drydem::testing_support::temp_dir;

std::string read_all(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + what.size()))
        ++n;
    return n;
}

/// Whitespace-separated values of the DataArray named `name`.
std::vector<double> data_array(const std::string& xml, const std::string& name) {
    const auto tag = xml.find("Name=\"" + name + "\"");
    EXPECT_NE(tag, std::string::npos) << name;
    const auto b = xml.find('>', tag) + 1;
    std::istringstream in(xml.substr(b, xml.find("</DataArray>", b) - b));
    std::vector<double> v;
    for (double x; in >> x;) v.push_back(x);
    return v;
}

ParticleStore three_particles() {
    ParticleStore s;
    s.add(10, 0, 3.25e-6, 4740, {1e-6, 2e-6, 3e-6});
    s.add(11, 5, 0.75e-6, 1187.5, {4e-6, 5e-6, 6e-6});
    s.add(12, 2, 4.3e-6, 4740, {7e-6, 8e-6, 9e-6});
    s.velocity[1] = {0.5, -0.25, 1e-3};
    s.force[2] = {0, 0, -1e-9};
    return s;
}

} // namespace

TEST(SnapshotWriters, VtpHasOneVertexPerParticleAndTimes) {
    const auto s = three_particles();
    const auto file = temp_dir() / "p_0001.vtp";
    write_vtp(file, s, 1e-7, 1.0);
    const auto xml = read_all(file);
    EXPECT_TRUE(xml.starts_with("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\""));
    EXPECT_NE(xml.find("NumberOfPoints=\"3\" NumberOfVerts=\"3\""), std::string::npos);
    // Balanced tags: a cheap well-formedness check.
    EXPECT_EQ(count(xml, "<DataArray"), count(xml, "</DataArray>"));
    EXPECT_EQ(count(xml, "<DataArray"), 3u + 7u + 1u + 2u); // field, point, points, verts
    for (const std::string tag : {"PolyData", "FieldData", "Piece", "PointData", "Points", "Verts"})
        EXPECT_EQ(count(xml, "<" + tag + ">") + count(xml, "<" + tag + " "),
                  count(xml, "</" + tag + ">"))
            << tag;
    EXPECT_EQ(data_array(xml, "TimeValue"), std::vector<double>{1.0});
    EXPECT_EQ(data_array(xml, "sim_time_s"), std::vector<double>{1e-7});
    EXPECT_EQ(data_array(xml, "id"), (std::vector<double>{10, 11, 12}));
    EXPECT_EQ(data_array(xml, "type"), (std::vector<double>{1, 6, 3}));
    EXPECT_EQ(data_array(xml, "diameter"), (std::vector<double>{6.5e-6, 1.5e-6, 8.6e-6}));
    EXPECT_EQ(data_array(xml, "Points").size(), 9u);
    EXPECT_EQ(data_array(xml, "Points")[5], 6e-6);
    EXPECT_EQ(data_array(xml, "velocity")[4], -0.25);
    EXPECT_EQ(data_array(xml, "force")[8], -1e-9);
    EXPECT_EQ(data_array(xml, "connectivity"), (std::vector<double>{0, 1, 2}));
    EXPECT_EQ(data_array(xml, "offsets"), (std::vector<double>{1, 2, 3}));
}

TEST(SnapshotWriters, VtpOfEmptyStoreIsValid) {
    const auto file = temp_dir() / "empty.vtp";
    write_vtp(file, ParticleStore{}, 0.0, 0.0);
    const auto xml = read_all(file);
    EXPECT_NE(xml.find("NumberOfPoints=\"0\""), std::string::npos);
    EXPECT_EQ(count(xml, "<DataArray"), count(xml, "</DataArray>"));
}

TEST(SnapshotWriters, PvdListsFramesAndIsValidAfterEveryAdd) {
    const auto file = temp_dir() / "particles.pvd";
    PvdWriter pvd(file);
    pvd.add(0.0, "frames/p_0000.vtp");
    EXPECT_EQ(count(read_all(file), "<DataSet"), 1u);
    EXPECT_TRUE(read_all(file).ends_with("</VTKFile>\n"));
    pvd.add(12.5, "frames/p_0001.vtp");
    const auto xml = read_all(file);
    EXPECT_EQ(count(xml, "<DataSet"), 2u);
    EXPECT_NE(xml.find("<VTKFile type=\"Collection\""), std::string::npos);
    EXPECT_NE(xml.find("timestep=\"0\""), std::string::npos);
    EXPECT_NE(xml.find("timestep=\"12.5\" group=\"\" part=\"0\" file=\"frames/p_0001.vtp\""),
              std::string::npos)
        << xml;

    // A resumed run keeps the earlier frames.
    PvdWriter resumed(file);
    EXPECT_EQ(resumed.load_existing(), 2u);
    resumed.add(25.0, "frames/p_0002.vtp");
    EXPECT_EQ(count(read_all(file), "<DataSet"), 3u);
    EXPECT_EQ(PvdWriter(file.parent_path() / "none.pvd").load_existing(), 0u);
}

TEST(SnapshotWriters, LammpsDumpFrameLayout) {
    const auto s = three_particles();
    std::ostringstream os;
    append_lammps_dump(os, s, Box{30e-6, 40e-6}, 42, 1.3e-4);
    const auto text = os.str();
    EXPECT_TRUE(text.starts_with("ITEM: TIMESTEP\n42\nITEM: NUMBER OF ATOMS\n3\n"
                                 "ITEM: BOX BOUNDS pp pp fm\n0 3e-05\n0 4e-05\n0 0.00013\n"
                                 "ITEM: ATOMS id type x y z radius vx vy vz\n"))
        << text;
    EXPECT_NE(text.find("\n11 6 4e-06 5e-06 6e-06 7.5e-07 0.5 -0.25 0.001\n"), std::string::npos)
        << text;
    EXPECT_EQ(count(text, "\n"), 9u + 3u);
}

TEST(SnapshotWriters, CsvSeriesFlushesEveryRowAndAppends) {
    const auto file = temp_dir() / "timeseries.csv";
    {
        CsvSeriesWriter w(file, {"process_time_s", "liquid_level_um", "contacts"});
        w.row({0.0, 130.5148, 0});
        const std::vector<double> r{1.5, 1.0 / 3.0, 12345};
        w.row(r);
        // Visible on disk before the writer is closed (a run that dies keeps its rows).
        EXPECT_EQ(read_all(file), "process_time_s,liquid_level_um,contacts\n0,130.5148,0\n"
                                  "1.5,0.3333333333,12345\n");
        EXPECT_THROW(w.row({1.0, 2.0}), RunError);
    }
    {
        CsvSeriesWriter w(file, {"process_time_s", "liquid_level_um", "contacts"}, true);
        w.row({3.0, 4.0, 5.0});
    }
    EXPECT_EQ(count(read_all(file), "process_time_s"), 1u);
    EXPECT_TRUE(read_all(file).ends_with("\n3,4,5\n"));
    EXPECT_THROW(CsvSeriesWriter(file, {"other_s"}, true), RunError);
}
