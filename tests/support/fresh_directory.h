// Test helper: an empty directory of the running test's own under TEST_TMPDIR (the build
// tree's tests/tmp), so that its listing shows every file the code under test leaves behind
// and tests run in parallel processes never share one.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace musclesim::testing {

// `prefix` + the test's name + `suffix`, emptied and made again (no "/" at the end).
inline std::string FreshDirectory(const std::string& prefix, const std::string& suffix = "") {
  const std::string dir = ::testing::TempDir() + prefix +
                          ::testing::UnitTest::GetInstance()->current_test_info()->name() + suffix;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace musclesim::testing
