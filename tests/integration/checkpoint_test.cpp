// SPDX-License-Identifier: MIT
// Checkpoints (README "Outputs" `checkpoint/`, ARCHITECTURE.md): an engine restored from
// the serialized state continues bit for bit like the one that never stopped, with every drying
// force law on (contact histories, lubrication, capillary front, substrate); damaged or foreign
// files are refused with a clear error.
#include "drydem/drying/law_parameters.hpp"
#include "drydem/drying/derived_checks.hpp"
#include "drydem/core/error.hpp"
#include "drydem/drying/liquid_level.hpp"
#include "drydem/drying/scaling.hpp"
#include "drydem/engine/simulation.hpp"
#include "drydem/output/checkpoint.hpp"
#include "drydem/setup/formulation.hpp"
#include "drydem/setup/insertion.hpp"
#include <gtest/gtest.h>
#include "thin_film_case.hpp"
#include "test_dirs.hpp"
#include <cstring>
#include <fstream>

using namespace drydem;

namespace {

using test::Case;
using test::thin_film;

/// The quasi-static step at this case's scaled level speed: a step of ~1e-9 s moves the level
/// ~10 nm, so that 60 steps carry the level into the film and its particles into contact.
EngineSettings quasi_static() {
    EngineSettings es;
    es.integrator = Integrator::quasi_static;
    es.dt = 0.0;
    es.quasi_static.max_step = 1e-9;
    es.quasi_static.max_displacement = 40e-9;
    es.quasi_static.tolerance = 1e-6;
    return es;
}

Simulation make(const Case& k, ParticleStore p, int threads, EngineSettings es = {}) {
    if (es.integrator != Integrator::quasi_static) es.dt = 8e-12;
    es.skin = 0.01e-6; // frequent rebuilds and re-sorts within a few hundred steps
    es.sort_every = 2;
    es.threads = threads;
    es.initial_liquid_level = k.schedule.level(0.0);
    Simulation sim(std::move(p), Box{k.c.box_x, k.c.box_y},
                   make_drying_force_field(k.c, k.recipe, k.scaled), es);
    const LiquidLevelSchedule sched = k.schedule;
    sim.set_liquid_level_schedule([sched](double t) { return sched.level(t); });
    return sim;
}

Simulation restore(const Case& k, const std::vector<unsigned char>& bytes, int threads,
                   EngineSettings es = {}) {
    BinaryReader r(bytes, "memory");
    EngineState s = read_engine_state(r);
    EXPECT_TRUE(r.at_end());
    es.skin = 0.01e-6;
    es.sort_every = 2;
    es.threads = threads;
    Simulation sim(std::move(s), Box{k.c.box_x, k.c.box_y},
                   make_drying_force_field(k.c, k.recipe, k.scaled), es);
    const LiquidLevelSchedule sched = k.schedule;
    sim.set_liquid_level_schedule([sched](double t) { return sched.level(t); });
    return sim;
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

} // namespace

TEST(Checkpoint, RestoredEngineContinuesBitForBit) {
    const Case k = thin_film();
    for (int threads : {1, 2}) {
        Simulation a = make(
            k, insert_particles(k.recipe, Box{k.c.box_x, k.c.box_y}, k.recipe.wet_film_height, 5),
            threads);
        a.run(400); // past several rebuilds and a re-sort, contacts formed
        ASSERT_GT(a.neighbors().builds(), 2u);
        BinaryWriter w;
        write_engine_state(w, a.state());
        Simulation b = restore(k, w.bytes(), threads);
        EXPECT_EQ(b.step_count(), a.step_count());
        // The step after a checkpoint may rebuild the list or not: both continue identically.
        a.run(400);
        b.run(400);
        const ParticleStore &pa = a.particles(), &pb = b.particles();
        EXPECT_TRUE(same_bits(pa.id, pb.id)) << threads << " threads";
        EXPECT_TRUE(same_bits(pa.position, pb.position)) << threads << " threads";
        EXPECT_TRUE(same_bits(pa.velocity, pb.velocity)) << threads << " threads";
        EXPECT_TRUE(same_bits(pa.omega, pb.omega)) << threads << " threads";
        EXPECT_TRUE(same_bits(pa.force, pb.force)) << threads << " threads";
        EXPECT_TRUE(same_bits(a.body_states(), b.body_states())) << threads << " threads";
        EXPECT_EQ(a.time(), b.time());
        EXPECT_EQ(a.liquid_level(), b.liquid_level());
        EXPECT_EQ(a.neighbors().builds(), b.neighbors().builds());
        EXPECT_GT(a.neighbors().builds(), 4u);
        EXPECT_GT(a.stats().contacts, 0u);
        EXPECT_EQ(a.stats().contacts, b.stats().contacts);
    }
}

TEST(Checkpoint, QuasiStaticStepContinuesBitForBit) {
    const Case k = thin_film();
    for (int threads : {1, 2}) {
        Simulation a = make(
            k, insert_particles(k.recipe, Box{k.c.box_x, k.c.box_y}, k.recipe.wet_film_height, 5),
            threads, quasi_static());
        a.run(60);
        BinaryWriter w;
        write_engine_state(w, a.state());
        Simulation b = restore(k, w.bytes(), threads, quasi_static());
        a.run(60);
        b.run(60);
        const ParticleStore &pa = a.particles(), &pb = b.particles();
        EXPECT_TRUE(same_bits(pa.position, pb.position)) << threads << " threads";
        EXPECT_TRUE(same_bits(pa.velocity, pb.velocity)) << threads << " threads";
        EXPECT_TRUE(same_bits(a.body_states(), b.body_states())) << threads << " threads";
        EXPECT_EQ(a.time(), b.time());
        EXPECT_EQ(a.settings().dt, b.settings().dt);
        EXPECT_GT(a.neighbors().builds(), 2u);
        EXPECT_GT(a.stats().contacts, 0u);
        EXPECT_EQ(a.stats().contacts, b.stats().contacts);
    }
}

TEST(Checkpoint, FileIsVerifiedAndDamageIsRefused) {
    const auto dir = testing_support::temp_dir();
    BinaryWriter w;
    w.str("hello");
    w.vec(std::vector<double>{1.0, 2.5, -3.0});
    w.pod(std::int64_t(42));
    write_checkpoint_file(dir / "state.bin", w);
    {
        const auto bytes = read_checkpoint_file(dir / "state.bin");
        BinaryReader r(bytes, "state.bin");
        EXPECT_EQ(r.str(), "hello");
        EXPECT_EQ(r.vec<double>(), (std::vector<double>{1.0, 2.5, -3.0}));
        EXPECT_EQ(r.pod<std::int64_t>(), 42);
        EXPECT_TRUE(r.at_end());
        EXPECT_THROW(r.pod<double>(), InputError); // reading past the end
    }
    // One flipped bit in the payload.
    std::fstream f(dir / "state.bin", std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(20);
    char ch;
    f.seekg(20);
    f.get(ch);
    f.seekp(20);
    f.put(char(ch ^ 1));
    f.close();
    try {
        (void)read_checkpoint_file(dir / "state.bin");
        ADD_FAILURE() << "damaged checkpoint accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("damaged"), std::string::npos) << e.what();
    }
    std::ofstream(dir / "other.bin") << "not a checkpoint at all, just text";
    EXPECT_THROW((void)read_checkpoint_file(dir / "other.bin"), InputError);
    EXPECT_THROW((void)read_checkpoint_file(dir / "missing.bin"), InputError);
}

// The engine state starts with the pair laws' layout (names and state sizes): a checkpoint written
// by a build with another list of laws is refused before its pair states are misread.
TEST(Checkpoint, AnotherListOfLawsIsRefused) {
    // Another pair-law list, then another body-law list (a calendering plate added).
    const std::string pair = "pair " + std::string(PairLaws::layout()),
                      body = " body " + std::string(BodyLaws::layout());
    for (const std::string& other : {"pair hertz_mindlin:24;binder_bridge:16;" + body,
                                     pair + " body substrate_contact:24;plate:8;"}) {
        BinaryWriter w;
        w.vec(std::vector<char>(other.begin(), other.end()));
        BinaryReader r(w.bytes(), "state.bin");
        try {
            (void)read_engine_state(r);
            ADD_FAILURE() << "a checkpoint of another list of laws was accepted: " << other;
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(other), std::string::npos) << what;
            EXPECT_NE(what.find(law_layout_text()), std::string::npos) << what;
        }
    }
    // The layout of this build reads back as its own.
    BinaryWriter ok;
    const std::string mine = law_layout_text();
    EXPECT_EQ(mine, pair + body);
    ok.vec(std::vector<char>(mine.begin(), mine.end()));
    BinaryReader r2(ok.bytes(), "state.bin");
    try {
        (void)read_engine_state(r2);
        ADD_FAILURE() << "an empty engine state was accepted";
    } catch (const InputError& e) { // the rest is missing: truncated, not a layout error
        EXPECT_NE(std::string(e.what()).find("end early"), std::string::npos) << e.what();
    }
}
