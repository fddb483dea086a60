// Issue 15, classes 5, 6 and 8: a config is checked whole at load (every cell's map spec, the
// sweep's size, duplicate keys and axis values, one default for an absent or empty object), and
// command-line numbers are read strictly against the config's ranges.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "cli/cli_numbers.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/sweep_config.h"
#include "engine/plan/sweep_plan.h"
#include "engine/plan/sweep_size.h"
#include "engine/sweep/sweep_runner.h"
#include "tests/address_space_limit.h"
#include "tests/engine/config_error.h"
#include "tests/test_size.h"

namespace agv {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The config text in a file of its own, loaded as `agvbench run` and `validate` load it.
std::string load_error(const std::string& text) {
  const fs::path path =
      fs::temp_directory_path() / ("agv_config_validation_" + std::to_string(getpid()) + ".json");
  std::ofstream(path) << text;
  std::string error = "no error";
  try {
    load_config(path.string());
  } catch (const InputError& e) {
    error = e.what();
  }
  fs::remove(path);
  return error;
}

const json kSmall = {
    {"sizes", {16, 64}}, {"densities", {0.1}}, {"maps_per_cell", 2}, {"planners", {"astar"}}};

// Class 5: what make_map refuses for one size is refused at load for every size.
TEST(ConfigValidation, MapOptionsAreCheckedForEverySize) {
  ASSERT_EQ(config_error(kSmall), "no error");
  json j = kSmall;
  j["map"] = {{"endpoints", "random"}, {"min_distance", 40}};  // fits 64x64, not 16x16
  const std::string e = config_error(j);
  EXPECT_NE(e.find("map.min_distance: 40 is outside [0, 21.2132]"), std::string::npos) << e;
  EXPECT_NE(e.find("sizes[0] (16x16)"), std::string::npos) << e;
  j["map"]["min_distance"] = 20;
  EXPECT_EQ(config_error(j), "no error");

  j = kSmall;
  j["sizes"] = {64, {64, 16}};
  j["generators"] = {{{"name", "maze"}, {"params", {{"corridor", 20}}}}};
  const std::string maze = config_error(j);
  EXPECT_NE(maze.find("generators[0].params.corridor: 20 is outside [1, 16]"), std::string::npos)
      << maze;
}

TEST(ConfigValidation, LoadNamesTheFileAndTheField) {
  json j = kSmall;
  j["map"] = {{"endpoints", "random"}, {"min_distance", 4096}};
  const std::string e = load_error(j.dump(1));
  EXPECT_NE(e.find(".json: map.min_distance: 4096 is outside"), std::string::npos) << e;
}

// Class 5: a sweep that cannot be held in memory is refused with the field to lower, not left
// to end in std::bad_alloc.
TEST(ConfigValidation, SweepTooLargeForMemoryIsRefused) {
  json sizes = json::array();
  for (int side = 2; side < 1002; ++side) sizes.push_back(side);
  json j = kSmall;
  j["sizes"] = sizes;
  j["maps_per_cell"] = 10000000;  // 10^10 map tasks: terabytes of slots
  ASSERT_GT(usable_memory().bytes, 0.0);
  const std::string e = config_error(j);
  EXPECT_EQ(e.rfind("maps_per_cell: 10000000 maps in each of 1000 cells", 0), 0u) << e;
  EXPECT_NE(e.find("lower maps_per_cell"), std::string::npos) << e;

  // An address-space limit (ulimit -v) is memory the sweep cannot have either: the estimate sees
  // what it leaves above what is mapped already, instead of a bad_alloc mid-sweep. Not under a
  // sanitizer, whose reserved address space such a limit would starve.
  if (!test::kSanitized) {
    constexpr double kRoom = 512.0 * 1024 * 1024;
    UsableMemory m;
    std::string why;
    {
      const test::AddressSpaceLimit limit(kRoom);
      ASSERT_FALSE(limit.failed());
      if (limit.active()) {
        m = usable_memory();
        json big = kSmall;
        big["maps_per_cell"] = 2000000;  // 2 million slots: about a gigabyte, past half of kRoom
        why = config_error(big);
        // A million runs over 400 cells: what `run` holds, releasing finished cells, fits; every
        // slot kept to the end (run --db, merge, export: about 500 MB) does not.
        json many = kSmall;
        many["densities"] = json::array();
        for (int d = 1; d <= 200; ++d) many["densities"].push_back(d / 1000.0);
        many["maps_per_cell"] = 2500;
        EXPECT_EQ(config_error(many), "no error");
        const SweepConfig many_config = parse_config(many);
        std::string kept = "no error";
        try {
          check_sweep_size(many_config, true);
        } catch (const InputError& refused) {
          kept = refused.what();
        }
        EXPECT_NE(kept.find("(every run's slot kept to the end)"), std::string::npos) << kept;
      }
    }
    if (!m.source.empty()) {
      EXPECT_EQ(m.source, "the address-space limit (ulimit -v) leaves");
      EXPECT_GT(m.bytes, kRoom / 2);
      EXPECT_LE(m.bytes, kRoom);
      EXPECT_NE(why.find("the address-space limit (ulimit -v) leaves"), std::string::npos) << why;
    }
  }

  // The estimate grows with what the engine holds: a slot per map task and planner.
  const SweepConfig small = parse_config(kSmall);
  const SweepSize size = sweep_size(small);
  EXPECT_EQ(size.map_tasks, 4);
  EXPECT_EQ(size.run_slots, 4);
  EXPECT_EQ(size.scheduled_runs, 4);
  EXPECT_GE(size.bytes, 4.0 * (sizeof(RunSlot) + sizeof(MapSlot)));
  // Scoped planners: counted as scheduled_runs counts them on the expanded plan.
  json scoped = kSmall;
  scoped["densities"] = {0.1, 0.2, 0.3};
  scoped["maps_per_cell"] = 5;
  scoped["planners"] = {
      "astar",
      {{"name", "rrt"},
       {"only", {{"sizes", {16}}, {"densities", {0.1, 0.3}}, {"maps_per_cell", 2}}}},
      {{"name", "dijkstra"}, {"only", {{"generators", {"uniform", "uniform"}}}}}};
  const SweepConfig scoped_config = parse_config(scoped);
  const SweepSize scoped_size = sweep_size(scoped_config);
  EXPECT_EQ(scoped_size.run_slots, 2 * 3 * 5 * 3);
  EXPECT_EQ(scoped_size.scheduled_runs,
            static_cast<double>(scheduled_runs(scoped_config, plan_sweep(scoped_config))));
  // The shipped configs fit.
  for (const char* name :
       {"default", "quick", "paper-000", "paper-002", "paper-003", "paper-004", "paper-004-nodes",
        "paper-000-random", "paper-002-random", "paper-003-random", "paper-004-random"})
    EXPECT_NO_THROW(load_config(std::string(AGV_SOURCE_DIR) + "/configs/" + name + ".json"))
        << name;
}

// Class 6: a key given twice in one object is refused with its line; the same key in two
// objects is fine.
TEST(ConfigValidation, DuplicateKeysAreRefusedWithTheirLine) {
  const std::string e = load_error(
      "{\"sizes\": [16],\n \"planners\": [\"astar\"],\n \"map\": {\"endpoints\": \"corners\",\n"
      "   \"endpoints\": \"random\"}}\n");
  EXPECT_NE(e.find(".json:4:4: key \"endpoints\" appears twice"), std::string::npos) << e;
  const std::string top =
      load_error("{\"seed\": 1, \"planners\": [\"astar\"], \"sizes\": [16], \"seed\": 2}");
  EXPECT_NE(top.find(":1:51: key \"seed\" appears twice"), std::string::npos) << top;
  EXPECT_EQ(load_error("{\"sizes\": [16], \"planners\": [{\"name\": \"astar\"}, {\"name\": "
                       "\"astar\", \"label\": \"b\", \"params\": {\"diagonal_cost\": 1.5}}]}"),
            "no error");
  // A key-like string value does not count as a key.
  EXPECT_EQ(load_error("{\"name\": \"seed\", \"seed\": 3, \"planners\": [\"astar\"]}"), "no error");
}

// Class 6: axis values that would give two cells one key.
TEST(ConfigValidation, DuplicateAxisValuesAreRefused) {
  json j = kSmall;
  j["sizes"] = {16, {16, 16}};
  std::string e = config_error(j);
  EXPECT_NE(e.find("sizes[1]: 16x16 is also sizes[0]"), std::string::npos) << e;
  j = kSmall;
  j["densities"] = {0.1, 0.2, 0.10000000001};
  e = config_error(j);
  EXPECT_NE(e.find("densities[2]: 0.10000000001 names the same cells as densities[0] (0.1)"),
            std::string::npos)
      << e;
  j["densities"] = {0.1, 0.1000000001};  // differs in the 10th digit: two cells, two keys
  EXPECT_EQ(config_error(j), "no error");
  j = kSmall;
  j["generators"] = {"uniform", "uniform"};
  EXPECT_NE(config_error(j).find("generators[1]: generator \"uniform\" appears twice"),
            std::string::npos);
  j["generators"] = {{{"name", "maze"}, {"params", {{"corridor", 2}}}},
                     {{"name", "maze"}, {"params", {{"corridor", 2}}}}};
  EXPECT_NE(config_error(j).find("generators[1]: generator \"maze\" appears twice"),
            std::string::npos);
  // Every cell key of an accepted config is distinct.
  j = kSmall;
  j["generators"] = {"uniform", "maze"};
  j["densities"] = {0.1, 0.2};
  const SweepConfig config = parse_config(j);
  std::set<std::string> keys;
  for (const auto& cell : plan_sweep(config).cells) EXPECT_TRUE(keys.insert(cell.key).second);
}

// Class 6: an optional object left out and one written empty give the same config.
TEST(ConfigValidation, AbsentAndEmptyObjectsGiveOneDefault) {
  const json absent = config_as_run(parse_config(kSmall));
  for (const char* key : {"map", "collision", "motion", "references"}) {
    json j = kSmall;
    j[key] = json::object();
    EXPECT_EQ(config_as_run(parse_config(j)), absent) << key;
  }
  EXPECT_EQ(absent["map"]["require_solvable"], true);
  json j = kSmall;
  j["planners"] = {{{"name", "astar"}, {"params", json::object()}, {"only", json::object()}}};
  j["generators"] = {{{"name", "uniform"}, {"params", json::object()}}};
  EXPECT_EQ(config_as_run(parse_config(j)), absent);
}

// "references": {"any_angle": false} is another sweep (its hash and config as run say so); true
// is the default and leaves the hash of every config written before the option alone.
TEST(ConfigValidation, AnyAngleReferenceCanBeLeftOut) {
  const SweepConfig plain = parse_config(kSmall);
  EXPECT_TRUE(plain.any_angle_reference);
  EXPECT_FALSE(config_as_run(plain).contains("references"));
  json j = kSmall;
  j["references"] = {{"any_angle", true}};
  EXPECT_EQ(config_hash(parse_config(j)), config_hash(plain));
  j["references"] = {{"any_angle", false}};
  const SweepConfig off = parse_config(j);
  EXPECT_FALSE(off.any_angle_reference);
  EXPECT_EQ(config_as_run(off)["references"], json({{"any_angle", false}}));
  EXPECT_NE(config_hash(off), config_hash(plain));
  // The config as run reads back as the same sweep (journals, isolated workers, merge).
  EXPECT_EQ(config_hash(parse_config(config_as_run(off))), config_hash(off));
  j["references"] = {{"any_angle", "no"}};
  EXPECT_NE(config_error(j).find("references.any_angle: expected true or false"), std::string::npos)
      << config_error(j);
  j["references"] = {{"optimal", false}};
  EXPECT_NE(config_error(j).find("references.optimal"), std::string::npos) << config_error(j);
}

// Integers past 2^63 - 1 are refused as written (nlohmann holds them unsigned; read as long long
// they would wrap negative, which only the ranges' lower bounds caught).
TEST(ConfigValidation, HugeIntegersAreRefusedAsWritten) {
  json j = kSmall;
  j["seed"] = json::parse("18446744073709551615");
  EXPECT_NE(config_error(j).find("seed: 18446744073709551615 is outside"), std::string::npos)
      << config_error(j);
  j = kSmall;
  j["planners"] = {
      {{"name", "rrt"}, {"params", {{"max_iterations", json::parse("18446744073709551615")}}}}};
  EXPECT_NE(config_error(j).find("max_iterations: 18446744073709551615 is outside"),
            std::string::npos)
      << config_error(j);
}

// Class 8: command-line numbers, the whole text one number in the config's range.
TEST(CliNumbers, RefusesOverflowNanNegativeAndTrailingText) {
  EXPECT_EQ(parse_cli_integer("42", "--seed", kSeedRange), 42);
  EXPECT_EQ(parse_cli_number("0.25", "--density", kDensityRange), 0.25);
  const auto integer_error = [](std::string text, IntRange range) {
    return cli_integer_error(text, range);
  };
  const auto number_error = [](std::string text, NumberRange range) {
    return cli_number_error(text, range);
  };
  EXPECT_NE(integer_error("4294967297", {1, 2147483647}).find("is outside"), std::string::npos);
  EXPECT_NE(integer_error("99999999999999999999", kSeedRange).find("is outside"),
            std::string::npos);
  EXPECT_NE(integer_error("-1", kSeedRange).find("-1 is outside [0, 9007199254740992]"),
            std::string::npos);
  EXPECT_NE(integer_error("3x", kSeedRange).find("expected an integer"), std::string::npos);
  EXPECT_NE(integer_error("", kSeedRange).find("expected an integer"), std::string::npos);
  EXPECT_NE(integer_error(" 3", kSeedRange).find("expected an integer"), std::string::npos);
  EXPECT_NE(integer_error("0x10", kSeedRange).find("expected an integer"), std::string::npos);
  EXPECT_NE(integer_error("1.5", kSeedRange).find("expected an integer"), std::string::npos);
  EXPECT_NE(number_error("nan", {0, 1}).find("not a finite number"), std::string::npos);
  EXPECT_NE(number_error("-inf", {0, 1}).find("not a finite number"), std::string::npos);
  EXPECT_NE(number_error("1e999", {0, 1}).find("is outside"), std::string::npos);
  EXPECT_NE(number_error("-1", {0, 1}).find("-1 is outside [0, 1]"), std::string::npos);
  EXPECT_NE(number_error("0.5abc", {0, 1}).find("expected a number"), std::string::npos);
  EXPECT_NE(number_error("+0.5", {0, 1}).find("expected a number"), std::string::npos);
  EXPECT_EQ(number_error("1e-5", {0, 1}), "");
  // Accepted text is rewritten canonically, so CLI11 (which reads "010" as octal 8) converts
  // the value that was checked.
  std::string text = "010";
  EXPECT_EQ(cli_integer_error(text, kSeedRange), "");
  EXPECT_EQ(text, "10");
  try {
    parse_cli_integer("-1", "--map-index", kMapIndexRange);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--map-index: -1 is outside [0, 9999999]");
  }
}

}  // namespace
}  // namespace agv
