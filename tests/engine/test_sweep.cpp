// The sweep end to end: determinism across thread counts, streamed records, config checking.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "engine/outputs/report.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/sweep_config.h"
#include "engine/plan/sweep_plan.h"
#include "engine/sweep/sweep_runner.h"
#include "engine/system/phase_clock.h"
#include "generators/registry.h"
#include "tests/engine/config_error.h"
#include "tests/test_size.h"

namespace agv {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kReducedMaps = 6;
constexpr int kReducedScopedMaps = 2;

// The default config at reduced size: every generator and planner (or the first `keep` of
// them and, with `keep_scoped`, its first scoped one), fewer and smaller maps; the scoped
// planners (fusion) keep their scope's shape: the smaller size, the first maps.
SweepConfig reduced_default(std::size_t keep = 1000, bool keep_scoped = true) {
  std::ifstream in(std::string(AGV_SOURCE_DIR) + "/configs/default.json");
  json j = json::parse(in);
  j["sizes"] = json::array({24, 40});
  j["maps_per_cell"] = kReducedMaps;
  json planners = json::array();
  bool scoped_kept = false;
  for (auto p : j["planners"]) {
    const bool scoped = p.is_object() && p.contains("only");
    if (scoped) p["only"] = {{"sizes", {24}}, {"maps_per_cell", kReducedScopedMaps}};
    if (planners.size() < keep || (keep_scoped && scoped && !scoped_kept)) planners.push_back(p);
    scoped_kept = scoped_kept || scoped;
  }
  j["planners"] = planners;
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

// perf/bench_sweep's breakdown (engine/system/phase_clock.h): off, it counts nothing; on, its
// planner phase is exactly the runs' own planning times, and every engine phase has run (the
// sinks' with a journal to write, as `run --runs-out` has).
TEST(PhaseClock, CountsThePlannersTimesExactlyAndNothingWhenOff) {
  const SweepConfig config = reduced_default(3, false);
  SweepOptions options;
  options.threads = 2;
  reset_phase_clock();
  run_sweep(config, options);
  for (const std::int64_t ns : phase_clock_totals()) EXPECT_EQ(ns, 0);
  const fs::path runs =
      fs::temp_directory_path() / ("agv_test_phases_" + std::to_string(::getpid()) + ".jsonl");
  options.runs_path = runs.string();
  enable_phase_clock(true);
  const SweepResults r = run_sweep(config, options);
  enable_phase_clock(false);
  fs::remove(runs);
  const PhaseTotals t = phase_clock_totals();
  std::int64_t plan_ns = 0;
  for (const CellResults& cell : r.cells)
    for (const RunSlot& slot : cell.runs)
      if (slot.done) plan_ns += slot.plan_time_ns;
  const auto at = [&t](EnginePhase p) { return t[static_cast<std::size_t>(p)]; };
  EXPECT_EQ(at(EnginePhase::planner), plan_ns);
  EXPECT_GT(at(EnginePhase::map), 0);
  EXPECT_GT(at(EnginePhase::reference), 0);
  EXPECT_GT(at(EnginePhase::record), 0);
  EXPECT_GT(at(EnginePhase::sinks), 0);
  // The references are computed while a run is judged: inside the judge phase.
  EXPECT_GE(at(EnginePhase::judge), at(EnginePhase::reference));
  reset_phase_clock();
  for (const std::int64_t ns : phase_clock_totals()) EXPECT_EQ(ns, 0);
}

TEST(Sweep, ReportIsIdenticalOnOneAndTwoThreads) {
  const SweepConfig config = reduced_default();
  const std::string one = deterministic_text(config, 1, "");
  const std::string two = deterministic_text(config, 2, "");
  EXPECT_EQ(one, two);
  // And the sweep did real work: every planner ran on every map of its scope, and a scoped
  // planner has no entry in the cells outside it.
  const json report = json::parse(one);
  std::size_t scoped = 0;
  for (const auto& p : config.planners) scoped += p.only.everywhere() ? 0 : 1;
  ASSERT_GT(scoped, 0U) << "the default config runs the fusion planners on a scope";
  for (const auto& cell : report["cells"]) {
    const bool small = cell["width"] == 24;
    EXPECT_EQ(cell["planners"].size(), config.planners.size() - (small ? 0 : scoped));
    EXPECT_EQ(cell["paired"].size(), cell["planners"].size() - 1);
    for (const auto& p : cell["planners"]) {
      bool is_scoped = false;
      for (const auto& e : config.planners)
        is_scoped = is_scoped || (e.label == p["planner"] && !e.only.everywhere());
      EXPECT_EQ(p["runs"], is_scoped ? kReducedScopedMaps : kReducedMaps)
          << cell["cell"] << p["planner"];
    }
  }
  EXPECT_EQ(report["coverage"]["runs_expected"], scheduled_runs(config, plan_sweep(config)));
  EXPECT_EQ(report["coverage"]["runs_present"], report["coverage"]["runs_expected"]);
  EXPECT_TRUE(report["complete"].get<bool>());
}

TEST(Sweep, RecordsOnePerRunWithReplayFields) {
  const SweepConfig config = reduced_default(static_cast<std::size_t>(test::sized(3, 1)));
  const fs::path runs =
      fs::temp_directory_path() / ("agv_test_runs_" + std::to_string(::getpid()) + ".jsonl");
  deterministic_text(config, 2, runs.string());
  std::ifstream in(runs);
  std::string line;
  std::size_t n = 0;
  std::set<std::string> ids;
  json header;
  while (std::getline(in, line)) {
    const json rec = json::parse(line);
    if (header.is_null()) {
      // The header first: what replays a run (seed, cells with generator, size and density,
      // planner labels) is there once.
      header = rec;
      for (const char* key :
           {"tool", "journal_version", "config_hash", "seed", "cells", "planners"})
        EXPECT_TRUE(rec.contains(key)) << key;
      continue;
    }
    if (rec.value("record", "") == "map") continue;
    for (const char* key : {"cell", "planner", "map_index", "outcome", "plan_time_ns", "phases"})
      EXPECT_TRUE(rec.contains(key)) << key;
    const json& cell = header.at("cells").at(rec.at("cell").get<std::size_t>());
    for (const char* key : {"cell", "generator", "size", "density"})
      EXPECT_TRUE(cell.contains(key)) << key;
    ids.insert(task_id(header.at("config_hash"), plan_sweep(config).cells.at(rec.at("cell")),
                       rec.at("map_index"),
                       header.at("planners").at(rec.at("planner").get<std::size_t>()).at("label")));
    ++n;
  }
  const auto expected = static_cast<std::size_t>(scheduled_runs(config, plan_sweep(config)));
  // The kept planners on every map, the scoped one on the 24x24 cells' first maps (half the
  // cells).
  const SweepPlan plan = plan_sweep(config);
  const auto everywhere = static_cast<std::int64_t>(test::sized(3, 1));
  ASSERT_EQ(config.planners.size(), static_cast<std::size_t>(everywhere + 1));
  EXPECT_EQ(expected, static_cast<std::size_t>(everywhere * plan.map_tasks()) +
                          plan.cells.size() / 2 * kReducedScopedMaps);
  EXPECT_EQ(n, expected);
  EXPECT_EQ(ids.size(), expected) << "task ids must be unique";
  fs::remove(runs);
}

// The config as run is what isolation workers and merges parse: it must read back as itself.
TEST(Config, ConfigAsRunReadsBackToTheSameConfig) {
  const SweepConfig config = reduced_default();
  const SweepConfig again = parse_config(config_as_run(config));
  EXPECT_EQ(config_as_run(again).dump(), config_as_run(config).dump());
  EXPECT_EQ(config_hash(again), config_hash(config));
  for (std::size_t p = 0; p < config.planners.size(); ++p)
    EXPECT_EQ(again.planners[p].only.everywhere(), config.planners[p].only.everywhere());
}

TEST(Sweep, DifferentSeedsGiveDifferentMaps) {
  SweepConfig a = reduced_default(1, false);  // the maps differ: one planner shows it
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
  fs::create_directories(dir / "sub");
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
  const json base = {{"planners", {"astar"}}, {"sizes", {16}}};
  EXPECT_EQ(config_error(base), "no error");
  json j = base;
  j["densities"] = {0.1, 2.0};
  EXPECT_NE(config_error(j).find("densities[1]"), std::string::npos);
  j = base;
  j["planners"] = {"astar", "astar"};
  EXPECT_NE(config_error(j).find("appears twice"), std::string::npos);
  j = base;
  j["map"] = {{"endpoints", "diagonal"}};
  EXPECT_NE(config_error(j).find("map.endpoints"), std::string::npos);
  j = base;
  j["generators"] = {"fractal"};
  EXPECT_NE(config_error(j).find("generators[0]"), std::string::npos);
  j = base;
  j["baseline"] = "rrt";
  EXPECT_NE(config_error(j).find("baseline"), std::string::npos);
  j = base;
  j["sizes"] = {1};
  EXPECT_NE(config_error(j).find("sizes[0]"), std::string::npos);
}

TEST(Config, ScopeErrorsNameTheField) {
  const json base = {{"sizes", {16, 32}},
                     {"densities", {0.1, 0.2}},
                     {"maps_per_cell", 10},
                     {"planners", {"astar", {{"name", "rrt"}, {"only", {{"sizes", {16}}}}}}}};
  EXPECT_EQ(config_error(base), "no error");
  json j = base;
  j["planners"][1]["only"] = {{"sizes", {20}}};
  EXPECT_NE(config_error(j).find("planners[1].only.sizes[0]: not one of the sweep's sizes"),
            std::string::npos)
      << config_error(j);
  j["planners"][1]["only"] = {{"densities", {0.1, 0.3}}};
  EXPECT_NE(config_error(j).find("planners[1].only.densities[1]"), std::string::npos);
  j["planners"][1]["only"] = {{"generators", {"maze"}}};
  EXPECT_NE(config_error(j).find("planners[1].only.generators[0]"), std::string::npos);
  j["planners"][1]["only"] = {{"maps_per_cell", 11}};
  EXPECT_NE(config_error(j).find("planners[1].only.maps_per_cell"), std::string::npos);
  j["planners"][1]["only"] = {{"maps", 3}};
  EXPECT_NE(config_error(j).find("planners[1].only.maps: unknown field"), std::string::npos);
  j = base;
  j["baseline"] = "rrt";
  EXPECT_NE(config_error(j).find("baseline: \"rrt\" has an \"only\" scope"), std::string::npos);
}

TEST(Sweep, ScopedPlannerRunsOnlyOnItsCellsAndMapsAndIsPairedThere) {
  const json j = {
      {"seed", 3},
      {"generators", {"uniform", "rooms"}},
      {"sizes", {16, 24}},
      {"densities", {0.1, 0.2}},
      {"maps_per_cell", 5},
      {"planners",
       {"astar",
        {{"name", "dijkstra"},
         {"only", {{"generators", {"rooms"}}, {"densities", {0.2}}, {"maps_per_cell", 3}}}}}}};
  const SweepConfig config = parse_config(j);
  const SweepPlan plan = plan_sweep(config);
  EXPECT_EQ(scheduled_runs(config, plan), 8 * 5 + 2 * 3);
  const json report = build_report(config, run_sweep(config, {}));
  for (const auto& cell : report["cells"]) {
    const bool in_scope = cell["generator"] == "rooms" && cell["density"] == 0.2;
    ASSERT_EQ(cell["planners"].size(), in_scope ? 2U : 1U) << cell["cell"];
    ASSERT_EQ(cell["paired"].size(), in_scope ? 1U : 0U) << cell["cell"];
    if (!in_scope) continue;
    EXPECT_EQ(cell["planners"][1]["runs"], 3);
    // Dijkstra is optimal like A*: three pairs, each a tie on length.
    EXPECT_EQ(cell["paired"][0]["metrics"]["path_length"]["pairs"], 3);
    EXPECT_EQ(cell["paired"][0]["metrics"]["path_length"]["ties"], 3);
  }
  EXPECT_EQ(report["coverage"]["runs_expected"], 46);
  EXPECT_EQ(report["coverage"]["runs_present"], 46);
  EXPECT_EQ(report["config"]["planners"][1]["only"]["maps_per_cell"], 3);
  EXPECT_FALSE(report["config"]["planners"][0].contains("only"));
}

TEST(Config, GeneratorEntriesTakeShapeParams) {
  const json j = {{"generators", {"uniform", {{"name", "rooms"}, {"params", {{"room_size", 6}}}}}},
                  {"sizes", {16}},
                  {"planners", {"astar"}}};
  const SweepConfig c = parse_config(j);
  ASSERT_EQ(c.generators.size(), 2U);
  EXPECT_EQ(c.generators[1].resolved, (json{{"door_width", 2}, {"room_size", 6}}));
  const json run = config_as_run(c);
  // Only the generators the sweep uses, each with every shape parameter resolved; "map" keeps
  // the common options only.
  EXPECT_EQ(run["generators"],
            (json{{{"name", "uniform"}, {"params", json::object()}},
                  {{"name", "rooms"}, {"params", {{"door_width", 2}, {"room_size", 6}}}}}));
  EXPECT_FALSE(run["map"].contains("room_size"));
  EXPECT_FALSE(run["map"].contains("block_min"));
  const SweepPlan plan = plan_sweep(c);
  EXPECT_EQ(plan.cells.back().spec.generator, "rooms");
  EXPECT_EQ(plan.cells.back().spec.params, c.generators[1].resolved);
  EXPECT_EQ(plan.cells.back().key, "rooms/16x16/0.2");
  // Reads back as itself (isolation workers and merges parse the config as run).
  EXPECT_EQ(config_as_run(parse_config(run)).dump(), run.dump());
}

TEST(Config, ShapeParamErrorsNameTheField) {
  const json base = {{"generators", {"uniform", {{"name", "rooms"}, {"params", json::object()}}}},
                     {"sizes", {16}},
                     {"planners", {"astar"}}};
  EXPECT_EQ(config_error(base), "no error");
  json j = base;
  j["generators"][1]["params"] = {{"room_size", 1}};
  EXPECT_EQ(config_error(j), "generators[1].params.room_size: 1 is outside [2, 8192]");
  j["generators"][1]["params"] = {{"corridor", 2}};
  EXPECT_NE(config_error(j).find("generators[1].params.corridor: unknown parameter"),
            std::string::npos)
      << config_error(j);
  j["generators"][1] = {{"name", "blocks"}, {"params", {{"block_min", 4}, {"block_max", 3}}}};
  EXPECT_EQ(config_error(j), "generators[1].params.block_max: 3 is smaller than block_min (4)");
  j["generators"][1] = {{"name", "maze"}, {"params", {{"corridor", 17}}}};
  EXPECT_NE(config_error(j).find("generators[1].params.corridor: 17 is outside [1, 16]"),
            std::string::npos)
      << config_error(j);
  j["generators"][1] = {{"name", "maze"}, {"shape", {{"corridor", 2}}}};
  EXPECT_EQ(config_error(j), "generators[1].shape: unknown field");
  j["generators"][1] = {{"params", json::object()}};
  EXPECT_EQ(config_error(j), "generators[1].name: missing");
  j["generators"][1] = "uniform";
  EXPECT_NE(config_error(j).find("generators[1]: generator \"uniform\" appears twice"),
            std::string::npos);
  j["generators"][1] = 3;
  EXPECT_NE(config_error(j).find("generators[1]: expected a generator name"), std::string::npos);
}

TEST(Config, ShapeParamInMapSaysWhereItGoes) {
  const json j = {{"generators", {"rooms"}}, {"planners", {"astar"}}, {"map", {{"room_size", 6}}}};
  EXPECT_EQ(config_error(j),
            "map.room_size: a shape parameter of generator \"rooms\"; it now goes in that "
            "generator's entry: \"generators\": [{\"name\": \"rooms\", \"params\": "
            "{\"room_size\": 6}}]");
}

// Only the generators a sweep uses enter its hash: a generator added to the registry (or a
// parameter of one the sweep does not use) leaves existing journals valid.
TEST(Config, HashIgnoresGeneratorsTheSweepDoesNotUse) {
  const json j = {{"generators", {"uniform", "maze"}}, {"sizes", {16}}, {"planners", {"astar"}}};
  const std::string before = config_hash(parse_config(j));
  GeneratorInfo extra;
  extra.name = "test_hash_extra";
  extra.summary = "a generator only this test knows";
  extra.params = {ParamSpec::integer("spacing", 3, 1, 9, "unused")};
  extra.generate = [](const Params&, MapContext& ctx) {
    ctx.canvas.reset(ctx.width, ctx.height, false);
  };
  add_generator_for_testing(extra);
  EXPECT_EQ(config_hash(parse_config(j)), before);
  // The new generator is usable and, once used, does enter the hash.
  json with = j;
  with["generators"].push_back({{"name", "test_hash_extra"}, {"params", {{"spacing", 4}}}});
  const SweepConfig c = parse_config(with);
  EXPECT_NE(config_hash(c), before);
  EXPECT_EQ(config_as_run(c)["generators"][2]["params"], (json{{"spacing", 4}}));
  // Spelling out a default is the same config as leaving it out.
  json spelled = j;
  spelled["generators"][1] = {{"name", "maze"}, {"params", {{"corridor", 1}}}};
  EXPECT_EQ(config_hash(parse_config(spelled)), before);
  spelled["generators"][1]["params"]["corridor"] = 2;
  EXPECT_NE(config_hash(parse_config(spelled)), before);
}

// configs/movingai.json reads the MovingAI sets where the project's checkouts have them,
// ../shared/maps beside the checkout: it is loaded by the test below, which needs them there.
TEST(Config, ShippedConfigsParse) {
  for (const auto& entry : fs::directory_iterator(std::string(AGV_SOURCE_DIR) + "/configs")) {
    if (entry.path().extension() != ".json" || entry.path().filename() == "movingai.json") continue;
    EXPECT_NO_THROW(load_config(entry.path().string())) << entry.path();
  }
}

TEST(Config, FullSetsMovingAiConfigParses) {
  const fs::path sets = fs::path(AGV_SOURCE_DIR) / ".." / "shared" / "maps";
  if (!fs::is_directory(sets))
    GTEST_SKIP() << "configs/movingai.json needs the MovingAI sets in ../shared/maps";
  const SweepConfig config = load_config(std::string(AGV_SOURCE_DIR) + "/configs/movingai.json");
  const SweepPlan plan = plan_sweep(config);
  EXPECT_EQ(plan.cells.size(), 5u);  // the five maps of ../shared/maps
  for (const auto& cell : plan.cells) EXPECT_NE(cell.file, nullptr) << cell.key;
}

}  // namespace
}  // namespace agv
