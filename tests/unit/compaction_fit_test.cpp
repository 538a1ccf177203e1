// SPDX-License-Identifier: MIT
// The compaction curve's fit (calendering/compaction_fit.hpp) recovers a known curve, and refuses
// what no compaction curve is.
#include "drydem/calendering/compaction_fit.hpp"
#include "drydem/calendering/nip.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <vector>

namespace {
using namespace drydem;

std::vector<double> curve(const std::vector<double>& p, double e_min, double e_0, double p_c) {
    std::vector<double> e;
    for (double x : p) e.push_back(e_min + (e_0 - e_min) * std::exp(-x / p_c));
    return e;
}

TEST(CompactionFit, RecoversAKnownCurve) {
    // Sangros Gimenez 2019's pressures and a curve through the range of their porosities.
    const std::vector<double> p{0.0, 5e6, 19.8e6, 42.7e6, 79.1e6, 120e6, 159.4e6};
    const std::vector<double> e = curve(p, 0.20, 0.52, 40e6);
    const CompactionFit f = fit_compaction(p, e);
    ASSERT_TRUE(f.ok);
    EXPECT_NEAR(f.porosity_min, 0.20, 1e-6);
    EXPECT_NEAR(f.porosity_zero, 0.52, 1e-6);
    EXPECT_NEAR(f.resistance / 40e6, 1.0, 1e-5);
    EXPECT_LT(f.rms, 1e-7);
    EXPECT_EQ(f.points, 7);
}

TEST(CompactionFit, NoisyPointsStayClose) {
    std::vector<double> p;
    for (int k = 0; k <= 40; ++k) p.push_back(2.5e6 * k);
    std::vector<double> e = curve(p, 0.25, 0.45, 25e6);
    for (std::size_t k = 0; k < e.size(); ++k) e[k] += (k % 2 ? 1 : -1) * 0.002;
    const CompactionFit f = fit_compaction(p, e);
    ASSERT_TRUE(f.ok);
    EXPECT_NEAR(f.porosity_min, 0.25, 0.01);
    EXPECT_NEAR(f.resistance / 25e6, 1.0, 0.1);
    EXPECT_NEAR(f.rms, 0.002, 0.0005);
}

TEST(CompactionFit, RefusesWhatIsNoCompaction) {
    EXPECT_FALSE(
        fit_compaction(std::vector<double>{0, 1e6, 2e6}, std::vector<double>{0.5, 0.4, 0.3}).ok);
    const std::vector<double> p{0.0, 1e6, 2e6, 3e6, 4e6};
    EXPECT_FALSE(fit_compaction(p, std::vector<double>{0.3, 0.35, 0.4, 0.45, 0.5}).ok); // rises
    EXPECT_FALSE(fit_compaction(std::vector<double>(5, 0.0), std::vector<double>(5, 0.4)).ok);
    EXPECT_FALSE(fit_compaction(p, std::vector<double>{0.4, 0.3}).ok); // sizes differ
}

} // namespace

// The nip's mean pressure for a line load (calendering/nip.hpp): q / sqrt(2 R Δh).
TEST(NipPressure, LineLoadOverTheEntryArcOfTheRoll) {
    // 100 N/mm on a 215 mm roll taking 10 µm off: l = sqrt(2 × 0.215 × 1e-5) = 2.074 mm.
    EXPECT_NEAR(drydem::nip_pressure(100e3, 0.215, 60e-6, 50e-6), 100e3 / 2.0736441353e-3, 1e-3);
    EXPECT_TRUE(std::isinf(drydem::nip_pressure(100e3, 0.215, 60e-6, 60e-6)));
    // The deeper the roll presses, the longer the nip and the lower the mean pressure.
    EXPECT_GT(drydem::nip_pressure(1e3, 0.2, 60e-6, 55e-6),
              drydem::nip_pressure(1e3, 0.2, 60e-6, 50e-6));
}
