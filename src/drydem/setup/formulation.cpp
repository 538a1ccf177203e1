// SPDX-License-Identifier: MIT
#include "drydem/core/sphere.hpp"
#include "drydem/setup/formulation.hpp"
#include "drydem/setup/solids.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace drydem {

namespace {

/// C-3 rounding without overflow: a count beyond 2^58 (or NaN) is left at 0 here and refused by
/// check_derived_quantities() with the keys that caused it.
std::int64_t rounded_count(double exact) {
    return std::isfinite(exact) && exact >= 0.0 && exact < 0x1p58 ? std::llround(exact) : 0;
}
} // namespace

FilmRecipe make_recipe(const Config& c) {
    FilmRecipe r;
    r.base_area = c.box_x * c.box_y;
    // Eq. 4: density of the dry solids from the mass fractions.
    r.solids_density = solids_density(c.ncm_mass_fraction, c.ncm_density, c.pvdf_mass_fraction,
                                      c.pvdf_density, c.cb_mass_fraction, c.cb_density);
    // Eq. 3 (I-4: the prefactor is the solids mass fraction x_s).
    const double xs = c.solids_mass_fraction, xf = 1.0 - xs;
    r.wet_film_height = c.areal_loading / xs * (xf / c.solvent_density + xs / r.solids_density);
    r.dry_mass = c.areal_loading * r.base_area;
    // M-1.2: NCM classes of equal volume.
    r.ncm_volume = c.ncm_mass_fraction * r.dry_mass / c.ncm_density;
    const double per_class = r.ncm_volume / double(c.ncm_diameters.size());
    for (double d : c.ncm_diameters) {
        SizeClass s;
        s.diameter = d;
        s.density = c.ncm_density;
        s.count_exact = per_class / sphere_volume(0.5 * d);
        s.count = rounded_count(s.count_exact);
        r.species.push_back(s);
    }
    // M-1.3: CB count from the agglomerate envelope volume, density carbon + pore NMP.
    r.cb_carbon_mass = c.cb_mass_fraction * r.dry_mass;
    r.cb_envelope_volume = r.cb_carbon_mass / (c.cb_density * (1.0 - c.cb_porosity));
    r.cb_effective_density = cb_agglomerate_density(c);
    r.cb_porosity = c.cb_porosity;
    SizeClass cb;
    cb.diameter = c.cb_diameter;
    cb.density = r.cb_effective_density;
    cb.count_exact = r.cb_envelope_volume / sphere_volume(0.5 * c.cb_diameter);
    cb.count = rounded_count(cb.count_exact);
    cb.is_cb = true;
    r.species.push_back(cb);
    r.pvdf_mass = c.pvdf_mass_fraction * r.dry_mass;
    // Every particle must fit below the initial level (C-2).
    for (const SizeClass& s : r.species)
        if (s.count > 0 && s.diameter > r.wet_film_height)
            throw InputError(fmt::format(
                "film too thin for its particles: wet film height {:.4g} um (film.areal_loading = "
                "{:.4g} mg/cm2) < particle diameter {:.4g} um; raise film.areal_loading or drop "
                "the "
                "largest class in formulation.ncm_diameters",
                r.wet_film_height * 1e6, c.areal_loading * 100, s.diameter * 1e6));
    return r;
}

std::int64_t FilmRecipe::particle_count() const {
    std::int64_t n = 0;
    for (const SizeClass& s : species) n += s.count;
    return n;
}

double FilmRecipe::largest_diameter() const {
    double d = 0.0;
    for (const SizeClass& s : species) d = std::max(d, s.diameter);
    return d;
}

double cb_agglomerate_density(const Config& c) {
    return (1.0 - c.cb_porosity) * c.cb_density + c.cb_porosity * c.solvent_density;
}

double FilmRecipe::sphere_height(double cb_inner_porosity) const {
    double v = 0.0;
    for (const SizeClass& s : species)
        v += double(s.count) * sphere_volume(0.5 * s.diameter) *
             (s.is_cb ? envelope_ratio(cb_porosity, cb_inner_porosity) : 1.0);
    return v / base_area;
}

double FilmRecipe::realised_dry_mass() const {
    double m = pvdf_mass;
    for (const SizeClass& s : species) {
        // CB particles carry pore solvent: only their carbon counts as dry mass.
        const double per_particle = s.is_cb ? cb_carbon_mass / std::max(1e-300, s.count_exact)
                                            : s.density * sphere_volume(0.5 * s.diameter);
        m += per_particle * s.count;
    }
    return m;
}

CoatingDensity coating_density(double areal_mass, double thickness, double solids_density) {
    const double rho = areal_mass / thickness;
    return {rho, 1.0 - rho / solids_density};
}

} // namespace drydem
