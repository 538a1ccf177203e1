// SPDX-License-Identifier: MIT
// Configuration parsing (docs/configuration.md): the embedded default equals Config{}, every
// example parses, and bad input throws InputError naming the key, the value and what is allowed.
#include "drydem/drying/derived_checks.hpp"
#include "drydem/core/error.hpp"
#include "drydem/io/config.hpp"
#include "drydem/io/config_schema.hpp"
#include "drydem/io/units.hpp"
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

namespace {
using namespace drydem;

/// The message of the InputError thrown by load_config (fails the test when none is thrown).
std::string input_error(std::string_view text, const std::vector<std::string>& overrides = {}) {
    try {
        load_config(text, "test.toml", overrides);
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no InputError for: " << text;
    return {};
}

// The embedded default (the paper's 20.1 mg/cm2 case, M-1 ... M-9) is written from
// io/config_keys.def, whose rows also give Config{}'s defaults: parsed back, every key's value
// equals the struct's default bit for bit (a default text that rounds differently, e.g. "0.67 um/s"
// against 0.670e-6 written another way, fails here, naming the key).
TEST(Config, EmbeddedDefaultEqualsConfigDefaultsBitForBit) {
    const Config parsed = load_config(default_config_toml(), "default");
    const Config defaults;
    const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
    for (const config_schema::Field& f : config_schema::schema().fields)
        std::visit(
            [&](auto member) {
                using T = std::remove_cvref_t<decltype(defaults.*member)>;
                if constexpr (std::is_same_v<T, double>) {
                    EXPECT_EQ(bits(parsed.*member), bits(defaults.*member))
                        << f.key << ": " << f.default_text << " reads as " << parsed.*member;
                } else if constexpr (std::is_same_v<T, std::vector<double>>) {
                    ASSERT_EQ((parsed.*member).size(), (defaults.*member).size()) << f.key;
                    for (std::size_t i = 0; i < (defaults.*member).size(); ++i)
                        EXPECT_EQ(bits((parsed.*member)[i]), bits((defaults.*member)[i]))
                            << f.key << "[" << i << "]";
                } else {
                    EXPECT_EQ(parsed.*member, defaults.*member) << f.key;
                }
            },
            f.member);
    EXPECT_EQ(to_toml(parsed), to_toml(defaults));
    EXPECT_EQ(parsed.name, "lippke2022-20.1mgcm2");
    EXPECT_EQ(parsed.areal_loading, 0.201);
}

// The schema's rows are well formed: keys unique and in their section, every key documented with
// a default text, and every section of the default text is a TOML table that holds its keys.
TEST(Config, EveryKeyIsDeclaredOnceInItsSection) {
    const auto& s = config_schema::schema();
    std::set<std::string_view> keys;
    std::string_view section;
    for (const config_schema::Row& r : s.rows) {
        if (r.kind == config_schema::Row::section) section = r.text;
        if (r.kind != config_schema::Row::key) continue;
        const config_schema::Field& f = s.fields[r.field];
        EXPECT_TRUE(keys.insert(f.key).second) << f.key << " is declared twice";
        EXPECT_EQ(f.section(), section) << f.key << " stands under [" << section << "]";
        EXPECT_FALSE(f.default_text.empty()) << f.key;
        EXPECT_FALSE(f.doc.empty()) << f.key;
        EXPECT_EQ(config_schema::find(f.key), &f);
    }
    EXPECT_EQ(keys.size(), s.fields.size());
    EXPECT_EQ(config_schema::find("run.nmae"), nullptr);
}

// docs/configuration.md is `drydem config doc`: the key reference cannot drift from the schema.
TEST(Config, KeyReferenceDocIsGeneratedFromTheSchema) {
    const std::filesystem::path doc =
        std::filesystem::path(DRYDEM_SOURCE_DIR) / "docs" / "configuration.md";
    std::ifstream in(doc);
    ASSERT_TRUE(in) << doc;
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), config_reference_markdown())
        << "docs/configuration.md differs from the schema (src/drydem/io/config_keys.def); "
           "regenerate it: "
           "build/drydem config doc > docs/configuration.md";
    for (const config_schema::Field& f : config_schema::schema().fields)
        EXPECT_NE(text.str().find(fmt::format("| `{}` |", f.key)), std::string::npos) << f.key;
}

