// SPDX-License-Identifier: MIT
// From formulation and areal loading to particle counts, densities and the wet-film height
// (paper Eq. 3-4; model.md M-1).
#pragma once
#include "drydem/io/config.hpp"
#include <cstdint>
#include <vector>

namespace drydem {

/// One particle species of the film: an NCM size class or the CB agglomerate spheres.
struct SizeClass {
    double diameter = 0.0;    ///< [m]
    double density = 0.0;     ///< particle density [kg/m^3]
    double count_exact = 0.0; ///< unrounded count
    std::int64_t count = 0;   ///< rounded count (C-3); 0 where count_exact is not finite
    bool is_cb = false;
};

struct FilmRecipe {
    double base_area = 0.0;            ///< A [m^2]
    double solids_density = 0.0;       ///< ρ_s, Eq. 4 [kg/m^3]
    double wet_film_height = 0.0;      ///< H_wet, Eq. 3 [m]
    double ncm_volume = 0.0;           ///< V_NCM nominal [m^3]
    double cb_carbon_mass = 0.0;       ///< m_CB [kg]
    double cb_envelope_volume = 0.0;   ///< V_CB,env [m^3]
    double cb_effective_density = 0.0; ///< ρ_CB,eff = (1-ε) ρ_CB + ε ρ_f (M-1.3)
    double cb_porosity = 0.0;          ///< ε, the agglomerates' inner porosity as dried
    double pvdf_mass = 0.0;            ///< nominal PVDF mass in the box [kg]
    double dry_mass = 0.0;             ///< nominal L A [kg]
    /// Species in the order NCM classes (as configured), then CB; species index = position.
    std::vector<SizeClass> species;

    [[nodiscard]] int cb_species() const { return int(species.size()) - 1; }
    [[nodiscard]] std::int64_t particle_count() const;
    [[nodiscard]] double largest_diameter() const;
    /// The inserted spheres' own volume over A: NCM particles and CB envelopes with their inner
    /// pores [m]. At this height they would fill the gap (calendering's reachable porosity).
    [[nodiscard]] double sphere_height() const { return sphere_height(cb_porosity); }
    /// The same with the agglomerates compacted to the inner porosity `cb_inner_porosity`, their
    /// solid kept (calendering, model.md M-2.11).
    [[nodiscard]] double sphere_height(double cb_inner_porosity) const;
    /// Realised dry mass (C-3): inserted NCM + CB carbon + nominal PVDF [kg].
    [[nodiscard]] double realised_dry_mass() const;
};

FilmRecipe make_recipe(const Config& c);

/// ρ_CB,eff = (1 - ε) ρ_CB + ε ρ_f: a CB agglomerate's density with its pores full of solvent
/// (M-1.3), as inserted and as dried.
double cb_agglomerate_density(const Config& c);

/// Coating density and porosity from the final thickness (M-8.4): ρ = L/H, ε = 1 - ρ/ρ_s.
struct CoatingDensity {
    double density; ///< [kg/m^3]
    double porosity;
};
CoatingDensity coating_density(double areal_mass, double thickness, double solids_density);

} // namespace drydem
