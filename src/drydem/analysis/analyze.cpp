// SPDX-License-Identifier: MIT
#include "drydem/analysis/analyze.hpp"
#include "drydem/analysis/amg_solver.hpp"
#include "drydem/analysis/bulk.hpp"
#include "drydem/analysis/distance_transform.hpp"
#include "drydem/analysis/pore_size.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <cmath>
#include <future>
#include <omp.h>
#include <unistd.h>

namespace drydem::analysis {

namespace {

double since(std::chrono::steady_clock::time_point& t) {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - t).count();
    t = now;
    return s;
}

/// Volume histogram of diameters 2 sqrt(r²) voxels over the pore voxels below k_top.
std::vector<double> diameter_histogram(const VoxelGrid& g, const std::vector<std::uint16_t>& r2,
                                       int k_top, double& unreached) {
    std::vector<double> bins(520, 0.0);
    std::vector<std::uint64_t> by_r2(65536, 0);
    std::uint64_t pores = 0, zero = 0;
    const std::size_t n = std::size_t(k_top) * std::size_t(g.nx) * std::size_t(g.ny);
    for (std::size_t idx = 0; idx < n; ++idx) {
        if (g.label[idx] != label_pore) continue;
        ++pores;
        if (r2[idx] == 0)
            ++zero;
        else
            ++by_r2[r2[idx]];
    }
    for (std::size_t v = 1; v < by_r2.size(); ++v)
        if (by_r2[v]) bins[std::size_t(2.0 * std::sqrt(double(v)))] += double(by_r2[v]);
    if (pores > 0)
        for (double& b : bins) b /= double(pores);
    unreached = pores > 0 ? double(zero) / double(pores) : 0.0;
    while (!bins.empty() && bins.back() == 0.0) bins.pop_back();
    return bins;
}

} // namespace

