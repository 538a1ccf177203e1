// SPDX-License-Identifier: MIT
#include "drydem/drying/film_setup.hpp"
#include "drydem/core/error.hpp"
#include "drydem/io/particle_io.hpp"
#include "drydem/setup/insertion.hpp"
#include <fmt/format.h>
#include <spdlog/logger.h>
#include <algorithm>
#include <cmath>

namespace drydem {

ParticleStore particles_from_file(const std::filesystem::path& file, const FilmRecipe& recipe,
                                  const Box& box) {
    const ParticleFile in = read_particles(file);
    auto same = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(a, b); };
    if ((in.lx && !same(*in.lx, box.lx)) || (in.ly && !same(*in.ly, box.ly)))
        throw InputError(fmt::format(
            "--particles {}: the file's periodic box is {:.6g} x {:.6g} um but the config's is "
            "{:.6g} x {:.6g} um; set film.box_x and film.box_y to the file's box",
            file.string(), in.lx.value_or(box.lx) * 1e6, in.ly.value_or(box.ly) * 1e6, box.lx * 1e6,
            box.ly * 1e6));
    // Refused before step 1 with the line and the reason: coincident spheres or one below the
    // substrate would otherwise blow up and be blamed on the time step or the forces.
    check_particle_geometry(in, box.lx, box.ly, file);
    ParticleStore p;
    for (const ParticleRecord& r : in.particles) {
        if (r.type < 1 || r.type > int(recipe.species.size()))
            throw InputError(fmt::format("--particles {}: particle {} has type {}; the config "
                                         "defines types 1..{} (NCM classes, then CB)",
                                         file.string(), r.id, r.type, recipe.species.size()));
        const int sp = r.type - 1;
        const double rho = std::isnan(r.density) ? recipe.species[sp].density : r.density;
        Vec3 x = r.position;
        x.x -= in.xlo.value_or(0.0);
        x.y -= in.ylo.value_or(0.0);
        box.wrap(x);
        p.add(r.id, std::uint8_t(sp), r.radius, rho, x);
    }
    return p;
}

Film describe_film(const Config& c) {
    Film f{make_recipe(c), scale_parameters(c), Box{c.box_x, c.box_y}, {}};
    f.schedule = {f.recipe.wet_film_height, f.scaled.level_speeds_scaled,
                  f.scaled.zone_duration_scaled};
    f.areal_mass = f.recipe.realised_dry_mass() / f.recipe.base_area;
    return f;
}

void count_species(Film& film, const ParticleStore& particles) {
    film.n_ncm = film.n_cb = 0;
    for (std::uint8_t s : particles.species)
        (film.recipe.species[s].is_cb ? film.n_cb : film.n_ncm)++;
}

ParticleStore wet_film_particles(const Config& c, const RunOptions& options, const Film& film,
                                 spdlog::logger& log) {
    const FilmRecipe& recipe = film.recipe;
    if (!options.particles_file)
        return insert_particles(recipe, film.box, recipe.wet_film_height, c.seed);
    ParticleStore p = particles_from_file(*options.particles_file, recipe, film.box);
    double top = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) top = std::max(top, p.position[i].z + p.radius[i]);
    if (top > recipe.wet_film_height)
        log.warn("--particles: the highest particle top ({:.4g} um) is above the initial liquid "
                 "level H_wet = {:.4g} um of this config (film.areal_loading); the end criterion "
                 "may fire at once",
                 top * 1e6, recipe.wet_film_height * 1e6);
    return p;
}

} // namespace drydem
