// SPDX-License-Identifier: MIT
// The whole structure analysis of one snapshot (`drydem analyze`, and at the end of every run):
// bulk numbers, exact profiles, coordination, and on the voxel image the chord lengths, local
// thickness and simulated mercury intrusion. A plain value in, a plain value out (no I/O).
#pragma once
#include "drydem/analysis/binder_migration.hpp"
#include "drydem/analysis/bulk.hpp"
#include "drydem/analysis/chords.hpp"
#include "drydem/analysis/coordination.hpp"
#include "drydem/analysis/overlap_census.hpp"
#include "drydem/analysis/profiles.hpp"
#include "drydem/analysis/surfaces.hpp"
#include "drydem/analysis/transport.hpp"
#include "drydem/analysis/voxel_grid.hpp"
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace drydem::analysis {

/// Peak memory of the voxel analysis per voxel of the image [bytes]: labels, 16-bit distance, level
/// and painted maps, invasion queue, ridge centres (measured 3.5 GB for 5.3e8 voxels, docs/performance.md).
inline constexpr double voxel_analysis_bytes = 7.5;

struct AnalysisOptions {
    double voxel = 0.1e-6;      ///< voxel edge [m]; 0 = no voxel analysis
    double profile_dz = 0.5e-6; ///< slab width of the profiles [m]
    double contact_gap = 0.0;   ///< coordination: surface gap that still counts as contact [m]
    /// Top of the pore statistics: "half_solid" (the robust thickness; the rough top is not pore
    /// space of the coating) or "highest" (the paper's thickness).
    std::string pore_top = "half_solid";
    bool keep_grid = false; ///< hand the voxel image back (for export)
    /// Tortuosity and conductivities (transport.hpp) on the coating below the pore top; no voxel
    /// sizes = none.
    TransportOptions transport;
    SurfaceOptions surfaces; ///< NCM surface in contact with electrolyte and CB (surfaces.hpp)
    /// Binder migration (binder_migration.hpp) from the run's timeseries.csv; empty = none. Its
    /// Bruggeman exponent is the film's through-plane one when the transport solve gives one in
    /// [1, 5], else BinderParams::bruggeman.
    std::string timeseries;
    /// The run's dump (snapshots/dump.lammpstrj): its frames give the porosity profile while the
    /// film shrinks (binder_migration.hpp); empty or missing = the affine compression. Its
    /// particles are read with these defaults and this phase rule.
    std::string dump;
    FileDefaults dump_defaults;
    PhaseRule dump_rule;
    BinderParams binder;
    std::vector<double> binder_rate_factors{0.5, 2.0}; ///< also with the drying this much faster
    std::function<void(const std::string&)> log;       ///< progress lines, may be empty
};

/// Volume-weighted pore size distribution on diameter bins of one voxel edge.
struct PoreSizeDistribution {
    double bin = 0.0;             ///< bin width [m]; bin m = [m bin, (m + 1) bin)
    std::vector<double> volume;   ///< pore volume fraction per bin (local thickness)
    std::vector<double> intruded; ///< pore volume fraction per bin first intruded at that diameter
    double not_intruded = 0.0;    ///< pore volume fraction never reached from the top
    double peak = 0.0;            ///< local-thickness mode (bin centre) [m]
    double median = 0.0;          ///< volume median diameter (local thickness) [m]
    double mip_median = 0.0;      ///< diameter where half the intruded volume is in [m]
};

struct AnalysisResult {
    Bulk bulk;
    Profiles profiles;
    Coordination coordination;
    OverlapCensus overlaps; ///< how far the soft contacts interpenetrate
    bool voxelized = false;
    int nx = 0, ny = 0, nz = 0;
    double voxel = 0.0;
    double pore_top = 0.0;       ///< top of the pore statistics [m]
    int pore_top_layer = 0;      ///< layers below it
    double voxel_porosity = 0.0; ///< pore voxels / voxels below pore_top (between-sphere pores)
    double voxel_ncm_fraction = 0.0, voxel_cb_fraction = 0.0;
    double porosity_with_cb_pores = 0.0; ///< voxel pores + ε_CB of the CB voxels
    std::array<ChordHistogram, 3> chords;
    PoreSizeDistribution psd;
    bool distance_saturated = false;    ///< some pore was wider than the 16-bit distance range
    std::size_t memory_bytes = 0;       ///< peak of the voxel work arrays
    std::optional<VoxelGrid> grid;      ///< when keep_grid
    std::optional<Transport> transport; ///< when transport voxel sizes are given
    Surfaces surfaces;
    std::optional<BinderProfile> binder;
    std::vector<std::pair<double, BinderProfile>> binder_rates; ///< (rate factor, profile)
    double base_area = 0.0;                                     ///< periodic x-y base [m^2]
    std::vector<double> seconds; ///< voxelize, EDT, chords, local thickness, intrusion
};

[[nodiscard]] AnalysisResult analyze_structure(const Structure& s, const AnalysisOptions& o);

} // namespace drydem::analysis
