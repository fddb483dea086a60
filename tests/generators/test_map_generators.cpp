// Map generators: exact counts, determinism, solvability (checked by an independent BFS), the
// endpoint protocols and spec validation. Also the connectivity check they rely on.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/connectivity.h"
#include "core/corner_rule.h"
#include "core/rng.h"
#include "generators/map_generators.h"
#include "generators/registry.h"

namespace agv {
namespace {

constexpr CornerRule kRules[] = {CornerRule::allow, CornerRule::no_squeeze,
                                 CornerRule::no_corner_cut};

// Plain BFS over cells with std::queue, sharing nothing with connectivity.cpp but the rule.
std::vector<std::uint8_t> reach(const Grid& g, Cell from, CornerRule rule) {
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(g.width()) * g.height(), 0);
  if (g.blocked(from)) return seen;
  auto blocked = [&](int x, int y) { return g.blocked(x, y); };
  std::queue<Cell> open;
  open.push(from);
  seen[static_cast<std::size_t>(from.y) * g.width() + from.x] = 1;
  while (!open.empty()) {
    const Cell c = open.front();
    open.pop();
    for (int d = 0; d < 8; ++d) {
      if (!move_allowed(blocked, c.x, c.y, d, rule)) continue;
      const Cell n{c.x + kDx[d], c.y + kDy[d]};
      auto& s = seen[static_cast<std::size_t>(n.y) * g.width() + n.x];
      if (s) continue;
      s = 1;
      open.push(n);
    }
  }
  return seen;
}

bool bfs_connected(const Grid& g, Cell a, Cell b, CornerRule rule) {
  return reach(g, a, rule)[static_cast<std::size_t>(b.y) * g.width() + b.x] != 0;
}

// Free cells reachable from `from` with 4-connected moves.
std::int64_t reachable_4(const Grid& g, Cell from) {
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(g.width()) * g.height(), 0);
  std::vector<Cell> stack = {from};
  seen[static_cast<std::size_t>(from.y) * g.width() + from.x] = 1;
  std::int64_t n = 0;
  while (!stack.empty()) {
    const Cell c = stack.back();
    stack.pop_back();
    ++n;
    for (int d = 0; d < 4; ++d) {
      const Cell m{c.x + kDx[d], c.y + kDy[d]};
      if (g.blocked(m)) continue;
      auto& s = seen[static_cast<std::size_t>(m.y) * g.width() + m.x];
      if (!s) {
        s = 1;
        stack.push_back(m);
      }
    }
  }
  return n;
}

MapSpec spec_of(const std::string& generator, int w, int h, double density) {
  MapSpec s;
  s.generator = generator;
  s.width = w;
  s.height = h;
  s.density = density;
  return s;
}

// Sets the shape parameters among `values` that the spec's generator declares (a loop over every
// generator sets the maze's corridor and the rooms' room_size alike).
void set_shape(MapSpec& s, const nlohmann::json& values) {
  const GeneratorInfo* info = find_generator(s.generator);
  ASSERT_NE(info, nullptr) << s.generator;
  for (const auto& p : info->params)
    if (values.contains(p.name)) s.params[p.name] = values[p.name];
}

std::vector<std::string> generator_names() {
  std::vector<std::string> names;
  for (const auto& g : generator_registry()) names.push_back(g.name);
  return names;
}

MapInstance make(const MapSpec& s, std::uint64_t seed) {
  Rng rng(seed, 17);
  return make_map(s, rng);
}

std::int64_t target_count(const MapSpec& s) {
  const std::int64_t reserved = s.endpoints == EndpointMode::corners ? 2 : 0;
  return std::llround(s.density * static_cast<double>(std::int64_t{s.width} * s.height - reserved));
}

TEST(MapGenerators, NamesAreListed) {
  EXPECT_EQ(generator_names(), (std::vector<std::string>{"uniform", "blocks", "maze", "rooms"}));
}

