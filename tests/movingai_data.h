#pragma once
// Where the tests find MovingAI benchmark maps (docs/TESTING.md "Test data"): none ship with the
// checkout; the sets are looked up by one rule, and a test that needs them is skipped by name
// when they are absent. Such a test has "FullSets" in its name: scripts/test.sh fails a run in
// which any other test was skipped.

#include <cstdlib>
#include <filesystem>
#include <string>

namespace agv::testdata {

// The sets: $AGVBENCH_MOVINGAI_DIR if set (it must then exist: a mistyped folder is an
// error, not a silent skip), else ../shared/maps beside the checkout if present, else "".
inline std::string movingai_sets() {
  namespace fs = std::filesystem;
  if (const char* dir = std::getenv("AGVBENCH_MOVINGAI_DIR"); dir && *dir) return dir;
  const fs::path beside = fs::path(AGV_SOURCE_DIR) / ".." / "shared" / "maps";
  return fs::is_directory(beside) ? fs::weakly_canonical(beside).string() : std::string();
}

inline constexpr const char* kNoSetsReason =
    "needs the full MovingAI sets: set AGVBENCH_MOVINGAI_DIR or put them in ../shared/maps "
    "beside the checkout";

}  // namespace agv::testdata

// Declares `var` as the full sets' folder, or skips the test (GTEST_SKIP, which ctest shows as
// skipped) when there is none; fails it when AGVBENCH_MOVINGAI_DIR names no folder.
#define AGV_MOVINGAI_SETS_OR_SKIP(var)                             \
  const std::string var = ::agv::testdata::movingai_sets();        \
  if (var.empty()) GTEST_SKIP() << ::agv::testdata::kNoSetsReason; \
  ASSERT_TRUE(std::filesystem::is_directory(var))                  \
      << "AGVBENCH_MOVINGAI_DIR=" << var << " is not a folder"