// The SI unit the key reference names for each dimension is one parse_quantity reads as 1.
TEST(Config, SiUnitOfEveryDimensionReadsBack) {
    for (int d = int(Dimension::length); d <= int(Dimension::diffusivity); ++d) {
        const auto dim = Dimension(d);
        ASSERT_FALSE(si_unit(dim).empty()) << dimension_name(dim);
        EXPECT_EQ(parse_quantity(fmt::format("1 {}", si_unit(dim)), dim, "test"), 1.0)
            << si_unit(dim);
    }
    EXPECT_EQ(si_unit(Dimension::dimensionless), "");
}

// The analysis's material inputs carry their units (issue 15): conductivities in S/m (siemens, not
// seconds), the binder's diffusivity in m^2/s; a wrong unit names the key.
TEST(Config, ConductivityAndDiffusivityHaveUnits) {
    EXPECT_DOUBLE_EQ(parse_quantity("1 mS/cm", Dimension::electrical_conductivity, "k"), 0.1);
    EXPECT_DOUBLE_EQ(parse_quantity("2 S/m", Dimension::electrical_conductivity, "k"), 2.0);
    EXPECT_DOUBLE_EQ(parse_quantity("1 cm^2/s", Dimension::diffusivity, "k"), 1e-4);
    const Config c = load_config("[analysis]\nncm_conductivity = \"10 mS/m\"\n"
                                 "binder_diffusivity = \"6.5 um^2/s\"\n",
                                 "t", {});
    EXPECT_DOUBLE_EQ(c.analysis_ncm_conductivity, 1e-2);
    EXPECT_DOUBLE_EQ(c.analysis_binder_diffusivity, 6.5e-12);
    const std::string msg = input_error("[analysis]\ncb_conductivity = \"100 s/m\"\n");
    EXPECT_NE(msg.find("analysis.cb_conductivity"), std::string::npos) << msg;
    EXPECT_NE(msg.find("electrical conductivity"), std::string::npos) << msg;
}

// Every shipped example is a valid configuration.
TEST(Config, EveryExampleParses) {
    const std::filesystem::path dir = std::filesystem::path(DRYDEM_SOURCE_DIR) / "examples";
    int n = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".toml") continue;
        ++n;
        EXPECT_NO_THROW(load_config_file(entry.path().string())) << entry.path();
    }
    EXPECT_GE(n, 6); // quick, quick_hamaker_printed, paper_20.1 ... paper_35.4
}

// The four paper loadings (M-8.1, paper Table 2) and the C-12 sensitivity case.
TEST(Config, PaperExamplesCarryTable2Rates) {
    const std::filesystem::path dir = std::filesystem::path(DRYDEM_SOURCE_DIR) / "examples";
    struct Case {
        const char* file;
        double loading, s1, s2;
        const char* name;
    };
    for (const Case& k :
         {Case{"paper_20.1.toml", 0.201, 0.670e-6, 1.193e-6, "lippke2022-20.1mgcm2"},
          Case{"paper_25.2.toml", 0.252, 0.683e-6, 1.323e-6, "lippke2022-25.2mgcm2"},
          Case{"paper_30.3.toml", 0.303, 0.667e-6, 1.360e-6, "lippke2022-30.3mgcm2"},
          Case{"paper_35.4.toml", 0.354, 0.650e-6, 1.383e-6, "lippke2022-35.4mgcm2"}}) {
        const Config c = load_config_file((dir / k.file).string());
        EXPECT_EQ(c.name, k.name);
        EXPECT_NEAR(c.areal_loading, k.loading, 1e-12);
        EXPECT_DOUBLE_EQ(c.box_x, 75e-6);
        EXPECT_DOUBLE_EQ(c.box_y, 75e-6);
        ASSERT_EQ(c.shrinkage_rates.size(), 2u);
        EXPECT_NEAR(c.shrinkage_rates[0], k.s1, 1e-15);
        EXPECT_NEAR(c.shrinkage_rates[1], k.s2, 1e-15);
        // No pinned step: a 1e-11 s cap would make the semi-implicit run ten times longer.
        EXPECT_EQ(c.time_step, Config{}.time_step) << k.file;
    }
    const Config quick = load_config_file((dir / "quick.toml").string());
    const Config printed = load_config_file((dir / "quick_hamaker_printed.toml").string());
    EXPECT_NE(printed.name, quick.name);
    EXPECT_DOUBLE_EQ(printed.hamaker_ncm_cb, 9.5e-19);
    Config same = printed;
    same.name = quick.name;
    same.hamaker_ncm_cb = quick.hamaker_ncm_cb;
    EXPECT_EQ(to_toml(same), to_toml(quick)); // otherwise identical to the quick case
}

