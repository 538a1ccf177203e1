// SPDX-License-Identifier: MIT
#include "drydem/analysis/profiles.hpp"
#include "drydem/setup/solids.hpp"
#include <algorithm>
#include <cmath>
#include <numbers>

namespace drydem::analysis {

double sphere_slab_volume(double zc, double r, double a, double b) {
    const double u1 = std::max(a - zc, -r), u2 = std::min(b - zc, r);
    if (!(u2 > u1)) return 0.0;
    return std::numbers::pi * (r * r * (u2 - u1) - (u2 * u2 * u2 - u1 * u1 * u1) / 3.0);
}

std::vector<double> Profiles::solid() const {
    std::vector<double> s(size());
    for (std::size_t k = 0; k < size(); ++k) s[k] = ncm[k] + cb_envelope[k];
    return s;
}

Profiles volume_fraction_profiles(const Structure& s, double dz, double top) {
    Profiles p;
    p.dz = dz;
    const std::size_t n = std::max<std::size_t>(1, std::size_t(std::ceil(top / dz - 1e-9)));
    std::vector<double> v_ncm(n, 0.0), v_cb(n, 0.0), v_carbon(n, 0.0);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double zc = s.position[i].z, r = s.radius[i];
        const long k0 = std::max(0L, long(std::floor((zc - r) / dz)));
        const long k1 = std::min(long(n) - 1, long(std::floor((zc + r) / dz)));
        const bool ncm = s.phase[i] == Phase::ncm;
        auto& v = ncm ? v_ncm : v_cb;
        const double carbon = ncm ? 0.0 : s.cb_solid_fraction(i);
        for (long k = k0; k <= k1; ++k) {
            const double a = double(k) * dz, b = std::min(top, double(k + 1) * dz);
            const double slab = sphere_slab_volume(zc, r, a, b);
            v[std::size_t(k)] += slab;
            v_carbon[std::size_t(k)] += carbon * slab;
        }
    }
    const Formulation& f = s.formulation;
    // M-8.4: binder volume per carbon volume when the dissolved PVDF ends up in the agglomerates.
    const double binder_per_carbon = binder_volume_per_carbon(f.pvdf_mass_fraction, f.pvdf_density,
                                                              f.cb_mass_fraction, f.cb_density);
    for (std::size_t k = 0; k < n; ++k) {
        const double a = double(k) * dz, b = std::min(top, double(k + 1) * dz);
        const double vol = s.box.area() * (b - a);
        const double ncm = v_ncm[k] / vol, env = v_cb[k] / vol;
        const double carbon = v_carbon[k] / vol;
        p.ncm.push_back(ncm);
        p.cb_envelope.push_back(env);
        p.cb_carbon.push_back(carbon);
        p.cbd.push_back(carbon * (1.0 + binder_per_carbon));
        p.pore.push_back(1.0 - ncm - env);
        p.pore_total.push_back(1.0 - ncm - carbon * (1.0 + binder_per_carbon));
    }
    return p;
}

} // namespace drydem::analysis