// The defaults the registry declares are the maps the configs have always produced: a spec
// that spells them out draws the same map as one that leaves them to the defaults.
TEST(MapGenerators, DeclaredDefaultsAreTheDefaults) {
  const std::vector<std::pair<std::string, nlohmann::json>> spelled = {
      {"blocks", {{"block_min", 2}, {"block_max", 5}}},
      {"maze", {{"corridor", 1}}},
      {"rooms", {{"room_size", 8}, {"door_width", 2}}}};
  for (const auto& [gen, params] : spelled) {
    MapSpec implicit = spec_of(gen, 37, 29, 0.3);
    MapSpec explicit_ = implicit;
    explicit_.params = params;
    MapSpec other = implicit;
    other.params = params;
    other.params.begin().value() = params.begin().value().get<int>() + 1;
    for (std::uint64_t seed = 0; seed < 4; ++seed) {
      EXPECT_TRUE(make(implicit, seed).grid.same_cells(make(explicit_, seed).grid)) << gen;
    }
    bool any_differs = false;
    for (std::uint64_t seed = 0; seed < 4; ++seed)
      any_differs = any_differs || !make(implicit, seed).grid.same_cells(make(other, seed).grid);
    EXPECT_TRUE(any_differs) << gen << ": the parameter does not reach the generator";
  }
}

TEST(MapGenerators, UniformHasExactObstacleCount) {
  const double densities[] = {0.0, 0.01, 0.1, 0.2, 0.3333, 0.5, 0.75, 0.9, 0.999};
  const int sizes[][2] = {{2, 2}, {13, 7}, {64, 64}, {100, 33}};
  for (const auto& size : sizes) {
    for (double p : densities) {
      for (EndpointMode mode : {EndpointMode::corners, EndpointMode::random}) {
        for (std::uint64_t seed = 0; seed < 10; ++seed) {
          MapSpec s = spec_of("uniform", size[0], size[1], p);
          s.endpoints = mode;
          if (mode == EndpointMode::random && target_count(s) > s.width * s.height - 2) continue;
          const MapInstance m = make(s, seed);
          ASSERT_EQ(m.grid.obstacle_count(), target_count(s))
              << size[0] << "x" << size[1] << " p=" << p << " seed " << seed;
          ASSERT_EQ(m.rejections, 0);
        }
      }
    }
  }
}

TEST(MapGenerators, BlocksHaveExactObstacleCountAndBlockShapes) {
  for (double p : {0.0, 0.05, 0.2, 0.4, 0.7, 0.95}) {
    for (std::uint64_t seed = 0; seed < 5; ++seed) {
      MapSpec s = spec_of("blocks", 40, 30, p);
      s.params = {{"block_min", 3}, {"block_max", 6}};
      const MapInstance m = make(s, seed);
      ASSERT_EQ(m.grid.obstacle_count(), target_count(s)) << "p=" << p;
    }
  }
  // With a single block size, obstacles come in 4x4 squares (clipped at the edges): at low
  // density few cells can be isolated.
  MapSpec s = spec_of("blocks", 60, 60, 0.1);
  s.params = {{"block_min", 4}, {"block_max", 4}};
  const MapInstance m = make(s, 1);
  int isolated = 0;
  for (int y = 0; y < 60; ++y) {
    for (int x = 0; x < 60; ++x) {
      if (!m.grid.blocked(x, y)) continue;
      int n = 0;
      for (int d = 0; d < 4; ++d) {
        const int nx = x + kDx[d];
        const int ny = y + kDy[d];
        n += (m.grid.in_bounds(nx, ny) && m.grid.blocked(nx, ny)) ? 1 : 0;
      }
      isolated += n == 0 ? 1 : 0;
    }
  }
  EXPECT_LE(isolated, 4);  // only a partial last block can leave a lone cell
}