namespace {

/// Binder migration (paper Eq. 1) over the run's drying history, and the same film dried faster.
template <class Say>
void analyze_binder(AnalysisResult& r, const AnalysisOptions& o, double coating_top, Say&& say) {
    DryingHistory h =
        read_drying_history(o.timeseries, coating_top, o.profile_dz, r.profiles.pore_total);
    if (!o.dump.empty() && std::filesystem::exists(o.dump))
        h.frames = porosity_frames(o.dump, h, o.dump_defaults, o.dump_rule);
    BinderParams bp = o.binder;
    if (r.transport && r.transport->solved()) {
        const TransportLevel& L = r.transport->reported();
        const double alpha = bruggeman_exponent(L.porosity, L.tau_z);
        if (alpha >= 1.0 && alpha <= 5.0) bp.bruggeman = alpha;
    }
    r.binder = binder_migration(h, bp);
    say(fmt::format("binder migration: Pe {:.3g}, binder at the substrate (bottom 10 %) {:.3f}, "
                    "top 10 % {:.3f} "
                    "of the mean, {} steps, {}",
                    r.binder->peclet, r.binder->bottom10, r.binder->top10, r.binder->steps,
                    r.binder->porosity_frames > 0
                        ? fmt::format("shrinkage from {} dump frames", r.binder->porosity_frames)
                        : std::string("affine shrinkage (no dump frames)")));
    // The same film dried f times faster: the time axis of the history divided by f.
    for (double f : o.binder_rate_factors) {
        DryingHistory hf = h;
        for (double& t : hf.time) t = h.time.front() + (t - h.time.front()) / f;
        for (PorosityFrame& fr : hf.frames)
            fr.time = h.time.front() + (fr.time - h.time.front()) / f;
        r.binder_rates.emplace_back(f, binder_migration(hf, bp));
    }
}

/// This machine's physical memory [bytes]; 0 where unknown.
double machine_memory_bytes() {
    return double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
}

/// Refuse what this machine cannot hold instead of dying in the allocation.
void check_voxel_memory(const Structure& s, const AnalysisOptions& o, double top) {
    const double voxels = double(voxel_count(s, o.voxel, top));
    const double need = voxel_analysis_bytes * voxels;
    const double have = machine_memory_bytes();
    if (voxels >= 4.0e9 || (have > 0.0 && need > 0.8 * have))
        throw InputError(fmt::format("voxel size {:.3g} um: the voxel image has {:.3g} voxels and "
                                     "needs about {:.1f} GB, more than this "
                                     "machine's {:.1f} GB allow (and at most 4e9 voxels); choose a "
                                     "coarser voxel size (analysis.voxel_size "
                                     "or --voxel, e.g. {:.2g} um)",
                                     o.voxel * 1e6, voxels, need / 1e9, have / 1e9,
                                     o.voxel * 1e6 * std::cbrt(need / (0.5 * have)) + 1e-3));
}

/// Pore sizes of the coating below the pore top: local thickness and simulated mercury intrusion,
/// with their medians and the peak.
template <class Say>
void pore_sizes(AnalysisResult& r, VoxelGrid& g, const AnalysisOptions& o,
                std::chrono::steady_clock::time_point t, Say&& say) {
    // The pore sizes of the coating: the layers below the pore top, open at that plane (where the
    // mercury enters). The rough surface above is no pore space of the coating.
    VoxelGrid owned;
    if (r.pore_top_layer < g.nz) {
        owned.nx = g.nx;
        owned.ny = g.ny;
        owned.nz = r.pore_top_layer;
        owned.ax = g.ax;
        owned.ay = g.ay;
        owned.az = g.az;
        const std::size_t n = std::size_t(owned.nz) * std::size_t(g.nx) * std::size_t(g.ny);
        if (o.keep_grid) {
            owned.label.assign(g.label.begin(), g.label.begin() + std::ptrdiff_t(n));
        } else {
            owned.label = std::move(g.label);
            owned.label.resize(n);
            owned.label.shrink_to_fit();
        }
    }
    const VoxelGrid& pg = r.pore_top_layer < g.nz ? owned : g;
    const std::vector<std::uint16_t> d2 = squared_distance_to_solid(pg);
    r.seconds.push_back(since(t));
    say(fmt::format("distance transform in {:.1f} s", r.seconds.back()));
    r.distance_saturated = std::any_of(d2.begin(), d2.end(),
                                       [](std::uint16_t v) { return v >= squared_distance_cap; });
    std::vector<std::uint16_t> levels = invasion_levels(pg, d2);
    r.seconds.push_back(since(t));
    say(fmt::format("invasion from the top in {:.1f} s", r.seconds.back()));
    {
        const std::vector<std::uint16_t> lt = local_thickness(pg, d2);
        double unused = 0.0;
        r.psd.volume = diameter_histogram(pg, lt, pg.nz, unused);
        r.seconds.push_back(since(t));
        say(fmt::format("local thickness in {:.1f} s", r.seconds.back()));
    }
    {
        const std::vector<std::uint16_t> mip = intrusion_map(pg, levels);
        std::vector<std::uint16_t>().swap(levels);
        r.psd.intruded = diameter_histogram(pg, mip, pg.nz, r.psd.not_intruded);
        r.seconds.push_back(since(t));
        say(fmt::format("mercury intrusion in {:.1f} s", r.seconds.back()));
    }
    // labels + distances + levels + one painted map, the peak of the pipeline above.
    r.memory_bytes = (o.keep_grid ? g.size() : 0) + pg.size() * (1 + 3 * sizeof(std::uint16_t));
    r.psd.bin = g.az;
    auto centre = [&](std::size_t m) { return (double(m) + 0.5) * r.psd.bin; };
    const auto peak = std::max_element(r.psd.volume.begin(), r.psd.volume.end());
    if (peak != r.psd.volume.end()) r.psd.peak = centre(std::size_t(peak - r.psd.volume.begin()));
    auto median_of = [&](const std::vector<double>& h) {
        double total = 0.0;
        for (double v : h) total += v;
        double acc = 0.0;
        for (std::size_t m = 0; m < h.size(); ++m) {
            if (acc + h[m] >= 0.5 * total && h[m] > 0.0)
                return (double(m) + (0.5 * total - acc) / h[m]) *
                       r.psd.bin; // linear within the bin
            acc += h[m];
        }
        return 0.0;
    };
    r.psd.median = median_of(r.psd.volume);
    r.psd.mip_median = median_of(r.psd.intruded);
}

/// The voxel image at analysis.voxel_size: porosity split, chord lengths, pore sizes.
template <class Say>
void voxel_pipeline(AnalysisResult& r, const Structure& s, const AnalysisOptions& o, double top,
                    Say&& say) {
    auto t = std::chrono::steady_clock::now();
    r.voxelized = true;
    VoxelGrid g = voxelize(s, o.voxel, top);
    r.nx = g.nx;
    r.ny = g.ny;
    r.nz = g.nz;
    r.voxel = g.az;
    r.seconds.push_back(since(t));
    say(fmt::format("voxel image {} x {} x {} ({:.3g} voxels, {:.3g} um) in {:.1f} s", g.nx, g.ny,
                    g.nz, double(g.size()), g.az * 1e6, r.seconds.back()));
    r.pore_top = o.pore_top == "highest" ? top : r.bulk.thickness_half_solid;
    r.pore_top_layer = std::clamp(int(std::lround(r.pore_top / g.az)), 1, g.nz);
    {
        std::uint64_t counts[3] = {0, 0, 0};
        const std::size_t n = std::size_t(r.pore_top_layer) * std::size_t(g.nx) * std::size_t(g.ny);
        for (std::size_t i = 0; i < n; ++i) ++counts[std::min<std::uint8_t>(g.label[i], 2)];
        r.voxel_porosity = double(counts[0]) / double(n);
        r.voxel_ncm_fraction = double(counts[1]) / double(n);
        r.voxel_cb_fraction = double(counts[2]) / double(n);
        // The agglomerates' inner pores, 1 - carbon / envelope over all of them (M-2.11).
        const Masses m = masses(s);
        const double inner =
            m.cb_envelope_volume > 0.0
                ? 1.0 - m.cb_carbon / (s.formulation.cb_density * m.cb_envelope_volume)
                : s.formulation.cb_porosity;
        r.porosity_with_cb_pores = r.voxel_porosity + inner * r.voxel_cb_fraction;
    }
    r.chords = chord_lengths(g, r.pore_top_layer);
    r.seconds.push_back(since(t));
    say(fmt::format("chord lengths in {:.1f} s", r.seconds.back()));

    pore_sizes(r, g, o, t, say);
    if (o.keep_grid) r.grid = std::move(g);
}

/// Whether the transport solves and the voxel pipeline fit in memory at the same time (half of
/// this machine's memory, as a margin for the particles and everything else).
bool fit_together(const Structure& s, const AnalysisOptions& o, double top, double coating_top) {
    const double need = voxel_analysis_bytes * double(voxel_count(s, o.voxel, top)) +
                        transport_peak_bytes(s, coating_top, o.transport);
    const double have = machine_memory_bytes();
    return have > 0.0 && need <= 0.5 * have;
}

} // namespace

