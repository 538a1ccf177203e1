// SPDX-License-Identifier: MIT
// The drying run's progress in a checkpoint (drying/run_state.hpp): named fields, one function
// to save and load them, and a clear error where the checkpoint's fields are not this build's.
#include "drydem/core/error.hpp"
#include "drydem/drying/run_state.hpp"
#include <gtest/gtest.h>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

using namespace drydem;

namespace {
struct Part {
    double next = 0.0;
    std::int32_t count = 0;
    void fields(StateFields& f) {
        f("part.next", next);
        f("part.count", count);
    }
};

std::vector<unsigned char> saved(const std::function<void(StateFields&)>& visit) {
    StateFields f;
    visit(f);
    BinaryWriter w;
    f.write(w);
    return w.bytes();
}

std::string load_error(const std::vector<unsigned char>& bytes,
                       const std::function<void(StateFields&)>& visit) {
    try {
        BinaryReader r(bytes, "state.bin");
        StateFields f(r, "state.bin");
        visit(f);
        f.check_all_loaded();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}
} // namespace

TEST(RunState, FieldsRoundTripBitForBit) {
    Part a{0.1 + 0.2, 7};
    const auto bytes = saved([&](StateFields& f) { a.fields(f); });
    Part b;
    EXPECT_EQ(load_error(bytes, [&](StateFields& f) { b.fields(f); }), "");
    EXPECT_EQ(b.next, a.next);
    EXPECT_EQ(b.count, 7);
}

TEST(RunState, AMissingFieldIsRefusedByName) {
    const auto bytes = saved([](StateFields& f) {
        double next = 1.0;
        f("part.next", next);
    });
    Part b;
    const std::string e = load_error(bytes, [&](StateFields& f) { b.fields(f); });
    EXPECT_NE(e.find("no run progress field 'part.count'"), std::string::npos) << e;
    EXPECT_NE(e.find("written by DryDEM"), std::string::npos) << e;
}

TEST(RunState, AFieldOfAnotherSizeIsRefused) {
    const auto bytes = saved([](StateFields& f) {
        double next = 1.0;
        std::int64_t count = 3; // was 64 bits wide in the writing build
        f("part.next", next);
        f("part.count", count);
    });
    Part b;
    const std::string e = load_error(bytes, [&](StateFields& f) { b.fields(f); });
    EXPECT_NE(e.find("'part.count' has 8 bytes, this build expects 4"), std::string::npos) << e;
}

TEST(RunState, AnUnknownFieldIsRefused) {
    const auto bytes = saved([](StateFields& f) {
        Part a;
        a.fields(f);
        bool extra = true;
        f("other.flag", extra);
    });
    Part b;
    const std::string e = load_error(bytes, [&](StateFields& f) { b.fields(f); });
    EXPECT_NE(e.find("'other.flag' is unknown to this build"), std::string::npos) << e;
}

TEST(RunState, AnotherFormatIsRefusedBeforeAnyField) {
    BinaryWriter w;
    w.pod(std::uint32_t(StateFields::kFormat + 1));
    w.str("DryDEM 9.9.9 (future)");
    w.pod(std::uint64_t(0));
    const std::string e = load_error(w.bytes(), [](StateFields&) {});
    EXPECT_NE(e.find("format"), std::string::npos) << e;
    EXPECT_NE(e.find("DryDEM 9.9.9 (future)"), std::string::npos) << e;
}

TEST(RunState, OneNameSavedTwiceIsAProgrammingError) {
    StateFields f;
    double x = 1.0;
    f("a", x);
    EXPECT_THROW(f("a", x), std::logic_error);
}

TEST(RunState, VectorsAndTextsRoundTripWithTheirLength) {
    std::vector<double> curve{0.5, 0.25 + 1e-17, -3.0};
    std::vector<std::int64_t> none;
    std::string run = "runs/L20.1 \"quoted\"";
    const auto bytes = saved([&](StateFields& f) {
        f("a.curve", curve);
        f("a.none", none);
        f("a.run", run);
    });
    std::vector<double> c2{9.0};
    std::vector<std::int64_t> n2{1, 2};
    std::string r2 = "old";
    EXPECT_EQ(load_error(bytes,
                         [&](StateFields& f) {
                             EXPECT_TRUE(f.has("a.curve"));
                             EXPECT_FALSE(f.has("a.other"));
                             f("a.curve", c2);
                             f("a.none", n2);
                             f("a.run", r2);
                         }),
              "");
    EXPECT_EQ(c2, curve);
    EXPECT_TRUE(n2.empty());
    EXPECT_EQ(r2, run);
}

TEST(RunState, AVectorOfAnotherElementSizeIsRefused) {
    const auto bytes = saved([](StateFields& f) {
        std::vector<char> three{1, 2, 3};
        f("a.values", three);
    });
    const std::string e = load_error(bytes, [](StateFields& f) {
        std::vector<double> values;
        f("a.values", values);
    });
    EXPECT_NE(e.find("'a.values' has 3 bytes, this build expects a multiple of 8"),
              std::string::npos)
        << e;
}
