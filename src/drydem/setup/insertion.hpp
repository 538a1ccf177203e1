// SPDX-License-Identifier: MIT
// Random sequential addition without overlap (model.md C-2): largest particles first, uniform in
// x, y and in r ≤ z ≤ H - r, so that every particle starts fully immersed below the level.
#pragma once
#include "drydem/core/box.hpp"
#include "drydem/core/particles.hpp"
#include "drydem/setup/formulation.hpp"
#include <cstdint>

namespace drydem {

/// Inserts every particle of the recipe into [0, lx) x [0, ly) x [0, height]. Species index =
/// position in recipe.species; ids 1..N in insertion order. Throws InputError when a particle
/// cannot be placed within `max_trials` attempts.
ParticleStore insert_particles(const FilmRecipe& recipe, const Box& box, double height,
                               std::uint64_t seed, std::uint64_t max_trials = 1000000);

} // namespace drydem