AnalysisResult analyze_structure(const Structure& s, const AnalysisOptions& o) {
    auto say = [&](const std::string& m) {
        if (o.log) o.log(m);
    };
    if (!(o.profile_dz > 0.0))
        throw InputError(fmt::format("profile slab width {} m: must be positive", o.profile_dz));
    if (o.pore_top != "half_solid" && o.pore_top != "highest")
        throw InputError(
            fmt::format("pore top '{}': allowed are 'half_solid' and 'highest'", o.pore_top));
    AnalysisResult r;
    const double top = highest_top(s);
    r.profiles = volume_fraction_profiles(s, o.profile_dz, top);
    r.bulk = bulk_properties(s, r.profiles.solid(), o.profile_dz);
    r.coordination = coordination(s, o.contact_gap);
    r.overlaps = overlap_census(s);
    r.base_area = s.box.area();
    r.surfaces = ncm_surfaces(s, o.surfaces);
    // Transport (tortuosity, conductivities) on its own coarser voxelizations, then the binder
    // migration that takes its Bruggeman exponent. Its AMG solves run on one core, so while the
    // pore-size pipeline below (OpenMP on all cores) runs it goes on in a thread of its own when
    // both fit in memory together: each part is deterministic and writes only its own members of
    // `r`, so the results are those of the sequential order.
    const double coating_top = o.pore_top == "highest" ? top : r.bulk.thickness_half_solid;
    const int threads = omp_get_max_threads(); // a new thread starts from OpenMP's defaults
    auto transport_and_binder = [&r, &s, &o, coating_top, threads, say] {
        omp_set_num_threads(threads);
        if (!o.transport.voxels.empty()) {
            TransportOptions to = o.transport;
            to.log = o.log;
            r.transport = film_transport(s, coating_top, to);
        }
        if (!o.timeseries.empty()) analyze_binder(r, o, coating_top, say);
    };
    const bool voxels = o.voxel > 0.0;
    if (voxels) check_voxel_memory(s, o, top);
    const bool together =
        voxels && !o.transport.voxels.empty() && fit_together(s, o, top, coating_top);
    std::future<void> background;
    if (together) {
        start_amg_solver(); // MPI starts in this thread
        background = std::async(std::launch::async, transport_and_binder);
    } else {
        transport_and_binder();
    }
    if (voxels) voxel_pipeline(r, s, o, top, say);
    if (background.valid()) {
        background.get();
        if (r.transport) r.transport->alongside_pore_sizes = true;
    }
    return r;
}

} // namespace drydem::analysis
