// SPDX-License-Identifier: MIT
#include "drydem/dryer_model/coupling.hpp"
#include "drydem/core/error.hpp"
#include <fmt/format.h>
#include <cmath>

namespace drydem::dryer {

CouplingResult couple_dryer_dem(FilmDryerParams p, const DemRunner& dem, double tolerance,
                                int max_iterations,
                                const std::function<void(const CouplingIteration&)>& on_iteration) {
    if (!(tolerance > 0) || max_iterations < 1)
        throw InputError(
            fmt::format("dryer coupling: tolerance {} m must be > 0 and max iterations "
                        "{} >= 1",
                        tolerance, max_iterations));
    CouplingResult result;
    for (int i = 1; i <= max_iterations; ++i) {
        CouplingIteration it;
        it.iteration = i;
        it.porosity_in = p.final_porosity; // D-6 step 1 / 5
        it.final_thickness_in = film_geometry(p).final_height;
        const DryerRun run = simulate_film_dryer(p); // step 2
        it.rates = schedule_rates(fit_section_rates(p, run));
        it.consolidation_time = run.consolidation_time;
        it.final_thickness_dem = dem(i, it.rates, it.porosity_in); // steps 3-4
        if (!(it.final_thickness_dem > film_geometry(p).solids_height))
            throw RunError(
                fmt::format("dryer coupling: the DEM returned a final thickness of {} um, "
                            "not above the solids height {} um",
                            it.final_thickness_dem * 1e6, film_geometry(p).solids_height * 1e6));
        it.porosity_dem = porosity_from_thickness(p, it.final_thickness_dem); // step 5
        it.change = it.final_thickness_dem - it.final_thickness_in;
        result.iterations.push_back(it);
        if (on_iteration) on_iteration(it);
        if (std::abs(it.change) < tolerance) {
            result.converged = true;
            result.message =
                fmt::format("converged after {} iteration(s): |Δh_f| = {:.3g} um < {:.3g} um", i,
                            std::abs(it.change) * 1e6, tolerance * 1e6);
            return result;
        }
        p.final_porosity = it.porosity_dem;
    }
    const CouplingIteration& last = result.iterations.back();
    result.message = fmt::format(
        "not converged: stopped at the maximum of {} iterations (dryer.coupling_max_iterations) "
        "with |Δh_f| = {:.3g} um >= tolerance {:.3g} um; last h_f = {:.4g} um",
        max_iterations, std::abs(last.change) * 1e6, tolerance * 1e6,
        last.final_thickness_dem * 1e6);
    return result;
}

} // namespace drydem::dryer
