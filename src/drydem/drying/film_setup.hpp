// SPDX-License-Identifier: MIT
// Set-up of a drying run (paper Sec. 4, model.md M-1, M-7, M-8.1): the film's recipe, the scaled
// parameters and the liquid-level schedule, and the particles of the wet film.
#pragma once
#include "drydem/drying/run_observer.hpp"
#include <filesystem>

namespace drydem {

/// Recipe (M-1), scaling (M-7), box and level schedule (M-8.1) of the config; no particles yet.
[[nodiscard]] Film describe_film(const Config& c);

/// Counts the NCM and CB particles into film.n_ncm, film.n_cb.
void count_species(Film& film, const ParticleStore& particles);

/// Particles from a file (a run's final.csv, `--particles`): species by type (type = species + 1),
/// density from the recipe where the file has none, positions wrapped into the box. InputError
/// where the file's box is not the config's or its geometry cannot be a film.
[[nodiscard]] ParticleStore particles_from_file(const std::filesystem::path& file,
                                                const FilmRecipe& recipe, const Box& box);

/// The wet film of a fresh run: particles inserted up to H_wet with run.seed, or read from
/// options.particles_file (InputError with the file line where they cannot be used).
[[nodiscard]] ParticleStore wet_film_particles(const Config& c, const RunOptions& options,
                                               const Film& film, spdlog::logger& log);

} // namespace drydem
