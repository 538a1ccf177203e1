// SPDX-License-Identifier: MIT
// Issue 14: input that is in range key by key but impossible as a whole (counts, heights, steps),
// strings that break the written config.toml, a unit nested 30,000 deep, and particle files no
// film can be. Each is an InputError naming the key or the file line and the reason.
#include "drydem/core/error.hpp"
#include "drydem/io/config.hpp"
#include "drydem/io/particle_io.hpp"
#include "drydem/io/units.hpp"
#include "drydem/drying/derived_checks.hpp"
#include "test_dirs.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace drydem;
namespace fs = std::filesystem;

namespace {

std::string config_error(const std::vector<std::string>& sets, std::string_view text = "") {
    try {
        (void)load_config(text, "test.toml", sets);
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no InputError for --set " << (sets.empty() ? "" : sets.front());
    return {};
}

bool has(const std::string& text, std::string_view part) {
    return text.find(part) != std::string::npos;
}

} // namespace

// 10 nm CB spheres in the default film: 1.56e11 particles, once -1,962,952,865 in an int.
TEST(DerivedQuantities, ParticleCountBeyondTheLimitNamesTheKeys) {
    const std::string msg = config_error({"formulation.cb_diameter=10nm"});
    EXPECT_TRUE(has(msg, "1.56e+11 CB particles of 0.01 um")) << msg;
    EXPECT_TRUE(has(msg, "allowed at most 1e+08")) << msg;
    EXPECT_TRUE(has(msg, "formulation.cb_diameter")) << msg;
    EXPECT_FALSE(has(msg, "bare number")) << msg; // "10nm" has a unit
}

TEST(DerivedQuantities, BareLengthGetsAUnitHint) {
    const std::string msg = config_error({"film.box_x=40"});
    EXPECT_TRUE(has(msg, "film.box_x = 40 is a bare number, i.e. 40 m")) << msg;
    EXPECT_TRUE(has(msg, "did you mean \"40 um\"?")) << msg;
    // The same size with its unit is refused for its count, without the hint.
    EXPECT_FALSE(has(config_error({"film.box_x=\"40 m\""}), "bare number"));
    EXPECT_NO_THROW(load_config("", "t", {"film.box_x=40e-6"})); // a bare SI value that fits
}

TEST(DerivedQuantities, FilmWithoutParticlesIsRefused) {
    EXPECT_TRUE(has(config_error({"film.areal_loading=1e-300"}), "the film has no particles"));
    EXPECT_TRUE(has(config_error({"film.areal_loading=1e-12"}), "the film has no particles"));
    const std::string pvdf =
        config_error({"formulation.ncm_mass_fraction=0", "formulation.cb_mass_fraction=0",
                      "formulation.pvdf_mass_fraction=1"});
    EXPECT_TRUE(has(pvdf, "0 NCM and 0 CB particles")) << pvdf;
}

TEST(DerivedQuantities, HugeValuesAreRefusedAtTheirKey) {
    const std::string rho = config_error({"materials.solvent_density=1e308"});
    EXPECT_TRUE(has(rho, "config key 'materials.solvent_density': 1e+308 is out of range")) << rho;
    const std::string k = config_error({"scaling.time_factor=1e308"});
    EXPECT_TRUE(has(k, "scaled gravity is inf")) << k;
    EXPECT_TRUE(has(k, "scaling.time_factor")) << k;
    const std::string relax = config_error({"drying.relaxation=1e308"});
    EXPECT_TRUE(
        has(relax, "drying.relaxation = 1e+308 s is not shorter than run.max_process_time = 300 s"))
        << relax;
    const std::string load = config_error({"film.areal_loading=1e308"});
    EXPECT_TRUE(has(load, "film.areal_loading")) << load;
    const std::string steps = config_error({"run.time_step=1e-300"});
    EXPECT_TRUE(has(steps, "steps of 1e-300 s; allowed at most 1e+12")) << steps;
}

// 6 m of dryer at 2 m/min is 180 s; at 1e-9 s per step that was 1.8e11 samples (~160 MB/s growth).
TEST(DerivedQuantities, DryerModelStepsAreBounded) {
    const std::string msg = config_error({"dryer.schedule=model", "dryer.time_step=1e-9s"});
    EXPECT_TRUE(has(msg, "the dryer model would take 1.8e+11 steps")) << msg;
    EXPECT_TRUE(has(msg, "dryer.time_step")) << msg;
    EXPECT_TRUE(has(config_error({"dryer.line_speed=1e-9m/min"}), "dryer.line_speed"));
}

TEST(DerivedQuantities, DefaultFilmIsFiniteAndPositive) {
    const DerivedQuantities d = derived_quantities(load_config(default_config_toml(), "default"));
    EXPECT_NEAR(d.wet_film_height, 130.51e-6, 0.01e-6);
    EXPECT_GT(d.particles, 1e4);
    EXPECT_LT(d.particles, max_particles);
    EXPECT_NEAR(d.steps, 8.5e3, 0.05e3);     // as `drydem check` prints (paper scheme's cap 1e-9 s)
    EXPECT_NEAR(d.dryer_steps, 9000.0, 1.0); // 3 zones of 2 m at 2 m/min, 0.02 s steps
}

TEST(ConfigStrings, SetValueMustBeOneValue) {
    const std::string msg = config_error({"run.seed=1\nfoo=2"});
    EXPECT_TRUE(has(msg, "defines further keys")) << msg;
}

// config.toml is written by the TOML library: whatever run.name holds reads back unchanged.
TEST(ConfigStrings, HostileNamesRoundTripThroughToToml) {
    for (const std::string name :
         {"say \"hi\"", "back\\slash", "quote ' and \"\"\" and '''", "# not a comment", "[table]",
          "ünïcödé µm", "x = 1", "trailing \\"}) {
        Config c;
        c.name = name;
        const std::string text = to_toml(c);
        Config back;
        ASSERT_NO_THROW(back = load_config(text, "config.toml")) << text;
        EXPECT_EQ(back.name, name);
        EXPECT_EQ(to_toml(back), text);
    }
}

TEST(ConfigStrings, NamesThatCannotNameAFolderAreRefused) {
    for (const std::string bad :
         {"run.name=\"a\\nb\"", "run.name=\"tab\\there\"", "run.name=\"../up\"", "run.name=\"a/b\"",
          "run.name=\"\"", "run.name=\"..\""}) {
        const std::string msg = config_error({bad});
        EXPECT_TRUE(has(msg, "config key 'run.name'")) << bad << ": " << msg;
        EXPECT_TRUE(has(msg, "without control characters")) << msg;
    }
    EXPECT_TRUE(has(config_error({"run.name=\xff\xfe"}), "config key 'run.name'")); // not UTF-8
}

TEST(UnitsNesting, DeepParenthesesAreAnErrorNotAStackOverflow) {
    const std::string deep = "1 " + std::string(30000, '(') + "m" + std::string(30000, ')');
    try {
        (void)parse_quantity(deep, Dimension::length, "film.box_x");
        ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(has(e.what(), "more than 16 nested parentheses"))
            << std::string(e.what()).substr(0, 200);
    }
    EXPECT_EQ(parse_quantity("2 " + std::string(16, '(') + "um" + std::string(16, ')'),
                             Dimension::length, "k"),
              2e-6);
    EXPECT_THROW(
        (void)parse_quantity("1 ((((((((((m^9)^9)^9)^9)^9)^9)^9)^9)^9)^9)", Dimension::length, "k"),
        InputError);
}

namespace {

using drydem::testing_support::temp_dir;

/// Three NCM spheres of radius 3 um on the substrate of a 40 um box, one line each (lines 2-4).
std::string packing(const std::string& third = "3,1,3e-6,4740,30e-6,30e-6,3e-6") {
    return "id,type,radius_m,density_kg_m3,x_m,y_m,z_m\n1,1,3e-6,4740,10e-6,10e-6,3e-6\n"
           "2,1,3e-6,4740,16.5e-6,10e-6,3e-6\n" +
           third + "\n";
}

std::string geometry_error(const std::string& text, double box = 40e-6) {
    const fs::path file = temp_dir() / "p.csv";
    std::ofstream(file, std::ios::binary) << text;
    try {
        check_particle_geometry(read_particles(file), box, box, file);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(ParticleGeometry, PossiblePackingsPass) {
    EXPECT_EQ(geometry_error(packing()), "");
    // Touching and slightly overlapping spheres are packings.
    EXPECT_EQ(geometry_error(packing("3,1,3e-6,4740,10e-6,15.5e-6,3e-6")),
              ""); // 0.5 um into particle 1
    // The peers' settled bed (7,526 spheres, LAMMPS data) passes.
    const fs::path bed = fs::path(DRYDEM_SOURCE_DIR "/tests/data/peers/settled_30um.data");
    const ParticleFile f = read_particles(bed);
    EXPECT_NO_THROW(check_particle_geometry(f, *f.lx, *f.ly, bed));
}

TEST(ParticleGeometry, ImpossibleParticlesNameTheLineAndTheReason) {
    const std::string same = geometry_error(packing("3,1,3e-6,4740,10e-6,10e-6,3e-6"));
    EXPECT_TRUE(has(same, "particle 1 (line 2) and particle 3 (line 4) coincide")) << same;
    const std::string deep = geometry_error(packing("3,1,3e-6,4740,11e-6,10e-6,3e-6"));
    EXPECT_TRUE(has(deep, "overlap grossly")) << deep;
    const std::string below = geometry_error(packing("3,1,3e-6,4740,30e-6,30e-6,-1e-6"));
    EXPECT_TRUE(has(below, "particle 3 (line 4) has its centre below the substrate")) << below;
    const std::string sunk = geometry_error(packing("3,1,3e-6,4740,30e-6,30e-6,0.2e-6"));
    EXPECT_TRUE(has(sunk, "sunk into the substrate by more than 90 % of its radius")) << sunk;
    // A soft CB pressed 80 % into the substrate, as in our own 20.1 mg/cm² films, is a packing.
    EXPECT_EQ(geometry_error(packing("3,1,3e-6,4740,30e-6,30e-6,0.6e-6")), "");
    const std::string huge = geometry_error(packing("3,1,1,4740,30e-6,30e-6,2"));
    EXPECT_TRUE(has(huge, "particle 3 (line 4) has radius 1e+06 um, too large")) << huge;
    const std::string far = geometry_error(packing("3,1,3e-6,4740,1,30e-6,3e-6"));
    EXPECT_TRUE(has(far, "more than 10 box lengths outside")) << far;
    // Across the periodic edge: x = 0.5 um and x = 39.5 um are 1 um apart.
    const std::string wrap =
        geometry_error("id,type,radius_m,x_m,y_m,z_m\n1,1,3e-6,0.5e-6,10e-6,3e-6\n"
                       "2,1,3e-6,39.5e-6,10e-6,3e-6\n");
    EXPECT_TRUE(has(wrap, "overlap grossly")) << wrap;
}

TEST(ParticleGeometry, InvertedDumpBoxIsRefusedAtItsLine) {
    const fs::path file = temp_dir() / "inverted.lammpstrj";
    std::ofstream(file)
        << "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS pp pp fm\n"
           "4e-05 0\n0 4e-05\n0 1e-4\nITEM: ATOMS id type radius x y z\n1 1 3e-6 1e-5 1e-5 3e-6\n";
    try {
        (void)read_particles(file);
        ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(
            has(e.what(), "inverted.lammpstrj:6: box bounds 4e-05 0 in x are inverted or empty"))
            << e.what();
    }
}

// Issue 33: values in range key by key whose derived quantities were not finite (`drydem check`
// printed -nan or inf and accepted them). Each is refused, naming a key behind it.
TEST(DerivedQuantities, NonFiniteModelQuantitiesAreRefused) {
    const std::pair<std::string, std::string> cases[] = {
        {"materials.poisson_ratio=-1", "materials.poisson_ratio"},
        {"materials.substrate_poisson_ratio=-1", "materials.substrate_poisson_ratio"},
        {"scaling.hamaker_factor=1e308", "scaling.hamaker_factor"},
        {"lubrication.kappa_c=1e-300", "lubrication.kappa_c"},
        {"scaling.viscosity_reduction=1e-300", "scaling.viscosity_reduction"},
        {"materials.cb_youngs_modulus=1e-300", "materials.cb_youngs_modulus"},
        {"analysis.voxel_size=1e-300", "analysis.voxel_size"},
    };
    for (const auto& [set, key] : cases) {
        const std::string msg = config_error({set});
        EXPECT_TRUE(has(msg, key)) << set << ": " << msg;
        EXPECT_FALSE(has(msg, "nan")) << set << ": " << msg;
    }
}

// A run estimated beyond a day is allowed but its estimate is there to warn with (`drydem check`,
// `drydem run`): k = 2.5 makes the default film ~1e11 steps.
TEST(DerivedQuantities, WallTimeEstimateOfAYearLongRun) {
    const DerivedQuantities d =
        derived_quantities(load_config("", "t", {"scaling.time_factor=2.5"}));
    EXPECT_GT(estimated_wall_time(d, 2), 365 * wall_time_warning);
    const DerivedQuantities paper =
        derived_quantities(load_config(default_config_toml(), "default"));
    EXPECT_LT(estimated_wall_time(paper, 2), wall_time_warning);
}