TEST(Config, UnknownKeyNamesKeyAndSuggestsNearest) {
    const std::string msg = input_error("[contact]\nfrictoin = 0.5\n");
    EXPECT_NE(msg.find("contact.frictoin"), std::string::npos) << msg;
    EXPECT_NE(msg.find("did you mean 'contact.friction'"), std::string::npos) << msg;
    // Also through an override.
    const std::string via_set = input_error("", {"contact.frictoin=0.5"});
    EXPECT_NE(via_set.find("contact.friction'"), std::string::npos) << via_set;
}

TEST(Config, WrongUnitNamesKeyAndValue) {
    const std::string msg = input_error("[film]\nbox_x = \"3 kg\"\n");
    EXPECT_NE(msg.find("film.box_x"), std::string::npos) << msg;
    EXPECT_NE(msg.find("3 kg"), std::string::npos) << msg;
}

TEST(Config, OutOfRangeIsRejected) {
    const std::string msg = input_error("[contact]\nrestitution = 1.5\n");
    EXPECT_NE(msg.find("contact.restitution"), std::string::npos) << msg;
    EXPECT_NE(msg.find("1.5"), std::string::npos) << msg;
    EXPECT_NE(msg.find("out of range"), std::string::npos) << msg;
    // The box must hold no two images of a partner (M-2.5): >= 36 um.
    EXPECT_THROW(load_config("", "t", {"film.box_x=30um"}), InputError);
}

TEST(Config, SetOverridesApply) {
    const Config c =
        load_config(default_config_toml(), "default",
                    {"run.seed=7", "film.areal_loading=\"5 mg/cm^2\"", "film.box_x=50um"});
    EXPECT_EQ(c.seed, 7u);
    EXPECT_NEAR(c.areal_loading, 0.05, 1e-15); // 5 mg/cm2 = 0.05 kg/m2
    EXPECT_NEAR(c.box_x, 50e-6, 1e-18);
    EXPECT_DOUBLE_EQ(c.box_y, 75e-6); // untouched
    EXPECT_NE(input_error("", {"run.seed"}).find("KEY=VALUE"), std::string::npos);
}

TEST(Config, MassFractionsMustSumToOne) {
    const std::string msg = input_error("[formulation]\nncm_mass_fraction = 0.90\n");
    EXPECT_NE(msg.find("mass_fraction"), std::string::npos) << msg;
    EXPECT_NE(msg.find("sum to 1"), std::string::npos) << msg;
    EXPECT_NO_THROW(
        load_config("[formulation]\nncm_mass_fraction = 0.90\npvdf_mass_fraction = 0.05\n"
                    "cb_mass_fraction = 0.05\n",
                    "t"));
}

