// SPDX-License-Identifier: MIT
// Random sequential insertion (model.md C-2, M-1.6; V-15 "no initial overlap, all particles
// between the substrate and the level").
#include "drydem/core/error.hpp"
#include "drydem/setup/insertion.hpp"
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace {
using namespace drydem;

struct Film {
    Config config;
    FilmRecipe recipe;
    Box box;
};

Film small_film(double box_um, double loading_mg_cm2) {
    Film f;
    f.config.box_x = f.config.box_y = box_um * 1e-6;
    f.config.areal_loading = loading_mg_cm2 * 1e-2;
    f.recipe = make_recipe(f.config);
    f.box = Box{f.config.box_x, f.config.box_y};
    return f;
}

/// Checks counts per species, ids, bounds and (brute force, minimum image) overlaps.
void check_layout(const Film& f, const ParticleStore& p) {
    const FilmRecipe& r = f.recipe;
    const double h = r.wet_film_height;
    ASSERT_EQ(p.size(), std::size_t(r.particle_count()));
    std::vector<int> per_species(r.species.size(), 0);
    for (std::size_t i = 0; i < p.size(); ++i) {
        ASSERT_LT(p.species[i], r.species.size());
        const SizeClass& s = r.species[p.species[i]];
        ++per_species[p.species[i]];
        EXPECT_DOUBLE_EQ(p.radius[i], 0.5 * s.diameter);
        EXPECT_DOUBLE_EQ(p.density[i], s.density);
        EXPECT_EQ(p.id[i], i + 1); // ids 1..N in insertion order
        const Vec3& x = p.position[i];
        EXPECT_GE(x.x, 0.0);
        EXPECT_LT(x.x, f.box.lx);
        EXPECT_GE(x.y, 0.0);
        EXPECT_LT(x.y, f.box.ly);
        EXPECT_GE(x.z, p.radius[i]) << "particle " << i << " cuts the substrate";
        EXPECT_LE(x.z, h - p.radius[i]) << "particle " << i << " pierces the level";
        EXPECT_EQ(norm2(p.velocity[i]), 0.0);
    }
    for (std::size_t k = 0; k < r.species.size(); ++k)
        EXPECT_EQ(per_species[k], r.species[k].count);
    // Largest first (C-2): insertion order has non-increasing radius.
    for (std::size_t i = 1; i < p.size(); ++i) EXPECT_LE(p.radius[i], p.radius[i - 1]);
    std::size_t overlaps = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = i + 1; j < p.size(); ++j) {
            const double rr = p.radius[i] + p.radius[j];
            overlaps += norm2(f.box.minimum_image(p.position[i], p.position[j])) < rr * rr;
        }
    EXPECT_EQ(overlaps, 0u);
}

TEST(Insertion, Box40At5mgPerCm2) {
    const Film f = small_film(40, 5);
    const ParticleStore p = insert_particles(f.recipe, f.box, f.recipe.wet_film_height, 12345);
    check_layout(f, p);
}

TEST(Insertion, Box36At3mgPerCm2) {
    const Film f = small_film(36, 3); // smallest allowed box side (M-2.5)
    const ParticleStore p = insert_particles(f.recipe, f.box, f.recipe.wet_film_height, 7);
    check_layout(f, p);
}

TEST(Insertion, SeedMakesLayoutReproducible) {
    const Film f = small_film(36, 3);
    const double h = f.recipe.wet_film_height;
    const ParticleStore a = insert_particles(f.recipe, f.box, h, 42);
    const ParticleStore b = insert_particles(f.recipe, f.box, h, 42);
    const ParticleStore c = insert_particles(f.recipe, f.box, h, 43);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(a.size(), c.size());
    std::size_t same_as_c = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a.position[i].x, b.position[i].x);
        EXPECT_EQ(a.position[i].y, b.position[i].y);
        EXPECT_EQ(a.position[i].z, b.position[i].z);
        EXPECT_EQ(a.species[i], b.species[i]);
        same_as_c += a.position[i].x == c.position[i].x && a.position[i].z == c.position[i].z;
    }
    EXPECT_EQ(same_as_c, 0u); // a different seed gives a different layout
}

/// The message of the InputError thrown by insert_particles (fails the test when none is thrown).
std::string insertion_error(const Film& f, double height, std::uint64_t max_trials) {
    try {
        insert_particles(f.recipe, f.box, height, 1, max_trials);
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no InputError";
    return {};
}

// C-2: an impossible insertion aborts with a clear message, never with silent overlaps.
TEST(Insertion, ImpossibleCasesThrowInputError) {
    const Film f = small_film(40, 5);
    // Too few trials for a 42 % packing of spheres.
    const std::string crowded = insertion_error(f, f.recipe.wet_film_height, 2);
    EXPECT_NE(crowded.find("random insertion failed"), std::string::npos) << crowded;
    EXPECT_NE(crowded.find("2 trials"), std::string::npos) << crowded;
    // A film thinner than the largest diameter (11.35 um).
    const std::string thin = insertion_error(f, 10e-6, 1000000);
    EXPECT_NE(thin.find("film too thin"), std::string::npos) << thin;
    EXPECT_NE(thin.find("11.35"), std::string::npos) << thin;
}

} // namespace
