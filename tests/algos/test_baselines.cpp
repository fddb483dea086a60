// The papers' baselines (PRM, RRT, RRT-Connect, ant colony) against truth (docs/ARCHITECTURE.md
// "Style" item 11): every returned path validates on hundreds of random solvable maps, success
// rates are printed (sampling planners may fail within their caps: that is data, not a bug), runs
// are reproducible from the seed, PRM converges towards the any-angle optimum from above, ants
// never revisit a cell and move legally, and the RRT nearest-neighbour indexes agree with a
// brute-force scan.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "algos/registry.h"
#include "algos/sampling/rrt_tree.h"
#include "algos/search/dijkstra.h"
#include "core/corner_rule.h"
#include "engine/judge/validator.h"
#include "generators/map_generators.h"
#include "tests/test_size.h"

namespace agv {
namespace {

double path_length(const std::vector<Point>& path) {
  double sum = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i)
    sum += std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
  return sum;
}

double euclid(Cell a, Cell b) { return std::hypot(b.x - a.x, b.y - a.y); }

ConfiguredPlanner make(const std::string& name, const nlohmann::json& params = {}) {
  return configure_planner(name, params.is_null() ? nlohmann::json::object() : params, "test");
}

PlanResult run(const ConfiguredPlanner& p, const MapInstance& map, std::uint64_t seed,
               Scratch& scratch, Deadline deadline = Deadline::never()) {
  Rng rng(seed, 99);
  return p.planner->plan(PlanRequest{map.grid, map.start, map.goal, rng, scratch, deadline});
}

// 32x32 uniform maps, solvable under no_corner_cut (the strictest rule, so every planner's rule
// admits a path); endpoints alternate between the papers' corners and random pairs >= 12 apart.
MapInstance random_map(double density, int index) {
  MapSpec spec;
  spec.generator = "uniform";
  spec.width = 32;
  spec.height = 32;
  spec.density = density;
  spec.endpoints = index % 2 == 0 ? EndpointMode::corners : EndpointMode::random;
  spec.min_distance = 12.0;
  spec.require_solvable = true;
  spec.solvable_rule = CornerRule::no_corner_cut;
  Rng rng(0xBA5E, static_cast<std::uint64_t>(density * 100) * 100000 + index);
  return make_map(spec, rng);
}

constexpr double kDensities[] = {0.1, 0.2, 0.3};
// 510 maps per planner; 120 under a sanitizer (tests/test_size.h).
constexpr int kMapsPerDensity = test::sized(170, 40);

const std::vector<MapInstance>& sweep_maps() {
  static const std::vector<MapInstance> maps = [] {
    std::vector<MapInstance> m;
    for (const double d : kDensities)
      for (int i = 0; i < kMapsPerDensity; ++i) m.push_back(random_map(d, i));
    return m;
  }();
  return maps;
}

// --- every returned path validates; success rates printed ------------------------------------

class Baselines : public ::testing::TestWithParam<std::string> {};

TEST_P(Baselines, PathsValidateOnRandomMaps) {
  const auto planner = make(GetParam());
  Scratch scratch;
  const auto& maps = sweep_maps();
  std::vector<double> rate;
  for (std::size_t di = 0; di < std::size(kDensities); ++di) {
    int successes = 0;
    for (int i = 0; i < kMapsPerDensity; ++i) {
      const MapInstance& map = maps[di * kMapsPerDensity + static_cast<std::size_t>(i)];
      const PlanResult r = run(planner, map, 1000 + static_cast<std::uint64_t>(i), scratch);
      if (!r.ok()) {
        EXPECT_EQ(r.failure, Failure::limit) << GetParam() << " map " << i << ": " << r.message;
        EXPECT_TRUE(r.path.empty());
        continue;
      }
      ++successes;
      const ValidationResult v = validate_path(map.grid, map.start, map.goal, r.path, r.rule);
      ASSERT_TRUE(v.ok) << GetParam() << " density " << kDensities[di] << " map " << i << ": "
                        << v.reason;
      ASSERT_GE(path_length(r.path), euclid(map.start, map.goal) - 1e-9);
      // Its kind's counter (samples, ant_steps: docs/METRICS.md "Work counters") counted work.
      const auto counters = work_counter_values(r.work);
      ASSERT_EQ(counters.size(), 1U);
      ASSERT_GE(counters[0].second, 1) << counters[0].first;
    }
    rate.push_back(static_cast<double>(successes) / kMapsPerDensity);
    char key[64];
    std::snprintf(key, sizeof key, "success_rate_d%.1f", kDensities[di]);
    RecordProperty(key, std::to_string(rate.back()));
    std::printf("[ baseline ] %-6s density %.1f: success %d / %d (%.1f%%)\n", GetParam().c_str(),
                kDensities[di], successes, kMapsPerDensity, 100.0 * rate.back());
  }
  // A sane floor only: at density 0.1 every baseline finds a path on most maps.
  EXPECT_GT(rate[0], 0.5);
}

INSTANTIATE_TEST_SUITE_P(Planners, Baselines, ::testing::Values("prm", "rrt", "birrt", "aco"));

// --- reproducibility -------------------------------------------------------------------------

class Reproducible : public ::testing::TestWithParam<std::string> {};

TEST_P(Reproducible, SameSeedSamePathDifferentSeedsDiffer) {
  // ACO with fewer iterations keeps this quick; determinism does not depend on the count.
  const auto planner = make(GetParam(), GetParam() == "aco" ? nlohmann::json{{"iterations", 20}}
                                                            : nlohmann::json::object());
  Scratch scratch_a;
  Scratch scratch_b;
  int differ = 0;
  int compared = 0;
  for (int i = 0; i < 20; ++i) {
    const MapInstance map = random_map(0.2, 5000 + i);
    const PlanResult a = run(planner, map, 42, scratch_a);
    // A different scratch object, warmed by another plan first: buffers carry nothing over.
    run(planner, random_map(0.3, 6000 + i), 7, scratch_b);
    const PlanResult b = run(planner, map, 42, scratch_b);
    ASSERT_EQ(a.ok(), b.ok()) << "map " << i;
    ASSERT_EQ(a.path, b.path) << "map " << i;
    ASSERT_EQ(a.work, b.work) << "map " << i;
    const PlanResult c = run(planner, map, 43, scratch_a);
    if (a.ok() && c.ok()) {
      ++compared;
      if (a.path != c.path) ++differ;
    }
  }
  std::printf("[ baseline ] %-6s different seeds gave different paths on %d of %d maps\n",
              GetParam().c_str(), differ, compared);
  EXPECT_GE(differ * 2, compared);
}

INSTANTIATE_TEST_SUITE_P(Planners, Reproducible, ::testing::Values("prm", "rrt", "birrt", "aco"));

// --- trivial queries, caps and deadlines -----------------------------------------------------

TEST(BaselineEdges, StartEqualsGoalIsOnePoint) {
  MapInstance map;
  map.grid = Grid(8, 8);
  map.start = map.goal = {3, 4};
  Scratch scratch;
  for (const char* name : {"prm", "rrt", "birrt", "aco"}) {
    const PlanResult r = run(make(name), map, 1, scratch);
    ASSERT_TRUE(r.ok()) << name;
    ASSERT_EQ(r.path.size(), 1U) << name;
    EXPECT_EQ(r.path[0], centre(map.start)) << name;
  }
}

TEST(BaselineEdges, CapsAndDeadlinesGiveLimit) {
  // A wall with one gap far from the straight line.
  MapInstance map;
  map.grid = Grid(40, 40);
  for (int y = 0; y < 39; ++y) map.grid.set_blocked(20, y, true);
  map.start = {2, 2};
  map.goal = {37, 2};
  Scratch scratch;
  const Deadline past = Deadline::after(std::chrono::nanoseconds(-1));
  for (const char* name : {"prm", "rrt", "birrt", "aco"}) {
    const PlanResult r = run(make(name), map, 1, scratch, past);
    EXPECT_FALSE(r.ok()) << name;
    EXPECT_EQ(r.failure, Failure::limit) << name;
  }
  for (const char* name : {"rrt", "birrt"}) {
    const PlanResult r = run(make(name, {{"max_iterations", 1}}), map, 1, scratch);
    EXPECT_FALSE(r.ok()) << name;
    EXPECT_EQ(r.failure, Failure::limit) << name;
  }
  const PlanResult prm = run(make("prm", {{"samples", 0}}), map, 1, scratch);
  EXPECT_EQ(prm.failure, Failure::limit);
  EXPECT_EQ(prm.work.samples.value_or(-1), 0);  // start and goal only
}

TEST(BaselineEdges, ParametersDeclared) {
  EXPECT_EQ(make("aco").params.number("alpha"), 1.1);  // paper 002 Table 2
  EXPECT_EQ(make("aco").params.number("beta"), 4.0);
  EXPECT_EQ(make("aco").params.number("evaporation"), 0.5);
  EXPECT_EQ(make("aco").params.integer("ants"), 20);
  EXPECT_EQ(make("aco").params.integer("iterations"), 150);
  // The default collision model's rule (core/collision_model.h); paper 002's grid is `allow`.
  EXPECT_EQ(make("aco").params.choice("corner_rule"), "no_corner_cut");
  EXPECT_EQ(make("prm").params.choice("corner_rule"), "no_corner_cut");
  EXPECT_THROW(make("rrt", {{"step", 0.0}}), InputError);
  EXPECT_THROW(make("birrt", {{"goal_radius", 1.0}}), InputError);  // RRT only
  EXPECT_THROW(make("prm", {{"k", 0}}), InputError);
  EXPECT_THROW(make("aco", {{"evaporation", 1.0}}), InputError);
  for (const char* name : {"prm", "rrt", "birrt", "aco"})
    EXPECT_TRUE(find_planner(name)->stochastic) << name;
}

TEST(BaselineEdges, DeclaredCornerRuleReachesThePlanner) {
  // The rule a planner reports (and is validated under) is the one its parameter names.
  MapInstance map;
  map.grid = Grid(12, 12);
  map.start = {1, 1};
  map.goal = {10, 9};
  Scratch scratch;
  for (const char* name : {"prm", "rrt", "birrt", "aco"})
    for (const char* rule : {"allow", "no_squeeze", "no_corner_cut"}) {
      const PlanResult r = run(make(name, {{"corner_rule", rule}}), map, 1, scratch);
      EXPECT_EQ(to_string(r.rule), rule) << name;
    }
  // The sampling planners' other fields: a step of 50 cells crosses this empty map at once.
  const PlanResult rrt = run(make("rrt", {{"step", 50.0}, {"goal_bias", 1.0}}), map, 1, scratch);
  ASSERT_TRUE(rrt.ok());
  EXPECT_EQ(rrt.path.size(), 2U);
}

// --- PRM: towards the any-angle optimum, from above ------------------------------------------

// k grows as PRM*'s k(n) = e (1 + 1/d) ln n, d = 2 (Karaman & Frazzoli 2011): with a fixed k a
// k-nearest PRM's paths keep a constant zigzag excess however many samples it draws.
int prm_star_k(int samples) {
  return static_cast<int>(std::ceil(1.5 * std::exp(1.0) * std::log(samples + 2.0)));
}

// Mean length of the successful runs over `seeds` seeds (NaN when none succeeded).
double mean_prm_length(const MapInstance& map, int samples, int seeds, Scratch& scratch) {
  const auto prm = make("prm", {{"samples", samples}, {"k", prm_star_k(samples)}});
  double sum = 0.0;
  int found = 0;
  for (int s = 0; s < seeds; ++s) {
    const PlanResult r = run(prm, map, static_cast<std::uint64_t>(s), scratch);
    if (!r.ok()) continue;
    const double length = path_length(r.path);
    // Never below the straight line.
    EXPECT_GE(length, euclid(map.start, map.goal) - 1e-9);
    sum += length;
    ++found;
  }
  return found > 0 ? sum / found : std::numeric_limits<double>::quiet_NaN();
}

TEST(Prm, EmptyMapApproachesTheStraightLine) {
  MapInstance map;
  map.grid = Grid(32, 32);
  map.start = {0, 31};
  map.goal = {31, 0};
  Scratch scratch;
  const double straight = euclid(map.start, map.goal);
  double previous = std::numeric_limits<double>::infinity();
  for (const int samples : {50, 200, 800, 3200, 12800}) {
    const double mean = mean_prm_length(map, samples, 10, scratch);
    ASSERT_FALSE(std::isnan(mean)) << samples;
    std::printf("[ baseline ] prm empty 32x32, %4d samples: mean length / straight %.4f\n", samples,
                mean / straight);
    EXPECT_LT(mean, previous + 1e-9) << samples;
    previous = mean;
  }
  EXPECT_LT(previous, straight * 1.005);
}

TEST(Prm, ObstacleMapsApproachTheAnyAngleOptimumFromAbove) {
  // The any-angle optimum lies between the Euclidean distance and the 8-connected optimum, so a
  // converging PRM ends up below the grid optimum on average, and never below the straight line.
  Scratch scratch;
  double ratio_sparse = 0.0;
  double ratio_dense = 0.0;
  int maps = 0;
  for (int i = 0; i < 12; ++i) {
    const MapInstance map = random_map(0.2, 7000 + i);
    const double grid_optimum =
        *shortest_length(map.grid, map.start, map.goal, CornerRule::no_corner_cut, scratch);
    const double sparse = mean_prm_length(map, 500, 4, scratch);
    const double dense = mean_prm_length(map, 5000, 4, scratch);
    ASSERT_FALSE(std::isnan(dense)) << "map " << i;
    if (std::isnan(sparse)) continue;  // narrow passages: 500 samples did not connect
    ratio_sparse += sparse / grid_optimum;
    ratio_dense += dense / grid_optimum;
    ++maps;
  }
  ASSERT_GE(maps, 6);
  ratio_sparse /= maps;
  ratio_dense /= maps;
  std::printf(
      "[ baseline ] prm density 0.2, %d maps: mean length / 8-connected optimum %.4f "
      "(500 samples), %.4f (5000 samples)\n",
      maps, ratio_sparse, ratio_dense);
  EXPECT_LT(ratio_dense, ratio_sparse);
  EXPECT_LT(ratio_dense, 1.0);
}

// --- ACO: tabu and legal moves ---------------------------------------------------------------

// Empty when the path is a chain of legal 8-connected moves between distinct cell centres.
std::string grid_walk_problem(const Grid& grid, const std::vector<Point>& path, CornerRule rule) {
  std::set<std::pair<int, int>> seen;
  auto blocked = [&](int x, int y) { return grid.blocked(x, y); };
  for (std::size_t i = 0; i < path.size(); ++i) {
    const Cell c{static_cast<int>(std::floor(path[i].x)), static_cast<int>(std::floor(path[i].y))};
    if (path[i] != centre(c)) return "not a cell centre at " + std::to_string(i);
    if (!seen.insert({c.x, c.y}).second) return "cell revisited at " + std::to_string(i);
    if (i == 0) continue;
    const Cell p{static_cast<int>(std::floor(path[i - 1].x)),
                 static_cast<int>(std::floor(path[i - 1].y))};
    int dir = -1;
    for (int d = 0; d < 8; ++d)
      if (p.x + kDx[d] == c.x && p.y + kDy[d] == c.y) dir = d;
    if (dir < 0) return "not adjacent at " + std::to_string(i);
    if (!move_allowed(blocked, p.x, p.y, dir, rule)) return "illegal move at " + std::to_string(i);
  }
  return {};
}

TEST(Aco, NeverRevisitsAndMovesLegallyUnderEachRule) {
  Scratch scratch;
  for (const CornerRule rule :
       {CornerRule::allow, CornerRule::no_squeeze, CornerRule::no_corner_cut}) {
    const auto aco =
        make("aco", {{"corner_rule", std::string(to_string(rule))}, {"iterations", 30}});
    int successes = 0;
    for (int i = 0; i < 60; ++i) {
      const MapInstance map = random_map(0.3, 8000 + i);
      const PlanResult r = run(aco, map, static_cast<std::uint64_t>(i), scratch);
      if (!r.ok()) continue;
      ++successes;
      ASSERT_EQ(r.rule, rule);
      ASSERT_EQ(grid_walk_problem(map.grid, r.path, rule), "") << to_string(rule) << " map " << i;
      ASSERT_TRUE(validate_path(map.grid, map.start, map.goal, r.path, rule).ok);
    }
    EXPECT_GT(successes, 0) << to_string(rule);
  }
}

TEST(Aco, MoreIterationsNeverLengthen) {
  // The best path over all iterations is kept, and the first iterations draw the same numbers.
  Scratch scratch;
  for (int i = 0; i < 20; ++i) {
    const MapInstance map = random_map(0.2, 9000 + i);
    const PlanResult short_run = run(make("aco", {{"iterations", 10}}), map, 5, scratch);
    const PlanResult long_run = run(make("aco", {{"iterations", 40}}), map, 5, scratch);
    if (!short_run.ok()) continue;
    ASSERT_TRUE(long_run.ok());
    EXPECT_LE(path_length(long_run.path), path_length(short_run.path) + 1e-9) << "map " << i;
  }
}

// --- RRT tree: both indexes are exact nearest-neighbour queries ------------------------------

TEST(RrtTree, IndexesAgreeWithBruteForce) {
  const Grid grid(64, 48);
  Rng rng(3, 4);
  RrtTree buckets;
  RrtTree kdtree;
  for (int round = 0; round < 3; ++round) {  // reset reuses the buffers
    const Point root{rng.uniform(0, 64), rng.uniform(0, 48)};
    buckets.reset(grid, root, NearestIndex::buckets);
    kdtree.reset(grid, root, NearestIndex::kdtree);
    for (int n = 0; n < 2000; ++n) {
      // Clustered points, so that many queries land far from every node.
      const Point p{rng.uniform(0, 16) + (round == 1 ? 48 : 0), rng.uniform(0, 48)};
      const Point q{rng.uniform(0, 64), rng.uniform(0, 48)};
      double best = std::numeric_limits<double>::infinity();
      for (int i = 0; i < buckets.size(); ++i) {
        const Point t = buckets.point(i);
        best = std::min(best, std::hypot(t.x - q.x, t.y - q.y));
      }
      for (RrtTree* tree : {&buckets, &kdtree}) {
        const Point t = tree->point(tree->nearest(q));
        ASSERT_DOUBLE_EQ(std::hypot(t.x - q.x, t.y - q.y), best) << "round " << round << " n " << n;
      }
      buckets.add(p, n % buckets.size());
      kdtree.add(p, n % kdtree.size());
    }
  }
}

TEST(RrtTree, IndexChoiceDoesNotChangeThePlan) {
  Scratch scratch;
  for (const char* name : {"rrt", "birrt"}) {
    const auto with_buckets = make(name, {{"nn_index", "buckets"}});
    const auto with_kdtree = make(name, {{"nn_index", "kdtree"}});
    for (int i = 0; i < 30; ++i) {
      const MapInstance map = random_map(0.2, 9500 + i);
      const PlanResult a = run(with_buckets, map, 11, scratch);
      const PlanResult b = run(with_kdtree, map, 11, scratch);
      ASSERT_EQ(a.path, b.path) << name << " map " << i;
    }
  }
}

}  // namespace
}  // namespace agv