// The resolved config written into each output folder reads back to the same configuration.
TEST(Config, ToTomlRoundTrip) {
    Config c =
        load_config(default_config_toml(), "default",
                    {"run.seed=99", "film.box_x=\"41.3 um\"", "materials.contact_angle=\"33 deg\"",
                     "lubrication.uses_reduced_viscosity=true", "numerics.stability_guard=\"warn\"",
                     "dryer.shrinkage_rates=[\"0.7 um/s\", \"1.1 um/s\", \"0.4 um/s\"]"});
    const std::string text = to_toml(c);
    const Config back = load_config(text, "resolved.toml");
    EXPECT_EQ(to_toml(back), text);
    EXPECT_EQ(back.seed, 99u);
    EXPECT_EQ(back.shrinkage_rates.size(), 3u);
    EXPECT_TRUE(back.lubrication_uses_reduced_viscosity);
    EXPECT_EQ(to_toml(load_config(to_toml(Config{}), "defaults")), to_toml(Config{}));
}

} // namespace

// Minimum image needs a box side of at least twice the widest reach plus skin: for two 11.35 um
// spheres d + r_L = 1.5 d (M-4.1), so 2 (17.025 + 0.2) um = 34.45 um with the paper scheme's
// semi-implicit skin; 20 um spheres need 60.4 um.
TEST(Config, BoxMustHoldTwiceTheLargestInteractionRange) {
    EXPECT_NO_THROW(load_config("", "t", {"film.box_x=36um", "film.box_y=36um"}));
    const std::string msg = input_error(
        "", {"formulation.ncm_diameters=[\"20 um\"]", "film.box_x=50um", "film.box_y=80um"});
    EXPECT_NE(msg.find("film.box_x"), std::string::npos) << msg;
    EXPECT_NE(msg.find("50 um"), std::string::npos) << msg;
    EXPECT_NE(msg.find("60.4"), std::string::npos) << msg;
    EXPECT_NO_THROW(load_config(
        "", "t", {"formulation.ncm_diameters=[\"20 um\"]", "film.box_x=61um", "film.box_y=61um"}));
}

// The reach is the pair laws' (interaction_range), not a fixed 1.5 d: a van der Waals cutoff of
// 10 um beyond contact makes two 11.35 um spheres reach 21.35 um, so a 40 um box (enough with the
// default cutoff r_L) is refused: 2 (21.35 + 0.2) um = 43.1 um.
TEST(Config, BoxBoundFollowsTheForceLawsRange) {
    EXPECT_NO_THROW(load_config("", "t", {"film.box_x=40um", "film.box_y=40um"}));
    const std::string msg =
        input_error("", {"film.box_x=40um", "film.box_y=40um", "van_der_waals.cutoff=\"10 um\""});
    EXPECT_NE(msg.find("film.box_x"), std::string::npos) << msg;
    EXPECT_NE(msg.find("43.1"), std::string::npos) << msg;
    EXPECT_NE(msg.find("11.35 and 11.35 um"), std::string::npos) << msg;
}

TEST(Config, NegativeOrZeroDiameterIsRejected) {
    const std::string msg = input_error("", {"formulation.ncm_diameters=[\"-3 um\"]"});
    EXPECT_NE(msg.find("formulation.ncm_diameters"), std::string::npos) << msg;
    EXPECT_NE(msg.find("out of range"), std::string::npos) << msg;
    EXPECT_NE(input_error("", {"formulation.cb_diameter=0"}).find("formulation.cb_diameter"),
              std::string::npos);
}

TEST(Config, StudyMeasuredValuesNeedOnePerMeasuredLoading) {
    const Config ok =
        load_config("[study]\nloadings = [\"20.1 mg/cm^2\", \"25.2 mg/cm^2\"]\nseeds = 2\n"
                    "measured_loadings = [\"20.1 mg/cm^2\"]\nmeasured_thickness = [\"84 um\"]\n",
                    "t");
    ASSERT_EQ(ok.study_loadings.size(), 2u);
    EXPECT_DOUBLE_EQ(ok.study_loadings[1], 0.252);
    EXPECT_DOUBLE_EQ(ok.measured_thickness[0], 84e-6);
    EXPECT_TRUE(ok.measured_density.empty());
    const std::string msg =
        input_error("[study]\nmeasured_loadings = [\"20.1 mg/cm^2\", \"25.2 mg/cm^2\"]\n"
                    "measured_thickness = [\"84 um\"]\n");
    EXPECT_NE(msg.find("study.measured_thickness"), std::string::npos) << msg;
    EXPECT_NE(msg.find("one per measured loading"), std::string::npos) << msg;
    EXPECT_NE(input_error("[study]\nseeds = 0\n").find("study.seeds"), std::string::npos);
    // Arrays that must not be empty still say so.
    EXPECT_NE(input_error("[formulation]\nncm_diameters = []\n").find("non-empty"),
              std::string::npos);
}

