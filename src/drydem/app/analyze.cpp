// SPDX-License-Identifier: MIT
// `drydem analyze SNAPSHOT`: the structure analysis of a particle file (ours, the peers' CSV, a
// LAMMPS/LIGGGHTS data or dump file) into analysis.json, profiles.csv, psd_*.csv, plots and, on
// request, the voxel image.
#include "drydem/drying/analysis_inputs.hpp"
#include "drydem/app/commands.hpp"
#include "drydem/analysis/analyze.hpp"
#include "drydem/core/error.hpp"
#include "drydem/output/analysis_writer.hpp"
#include "drydem/output/python_script.hpp"
#include "drydem/io/particle_io.hpp"
#include "drydem/output/voxel_export.hpp"
#include <fmt/format.h>
#include <omp.h>
#include <sys/resource.h>
#include <chrono>
#include <cmath>
#include <cstdlib>

namespace drydem::app {

namespace fs = std::filesystem;

void run_plot_script(const std::string& script_name, const fs::path& dir) {
    switch (run_python_script(script_name, {dir.string()})) {
    case ScriptRun::ok:
        break;
    case ScriptRun::unavailable:
        fmt::print(stderr, "warning: /usr/bin/python3 or scripts/{} missing; no plots\n",
                   script_name);
        break;
    case ScriptRun::failed:
        fmt::print(stderr, "warning: plotting failed\n");
        break;
    }
}

int run_analyze(const Config& c, const AnalyzeOptions& o) {
    const auto t0 = std::chrono::steady_clock::now();
    if (o.threads > 0) omp_set_num_threads(o.threads);
    const ParticleFile file = read_particles(o.snapshot);
    check_particle_geometry(file, file.lx.value_or(c.box_x), file.ly.value_or(c.box_y), o.snapshot);
    analysis::PhaseRule rule;
    if (o.cb_type > 0) rule.cb_type = o.cb_type;
    const analysis::Structure s = analysis::structure_from_file(file, file_defaults(c), rule);
    analysis::AnalysisOptions a = o.analysis;
    // A run folder's snapshot: its time series drives the binder migration model.
    if (const fs::path ts = o.snapshot.parent_path() / "timeseries.csv";
        a.timeseries.empty() && o.snapshot.filename() == "final.csv" && fs::exists(ts))
        a.timeseries = ts.string();
    // ... and its dump frames the porosity profile while the film shrinks.
    if (const fs::path dump = o.snapshot.parent_path() / "snapshots" / "dump.lammpstrj";
        !a.timeseries.empty() && a.dump.empty() && fs::exists(dump)) {
        a.dump = dump.string();
        a.dump_defaults = file_defaults(c);
        a.dump_rule = rule;
    }
    a.keep_grid = o.export_voxels || o.tiff;
    if (!o.quiet) a.log = [](const std::string& m) { fmt::print("  {}\n", m); };
    if (a.voxel > 0.0) {
        const double top = analysis::highest_top(s);
        const double voxels = double(analysis::voxel_count(s, a.voxel, top));
        if (!o.quiet)
            fmt::print("{}: {} particles ({}), box {:.4g} x {:.4g} um; voxel image {:.3g} voxels, "
                       "about {:.2g} GB\n",
                       o.snapshot.string(), s.size(), file.format, s.box.lx * 1e6, s.box.ly * 1e6,
                       voxels, voxels * analysis::voxel_analysis_bytes / 1e9);
    }
    const analysis::AnalysisResult r = analysis::analyze_structure(s, a);
    // Never an impossible number as a result (the file checks above should make this unreachable).
    if (!(r.bulk.density > 0.0 && std::isfinite(r.bulk.density) && r.bulk.porosity >= 0.0 &&
          r.bulk.porosity < 1.0))
        throw InputError(
            fmt::format("{}: the particles give density {:.4g} g/cm3 and porosity {:.4g}, which no "
                        "film has; check the box and the particle sizes",
                        o.snapshot.string(), r.bulk.density * 1e-3, r.bulk.porosity));
    write_analysis(o.output_dir, r, a, o.snapshot.string());
    if (r.grid) {
        const VoxelExport e = write_voxel_image(o.output_dir, *r.grid, o.snapshot.string(), o.tiff);
        if (!o.quiet)
            fmt::print("  voxel image: {}, {}{}\n", e.raw.string(), e.mhd.string(),
                       e.tiff.empty() ? "" : ", " + e.tiff.string());
    }
    if (o.plots) run_plot_script("plot_analysis.py", o.output_dir);
    rusage use{};
    getrusage(RUSAGE_SELF, &use);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const analysis::Bulk& b = r.bulk;
    fmt::print("thickness {:.3f} um (highest top; half-solid {:.3f} um), density {:.4f} g/cm3, "
               "porosity {:.4f}\n",
               b.thickness * 1e6, b.thickness_half_solid * 1e6, b.density * 1e-3, b.porosity);
    fmt::print("coordination: NCM-NCM {:.3f}, NCM-CB {:.3f} per NCM, CB-CB {:.3f} per CB (gap "
               "{:.3g} um)\n",
               r.coordination.ncm_with_ncm(), r.coordination.ncm_with_cb(),
               r.coordination.cb_with_cb(), r.coordination.gap * 1e6);
    if (r.voxelized) {
        fmt::print(
            "pores: voxel porosity {:.4f} (with CB pores {:.4f}), chord mean x/y/z "
            "{:.3f}/{:.3f}/{:.3f} um, "
            "local-thickness peak {:.3f} um, median {:.3f} um, mercury median {:.3f} um\n",
            r.voxel_porosity, r.porosity_with_cb_pores, r.chords[0].mean_voxels() * r.voxel * 1e6,
            r.chords[1].mean_voxels() * r.voxel * 1e6, r.chords[2].mean_voxels() * r.voxel * 1e6,
            r.psd.peak * 1e6, r.psd.median * 1e6, r.psd.mip_median * 1e6);
        if (r.distance_saturated)
            fmt::print(
                stderr,
                "warning: some pores are wider than 255 voxels; their sizes are cut at that\n");
    }
    if (r.transport && r.transport->solved()) {
        const analysis::TransportLevel& L = r.transport->reported();
        fmt::print("transport ({:.3g} um voxels, coating below {:.2f} um{}): tortuosity factor "
                   "through-plane {:.3f}, "
                   "in-plane {:.3f} / {:.3f} (x / y), porosity {:.4f}, Bruggeman exponent {:.3f}; "
                   "electronic "
                   "conductivity {:.4g} S/m, CB network {}\n",
                   L.voxel * 1e6, L.nz * L.voxel * 1e6,
                   r.transport->window > 0.0
                       ? fmt::format(", window {:.4g} um", r.transport->window * 1e6)
                       : "",
                   L.tau_z, L.tau_x, L.tau_y, L.porosity,
                   analysis::bruggeman_exponent(L.porosity, L.tau_z), L.electronic_z.sigma_eff,
                   L.cb_z.percolates ? fmt::format("percolates ({:.4g} S/m)", L.cb_z.sigma_eff)
                                     : "does not percolate");
    }
    if (r.surfaces.computed)
        fmt::print("NCM surface: {:.3f} wetted by electrolyte, {:.3f} covered by CB (gap {:.3g} "
                   "um), {:.3f} in NCM "
                   "contacts\n",
                   r.surfaces.electrolyte_fraction(), r.surfaces.cb_covered_fraction(),
                   r.surfaces.gap * 1e6,
                   r.surfaces.total > 0 ? r.surfaces.ncm_contact / r.surfaces.total : 0.0);
    fmt::print("written to {} in {:.1f} s (peak memory {:.0f} MB)\n", o.output_dir.string(), wall,
               double(use.ru_maxrss) / 1024.0);
    return 0;
}

} // namespace drydem::app
