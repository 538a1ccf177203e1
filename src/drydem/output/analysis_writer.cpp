// SPDX-License-Identifier: MIT
#include "drydem/output/analysis_writer.hpp"
#include "drydem/io/particle_io.hpp"
#include "drydem/git_hash.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <cmath>

namespace drydem {

using namespace analysis;

namespace {

/// The overlap census: per type δ / r_smaller over the overlapping pairs, and the lens volume.
nlohmann::ordered_json overlap_json(const OverlapCensus& c) {
    auto stats = [](const OverlapStats& o) {
        return nlohmann::ordered_json{
            {"pairs", o.pairs}, {"mean", o.mean}, {"median", o.median},
            {"p99", o.p99},     {"max", o.max},   {"lens_volume_um3", o.lens_volume * 1e18}};
    };
    return {{"definition",
             "overlap / smaller radius over the overlapping pairs (substrate: (r - z) / r)"},
            {"cb_cb", stats(c.cb_cb)},
            {"ncm_cb", stats(c.ncm_cb)},
            {"ncm_ncm", stats(c.ncm_ncm)},
            {"cb_substrate", stats(c.cb_substrate)},
            {"ncm_substrate", stats(c.ncm_substrate)},
            {"all", stats(c.all)},
            {"lens_volume_fraction_of_solid", c.lens_fraction()}};
}

/// Thickness, density, porosity, masses (Bulk) and the coordination numbers.
void add_bulk(nlohmann::ordered_json& j, const AnalysisResult& r) {
    const Bulk& b = r.bulk;
    j["thickness_um"] = b.thickness * 1e6;
    j["thickness_half_solid_um"] = b.thickness_half_solid * 1e6;
    j["bulk_solid_fraction"] = b.bulk_solid_fraction;
    j["areal_loading_mg_cm2"] = b.areal_loading * 100.0;
    j["density_g_cm3"] = b.density * 1e-3;
    j["porosity"] = b.porosity;
    j["density_half_solid_g_cm3"] = b.density_half_solid * 1e-3;
    j["porosity_half_solid"] = b.porosity_half_solid;
    j["solids_density_g_cm3"] = b.solids_density * 1e-3;
    j["cb_binder_porosity_eq2"] = b.cb_binder_porosity;
    j["ncm_volume_fraction"] = b.ncm_volume_fraction;
    j["cb_envelope_volume_fraction"] = b.cb_envelope_volume_fraction;
    j["masses_ug"] = {{"ncm", b.mass.ncm * 1e9},
                      {"cb_carbon", b.mass.cb_carbon * 1e9},
                      {"pvdf", b.mass.pvdf * 1e9}};
    const Coordination& c = r.coordination;
    j["particles"] = {{"ncm", c.n_ncm}, {"cb", c.n_cb}};
    j["coordination"] = {
        {"contact_gap_um", c.gap * 1e6},
        {"contacts",
         {{"ncm_ncm", c.ncm_ncm},
          {"ncm_cb", c.ncm_cb},
          {"cb_cb", c.cb_cb},
          {"ncm_substrate", c.ncm_substrate},
          {"cb_substrate", c.cb_substrate}}},
        {"ncm_ncm", c.ncm_with_ncm()},
        {"ncm_cb", c.ncm_with_cb()},
        {"cb_ncm", c.cb_with_ncm()},
        {"cb_cb", c.cb_with_cb()},
        {"ncm_substrate_fraction", c.n_ncm ? double(c.ncm_substrate) / double(c.n_ncm) : 0.0},
        {"cb_substrate_fraction", c.n_cb ? double(c.cb_substrate) / double(c.n_cb) : 0.0},
        {"mean", c.mean()}};
    j["overlap"] = overlap_json(r.overlaps);
}

/// The voxel image's porosity, chord lengths, pore sizes and timings.
void add_voxels(nlohmann::ordered_json& j, const AnalysisResult& r, const AnalysisOptions& o) {
    const double a = r.voxel * 1e6;
    j["voxel_size_um"] = a;
    j["voxels"] = {r.nx, r.ny, r.nz};
    j["pore_top"] = o.pore_top;
    j["pore_top_um"] = r.pore_top_layer * a;
    j["voxel_porosity"] = r.voxel_porosity;
    j["voxel_ncm_fraction"] = r.voxel_ncm_fraction;
    j["voxel_cb_fraction"] = r.voxel_cb_fraction;
    j["porosity_with_cb_pores"] = r.porosity_with_cb_pores;
    const char* axes[3] = {"x", "y", "z"};
    nlohmann::ordered_json mean, lw, count;
    for (int d = 0; d < 3; ++d) {
        mean[axes[d]] = r.chords[std::size_t(d)].mean_voxels() * a;
        lw[axes[d]] = r.chords[std::size_t(d)].length_weighted_mean_voxels() * a;
        count[axes[d]] = r.chords[std::size_t(d)].chords();
    }
    j["pore_chord_mean_um"] = mean;
    j["pore_chord_length_weighted_mean_um"] = lw;
    j["pore_chords"] = count;
    j["psd_peak_um"] = r.psd.peak * 1e6;
    j["psd_median_um"] = r.psd.median * 1e6;
    j["mercury_median_um"] = r.psd.mip_median * 1e6;
    j["mercury_not_intruded_fraction"] = r.psd.not_intruded;
    j["distance_saturated"] = r.distance_saturated;
    j["timings_s"] = {{"voxelize", r.seconds.at(0)},           {"chords", r.seconds.at(1)},
                      {"distance_transform", r.seconds.at(2)}, {"invasion", r.seconds.at(3)},
                      {"local_thickness", r.seconds.at(4)},    {"intrusion", r.seconds.at(5)}};
    j["voxel_memory_mb"] = double(r.memory_bytes) / 1e6;
}

/// Tortuosity, MacMullin number, conductivities and the voxel-size convergence.
nlohmann::ordered_json skipped_json(const Transport& t) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (const SkippedLevel& k : t.skipped)
        a.push_back(
            {{"voxel_size_um", k.voxel * 1e6}, {"voxels", k.voxels}, {"max_voxels", t.max_voxels}});
    return a;
}

/// Relative change of the finest level's values against the next coarser one: how far from
/// converged in voxel size the reported numbers are.
nlohmann::ordered_json voxel_change_json(const Transport& t) {
    if (t.levels.size() < 2) return {};
    const TransportLevel &f = t.levels.back(), &c = t.levels[t.levels.size() - 2];
    auto change = [](double fine, double coarse) {
        return fine != 0.0 && std::isfinite(fine) && std::isfinite(coarse)
                   ? nlohmann::ordered_json((fine - coarse) / fine)
                   : nlohmann::ordered_json();
    };
    return {{"from_voxel_size_um", c.voxel * 1e6},
            {"tortuosity_through_plane", change(f.tau_z, c.tau_z)},
            {"tortuosity_in_plane", change(f.tau_x + f.tau_y, c.tau_x + c.tau_y)},
            {"electronic_conductivity", change(f.electronic_z.sigma_eff, c.electronic_z.sigma_eff)},
            {"cb_network_conductivity", change(f.cb_z.sigma_eff, c.cb_z.sigma_eff)}};
}

/// τ and σ_eff extrapolated to zero voxel size from the solved levels (Richardson); the observed
/// order is that of the through-plane τ.
nlohmann::ordered_json extrapolated_json(const Transport& t) {
    std::vector<double> h;
    for (const TransportLevel& l : t.levels) h.push_back(l.voxel);
    auto extrapolate = [&](auto get) {
        std::vector<double> v;
        for (const TransportLevel& l : t.levels) v.push_back(get(l));
        return extrapolate_to_zero_voxel(h, v);
    };
    auto value = [](const Extrapolation& e) {
        return std::isfinite(e.value) ? nlohmann::ordered_json(e.value) : nlohmann::ordered_json();
    };
    const Extrapolation tau_z = extrapolate([](const TransportLevel& l) { return l.tau_z; });
    return {{"tortuosity_through_plane", value(tau_z)},
            {"tortuosity_in_plane",
             value(extrapolate([](const TransportLevel& l) { return 0.5 * (l.tau_x + l.tau_y); }))},
            {"electronic_conductivity_S_m",
             value(extrapolate([](const TransportLevel& l) { return l.electronic_z.sigma_eff; }))},
            {"observed_order", tau_z.order_observed ? nlohmann::ordered_json(tau_z.order)
                                                    : nlohmann::ordered_json()}};
}

nlohmann::ordered_json transport_json(const Transport& t) {
    if (!t.solved()) return {{"skipped", skipped_json(t)}};
    const TransportLevel& L = t.reported();
    const double tau_in = 0.5 * (L.tau_x + L.tau_y);
    auto nan_null = [](double v) {
        return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json();
    };
    nlohmann::ordered_json tj;
    tj["coating_top_um"] = L.nz * L.voxel * 1e6;
    tj["voxel_size_um"] = L.voxel * 1e6;
    tj["voxels"] = {L.nx, L.ny, L.nz};
    tj["porosity"] = L.porosity;
    tj["pore_percolating_fraction"] = L.pore_z.percolating_fraction;
    tj["tortuosity_factor"] = {
        {"through_plane", L.tau_z}, {"in_plane", tau_in}, {"x", L.tau_x}, {"y", L.tau_y}};
    tj["macmullin_number"] = {{"through_plane", L.tau_z / L.porosity},
                              {"in_plane", tau_in / L.porosity}};
    tj["bruggeman_exponent"] = {
        {"through_plane", nan_null(bruggeman_exponent(L.porosity, L.tau_z))},
        {"in_plane", nan_null(bruggeman_exponent(L.porosity, tau_in))}};
    tj["ncm_conductivity_S_m"] = t.sigma_ncm;
    tj["cb_conductivity_S_m"] = t.sigma_cb;
    tj["electronic_conductivity_S_m"] = L.electronic_z.sigma_eff;
    tj["solid_percolates"] = L.electronic_z.percolates;
    tj["cb_percolates"] = L.cb_z.percolates;
    tj["cb_network_conductivity_S_m"] = L.cb_z.sigma_eff;
    tj["cb_percolating_fraction_of_cb"] =
        L.cb_z.conducting_fraction > 0 ? L.cb_z.percolating_fraction / L.cb_z.conducting_fraction
                                       : 0.0;
    bool converged = true;
    double balance = 0.0;
    for (const ConductionResult* cr : {&L.pore_z, &L.pore_x, &L.pore_y, &L.electronic_z, &L.cb_z}) {
        if (cr->unknowns == 0) continue;
        converged = converged && cr->converged;
        balance = std::max(balance, cr->flux_balance);
    }
    if (L.walk.walkers > 0) {
        auto tau = [&](int d) {
            return L.walk.diffusivity[d] > 0 ? 1.0 / L.walk.diffusivity[d] : 0.0;
        };
        auto err = [&](int d) {
            const double D = L.walk.diffusivity[d];
            return D > 0 ? L.walk.standard_error[d] / (D * D) : 0.0;
        };
        tj["random_walk"] = {
            {"method", "blind-ant walks in the pores, x, y periodic (second method)"},
            {"walkers", L.walk.walkers},
            {"steps", L.walk.steps},
            {"tortuosity_x", tau(0)},
            {"tortuosity_x_standard_error", err(0)},
            {"tortuosity_y", tau(1)},
            {"tortuosity_y_standard_error", err(1)},
            {"seconds", L.walk.seconds}};
    }
    const std::string method = std::string(L.pore_z.preconditioner) == "BoomerAMG"
                                   ? "conjugate gradients (hypre PCG), BoomerAMG preconditioner"
                                   : "Eigen ConjugateGradient, Jacobi preconditioner";
    tj["solver"] = {{"method", method}, {"converged", converged}, {"max_flux_balance", balance}};
    nlohmann::ordered_json conv = nlohmann::ordered_json::array();
    for (const TransportLevel& l : t.levels)
        conv.push_back({{"voxel_size_um", l.voxel * 1e6},
                        {"voxels", {l.nx, l.ny, l.nz}},
                        {"porosity", l.porosity},
                        {"tortuosity_through_plane", l.tau_z},
                        {"tortuosity_x", l.tau_x},
                        {"tortuosity_y", l.tau_y},
                        {"electronic_conductivity_S_m", l.electronic_z.sigma_eff},
                        {"cb_percolates", l.cb_z.percolates},
                        {"cg_iterations_through_plane", l.pore_z.iterations},
                        {"seconds", l.seconds},
                        {"memory_mb", double(l.memory_bytes) / 1e6}});
    tj["convergence"] = conv;
    // Overlapped with the pore sizes: seconds on shared cores, memory an upper bound.
    tj["solved_alongside_pore_sizes"] = t.alongside_pore_sizes;
    // Solved on a lateral window (analysis.transport_window) with closed sides; 0 = whole box.
    tj["window_um"] = t.window * 1e6;
    tj["relative_change_from_coarser_voxels"] = voxel_change_json(t);
    tj["extrapolated_to_zero_voxel"] = extrapolated_json(t);
    tj["skipped"] = skipped_json(t);
    return tj;
}

/// The NCM surface split (electrolyte, CB-covered, contacts, substrate).
void add_surfaces(nlohmann::ordered_json& j, const AnalysisResult& r) {
    const Surfaces& a = r.surfaces;
    const double volume = r.bulk.thickness * r.base_area;
    j["ncm_surface"] = {
        {"cb_coverage_gap_um", a.gap * 1e6},
        {"total_um2", a.total * 1e12},
        {"electrolyte_fraction", a.electrolyte_fraction()},
        {"cb_covered_fraction", a.cb_covered_fraction()},
        {"cb_overlap_fraction", a.total > 0 ? a.cb_overlap / a.total : 0.0},
        {"ncm_contact_fraction", a.total > 0 ? a.ncm_contact / a.total : 0.0},
        {"substrate_fraction", a.total > 0 ? a.substrate / a.total : 0.0},
        {"specific_surface_electrolyte_per_um", volume > 0 ? a.electrolyte / volume * 1e-6 : 0.0},
        {"specific_surface_electrolyte_m2_g",
         r.bulk.mass.ncm > 0 ? a.electrolyte / (r.bulk.mass.ncm * 1e3) : 0.0}};
}

/// The binder migration model's profile summary and its drying-rate variants.
void add_binder(nlohmann::ordered_json& j, const AnalysisResult& r, const AnalysisOptions& o) {
    const BinderProfile& bp = *r.binder;
    nlohmann::ordered_json rates = nlohmann::ordered_json::array();
    rates.push_back({{"rate_factor", 1.0},
                     {"peclet", bp.peclet},
                     {"bottom10", bp.bottom10},
                     {"top10", bp.top10}});
    for (const auto& [f, bf] : r.binder_rates)
        rates.push_back({{"rate_factor", f},
                         {"peclet", bf.peclet},
                         {"bottom10", bf.bottom10},
                         {"top10", bf.top10}});
    j["binder_migration"] = {
        {"model", "paper Eq. 1, 1D convection-diffusion (docs/analysis.md)"},
        {"diffusivity_m2_s", o.binder.diffusivity},
        {"evaporation_velocity_um_s", bp.evaporation_rate * 1e6},
        {"peclet", bp.peclet},
        {"consolidation_time_s", bp.consolidation_time},
        {"end_time_s", bp.end_time},
        {"bottom10_over_mean", bp.bottom10},
        {"top10_over_mean", bp.top10},
        {"mass_balance", bp.mass_balance},
        {"porosity_frames", bp.porosity_frames},
        {"shrinkage", bp.porosity_frames > 0 ? "the run's dump frames" : "affine"},
        {"drying_rate_factors", rates}};
}

} // namespace