TEST(MapGenerators, SameSeedSameMapDifferentSeedDifferentMap) {
  for (const std::string& gen : generator_names()) {
    for (EndpointMode mode : {EndpointMode::corners, EndpointMode::random}) {
      MapSpec s = spec_of(gen, 48, 40, 0.3);
      s.endpoints = mode;
      const MapInstance a = make(s, 42);
      const MapInstance b = make(s, 42);
      const MapInstance c = make(s, 43);
      EXPECT_TRUE(a.grid.same_cells(b.grid)) << gen;
      EXPECT_EQ(a.start, b.start) << gen;
      EXPECT_EQ(a.goal, b.goal) << gen;
      EXPECT_FALSE(a.grid.same_cells(c.grid)) << gen;
    }
  }
}

TEST(MapGenerators, DensityChangesEveryGenerator) {
  for (const std::string& gen : generator_names()) {
    std::int64_t previous = -1;
    for (double p : {0.0, 0.1, 0.2, 0.3, 0.45}) {
      const MapInstance m = make(spec_of(gen, 64, 64, p), 7);
      EXPECT_GT(m.grid.obstacle_count(), previous) << gen << " p=" << p;
      previous = m.grid.obstacle_count();
    }
  }
}

TEST(MapGenerators, MazeBraidsDownToDensityAndStaysConnected) {
  for (int corridor : {1, 2, 3}) {
    // Below the perfect maze's wall fraction (about 0.47 for corridor 1, less where a stretched
    // last corridor widens the free area).
    for (double p : {0.0, 0.1, 0.25, 0.35, 0.4}) {
      for (std::uint64_t seed = 0; seed < 4; ++seed) {
        MapSpec s = spec_of("maze", 61, 50, p);
        s.params["corridor"] = corridor;
        const MapInstance m = make(s, seed);
        const std::int64_t t = target_count(s);
        // At or below the target, by less than one (possibly stretched) wall piece.
        EXPECT_LE(m.grid.obstacle_count(), t);
        EXPECT_LT(t - m.grid.obstacle_count(), 3 * corridor * corridor + 1);
        // Braiding only opens walls: the maze stays one 4-connected region.
        EXPECT_EQ(reachable_4(m.grid, m.start), m.grid.free_count()) << corridor << " " << p;
        EXPECT_FALSE(m.grid.blocked(m.start));
        EXPECT_FALSE(m.grid.blocked(m.goal));
      }
    }
  }
}

TEST(MapGenerators, MazeAboveItsWallFractionGetsClutterToTheExactCount) {
  MapSpec s = spec_of("maze", 41, 41, 0.7);
  const MapInstance m = make(s, 3);
  EXPECT_EQ(m.grid.obstacle_count(), target_count(s));
}

TEST(MapGenerators, RoomsHaveWallsDoorsAndClutter) {
  // 35 = 4 rooms of 8 + 3 walls: walls at x, y = 8, 17, 26.
  MapSpec s = spec_of("rooms", 35, 35, 0.3);
  s.params = {{"room_size", 8}, {"door_width", 2}};
  for (std::uint64_t seed = 0; seed < 5; ++seed) {
    const MapInstance m = make(s, seed);
    EXPECT_EQ(m.grid.obstacle_count(), target_count(s));
    for (int wall : {8, 17, 26}) {
      EXPECT_TRUE(m.grid.blocked(wall, wall));  // junctions stand
      int open_cells = 0;
      for (int y = 0; y < 35; ++y) open_cells += m.grid.blocked(wall, y) ? 0 : 1;
      EXPECT_EQ(open_cells, 4 * 2);  // one 2-cell door per room row
    }
  }
  // Below the walls' own fraction, whole segments go: every free cell stays reachable.
  for (double p : {0.0, 0.05, 0.12}) {
    const MapInstance m = make(spec_of("rooms", 50, 44, p), 9);
    EXPECT_EQ(reachable_4(m.grid, m.start), m.grid.free_count());
    EXPECT_LE(m.grid.obstacle_count(), target_count(spec_of("rooms", 50, 44, p)));
  }
}

