// The sweep end to end: determinism across thread counts, streamed records, config checking.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "engine/report.h"
#include "engine/sweep_config.h"
#include "engine/sweep_runner.h"

namespace agv {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The default config at reduced size: every generator and planner, fewer and smaller maps.
SweepConfig reduced_default() {
  std::ifstream in(std::string(AGV_SOURCE_DIR) + "/configs/default.json");
  json j = json::parse(in);
  j["sizes"] = json::array({24, 40});
  j["maps_per_cell"] = 6;
  return parse_config(j);
}

std::string deterministic_text(const SweepConfig& config, int threads, const std::string& runs) {
  SweepOptions options;
  options.threads = threads;
  options.runs_path = runs;
  const SweepResults r = run_sweep(config, options);
  EXPECT_EQ(r.threads, threads);
  return deterministic_part(build_report(config, r)).dump(1);
}

TEST(Sweep, ReportIsIdenticalOnOneAndTwoThreads) {
  const SweepConfig config = reduced_default();
  const std::string one = deterministic_text(config, 1, "");
  const std::string two = deterministic_text(config, 2, "");
  EXPECT_EQ(one, two);
  // And the sweep did real work: every planner ran on every map.
  const json report = json::parse(one);
  for (const auto& cell : report["cells"])
    for (const auto& p : cell["planners"]) EXPECT_EQ(p["runs"], 6) << cell["cell"];
}

TEST(Sweep, RecordsOnePerRunWithReplayFields) {
  const SweepConfig config = reduced_default();
  const fs::path runs =
      fs::temp_directory_path() / ("agv_test_runs_" + std::to_string(::getpid()) + ".jsonl");
  deterministic_text(config, 2, runs.string());
  std::ifstream in(runs);
  std::string line;
  std::size_t n = 0;
  std::set<std::string> ids;
  while (std::getline(in, line)) {
    const json rec = json::parse(line);
    for (const char* key : {"task_id", "planner", "generator", "size", "density", "map_index",
                            "seed", "outcome", "metrics", "timing"})
      EXPECT_TRUE(rec.contains(key)) << key;
    ids.insert(rec["task_id"].get<std::string>());
    ++n;
  }
  const auto expected =
      static_cast<std::size_t>(plan_sweep(config).map_tasks()) * config.planners.size();
  EXPECT_EQ(n, expected);
  EXPECT_EQ(ids.size(), expected) << "task ids must be unique";
  fs::remove(runs);
}

TEST(Sweep, DifferentSeedsGiveDifferentMaps) {
  SweepConfig a = reduced_default();
  SweepConfig b = a;
  b.seed = a.seed + 1;
  const json ra = deterministic_part(build_report(a, run_sweep(a, {})));
  const json rb = deterministic_part(build_report(b, run_sweep(b, {})));
  EXPECT_NE(ra["cells"].dump(), rb["cells"].dump());
}

TEST(Sweep, AtomicWriteLeavesNoTemporaryFile) {
  const fs::path dir =
      fs::temp_directory_path() / ("agv_atomic_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string path = (dir / "sub" / "r.json").string();
  write_json_atomic(json{{"a", 1}}, path);
  write_json_atomic(json{{"a", 2}}, path);
  std::ifstream in(path);
  EXPECT_EQ(json::parse(in)["a"], 2);
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir / "sub")) files += e.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 1U);
  fs::remove_all(dir);
}

TEST(Config, ErrorsNameTheField) {
  auto message = [](const json& j) {
    try {
      parse_config(j);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const json base = {{"planners", {"astar"}}, {"sizes", {16}}};
  EXPECT_EQ(message(base), "no error");
  json j = base;
  j["densities"] = {0.1, 2.0};
  EXPECT_NE(message(j).find("densities[1]"), std::string::npos);
  j = base;
  j["planners"] = {"astar", "astar"};
  EXPECT_NE(message(j).find("appears twice"), std::string::npos);
  j = base;
  j["map"] = {{"endpoints", "diagonal"}};
  EXPECT_NE(message(j).find("map.endpoints"), std::string::npos);
  j = base;
  j["generators"] = {"fractal"};
  EXPECT_NE(message(j).find("generators[0]"), std::string::npos);
  j = base;
  j["baseline"] = "rrt";
  EXPECT_NE(message(j).find("baseline"), std::string::npos);
  j = base;
  j["sizes"] = {1};
  EXPECT_NE(message(j).find("sizes[0]"), std::string::npos);
}

TEST(Config, ShippedConfigsParse) {
  for (const auto& entry : fs::directory_iterator(std::string(AGV_SOURCE_DIR) + "/configs")) {
    if (entry.path().extension() != ".json") continue;
    EXPECT_NO_THROW(load_config(entry.path().string())) << entry.path();
  }
}

}  // namespace
}  // namespace agv
