// SPDX-License-Identifier: MIT
// Particle files: peers' CSV and LAMMPS data files, dumps, our CSV round trip (io/particle_io.hpp).
#include "drydem/core/error.hpp"
#include "drydem/core/particles.hpp"
#include "drydem/io/particle_io.hpp"
#include "drydem/io/snapshot_writers.hpp"
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include "test_dirs.hpp"
#include <map>
#include <random>
#include <string>

using namespace drydem;
namespace fs = std::filesystem;

namespace {

const fs::path kPeers = fs::path(DRYDEM_SOURCE_DIR "/tests/data/peers");

using drydem::testing_support::temp_dir;

fs::path write_text(const fs::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
    return file;
}

std::string error_of(const fs::path& file) {
    try {
        (void)read_particles(file);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(ParticleIo, ReadsPeersCsv) {
    const auto f = read_particles(kPeers / "gas_30um.csv");
    EXPECT_EQ(f.format, "csv");
    ASSERT_EQ(f.particles.size(), 7526u);
    EXPECT_FALSE(f.lx.has_value());
    const auto& p = f.particles.front(); // 1,5,5.675000e-06,4740,1.249859617636e-05,...
    EXPECT_EQ(p.id, 1u);
    EXPECT_EQ(p.type, 5);
    EXPECT_EQ(p.radius, 5.675e-6);
    EXPECT_EQ(p.density, 4740.0);
    EXPECT_EQ(p.position.x, 1.249859617636e-05);
    EXPECT_EQ(p.position.y, 3.050750837121e-07);
    EXPECT_EQ(p.position.z, 1.040105454868e-04);
    std::map<int, std::size_t> count;
    for (const auto& r : f.particles) {
        ++count[r.type];
        if (r.type == 1) {
            EXPECT_EQ(r.radius, 3.25e-6);
        }
        if (r.type == 6) {
            EXPECT_EQ(r.radius, 0.75e-6);
            EXPECT_EQ(r.density, 1187.5);
        }
    }
    // Counts of the 30 um base from the peers' README.
    EXPECT_EQ(count,
              (std::map<int, std::size_t>{{1, 50}, {2, 31}, {3, 22}, {4, 14}, {5, 9}, {6, 7400}}));
}

TEST(ParticleIo, ReadsPeersDataFile) {
    const auto f = read_particles(kPeers / "settled_30um.data");
    EXPECT_EQ(f.format, "lammps data");
    ASSERT_EQ(f.particles.size(), 7526u);
    ASSERT_TRUE(f.lx && f.ly && f.xlo && f.ylo);
    EXPECT_EQ(*f.lx, 30e-6);
    EXPECT_EQ(*f.ly, 30e-6);
    EXPECT_EQ(*f.xlo, 0.0);
    const auto& p = f.particles.front(); // 1 5 1.135000e-05 4740 1.036315881267e-05 ...
    EXPECT_EQ(p.id, 1u);
    EXPECT_EQ(p.type, 5);
    EXPECT_EQ(p.radius, 5.675e-6); // diameter column halved
    EXPECT_EQ(p.density, 4740.0);
    EXPECT_EQ(p.position.x, 1.036315881267e-05);
    EXPECT_EQ(p.position.z, 6.603403385110e-05);
    EXPECT_EQ(f.particles.back().id, 7526u);
    EXPECT_EQ(f.particles.back().radius, 0.75e-6);

    // The gas data file and the gas CSV describe the same particles.
    const auto gas = read_particles(kPeers / "gas_30um.data");
    const auto csv = read_particles(kPeers / "gas_30um.csv");
    ASSERT_EQ(gas.particles.size(), csv.particles.size());
    for (std::size_t k = 0; k < gas.particles.size(); ++k) {
        EXPECT_EQ(gas.particles[k].id, csv.particles[k].id);
        EXPECT_EQ(gas.particles[k].radius, csv.particles[k].radius);
        EXPECT_EQ(gas.particles[k].position.z, csv.particles[k].position.z);
    }
}

TEST(ParticleIo, DataFileWithSectionsImageFlagsAndComments) {
    const auto dir = temp_dir();
    const auto file = write_text(dir / "w.data", R"(LAMMPS data file via write_data, timestep = 100

3 atoms
2 atom types

-1.0e-05 2.0e-05 xlo xhi
0 4.0e-05 ylo yhi
0 1e-4 zlo zhi

Atoms # sphere

3 2 3e-06 1187.5 1e-06 2e-06 3e-06 0 0 0
1 1 1e-05 4740 4e-06 5e-06 6e-06 1 0 0   # trailing comment
2 1 1e-05 4740 7e-06 8e-06 9e-06

Velocities

1 0 0 0 0 0 0
2 0 0 0 0 0 0
3 0 0 0 0 0 0
)");
    const auto f = read_particles(file);
    ASSERT_EQ(f.particles.size(), 3u);
    EXPECT_EQ(f.particles[0].id, 3u);
    EXPECT_EQ(f.particles[0].radius, 1.5e-6);
    EXPECT_EQ(f.particles[1].position.x, 4e-6); // image flags ignored: positions as stored
    EXPECT_DOUBLE_EQ(*f.lx, 3e-5);              // 2e-5 - (-1e-5)
    EXPECT_EQ(*f.xlo, -1e-5);
    EXPECT_EQ(*f.ly, 4e-5);
}

TEST(ParticleIo, ReadsOwnFinalCsvWithoutDensity) {
    const auto dir = temp_dir();
    const auto file = write_text(dir / "final.csv", "id, type, radius_m, x_m, y_m, z_m\r\n"
                                                    "7, 1, 3.25e-06, 1e-6, 2e-6, 3e-6\r\n"
                                                    "\r\n"
                                                    "8, 6, 0.75e-06, 4e-6, 5e-6, 6e-6\r\n");
    const auto f = read_particles(file);
    ASSERT_EQ(f.particles.size(), 2u);
    EXPECT_TRUE(std::isnan(f.particles[0].density)); // the caller fills it from the species
    EXPECT_EQ(f.particles[1].type, 6);
    EXPECT_EQ(f.particles[1].position.z, 6e-6);
}

TEST(ParticleIo, CsvRoundTripIsBitExactAndSortedById) {
    ParticleStore s;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0); // test data only: portability irrelevant
    for (std::uint32_t k = 0; k < 200; ++k) {
        const std::uint32_t id = (k * 7919u) % 1000u; // unsorted, unique
        s.add(id, static_cast<std::uint8_t>(k % 6), 1e-6 * (0.5 + u(rng)), 1000 + 4000 * u(rng),
              {75e-6 * u(rng), 75e-6 * u(rng), 1e-4 * u(rng)});
    }
    const auto file = temp_dir() / "final.csv";
    write_particles_csv(file, s);
    EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
    const auto f = read_particles(file);
    ASSERT_EQ(f.particles.size(), s.size());
    std::map<std::uint32_t, std::size_t> index;
    for (std::size_t i = 0; i < s.size(); ++i) index[s.id[i]] = i;
    std::size_t k = 0;
    for (const auto& [id, i] : index) { // map order = ascending id = file order
        const auto& r = f.particles[k++];
        ASSERT_EQ(r.id, id);
        EXPECT_EQ(r.type, s.species[i] + 1);
        EXPECT_EQ(r.radius, s.radius[i]);
        EXPECT_EQ(r.density, s.density[i]);
        EXPECT_EQ(r.position.x, s.position[i].x);
        EXPECT_EQ(r.position.y, s.position[i].y);
        EXPECT_EQ(r.position.z, s.position[i].z);
    }
}

TEST(ParticleIo, DumpLastFrameIsRead) {
    ParticleStore s;
    s.add(2, 0, 3.25e-6, 4740, {1e-6, 2e-6, 3e-6});
    s.add(1, 5, 0.75e-6, 1187.5, {4e-6, 5e-6, 6e-6});
    Box box{30e-6, 40e-6};
    const auto file = temp_dir() / "dump.lammpstrj";
    {
        std::ofstream os(file);
        append_lammps_dump(os, s, box, 0, 1e-4);
        s.position[0] = {7e-6, 8e-6, 9.123456789e-6};
        s.velocity[0] = {1e-3, 0, -2e-3};
        append_lammps_dump(os, s, box, 1000, 1e-4);
    }
    const auto f = read_particles(file);
    EXPECT_EQ(f.format, "lammps dump");
    ASSERT_EQ(f.particles.size(), 2u);
    EXPECT_EQ(*f.lx, 30e-6);
    EXPECT_EQ(*f.ly, 40e-6);
    EXPECT_EQ(f.particles[0].id, 1u); // sorted by id in the dump
    EXPECT_EQ(f.particles[0].type, 6);
    EXPECT_EQ(f.particles[1].type, 1);
    EXPECT_EQ(f.particles[1].radius, 3.25e-6);
    EXPECT_EQ(f.particles[1].position.x, 7e-6); // second frame
    EXPECT_DOUBLE_EQ(f.particles[1].position.z, 9.123456789e-6);
    EXPECT_TRUE(std::isnan(f.particles[1].density));
}

TEST(ParticleIo, ForeignDumpWithScaledCoordinatesAndMass) {
    const auto dir = temp_dir();
    const auto file = write_text(dir / "d.dump", R"(ITEM: TIMESTEP
5
ITEM: NUMBER OF ATOMS
1
ITEM: BOX BOUNDS pp pp fm
1e-5 3e-5
0 2e-5
0 1e-4
ITEM: ATOMS id type xs ys z vx diameter mass
4 2 0.5 0.25 5e-6 0 2e-6 4.1887902047863905e-15
)");
    const auto f = read_particles(file);
    ASSERT_EQ(f.particles.size(), 1u);
    EXPECT_DOUBLE_EQ(f.particles[0].position.x, 2e-5);
    EXPECT_DOUBLE_EQ(f.particles[0].position.y, 5e-6);
    EXPECT_EQ(f.particles[0].radius, 1e-6);
    EXPECT_NEAR(f.particles[0].density, 1000.0, 1e-9);
}

TEST(ParticleIo, ErrorsNameFileAndLine) {
    const auto dir = temp_dir();
    auto msg = error_of(write_text(dir / "a.csv", "id,type,radius_m,x_m,y_m,z_m\n"
                                                  "1,1,1e-6,0,0,0\n"
                                                  "2,1,abc,0,0,0\n"));
    EXPECT_NE(msg.find("a.csv:3:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("abc"), std::string::npos) << msg;

    msg = error_of(write_text(dir / "b.csv", "id,type,radius_m,x_m,y_m,z_m\n1,1,-1e-6,0,0,0\n"));
    EXPECT_NE(msg.find("b.csv:2:"), std::string::npos) << msg;

    msg = error_of(write_text(dir / "c.csv", "id,type,x_m,y_m,z_m\n1,1,0,0,0\n"));
    EXPECT_NE(msg.find("radius_m"), std::string::npos) << msg;

    msg = error_of(write_text(dir / "d.csv", "id,type,radius_m,x_m,y_m,z_m\n1,1,1e-6,0,0,0\n"
                                             "1,2,1e-6,0,0,0\n"));
    EXPECT_NE(msg.find("id 1 occurs more than once"), std::string::npos) << msg;

    msg = error_of(write_text(dir / "e.data", "title\n\n2 atoms\n\nAtoms # atomic\n\n1 1 0 0 0\n"));
    EXPECT_NE(msg.find("e.data:5:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("atom_style 'atomic'"), std::string::npos) << msg;

    msg =
        error_of(write_text(dir / "f.data", "title\n\n2 atoms\n\nAtoms\n\n1 1 1e-6 1000 0 0 0\n"));
    EXPECT_NE(msg.find("header says 2 atoms"), std::string::npos) << msg;

    msg = error_of(write_text(dir / "g.dump", "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n3\n"
                                              "ITEM: BOX BOUNDS pp pp fm\n0 1\n0 1\n0 1\n"
                                              "ITEM: ATOMS id type x y z radius\n1 1 0 0 0 1\n"));
    EXPECT_NE(msg.find("g.dump:9:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("incomplete"), std::string::npos) << msg;

    msg = error_of(write_text(dir / "h.data.gz", std::string("\x1f\x8b\x08\x00", 4)));
    EXPECT_NE(msg.find("gunzip"), std::string::npos) << msg;

    msg = error_of(dir / "missing.csv");
    EXPECT_NE(msg.find("missing.csv"), std::string::npos) << msg;
}

// A run's dump holds one frame per snapshot time; the binder model reads them all, in order, and
// the last one is what read_particles() reads.
TEST(ParticleIo, EveryDumpFrameIsReadInOrder) {
    const auto dir = temp_dir();
    const auto file = write_text(dir / "two.dump", R"(ITEM: TIMESTEP
0
ITEM: NUMBER OF ATOMS
2
ITEM: BOX BOUNDS pp pp fm
0 4e-5
0 4e-5
0 1e-4
ITEM: ATOMS id type x y z radius
1 1 1e-5 1e-5 9e-5 1e-6
2 2 2e-5 2e-5 8e-5 7.5e-7
ITEM: TIMESTEP
100
ITEM: NUMBER OF ATOMS
2
ITEM: BOX BOUNDS pp pp fm
0 4e-5
0 4e-5
0 1e-4
ITEM: ATOMS id type x y z radius
1 1 1e-5 1e-5 3e-5 1e-6
2 2 2e-5 2e-5 2e-5 7.5e-7
)");
    std::vector<drydem::DumpSnapshot> frames;
    drydem::for_each_dump_frame(file,
                                [&](drydem::DumpSnapshot&& d) { frames.push_back(std::move(d)); });
    ASSERT_EQ(frames.size(), 2u);
    EXPECT_EQ(frames[0].step, 0);
    EXPECT_EQ(frames[1].step, 100);
    ASSERT_EQ(frames[0].particles.particles.size(), 2u);
    EXPECT_DOUBLE_EQ(frames[0].particles.particles[0].position.z, 9e-5);
    EXPECT_DOUBLE_EQ(frames[1].particles.particles[0].position.z, 3e-5);
    EXPECT_DOUBLE_EQ(frames[1].particles.particles[1].radius, 7.5e-7);
    const auto last = read_particles(file);
    ASSERT_EQ(last.particles.size(), 2u);
    EXPECT_DOUBLE_EQ(last.particles[1].position.z, frames[1].particles.particles[1].position.z);
    EXPECT_THROW(drydem::for_each_dump_frame(write_text(dir / "x.csv", "id,type,x_m\n"),
                                             [](drydem::DumpSnapshot&&) {}),
                 drydem::InputError);
}
