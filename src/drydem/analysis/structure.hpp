// SPDX-License-Identifier: MIT
// The dried structure as the analysis sees it: spheres with a phase (NCM or CB agglomerate), a
// periodic x-y base and the substrate at z = 0, plus the formulation constants the masses need.
// Built from any particle file (ours, the peers' CSV, LAMMPS/LIGGGHTS data or dump) and a config.
#pragma once
#include "drydem/core/box.hpp"
#include "drydem/core/vec3.hpp"
#include "drydem/io/particle_io.hpp"
#include <cstdint>
#include <optional>
#include <vector>

namespace drydem::analysis {

enum class Phase : std::uint8_t { ncm = 1, cb = 2 }; ///< = voxel labels (0 = pore)

/// Formulation constants of the analysis (SI): where the dry mass sits. No defaults here: they are
/// the run configuration's, declared once (io/config_keys.def); drying/analysis_inputs.hpp fills
/// this from a config, and a structure without it reports no masses (NaN), never invented ones.
struct Formulation {
    double ncm_density{}; ///< [kg/m^3], used where the file has no density
    double cb_density{};  ///< carbon [kg/m^3]
    double cb_porosity{}; ///< ε_CB: carbon fraction of an agglomerate as dried is 1 - ε_CB
    /// ρ_0 of an agglomerate as dried (carbon + pore solvent, M-1.3) where the agglomerates may
    /// have compacted (M-2.11): a CB sphere's density in the file over ρ_0 is how far. 0 = they
    /// did not: every agglomerate has 1 - ε_CB of carbon, whatever density a file gives it
    double cb_agglomerate_density{};
    double pvdf_density{}; ///< [kg/m^3]
    double ncm_mass_fraction{}, cb_mass_fraction{}, pvdf_mass_fraction{};
    [[nodiscard]] double solids_density() const; ///< ρ_s, Eq. 4
};

struct Structure {
    Box box;                    ///< periodic x-y lengths
    std::vector<Vec3> position; ///< [m], x and y wrapped into [0, l)
    std::vector<double> radius; ///< [m]
    /// [kg/m^3] (file or formulation): NCM particles' own; CB agglomerates' (ρ_0 as dried, more
    /// where calendering compacted them)
    std::vector<double> density;
    std::vector<Phase> phase;
    Formulation formulation;

    [[nodiscard]] std::size_t size() const { return position.size(); }
    /// The carbon's share of CB sphere i's envelope, 1 - ε_i (M-2.11: from its density where
    /// formulation.cb_agglomerate_density is set, else 1 - ε_CB).
    [[nodiscard]] double cb_solid_fraction(std::size_t i) const;
    void add(const Vec3& x, double r, Phase ph, double rho = 0.0);
};

/// Which file types are CB (every other type is NCM). Default: our and the peers' convention, types
/// 1..n the NCM classes of the config and n + 1 the CB spheres.
struct PhaseRule {
    std::optional<int> cb_type;
};

/// What a particle file may leave out: the formulation, the periodic box and the number of NCM
/// size classes (types 1..n NCM, n + 1 CB by default). drying/analysis_inputs.hpp fills it from a
/// config; the analysis itself never reads one.
struct FileDefaults {
    Formulation formulation;
    double box_x = 0.0, box_y = 0.0; ///< [m]
    int ncm_classes = 1;
};

/// The structure of a particle file. The periodic box is the file's where it has one, else the
/// defaults'; a particle without a density gets the formulation's (NCM, or an agglomerate as
/// dried). Particles are wrapped into the
/// box. InputError for a type the rule does not know or a particle outside the base.
[[nodiscard]] Structure structure_from_file(const ParticleFile& file, const FileDefaults& d,
                                            const PhaseRule& rule = {});

} // namespace drydem::analysis