nlohmann::ordered_json analysis_json(const AnalysisResult& r, const AnalysisOptions& o,
                                     const std::string& source) {
    nlohmann::ordered_json j;
    j["source"] = source;
    add_bulk(j, r);
    j["profile_dz_um"] = o.profile_dz * 1e6;
    if (r.voxelized) add_voxels(j, r, o);
    if (r.transport) j["transport"] = transport_json(*r.transport);
    if (r.surfaces.computed) add_surfaces(j, r);
    if (r.binder) add_binder(j, r, o);
    j["version"] = DRYDEM_VERSION;
    j["git_commit"] = DRYDEM_GIT_HASH;
    return j;
}

void write_analysis(const std::filesystem::path& dir, const AnalysisResult& r,
                    const AnalysisOptions& o, const std::string& source) {
    std::filesystem::create_directories(dir);
    const auto j = analysis_json(r, o, source);
    write_file_atomically(dir / "analysis.json",
                          [&](std::ostream& os) { os << j.dump(2) << "\n"; });
    const Profiles& p = r.profiles;
    write_file_atomically(dir / "profiles.csv", [&](std::ostream& os) {
        os << "z_lo_um,z_hi_um,z_um,ncm,cb_envelope,cb_carbon,cb_carbon_binder,pore,pore_total,"
              "solid\n";
        const double top = r.bulk.thickness;
        for (std::size_t k = 0; k < p.size(); ++k) {
            const double a = double(k) * p.dz, b = std::min(top, double(k + 1) * p.dz);
            os << fmt::format(
                "{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", a * 1e6,
                b * 1e6, 0.5 * (a + b) * 1e6, p.ncm[k], p.cb_envelope[k], p.cb_carbon[k], p.cbd[k],
                p.pore[k], p.pore_total[k], p.ncm[k] + p.cb_envelope[k]);
        }
    });
    if (r.transport && r.transport->solved())
        write_file_atomically(dir / "transport_convergence.csv", [&](std::ostream& os) {
            os << "voxel_size_um,nx,ny,nz,porosity,tortuosity_z,tortuosity_x,tortuosity_y,"
                  "macmullin_z,"
                  "bruggeman_z,electronic_conductivity_S_m,cb_network_conductivity_S_m,cb_"
                  "percolates,"
                  "cg_iterations_z,seconds,memory_mb\n";
            for (const TransportLevel& l : r.transport->levels)
                os << fmt::format("{:.6g},{},{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}"
                                  ",{:.6g},{},{},{:.3g},{:.4g}\n",
                                  l.voxel * 1e6, l.nx, l.ny, l.nz, l.porosity, l.tau_z, l.tau_x,
                                  l.tau_y, l.tau_z / l.porosity,
                                  bruggeman_exponent(l.porosity, l.tau_z), l.electronic_z.sigma_eff,
                                  l.cb_z.sigma_eff, l.cb_z.percolates ? 1 : 0, l.pore_z.iterations,
                                  l.seconds, double(l.memory_bytes) / 1e6);
        });
    if (r.binder)
        write_file_atomically(dir / "binder_profile.csv", [&](std::ostream& os) {
            os << "z_um,binder_over_mean";
            for (const auto& fr : r.binder_rates)
                os << fmt::format(",binder_over_mean_rate_x{:g}", fr.first);
            os << "\n";
            for (std::size_t i = 0; i < r.binder->z.size(); ++i) {
                os << fmt::format("{:.6g},{:.6g}", r.binder->z[i] * 1e6, r.binder->binder[i]);
                for (const auto& fr : r.binder_rates)
                    os << fmt::format(",{:.6g}", fr.second.binder[i]);
                os << "\n";
            }
        });
    if (!r.voxelized) return;
    const double a = r.voxel * 1e6;
    write_file_atomically(dir / "psd_chord.csv", [&](std::ostream& os) {
        os << "chord_length_um,count_x,count_y,count_z,frequency_x,frequency_y,frequency_z,"
              "length_fraction_x,length_fraction_y,length_fraction_z\n";
        std::size_t n = 0;
        for (const auto& h : r.chords) n = std::max(n, h.count.size());
        double total[3], length[3];
        for (int d = 0; d < 3; ++d) {
            total[d] = double(r.chords[std::size_t(d)].chords());
            length[d] = r.chords[std::size_t(d)].mean_voxels() * total[d];
        }
        for (std::size_t m = 1; m < n; ++m) {
            std::uint64_t c[3];
            for (int d = 0; d < 3; ++d) {
                const auto& h = r.chords[std::size_t(d)].count;
                c[d] = m < h.size() ? h[m] : 0;
            }
            auto f = [&](int d) { return total[d] > 0 ? double(c[d]) / total[d] : 0.0; };
            auto l = [&](int d) {
                return length[d] > 0 ? double(c[d]) * double(m) / length[d] : 0.0;
            };
            os << fmt::format("{:.6g},{},{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n",
                              double(m) * a, c[0], c[1], c[2], f(0), f(1), f(2), l(0), l(1), l(2));
        }
    });
    write_file_atomically(dir / "psd_local_thickness.csv", [&](std::ostream& os) {
        os << "diameter_lo_um,diameter_hi_um,diameter_um,volume_fraction,cumulative_finer,"
              "mercury_volume_fraction,mercury_cumulative_intruded\n";
        const std::size_t n = std::max(r.psd.volume.size(), r.psd.intruded.size());
        double finer = 0.0, intruded_total = 0.0;
        for (double v : r.psd.intruded) intruded_total += v;
        double intruded_coarser =
            intruded_total; // intruded at pressures reaching this bin or coarser
        for (std::size_t m = 0; m < n; ++m) {
            const double v = m < r.psd.volume.size() ? r.psd.volume[m] : 0.0;
            const double w = m < r.psd.intruded.size() ? r.psd.intruded[m] : 0.0;
            finer += v;
            os << fmt::format("{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", double(m) * a,
                              double(m + 1) * a, (double(m) + 0.5) * a, v, finer, w,
                              intruded_coarser);
            intruded_coarser -= w;
        }
    });
}

} // namespace drydem
