// SPDX-License-Identifier: MIT
// Shared by the test suites: a value against its expectation within a relative tolerance.
#pragma once
#include <gtest/gtest.h>
#include <cmath>

namespace drydem::testing_support {

/// |actual - expected| ≤ rel |expected| (the law tests compare with values printed to 4-5 digits).
inline void expect_rel(double actual, double expected, double rel = 1e-4) {
    EXPECT_NEAR(actual, expected, rel * std::abs(expected));
}

} // namespace drydem::testing_support
