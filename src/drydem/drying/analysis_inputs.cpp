// SPDX-License-Identifier: MIT
#include "drydem/drying/analysis_inputs.hpp"
#include "drydem/setup/formulation.hpp"

namespace drydem {

analysis::Formulation analysis_formulation(const Config& c) {
    analysis::Formulation f;
    f.ncm_density = c.ncm_density;
    f.cb_density = c.cb_density;
    f.cb_porosity = c.cb_porosity;
    // Only compacting or extruding agglomerates (calendering) make a CB sphere's density a signal;
    // otherwise a file's CB density (a peer's rounded value, say) must not change the carbon.
    f.cb_agglomerate_density =
        c.cb_compaction_pressure > 0.0 || c.cb_extrusion ? cb_agglomerate_density(c) : 0.0;
    f.pvdf_density = c.pvdf_density;
    f.ncm_mass_fraction = c.ncm_mass_fraction;
    f.cb_mass_fraction = c.cb_mass_fraction;
    f.pvdf_mass_fraction = c.pvdf_mass_fraction;
    return f;
}

analysis::FileDefaults file_defaults(const Config& c) {
    return {analysis_formulation(c), c.box_x, c.box_y, int(c.ncm_diameters.size())};
}

analysis::AnalysisOptions end_of_run_analysis_options(const Config& c) {
    analysis::AnalysisOptions ao;
    ao.voxel = c.analysis_voxel_size;
    ao.profile_dz = c.analysis_profile_dz;
    ao.contact_gap = c.analysis_contact_gap;
    ao.pore_top = c.analysis_pore_top;
    set_transport_options(ao, c);
    return ao;
}

void set_transport_options(analysis::AnalysisOptions& o, const Config& c) {
    o.transport.voxels = c.analysis_transport_voxel_sizes;
    o.transport.max_voxels = c.analysis_transport_max_voxels;
    o.transport.window = c.analysis_transport_window;
    o.transport.sigma_ncm = c.analysis_ncm_conductivity;
    o.transport.sigma_cb = c.analysis_cb_conductivity;
    o.surfaces.points = c.analysis_surface_points;
    o.surfaces.cb_gap = c.analysis_cb_coverage_gap;
    o.binder.diffusivity = c.analysis_binder_diffusivity;
}

} // namespace drydem
