// SPDX-License-Identifier: MIT
// Shared by the test suites: a fresh scratch folder per test.
#pragma once
#include <gtest/gtest.h>
#include <filesystem>
#include <string>

namespace drydem::testing_support {

/// Fresh, empty folder named after the running test, under GoogleTest's temp dir.
inline std::filesystem::path temp_dir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    auto dir = std::filesystem::path(::testing::TempDir()) /
               (std::string("drydem_") + info->test_suite_name() + "_" + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace drydem::testing_support
