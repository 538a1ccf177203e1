// SPDX-License-Identifier: MIT
// The dryer <-> DEM coupling driver (dryer.md D-6) with a mock DEM.
#include "drydem/core/error.hpp"
#include "drydem/dryer_model/coupling.hpp"
#include "drydem/dryer_model/dryer_config.hpp"
#include <gtest/gtest.h>
#include <cmath>

namespace {
using namespace drydem;
using namespace drydem::dryer;

// A mock DEM whose final thickness depends weakly on the first shrinkage rate (a contraction):
// the iteration converges to its fixed point and the log sees every pass.
TEST(DryerCoupling, ConvergesOnMockDem) {
    FilmDryerParams p = film_dryer_preset("table2");
    int calls = 0, logged = 0;
    std::vector<double> seen_porosity;
    auto dem = [&](int iteration, const std::vector<double>& rates, double porosity_in) {
        EXPECT_EQ(iteration, ++calls);
        EXPECT_FALSE(rates.empty());
        seen_porosity.push_back(porosity_in);
        return 90e-6 + 2.0 * (rates[0] - 0.65e-6); // ~90 um, i.e. porosity ≈ 0.48
    };
    const CouplingResult r =
        couple_dryer_dem(p, dem, 0.5e-6, 10, [&](const CouplingIteration&) { ++logged; });
    EXPECT_TRUE(r.converged) << r.message;
    EXPECT_GE(r.iterations.size(), 2u);
    EXPECT_LE(r.iterations.size(), 4u);
    EXPECT_EQ(logged, int(r.iterations.size()));
    EXPECT_DOUBLE_EQ(seen_porosity.front(), 0.44); // starts from the guess
    // each pass starts from the porosity of the previous DEM result
    for (std::size_t i = 1; i < r.iterations.size(); ++i)
        EXPECT_DOUBLE_EQ(r.iterations[i].porosity_in, r.iterations[i - 1].porosity_dem);
    const CouplingIteration& last = r.iterations.back();
    EXPECT_LT(std::abs(last.change), 0.5e-6);
    EXPECT_NEAR(last.porosity_dem, 1.0 - 0.201 / (4287.5 * last.final_thickness_dem), 1e-4);
    EXPECT_NE(r.message.find("converged after"), std::string::npos);
}

// A DEM that keeps oscillating: the driver stops at max iterations with a clear message.
TEST(DryerCoupling, StopsAtMaxIterationsWithMessage) {
    FilmDryerParams p = film_dryer_preset("table2");
    int calls = 0;
    auto dem = [&](int, const std::vector<double>&, double) {
        return (++calls % 2) ? 85e-6 : 95e-6;
    };
    const CouplingResult r = couple_dryer_dem(p, dem, 0.5e-6, 3);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(calls, 3);
    EXPECT_EQ(r.iterations.size(), 3u);
    EXPECT_NE(r.message.find("not converged"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("maximum of 3 iterations"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("dryer.coupling_max_iterations"), std::string::npos) << r.message;
}

TEST(DryerCoupling, RejectsNonsenseFromTheDemAndBadSettings) {
    FilmDryerParams p = film_dryer_preset("table2");
    auto thin = [](int, const std::vector<double>&, double) { return 1e-6; }; // below the solids
    EXPECT_THROW((void)couple_dryer_dem(p, thin, 0.5e-6, 3), RunError);
    auto ok = [](int, const std::vector<double>&, double) { return 84e-6; };
    EXPECT_THROW((void)couple_dryer_dem(p, ok, 0.0, 3), InputError);
    EXPECT_THROW((void)couple_dryer_dem(p, ok, 0.5e-6, 0), InputError);
}

} // namespace
