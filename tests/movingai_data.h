#pragma once
// Where the tests find MovingAI benchmark maps (docs/TESTING.md "Test data"): a small subset
// ships in tests/data/movingai/ and is always there; the full sets are optional, looked up by
// one rule, and a test that needs them is skipped by name when they are absent. Such a test has
// "FullSets" in its name: scripts/test.sh fails a run in which any other test was skipped.

#include <cstdlib>
#include <filesystem>
#include <string>

namespace agv::testdata {

// The shipped subset (two synthetic 512x512 maps, each with a slice of its published .scen).
inline std::string shipped_maps() {
  return (std::filesystem::path(AGV_SOURCE_DIR) / "tests" / "data" / "movingai").string();
}

// The full sets: $AGVBENCH_MOVINGAI_DIR if set (it must then exist: a mistyped folder is an
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
