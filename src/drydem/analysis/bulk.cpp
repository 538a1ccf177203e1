// SPDX-License-Identifier: MIT
#include "drydem/core/sphere.hpp"
#include "drydem/analysis/bulk.hpp"
#include <algorithm>
#include <cmath>
#include <numbers>

namespace drydem::analysis {

Masses masses(const Structure& s) {
    Masses m;
    const Formulation& f = s.formulation;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double v = sphere_volume(s.radius[i]);
        if (s.phase[i] == Phase::ncm) {
            m.ncm += s.density[i] * v;
            m.ncm_volume += v;
        } else {
            // M-1.3: only the carbon of an agglomerate is dry mass; its pores held solvent.
            m.cb_carbon += s.cb_solid_fraction(i) * f.cb_density * v;
            m.cb_envelope_volume += v;
        }
    }
    // The binder is not resolved as particles (M-1.4): its mass follows the recipe's ratio to the
    // resolved solids, which equals the nominal PVDF mass when the counts are the recipe's (C-3).
    const double resolved = f.ncm_mass_fraction + f.cb_mass_fraction;
    m.pvdf = resolved > 0.0 ? f.pvdf_mass_fraction / resolved * (m.ncm + m.cb_carbon) : 0.0;
    return m;
}

double highest_top(const Structure& s) {
    double top = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) top = std::max(top, s.position[i].z + s.radius[i]);
    return top;
}

Bulk bulk_properties(const Structure& s, const std::vector<double>& solid, double dz) {
    Bulk b;
    b.mass = masses(s);
    b.solids_density = s.formulation.solids_density();
    const double area = s.box.area();
    b.areal_loading = b.mass.dry() / area;
    b.thickness = highest_top(s);
    // Bulk solid fraction: the mean over the film's middle (20 ... 60 % of the highest top), away
    // from the substrate's wall layer and the rough top.
    double sum = 0.0;
    int n = 0;
    for (std::size_t k = 0; k < solid.size(); ++k) {
        const double zc = (double(k) + 0.5) * dz;
        if (zc >= 0.2 * b.thickness && zc <= 0.6 * b.thickness) {
            sum += solid[k];
            ++n;
        }
    }
    b.bulk_solid_fraction = n > 0 ? sum / n : 0.0;
    // Robust thickness: from the top down, the first slab whose solid fraction reaches half the bulk
    // value; linear interpolation between its centre and the slab above.
    const double half = 0.5 * b.bulk_solid_fraction;
    b.thickness_half_solid = b.thickness;
    for (std::size_t k = solid.size(); k-- > 0;) {
        if (solid[k] >= half && half > 0.0) {
            const double zc = (double(k) + 0.5) * dz;
            if (k + 1 < solid.size()) {
                const double above = solid[k + 1];
                const double t = (solid[k] - half) / std::max(1e-300, solid[k] - above);
                b.thickness_half_solid = std::min(b.thickness, zc + t * dz);
            } else {
                b.thickness_half_solid = std::min(b.thickness, zc);
            }
            break;
        }
    }
    // M-8.4: ρ = L / H, ε = 1 - ρ / ρ_s.
    b.density = b.areal_loading / b.thickness;
    b.porosity = 1.0 - b.density / b.solids_density;
    b.density_half_solid = b.areal_loading / b.thickness_half_solid;
    b.porosity_half_solid = 1.0 - b.density_half_solid / b.solids_density;
    const double v_coat = area * b.thickness;
    b.ncm_volume_fraction = b.mass.ncm_volume / v_coat;
    b.cb_envelope_volume_fraction = b.mass.cb_envelope_volume / v_coat;
    // Eq. 2 (Mayer/Bockholt) on the simulated coating (model.md M-8.4).
    const double eps_c = b.porosity;
    const double cv_ncm = b.ncm_volume_fraction;
    const double eps_c_ncm = 1.0 - b.ncm_volume_fraction - b.cb_envelope_volume_fraction;
    b.cb_binder_porosity = (eps_c - eps_c_ncm) / (1.0 - cv_ncm - eps_c_ncm);
    return b;
}

} // namespace drydem::analysis