TEST(Config, WrongTypeNamesKey) {
    const std::string msg = input_error("[run]\nseed = \"many\"\n");
    EXPECT_NE(msg.find("run.seed"), std::string::npos) << msg;
    EXPECT_NE(msg.find("integer"), std::string::npos) << msg;
    EXPECT_NE(input_error("[lubrication]\nenabled = 1\n").find("true or false"), std::string::npos);
}

// force_ratio derives the capillary and Hamaker factors from k/b (docs/model.md M-7): a value of the
// paper scheme's own is refused, naming the key and what is allowed, never ignored.
TEST(Config, ForceRatioRefusesItsDerivedFactors) {
    for (const char* key : {"scaling.capillary_factor", "scaling.hamaker_factor"}) {
        const std::string msg =
            input_error("", {"scaling.scheme=\"force_ratio\"", std::string(key) + "=9000"});
        EXPECT_NE(msg.find(key), std::string::npos) << msg;
        EXPECT_NE(msg.find("force_ratio"), std::string::npos) << msg;
        EXPECT_NE(msg.find("allowed: 0"), std::string::npos) << msg;
    }
    const Config c =
        load_config("", "t", {"scaling.scheme=\"force_ratio\"", "scaling.stiffness_factor=20"});
    EXPECT_EQ(c.scaling_scheme, "force_ratio");
    EXPECT_EQ(c.stiffness_factor, 20.0);
    EXPECT_NE(input_error("", {"scaling.scheme=\"fast\""}).find("paper"), std::string::npos);
    EXPECT_NE(input_error("", {"scaling.stiffness_factor=0"}).find("scaling.stiffness_factor"),
              std::string::npos);
}

// numerics.critical_step_fraction (docs/model.md "Stability guard"): above 0.5 only with the
// semi-implicit kick, never above 0.65, and not at all with the quasi-static step.
TEST(Config, CriticalStepFractionAboveHalfOnlySemiImplicit) {
    EXPECT_EQ(load_config("", "t", {"numerics.critical_step_fraction=0.65"}).critical_step_fraction,
              0.65);
    EXPECT_EQ(
        load_config("", "t",
                    {"numerics.integrator=\"explicit\"", "numerics.critical_step_fraction=0.25"})
            .critical_step_fraction,
        0.25);
    const std::string explicit_msg = input_error(
        "", {"numerics.integrator=\"explicit\"", "numerics.critical_step_fraction=0.6"});
    EXPECT_NE(explicit_msg.find("numerics.critical_step_fraction = 0.6"), std::string::npos)
        << explicit_msg;
    EXPECT_NE(explicit_msg.find("up to 0.5"), std::string::npos) << explicit_msg;
    const std::string qs_msg = input_error(
        "", {"numerics.integrator=\"quasi_static\"", "numerics.critical_step_fraction=0.4"});
    EXPECT_NE(qs_msg.find("no stability guard"), std::string::npos) << qs_msg;
    EXPECT_NE(input_error("", {"numerics.critical_step_fraction=0.7"}).find("[0, 0.65]"),
              std::string::npos);
    EXPECT_NE(input_error("", {"numerics.critical_step_fraction=-0.1"}).find("[0, 0.65]"),
              std::string::npos);
}