TEST(MapGenerators, CornersAreReservedFree) {
  for (const std::string& gen : generator_names()) {
    for (double p : {0.0, 0.5, 0.9, 0.99}) {
      for (std::uint64_t seed = 0; seed < 5; ++seed) {
        MapSpec s = spec_of(gen, 23, 17, p);
        set_shape(s, {{"corridor", 2}, {"room_size", 4}});
        const MapInstance m = make(s, seed);
        EXPECT_EQ(m.start, (Cell{0, 16}));
        EXPECT_EQ(m.goal, (Cell{22, 0}));
        EXPECT_FALSE(m.grid.blocked(m.start)) << gen << " p=" << p;
        EXPECT_FALSE(m.grid.blocked(m.goal)) << gen << " p=" << p;
      }
    }
  }
}

TEST(MapGenerators, RequireSolvableHoldsAndCountsRejections) {
  // Densities where a fair share of maps is unsolvable (for the maze: a few clutter cells on top
  // of the perfect maze's ~0.47 walls).
  const std::pair<std::string, double> cases[] = {
      {"uniform", 0.42}, {"blocks", 0.45}, {"maze", 0.475}, {"rooms", 0.42}};
  for (const auto& [gen, p] : cases) {
    int total_rejections = 0;
    for (CornerRule rule : kRules) {
      for (std::uint64_t seed = 0; seed < 12; ++seed) {
        MapSpec s = spec_of(gen, 31, 31, p);
        s.require_solvable = true;
        s.solvable_rule = rule;
        set_shape(s, {{"room_size", 5}});
        const MapInstance m = make(s, seed);
        ASSERT_TRUE(bfs_connected(m.grid, m.start, m.goal, rule)) << gen;
        total_rejections += m.rejections;
        if (m.rejections > 0) {
          // The count is exact: one attempt fewer fails, and the same map comes back with
          // exactly enough attempts.
          MapSpec fewer = s;
          fewer.max_attempts = m.rejections;
          EXPECT_THROW(make(fewer, seed), std::runtime_error);
          MapSpec exact = s;
          exact.max_attempts = m.rejections + 1;
          EXPECT_TRUE(make(exact, seed).grid.same_cells(m.grid));
        }
      }
    }
    EXPECT_GT(total_rejections, 0) << gen;
  }
}

TEST(MapGenerators, RandomEndpointsRespectMinDistanceAndSolvability) {
  for (const std::string& gen : generator_names()) {
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
      MapSpec s = spec_of(gen, 40, 30, 0.25);
      s.endpoints = EndpointMode::random;
      s.min_distance = 25.0;
      s.require_solvable = true;
      const MapInstance m = make(s, seed);
      EXPECT_FALSE(m.grid.blocked(m.start));
      EXPECT_FALSE(m.grid.blocked(m.goal));
      EXPECT_NE(m.start, m.goal);
      EXPECT_GE(std::hypot(m.start.x - m.goal.x, m.start.y - m.goal.y), 25.0);
      EXPECT_TRUE(bfs_connected(m.grid, m.start, m.goal, s.solvable_rule));
    }
  }
}

TEST(MapGenerators, ImpossibleRequestsFailClearly) {
  MapSpec s = spec_of("uniform", 16, 16, 0.95);
  s.require_solvable = true;
  s.max_attempts = 5;
  try {
    make(s, 1);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("uniform"), std::string::npos) << what;
    EXPECT_NE(what.find("16x16"), std::string::npos) << what;
    EXPECT_NE(what.find("0.95"), std::string::npos) << what;
  }
  // Random endpoints that cannot be that far apart on what is left free.
  MapSpec r = spec_of("uniform", 10, 10, 0.98);
  r.endpoints = EndpointMode::random;
  r.min_distance = 12.0;
  r.max_attempts = 3;
  try {
    make(r, 1);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("min_distance"), std::string::npos) << e.what();
  }
}

