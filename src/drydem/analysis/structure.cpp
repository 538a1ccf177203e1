// SPDX-License-Identifier: MIT
#include "drydem/analysis/structure.hpp"
#include "drydem/setup/solids.hpp"
#include "drydem/core/error.hpp"
#include "drydem/forces/agglomerate_compaction.hpp"
#include <fmt/format.h>
#include <cmath>

namespace drydem::analysis {

double Formulation::solids_density() const {
    return drydem::solids_density(ncm_mass_fraction, ncm_density, pvdf_mass_fraction, pvdf_density,
                                  cb_mass_fraction, cb_density);
}

double Structure::cb_solid_fraction(std::size_t i) const {
    const Formulation& f = formulation;
    if (!(f.cb_agglomerate_density > 0.0) || !(density[i] > 0.0)) return 1.0 - f.cb_porosity;
    return 1.0 - agglomerate_porosity(f.cb_porosity, density[i], f.cb_agglomerate_density);
}

void Structure::add(const Vec3& x, double r, Phase ph, double rho) {
    position.push_back(x);
    radius.push_back(r);
    phase.push_back(ph);
    density.push_back(rho);
}

Structure structure_from_file(const ParticleFile& file, const FileDefaults& d,
                              const PhaseRule& rule) {
    Structure s;
    s.formulation = d.formulation;
    s.box.lx = file.lx.value_or(d.box_x);
    s.box.ly = file.ly.value_or(d.box_y);
    const int n_ncm = d.ncm_classes;
    const int cb_type = rule.cb_type.value_or(n_ncm + 1);
    for (const ParticleRecord& r : file.particles) {
        if (!rule.cb_type && (r.type < 1 || r.type > n_ncm + 1))
            throw InputError(fmt::format("particle {} has type {}; the config defines types 1..{} "
                                         "(NCM classes, then CB = {}); "
                                         "name the CB type with --cb-type",
                                         r.id, r.type, n_ncm + 1, n_ncm + 1));
        if (!(r.radius > 0.0) || !std::isfinite(r.position.z))
            throw InputError(fmt::format("particle {}: radius {} m / z {} m is not a valid sphere",
                                         r.id, r.radius, r.position.z));
        Vec3 x = r.position;
        x.x -= file.xlo.value_or(0.0);
        x.y -= file.ylo.value_or(0.0);
        s.box.wrap(x);
        const Phase ph = r.type == cb_type ? Phase::cb : Phase::ncm;
        const double nominal = ph == Phase::cb && d.formulation.cb_agglomerate_density > 0.0
                                   ? d.formulation.cb_agglomerate_density
                                   : d.formulation.ncm_density;
        s.add(x, r.radius, ph, std::isnan(r.density) ? nominal : r.density);
    }
    if (s.size() == 0) throw InputError("the particle file has no particles");
    return s;
}

} // namespace drydem::analysis
