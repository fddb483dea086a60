// The endpoint rules the papers' set-ups need (configs/paper-00N.json): fixed start and goal
// cells, and random pairs at a minimum distance, on many random maps of every generator; their
// config fields ("map.start", "map.goal") checked at load with the field named; and "sources",
// commentary echoed in the report's config and kept out of the config hash.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <queue>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/connectivity.h"
#include "core/corner_rule.h"
#include "core/rng.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/sweep_config.h"
#include "generators/map_generators.h"
#include "generators/registry.h"
#include "tests/engine/config_error.h"

namespace agv {
namespace {

using nlohmann::json;

// Plain BFS over cells under `rule`, independent of core/connectivity.cpp.
bool bfs_connected(const Grid& g, Cell a, Cell b, CornerRule rule) {
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(g.width()) * g.height(), 0);
  auto blocked = [&](int x, int y) { return g.blocked(x, y); };
  std::queue<Cell> open;
  open.push(a);
  seen[static_cast<std::size_t>(a.y) * g.width() + a.x] = 1;
  while (!open.empty()) {
    const Cell c = open.front();
    open.pop();
    if (c == b) return true;
    for (int d = 0; d < 8; ++d) {
      if (!move_allowed(blocked, c.x, c.y, d, rule)) continue;
      const Cell n{c.x + kDx[d], c.y + kDy[d]};
      auto& s = seen[static_cast<std::size_t>(n.y) * g.width() + n.x];
      if (s) continue;
      s = 1;
      open.push(n);
    }
  }
  return false;
}

std::int64_t obstacles(const Grid& g) {
  std::int64_t n = 0;
  for (int y = 0; y < g.height(); ++y)
    for (int x = 0; x < g.width(); ++x) n += g.blocked(x, y) ? 1 : 0;
  return n;
}

MapSpec spec_of(const std::string& gen, int w, int h, double density) {
  MapSpec s;
  s.generator = gen;
  s.width = w;
  s.height = h;
  s.density = density;
  s.max_attempts = 100000;
  return s;
}

MapInstance make(const MapSpec& s, std::uint64_t seed) {
  Rng rng(seed, 17);
  return make_map(s, rng);
}

// Paper 004's node test, (6, 7) -> (17, 16) 1-based y up on 21 x 21, and its fusion query.
TEST(EndpointRules, FixedEndpointsStayPutOnEveryMap) {
  const std::vector<std::pair<Cell, Cell>> queries = {
      {{5, 14}, {16, 5}}, {{3, 18}, {16, 5}}, {{16, 5}, {5, 14}}, {{0, 0}, {20, 20}}};
  for (const char* gen : {"uniform", "blocks"}) {
    for (const double density : {0.1, 0.2, 0.3}) {
      for (const auto& [start, goal] : queries) {
        MapSpec s = spec_of(gen, 21, 21, density);
        s.endpoints = EndpointMode::fixed;
        s.start = start;
        s.goal = goal;
        s.require_solvable = true;
        int rejections = 0;
        std::vector<std::uint8_t> first_cells;
        bool maps_differ = false;
        for (std::uint64_t seed = 0; seed < 150; ++seed) {
          const MapInstance m = make(s, seed);
          ASSERT_EQ(m.start, start) << gen;
          ASSERT_EQ(m.goal, goal) << gen;
          ASSERT_FALSE(m.grid.blocked(start)) << gen << " seed " << seed;
          ASSERT_FALSE(m.grid.blocked(goal)) << gen << " seed " << seed;
          ASSERT_TRUE(bfs_connected(m.grid, start, goal, s.solvable_rule)) << gen << " " << seed;
          // The density base excludes the two reserved cells, as for corners (uniform: exact).
          if (std::string(gen) == "uniform") {
            EXPECT_EQ(obstacles(m.grid), std::llround(density * (21 * 21 - 2))) << seed;
          }
          rejections += m.rejections;
          std::vector<std::uint8_t> cells;
          for (int y = 0; y < 21; ++y)
            for (int x = 0; x < 21; ++x) cells.push_back(m.grid.blocked(x, y) ? 1 : 0);
          if (seed == 0) first_cells = cells;
          maps_differ = maps_differ || cells != first_cells;
        }
        EXPECT_TRUE(maps_differ) << gen;
        // At 30 % some maps separate the two cells: the generator redrew the map (the endpoints
        // never moved, asserted above).
        if (density >= 0.3) {
          EXPECT_GT(rejections, 0) << gen;
        }
      }
    }
  }
}

// Fixed endpoints at the corners are the corners rule: the same reserved cells, the same draws,
// so the same maps seed for seed (paper 000's (1,1) -> (20,20) is exactly our corners).
TEST(EndpointRules, FixedAtTheCornersIsTheCornersRule) {
  for (const char* gen : {"uniform", "blocks", "maze", "rooms"}) {
    for (std::uint64_t seed = 0; seed < 60; ++seed) {
      MapSpec corners = spec_of(gen, 20, 20, 0.25);
      corners.require_solvable = true;
      MapSpec fixed = corners;
      fixed.endpoints = EndpointMode::fixed;
      fixed.start = {0, 19};
      fixed.goal = {19, 0};
      const MapInstance a = make(corners, seed);
      const MapInstance b = make(fixed, seed);
      ASSERT_TRUE(a.grid.same_cells(b.grid)) << gen << " seed " << seed;
      EXPECT_EQ(a.start, b.start);
      EXPECT_EQ(a.goal, b.goal);
      EXPECT_EQ(a.rejections, b.rejections);
    }
  }
}

// Every generator either returns the fixed cells free or says it could not.
TEST(EndpointRules, GeneratorsThatBlockAFixedCellRedrawOrFailClearly) {
  for (const char* gen : {"maze", "rooms"}) {
    for (const Cell start : {Cell{1, 1}, Cell{2, 3}, Cell{7, 7}}) {
      MapSpec s = spec_of(gen, 24, 24, 0.3);
      s.endpoints = EndpointMode::fixed;
      s.start = start;
      s.goal = {22, 22};
      s.max_attempts = 200;
      for (std::uint64_t seed = 0; seed < 20; ++seed) {
        try {
          const MapInstance m = make(s, seed);
          EXPECT_EQ(m.start, start);
          EXPECT_FALSE(m.grid.blocked(m.start)) << gen;
          EXPECT_FALSE(m.grid.blocked(m.goal)) << gen;
        } catch (const std::runtime_error& e) {
          EXPECT_NE(std::string(e.what()).find("fixed endpoints"), std::string::npos) << e.what();
        }
      }
    }
  }
}

// Paper 003's rule: random pairs at least 14 cells apart on 20 x 20.
TEST(EndpointRules, RandomPairsKeepTheirMinimumDistance) {
  for (const char* gen : {"uniform", "blocks", "rooms"}) {
    for (const double density : {0.1, 0.2, 0.3}) {
      MapSpec s = spec_of(gen, 20, 20, density);
      s.endpoints = EndpointMode::random;
      s.min_distance = 14.0;
      s.require_solvable = true;
      double shortest = 1e9;
      for (std::uint64_t seed = 0; seed < 200; ++seed) {
        const MapInstance m = make(s, seed);
        ASSERT_FALSE(m.grid.blocked(m.start));
        ASSERT_FALSE(m.grid.blocked(m.goal));
        const double d = std::hypot(m.start.x - m.goal.x, m.start.y - m.goal.y);
        ASSERT_GE(d, 14.0) << gen << " seed " << seed;
        shortest = std::min(shortest, d);
        ASSERT_TRUE(bfs_connected(m.grid, m.start, m.goal, s.solvable_rule));
      }
      // The bound is met, not overshot: some pair lies within a cell of it.
      EXPECT_LT(shortest, 15.0) << gen;
    }
  }
}

json fixed_config() {
  return {{"sizes", {21}},
          {"densities", {0.1}},
          {"planners", {"astar"}},
          {"map", {{"endpoints", "fixed"}, {"start", {5, 14}}, {"goal", {16, 5}}}}};
}

TEST(EndpointRules, ConfigFieldsAreCheckedWithTheFieldNamed) {
  EXPECT_EQ(config_error(fixed_config()), "no error");
  const SweepConfig c = parse_config(fixed_config());
  EXPECT_EQ(c.map.endpoints, EndpointMode::fixed);
  EXPECT_EQ(c.map.start, (Cell{5, 14}));
  EXPECT_EQ(c.map.goal, (Cell{16, 5}));

  json j = fixed_config();
  j["map"]["start"] = {21, 3};  // x = 21 on a 21-wide grid: 0-based, outside
  std::string e = config_error(j);
  EXPECT_NE(e.find("map.start: [21, 3] is outside the 21x21 grid"), std::string::npos) << e;
  EXPECT_NE(e.find("sizes[0]"), std::string::npos) << e;

  j = fixed_config();
  j["sizes"] = {32, 12};  // fits 32 x 32, not 12 x 12
  e = config_error(j);
  EXPECT_NE(e.find("map.start: [5, 14] is outside the 12x12 grid"), std::string::npos) << e;
  EXPECT_NE(e.find("sizes[1]"), std::string::npos) << e;

  j = fixed_config();
  j["map"]["goal"] = {5, 14};
  e = config_error(j);
  EXPECT_NE(e.find("map.goal: [5, 14] is the start cell"), std::string::npos) << e;

  j = fixed_config();
  j["map"].erase("goal");
  EXPECT_NE(config_error(j).find("map.goal: missing"), std::string::npos) << config_error(j);

  j = fixed_config();
  j["map"]["endpoints"] = "corners";
  EXPECT_NE(config_error(j).find("map.start: only with \"endpoints\": \"fixed\""),
            std::string::npos)
      << config_error(j);

  j = fixed_config();
  j["map"]["start"] = {5.5, 14};
  EXPECT_NE(config_error(j).find("map.start[0]: expected an integer"), std::string::npos)
      << config_error(j);
  j["map"]["start"] = {-1, 14};
  EXPECT_NE(config_error(j).find("map.start[0]: -1 is outside"), std::string::npos)
      << config_error(j);
  j["map"]["start"] = {5, 14, 0};
  EXPECT_NE(config_error(j).find("map.start: expected [x, y]"), std::string::npos)
      << config_error(j);
}

TEST(EndpointRules, FixedEndpointsRoundTripThroughTheConfigAsRun) {
  const SweepConfig c = parse_config(fixed_config());
  const json as_run = config_as_run(c);
  EXPECT_EQ(as_run["map"]["start"], json({5, 14}));
  EXPECT_EQ(as_run["map"]["goal"], json({16, 5}));
  const SweepConfig back = parse_config(as_run);
  EXPECT_EQ(config_hash(back), config_hash(c));
  // Other endpoint rules write no start or goal, so their configs keep the hash they had.
  json corners = fixed_config();
  corners["map"] = {{"endpoints", "corners"}};
  EXPECT_FALSE(config_as_run(parse_config(corners))["map"].contains("start"));
  // Moving an endpoint is another sweep.
  json moved = fixed_config();
  moved["map"]["goal"] = {16, 6};
  EXPECT_NE(config_hash(parse_config(moved)), config_hash(c));
}

TEST(EndpointRules, SourcesAreEchoedButNotHashed) {
  json j = fixed_config();
  const std::string bare_hash = config_hash(parse_config(j));
  j["sources"] = {{"sizes", "Paper 004 section 4.3: a 21 m x 21 m raster map"},
                  {"map", {{"endpoints", "Paper 004 section 4.1: (6, 7) to (17, 16)"}}}};
  const SweepConfig c = parse_config(j);
  EXPECT_EQ(config_hash(c), bare_hash);
  const json as_run = config_as_run(c);
  EXPECT_EQ(as_run["sources"], j["sources"]);
  EXPECT_EQ(config_hash(parse_config(as_run)), bare_hash);
  j["sources"]["sizes"] = "reworded";
  EXPECT_EQ(config_hash(parse_config(j)), bare_hash);
  EXPECT_FALSE(config_as_run(parse_config(fixed_config())).contains("sources"));

  j["sources"]["densities"] = 0.1;
  EXPECT_NE(config_error(j).find("sources.densities: expected a string"), std::string::npos)
      << config_error(j);
  j["sources"] = {{"map", {{"cell_edge", json::array()}}}};
  EXPECT_NE(config_error(j).find("sources.map.cell_edge: expected a string"), std::string::npos)
      << config_error(j);
  j["sources"] = "all from the paper";
  EXPECT_NE(config_error(j).find("sources: expected an object"), std::string::npos)
      << config_error(j);
}

// The shipped paper configs: both set-ups load, and every paper set-up says where its values come
// from.
TEST(EndpointRules, PaperConfigsLoadWithTheirSources) {
  for (const char* name : {"paper-000", "paper-002", "paper-003", "paper-004", "paper-004-nodes"}) {
    const SweepConfig c = load_config(std::string(AGV_SOURCE_DIR) + "/configs/" + name + ".json");
    for (const char* field : {"generators", "sizes", "densities", "map", "collision", "planners"})
      EXPECT_TRUE(c.sources.contains(field)) << name << " sources." << field;
    const SweepConfig r = load_config(std::string(AGV_SOURCE_DIR) + "/configs/" +
                                      std::string(name).substr(0, 9) + "-random.json");
    EXPECT_TRUE(r.sources.empty()) << name;
    EXPECT_NE(config_hash(c), config_hash(r)) << name;
  }
}

}  // namespace
}  // namespace agv