// numerics.implicit_stiffness (docs/model.md M-9.1) joins the semi-implicit kick only; "auto" (the
// default) turns it on where the guard alone sets the step (the paper's scheme) and off elsewhere.
TEST(Config, ImplicitStiffnessOnlyWithTheSemiImplicitKick) {
    const Config d = load_config("", "t", {});
    EXPECT_FALSE(d.implicit_stiffness.has_value());
    EXPECT_TRUE(d.implicit_stiffness_on());
    EXPECT_FALSE(
        load_config("", "t", {"numerics.implicit_stiffness=false"}).implicit_stiffness_on());
    EXPECT_TRUE(load_config("", "t", {"numerics.implicit_stiffness=true"}).implicit_stiffness_on());
    EXPECT_TRUE(
        load_config("", "t", {"numerics.implicit_stiffness=\"auto\""}).implicit_stiffness_on());
    // "auto" elsewhere: off, and no refusal.
    EXPECT_FALSE(
        load_config("", "t", {"numerics.integrator=\"explicit\""}).implicit_stiffness_on());
    EXPECT_FALSE(
        load_config("", "t", {"numerics.integrator=\"quasi_static\""}).implicit_stiffness_on());
    EXPECT_FALSE(load_config("", "t", {"scaling.scheme=\"force_ratio\""}).implicit_stiffness_on());
    EXPECT_TRUE(
        load_config("", "t", {"scaling.scheme=\"force_ratio\"", "numerics.implicit_stiffness=true"})
            .implicit_stiffness_on());
    // Written out and read back, "auto" stays "auto" (a resumed run re-derives it).
    EXPECT_FALSE(load_config(to_toml(d), "t", {}).implicit_stiffness.has_value());
    EXPECT_EQ(
        load_config(to_toml(load_config("", "t", {"numerics.implicit_stiffness=false"})), "t", {})
            .implicit_stiffness,
        std::optional<bool>(false));
    EXPECT_NE(input_error("", {"numerics.implicit_stiffness=\"yes\""})
                  .find("must be true, false or \"auto\""),
              std::string::npos);
    for (const char* integrator : {"explicit", "quasi_static"}) {
        const std::string m =
            input_error("", {std::string("numerics.integrator=\"") + integrator + "\"",
                             "numerics.implicit_stiffness=true"});
        EXPECT_NE(m.find("numerics.implicit_stiffness = true with numerics.integrator"),
                  std::string::npos)
            << m;
    }
    EXPECT_NE(input_error("", {"numerics.implicit_stiffness=1.5"}).find("implicit_stiffness"),
              std::string::npos);
}

// 0 (the default) is the integrator's own step: the guard alone (cap 1e-9 s, fraction 0.65) for
// the semi-implicit kick in the paper's scheme, where it was measured not to move the film;
// 1e-10 s and 0.5 in the force-ratio scheme, whose film moved at 0.65; 1e-11 s and 0.5 explicit.
TEST(Config, DefaultStepDependsOnIntegratorAndScheme) {
    const Config paper = load_config("", "t", {});
    EXPECT_EQ(paper.time_step_cap(), 1e-9);
    EXPECT_EQ(paper.critical_step_fraction_value(), 0.65);
    const Config force_ratio = load_config("", "t", {"scaling.scheme=\"force_ratio\""});
    EXPECT_EQ(force_ratio.time_step_cap(), 1e-10);
    EXPECT_EQ(force_ratio.critical_step_fraction_value(), 0.5);
    const Config expl = load_config("", "t", {"numerics.integrator=\"explicit\""});
    EXPECT_EQ(expl.time_step_cap(), 1e-11);
    EXPECT_EQ(expl.critical_step_fraction_value(), 0.5);
    const Config set =
        load_config("", "t", {"run.time_step=2e-10", "numerics.critical_step_fraction=0.3"});
    EXPECT_EQ(set.time_step_cap(), 2e-10);
    EXPECT_EQ(set.critical_step_fraction_value(), 0.3);
    EXPECT_EQ(load_config("", "t", {"numerics.integrator=\"quasi_static\""})
                  .critical_step_fraction_value(),
              0.5);
    // The skin: thinner where the guard alone sets the step, not for the calendering that follows.
    EXPECT_EQ(paper.neighbor_skin(), 0.2e-6);
    EXPECT_EQ(paper.neighbor_skin(true), 0.3e-6);
    EXPECT_EQ(force_ratio.neighbor_skin(), 0.3e-6);
    EXPECT_EQ(expl.neighbor_skin(), 0.1e-6);
}