TEST(MapGenerators, BadSpecsNameTheField) {
  struct Case {
    std::string generator;
    std::function<void(MapSpec&)> mutate;
    std::string field;
  };
  const std::vector<Case> cases = {
      {"uniform", [](MapSpec& s) { s.generator = "spiral"; }, "generator"},
      {"uniform", [](MapSpec& s) { s.width = 1; }, "width"},
      {"uniform", [](MapSpec& s) { s.width = 8193; }, "width"},
      {"uniform", [](MapSpec& s) { s.height = 0; }, "height"},
      {"uniform", [](MapSpec& s) { s.density = 1.2; }, "density: 1.2 is outside [0, 1)"},
      {"uniform", [](MapSpec& s) { s.density = 1.0; }, "density"},
      {"uniform", [](MapSpec& s) { s.density = -0.1; }, "density"},
      {"uniform", [](MapSpec& s) { s.density = std::nan(""); }, "density"},
      {"uniform", [](MapSpec& s) { s.cell_edge = 0.0; }, "cell_edge"},
      {"uniform", [](MapSpec& s) { s.min_distance = -1.0; }, "min_distance"},
      {"uniform", [](MapSpec& s) { s.min_distance = 100.0; }, "min_distance"},
      {"uniform", [](MapSpec& s) { s.max_attempts = 0; }, "max_attempts"},
      {"uniform", [](MapSpec& s) { s.params["corridor"] = 2; }, "params.corridor: unknown"},
      {"blocks", [](MapSpec& s) { s.params["block_min"] = 0; }, "params.block_min"},
      {"blocks", [](MapSpec& s) { s.params["block_max"] = 1; }, "params.block_max: 1 is smaller"},
      {"blocks", [](MapSpec& s) { s.params["block_max"] = 8193; }, "params.block_max"},
      {"maze", [](MapSpec& s) { s.params["corridor"] = 0; }, "params.corridor"},
      {"maze", [](MapSpec& s) { s.params["corridor"] = 65; },
       "params.corridor: 65 is outside [1, 64]"},
      {"maze", [](MapSpec& s) { s.params["corridor"] = 1.5; },
       "params.corridor: expected an integer"},
      {"rooms", [](MapSpec& s) { s.params["room_size"] = 1; }, "params.room_size"},
      {"rooms", [](MapSpec& s) { s.params["door_width"] = 0; }, "params.door_width"},
      {"rooms", [](MapSpec& s) { s.params = nlohmann::json::array(); }, "params: "},
  };
  for (const Case& c : cases) {
    MapSpec s = spec_of(c.generator, 64, 64, 0.2);
    c.mutate(s);
    try {
      make(s, 1);
      ADD_FAILURE() << "no exception for " << c.field;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(c.field, 0), 0U) << e.what();
    }
  }
}

TEST(Connectivity, AgreesWithIndependentBfs) {
  Rng rng(21, 4);
  ConnectivityScratch scratch;
  for (int trial = 0; trial < 300; ++trial) {
    const int w = rng.between(1, 25);
    const int h = rng.between(1, 25);
    Grid g(w, h);
    const double p = rng.uniform(0.0, 0.6);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) g.set_blocked(x, y, rng.chance(p));
    }
    const Cell a{rng.between(0, w - 1), rng.between(0, h - 1)};
    for (CornerRule rule : kRules) {
      const std::vector<std::uint8_t> seen = reach(g, a, rule);
      for (int k = 0; k < 5; ++k) {
        const Cell b{rng.between(0, w - 1), rng.between(0, h - 1)};
        const bool expected = seen[static_cast<std::size_t>(b.y) * w + b.x] != 0;
        ASSERT_EQ(connected(g, a, b, rule, scratch), expected);
        ASSERT_EQ(connected(g, a, b, rule), expected);
      }
    }
  }
  const Grid g(3, 3);
  EXPECT_FALSE(connected(g, Cell{0, 0}, Cell{5, 5}, CornerRule::allow));
}

}  // namespace
}  // namespace agv
