// The grid search core, A* and Dijkstra against known truth (docs/ARCHITECTURE.md "Style" item 11):
// the MovingAI optimal lengths, each other on random maps under every corner rule, and the legality
// of every move of every returned path.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "algos/registry.h"
#include "algos/search/astar.h"
#include "algos/search/dijkstra.h"
#include "algos/search/grid_search_params.h"
#include "algos/search/heuristics.h"
#include "algos/search/search_core.h"
#include "core/corner_rule.h"
#include "generators/movingai.h"
#include "tests/movingai_data.h"

namespace agv {
namespace {

double path_length(const std::vector<Point>& path) {
  double sum = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i)
    sum += std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
  return sum;
}

// Every waypoint a cell centre, consecutive cells 8-adjacent, each move legal under the rule.
// Returns an empty string when the path is legal, else what is wrong.
std::string path_problem(const Grid& grid, const std::vector<Point>& path, Cell start, Cell goal,
                         CornerRule rule) {
  if (path.empty()) return "empty path";
  std::vector<Cell> cells;
  for (const Point& p : path) {
    const Cell c{static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y))};
    if (p.x != c.x + 0.5 || p.y != c.y + 0.5) return "waypoint not at a cell centre";
    if (!grid.in_bounds(c) || grid.blocked(c)) return "waypoint on a blocked or outside cell";
    cells.push_back(c);
  }
  if (!(cells.front() == start)) return "path does not start at the start";
  if (!(cells.back() == goal)) return "path does not end at the goal";
  auto blocked = [&](int x, int y) { return grid.blocked(x, y); };
  for (std::size_t i = 1; i < cells.size(); ++i) {
    const int dx = cells[i].x - cells[i - 1].x;
    const int dy = cells[i].y - cells[i - 1].y;
    int dir = -1;
    for (int d = 0; d < 8; ++d)
      if (kDx[d] == dx && kDy[d] == dy) dir = d;
    if (dir < 0) return "consecutive cells not adjacent at step " + std::to_string(i);
    if (!move_allowed(blocked, cells[i - 1].x, cells[i - 1].y, dir, rule))
      return "move not allowed by the corner rule at step " + std::to_string(i);
  }
  return {};
}

ConfiguredPlanner make(const std::string& name, const nlohmann::json& params) {
  return configure_planner(name, params, "test");
}

PlanResult run(const ConfiguredPlanner& p, const Grid& grid, Cell start, Cell goal,
               Scratch& scratch, Deadline deadline = Deadline::never()) {
  Rng rng(1, 2);
  return p.planner->plan(PlanRequest{grid, start, goal, rng, scratch, deadline});
}

bool near(double a, double b, double rel) { return std::abs(a - b) <= rel * std::max(1.0, b); }

// --- heuristics and parameters ---------------------------------------------------------------

TEST(Heuristics, ValuesAndNames) {
  EXPECT_DOUBLE_EQ(heuristic_value(Heuristic::euclidean, 3, -4, kSqrt2), 5.0);
  EXPECT_DOUBLE_EQ(heuristic_value(Heuristic::manhattan, 3, -4, kSqrt2), 7.0);
  EXPECT_DOUBLE_EQ(heuristic_value(Heuristic::chebyshev, 3, -4, kSqrt2), 4.0);
  EXPECT_DOUBLE_EQ(heuristic_value(Heuristic::octile, 3, 4, 1.4), 3 * 1.4 + 1);
  // Paper 002 eq. 7 as printed: diagonal count x 1, straight count x diagonal_cost.
  EXPECT_DOUBLE_EQ(heuristic_value(Heuristic::octile_as_printed, 3, 4, 1.4), 3 + 1 * 1.4);
  EXPECT_DOUBLE_EQ(heuristic_value(Heuristic::zero, 3, 4, 1.4), 0.0);
  for (const auto& name : heuristic_names()) {
    const auto h = heuristic_from_string(name);
    ASSERT_TRUE(h.has_value()) << name;
    EXPECT_EQ(to_string(*h), name);
    // The functor used by the search agrees with heuristic_value.
    const double f = with_heuristic(*h, 1.4, [](auto fn) { return fn(7, 2); });
    EXPECT_DOUBLE_EQ(f, heuristic_value(*h, 7, 2, 1.4)) << name;
  }
  EXPECT_FALSE(heuristic_from_string("diagonal").has_value());
}

TEST(GridSearchParams, DefaultsAndValidation) {
  const auto astar = make("astar", nlohmann::json::object());
  // The default collision model's rule (core/collision_model.h), whatever the paper's A* used.
  EXPECT_EQ(astar.params.choice("corner_rule"), "no_corner_cut");
  EXPECT_EQ(astar.params.choice("heuristic"), "euclidean");
  EXPECT_DOUBLE_EQ(astar.params.number("diagonal_cost"), kSqrt2);
  const auto dijkstra = make("dijkstra", {{"corner_rule", "no_corner_cut"}});
  EXPECT_EQ(dijkstra.params.choice("corner_rule"), "no_corner_cut");
  EXPECT_THROW(make("dijkstra", {{"heuristic", "octile"}}), InputError);
  EXPECT_THROW(make("astar", {{"diagonal_cost", 2.5}}), InputError);
  EXPECT_THROW(make("astar", {{"corner_rule", "sideways"}}), InputError);
}

// --- (1) MovingAI optimal lengths ------------------------------------------------------------

// One case per (map, solver), so ctest can spread the CPU-minutes over its jobs: every query of
// the full sets' files, but every 4th of the maze's 12,120 (3,030 over all its buckets; all of
// them took 3 of the suite's 12 CPU-minutes, mostly in the maze's long corridors, to prove what a
// quarter proves).
struct ScenarioCase {
  const char* map;
  const char* solver;
  std::size_t every = 1;  // check queries 0, every, 2 * every, ...
};

// What ctest's test list shows for a case (gtest would print its bytes, pointers included).
void PrintTo(const ScenarioCase& c, std::ostream* os) {
  *os << c.map << " " << c.solver << " every " << c.every;
}

std::vector<ScenarioCase> scenario_cases(std::vector<const char*> maps) {
  std::vector<ScenarioCase> cases;
  for (const char* map : maps)
    for (const char* solver : {"astar", "dijkstra", "shortest_length"})
      cases.push_back({map, solver, std::string(map) == "maze512-1-0.map" ? 4u : 1u});
  return cases;
}

class MovingAiScenarios : public ::testing::TestWithParam<ScenarioCase> {
 protected:
  void check_every_scenario(const std::string& dir) const;
};

TEST_P(MovingAiScenarios, OptimalOnEveryScenario) {
  AGV_MOVINGAI_SETS_OR_SKIP(sets);
  check_every_scenario(sets + "/");
}

void MovingAiScenarios::check_every_scenario(const std::string& dir) const {
  const std::string map = GetParam().map;
  const std::string solver = GetParam().solver;
  const Grid grid = read_map(dir + map);
  const auto queries = read_scen(dir + map + ".scen");
  ASSERT_FALSE(queries.empty());
  std::optional<ConfiguredPlanner> planner;
  if (solver != "shortest_length") planner = make(solver, {{"corner_rule", "no_corner_cut"}});
  Scratch scratch;
  int failures = 0;
  for (std::size_t q = 0; q < queries.size() && failures < 5; q += GetParam().every) {
    const auto& s = queries[q];
    if (!planner) {
      const auto ref = shortest_length(grid, s.start, s.goal, CornerRule::no_corner_cut, scratch);
      if (!ref || !near(*ref, s.optimal_length, 1e-6)) {
        ++failures;
        ADD_FAILURE() << "query " << q << " (line " << s.line << "): " << (ref ? *ref : -1.0)
                      << " optimal " << s.optimal_length;
      }
      continue;
    }
    const PlanResult r = run(*planner, grid, s.start, s.goal, scratch);
    const std::string problem =
        r.ok() ? path_problem(grid, r.path, s.start, s.goal, CornerRule::no_corner_cut)
               : std::string("failed: ") + to_string(r.failure);
    if (!problem.empty() || !near(path_length(r.path), s.optimal_length, 1e-6)) {
      ++failures;
      ADD_FAILURE() << "query " << q << " (line " << s.line << "): length " << path_length(r.path)
                    << " optimal " << s.optimal_length << " " << problem;
    }
  }
}

std::string scenario_case_name(const ::testing::TestParamInfo<ScenarioCase>& info) {
  const std::string file = info.param.map;
  std::string name = file.substr(0, file.find('.')) + "_" + info.param.solver;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(FullSets, MovingAiScenarios,
                         ::testing::ValuesIn(scenario_cases({"arena2.map", "random512-10-0.map",
                                                             "maze512-1-0.map", "8room_000.map",
                                                             "Berlin_0_512.map"})),
                         scenario_case_name);

// --- (2) A* == Dijkstra on random maps, legal moves -----------------------------------------

struct RandomQuery {
  Cell start;
  Cell goal;
};

// Refills `grid` (32x32) until it is solvable under `rule` between random free endpoints;
// density cycles through 0.1..0.4 with k.
RandomQuery random_query(Grid& grid, Rng& rng, int k, CornerRule rule, Scratch& scratch) {
  const double density = 0.1 + 0.1 * (k % 4);
  for (;;) {
    for (int y = 0; y < grid.height(); ++y)
      for (int x = 0; x < grid.width(); ++x) grid.set_blocked(x, y, rng.chance(density));
    const RandomQuery q{{rng.between(0, grid.width() - 1), rng.between(0, grid.height() - 1)},
                        {rng.between(0, grid.width() - 1), rng.between(0, grid.height() - 1)}};
    grid.set_blocked(q.start, false);
    grid.set_blocked(q.goal, false);
    if (shortest_length(grid, q.start, q.goal, rule, scratch)) return q;
  }
}

class CornerRules : public ::testing::TestWithParam<CornerRule> {};

TEST_P(CornerRules, AStarMatchesDijkstraOnRandomMaps) {
  const CornerRule rule = GetParam();
  const std::string rule_name(to_string(rule));
  const auto astar = make("astar", {{"corner_rule", rule_name}});
  const auto astar_octile = make("astar", {{"corner_rule", rule_name}, {"heuristic", "octile"}});
  const auto dijkstra = make("dijkstra", {{"corner_rule", rule_name}});
  Scratch scratch;
  Grid grid(32, 32);
  Rng rng(20240611, static_cast<std::uint64_t>(rule));
  for (int k = 0; k < 1000; ++k) {
    const RandomQuery q = random_query(grid, rng, k, rule, scratch);
    const double ref = *shortest_length(grid, q.start, q.goal, rule, scratch);
    for (const auto* p : {&astar, &astar_octile, &dijkstra}) {
      const PlanResult r = run(*p, grid, q.start, q.goal, scratch);
      ASSERT_TRUE(r.ok()) << p->info->name << " map " << k;
      ASSERT_NEAR(path_length(r.path), ref, 1e-9 * std::max(1.0, ref))
          << p->info->name << " map " << k;
      ASSERT_EQ(path_problem(grid, r.path, q.start, q.goal, rule), "")
          << p->info->name << " map " << k;
      ASSERT_EQ(r.rule, rule);
      ASSERT_GE(r.work.search_expansions.value_or(-1), 1);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Rules, CornerRules,
                         ::testing::Values(CornerRule::allow, CornerRule::no_squeeze,
                                           CornerRule::no_corner_cut),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

// Each rule on the smallest map where they differ: (1,0) and (0,1) blocked, (0,0) -> (1,1).
TEST(CornerRuleSemantics, DiagonalSqueezeAndCornerCut) {
  Grid squeeze(2, 2);
  squeeze.set_blocked(1, 0, true);
  squeeze.set_blocked(0, 1, true);
  Grid corner(2, 2);
  corner.set_blocked(1, 0, true);
  Scratch scratch;
  for (const char* name : {"astar", "dijkstra"}) {
    const auto allow = make(name, {{"corner_rule", "allow"}});
    const auto no_squeeze = make(name, {{"corner_rule", "no_squeeze"}});
    const auto no_cut = make(name, {{"corner_rule", "no_corner_cut"}});
    EXPECT_NEAR(path_length(run(allow, squeeze, {0, 0}, {1, 1}, scratch).path), kSqrt2, 1e-12);
    EXPECT_EQ(run(no_squeeze, squeeze, {0, 0}, {1, 1}, scratch).failure, Failure::no_path);
    EXPECT_EQ(run(no_cut, squeeze, {0, 0}, {1, 1}, scratch).failure, Failure::no_path);
    EXPECT_NEAR(path_length(run(no_squeeze, corner, {0, 0}, {1, 1}, scratch).path), kSqrt2, 1e-12);
    EXPECT_NEAR(path_length(run(no_cut, corner, {0, 0}, {1, 1}, scratch).path), 2.0, 1e-12);
  }
}

// --- (3) unsolvable ---------------------------------------------------------------------------

TEST(Unsolvable, WallGivesNoPath) {
  Grid grid(40, 30);
  for (int y = 0; y < 30; ++y) grid.set_blocked(20, y, true);
  Scratch scratch;
  for (const char* name : {"astar", "dijkstra"}) {
    const PlanResult r = run(make(name, nlohmann::json::object()), grid, {2, 3}, {35, 20}, scratch);
    EXPECT_FALSE(r.ok()) << name;
    EXPECT_EQ(r.failure, Failure::no_path) << name;
    EXPECT_TRUE(r.path.empty()) << name;
    EXPECT_EQ(r.work.search_expansions.value_or(-1), 20 * 30)
        << name;  // the whole reachable side, once each
  }
  EXPECT_FALSE(shortest_length(grid, {2, 3}, {35, 20}, CornerRule::allow, scratch).has_value());
}

TEST(InvalidInput, BlockedEndpoint) {
  Grid grid(8, 8);
  grid.set_blocked(5, 5, true);
  Scratch scratch;
  const PlanResult r = run(make("astar", nlohmann::json::object()), grid, {0, 0}, {5, 5}, scratch);
  EXPECT_EQ(r.failure, Failure::invalid_input);
}

// --- (4) deadline -----------------------------------------------------------------------------

TEST(Deadline, ExpiredDeadlineGivesLimit) {
  Grid grid(1024, 1024);
  Scratch scratch;
  for (const char* name : {"astar", "dijkstra"}) {
    const PlanResult r = run(make(name, nlohmann::json::object()), grid, {0, 1023}, {1023, 0},
                             scratch, Deadline::after(std::chrono::nanoseconds(0)));
    EXPECT_FALSE(r.ok()) << name;
    EXPECT_EQ(r.failure, Failure::limit) << name;
  }
}

// --- (5) scratch reuse ------------------------------------------------------------------------

TEST(ScratchReuse, RepeatsAndSizeChanges) {
  Rng rng(7, 7);
  Grid small(48, 40);
  Grid large(300, 220);
  for (Grid* g : {&small, &large})
    for (int y = 0; y < g->height(); ++y)
      for (int x = 0; x < g->width(); ++x)
        if (rng.chance(0.25)) g->set_blocked(x, y, true);
  const Cell s_start{0, 0}, s_goal{47, 39}, l_start{1, 218}, l_goal{297, 3};
  for (Grid* g : {&small, &large}) g->set_blocked(0, 0, false);
  small.set_blocked(s_goal, false);
  large.set_blocked(l_start, false);
  large.set_blocked(l_goal, false);

  for (const char* name : {"astar", "dijkstra"}) {
    const auto p = make(name, {{"corner_rule", "no_corner_cut"}});
    Scratch scratch;
    Scratch fresh;
    const PlanResult a = run(p, small, s_start, s_goal, scratch);
    const PlanResult b = run(p, small, s_start, s_goal, scratch);
    const PlanResult c = run(p, large, l_start, l_goal, scratch);  // grows the buffers
    const PlanResult d = run(p, small, s_start, s_goal, scratch);  // back to the small grid
    const PlanResult e = run(p, large, l_start, l_goal, fresh);
    for (const PlanResult* r : {&a, &b, &d}) {
      EXPECT_EQ(r->ok(), a.ok()) << name;
      EXPECT_EQ(r->path, a.path) << name;
      EXPECT_EQ(r->work.search_expansions.value_or(-1), a.work.search_expansions.value_or(-1))
          << name;
    }
    EXPECT_EQ(c.ok(), e.ok()) << name;
    EXPECT_EQ(c.path, e.path) << name;
    EXPECT_EQ(c.work.search_expansions.value_or(-1), e.work.search_expansions.value_or(-1)) << name;
    const auto ref_small =
        shortest_length(small, s_start, s_goal, CornerRule::no_corner_cut, scratch);
    const auto ref_large =
        shortest_length(large, l_start, l_goal, CornerRule::no_corner_cut, scratch);
    EXPECT_EQ(a.ok(), ref_small.has_value()) << name;
    EXPECT_EQ(c.ok(), ref_large.has_value()) << name;
    if (ref_small) {
      EXPECT_NEAR(path_length(a.path), *ref_small, 1e-9) << name;
    }
    if (ref_large) {
      EXPECT_NEAR(path_length(c.path), *ref_large, 1e-9) << name;
    }
    ASSERT_EQ(a.phases.size(), 1U);
    EXPECT_EQ(a.phases[0].name, "search");
  }
}

// The one-byte search stamps wrap every 126 searches: ~300 searches on one Scratch, alternating
// two grids, must each match a search on a fresh Scratch.
TEST(ScratchReuse, StampWrapAround) {
  Rng rng(11, 3);
  Grid a(40, 30);
  Grid b(25, 45);
  for (Grid* g : {&a, &b})
    for (int y = 0; y < g->height(); ++y)
      for (int x = 0; x < g->width(); ++x) g->set_blocked(x, y, rng.chance(0.3));
  const auto astar = make("astar", {{"corner_rule", "no_squeeze"}});
  Scratch shared;
  for (int k = 0; k < 600; ++k) {
    Grid& g = k % 2 == 0 ? a : b;
    const Cell start{rng.between(0, g.width() - 1), rng.between(0, g.height() - 1)};
    const Cell goal{rng.between(0, g.width() - 1), rng.between(0, g.height() - 1)};
    if (g.blocked(start) || g.blocked(goal)) continue;
    Scratch fresh;
    const PlanResult x = run(astar, g, start, goal, shared);
    const PlanResult y = run(astar, g, start, goal, fresh);
    ASSERT_EQ(x.failure, y.failure) << k;
    ASSERT_EQ(x.path, y.path) << k;
    ASSERT_EQ(x.work.search_expansions.value_or(-1), y.work.search_expansions.value_or(-1)) << k;
  }
}

TEST(StartIsGoal, SingleWaypoint) {
  Grid grid(5, 5);
  Scratch scratch;
  const PlanResult r = run(make("astar", nlohmann::json::object()), grid, {2, 2}, {2, 2}, scratch);
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.path.size(), 1U);
  EXPECT_EQ(r.path[0], (Point{2.5, 2.5}));
  EXPECT_EQ(r.work.search_expansions.value_or(-1), 1);
}

// --- policy hooks used by the later variants ------------------------------------------------

// (d) a direction mask of the four cardinals makes the search 4-connected.
struct FourConnected : AStarPolicy<ManhattanHeuristic> {
  using AStarPolicy::AStarPolicy;
  std::uint8_t direction_mask(int, int, int, std::uint8_t) const { return 0x0F; }
};

// (c) g fixed at discovery to the straight-line distance from the start (MA* eq. 4.1b).
struct EuclidFromStart : AStarPolicy<EuclideanHeuristic> {
  EuclidFromStart(Cell s, Cell g) : AStarPolicy(EuclideanHeuristic{}, g), start(s) {}
  double child_g(double, double, int x, int y) const {
    return std::hypot(x - start.x, y - start.y);
  }
  Cell start;
};

// (b) + (g): the key sees the turn; a listener counts expansions and relaxations.
struct TurnPenalty : AStarPolicy<EuclideanHeuristic> {
  using AStarPolicy::AStarPolicy;
  double key(double g, double h, int dir_in, int dir_out) const {
    return g + (dir_in != kNoDirection && dir_in != dir_out ? 1.2 : 1.0) * h;
  }
};
struct CountingListener {
  void generated(int) { ++generations; }
  void expanded(int, double) { ++expansions; }
  void relaxed(int, double, double) { ++relaxations; }
  std::int64_t generations = 0;
  std::int64_t expansions = 0;
  std::int64_t relaxations = 0;
};

TEST(PolicyHooks, DirectionMaskGValueTurnKeyAndListener) {
  Grid grid(20, 20);
  for (int y = 3; y < 17; ++y) grid.set_blocked(10, y, true);
  GridSearchBuffers buffers;
  std::vector<Cell> cells;
  const Cell start{1, 10}, goal{18, 12};

  GridSearchSetup setup;
  auto four = grid_search(grid, start, goal, setup, Deadline::never(),
                          FourConnected(ManhattanHeuristic{}, goal), buffers);
  ASSERT_EQ(four.failure, Failure::none);
  trace_cells(buffers, grid, goal, cells);
  for (std::size_t i = 1; i < cells.size(); ++i)
    EXPECT_EQ(std::abs(cells[i].x - cells[i - 1].x) + std::abs(cells[i].y - cells[i - 1].y), 1);
  EXPECT_DOUBLE_EQ(four.goal_g, static_cast<double>(cells.size() - 1));

  auto fixed = grid_search(grid, start, goal, setup, Deadline::never(),
                           EuclidFromStart(start, goal), buffers);
  ASSERT_EQ(fixed.failure, Failure::none);
  EXPECT_DOUBLE_EQ(fixed.goal_g, std::hypot(goal.x - start.x, goal.y - start.y));
  trace_cells(buffers, grid, goal, cells);
  EXPECT_EQ(cells.front(), start);
  EXPECT_EQ(cells.back(), goal);

  CountingListener listener;
  auto turned = grid_search(grid, start, goal, setup, Deadline::never(),
                            TurnPenalty(EuclideanHeuristic{}, goal), buffers, listener);
  ASSERT_EQ(turned.failure, Failure::none);
  EXPECT_EQ(listener.expansions, turned.expanded);
  EXPECT_GE(listener.relaxations, turned.expanded - 1);
  // Generated: the source and every cell first put on the open list, i.e. every cell the
  // search's stamps mark open or closed; a re-relaxed open cell is not generated twice.
  std::int64_t labelled = 0;
  for (int i = 0; i < grid.padded_size(); ++i)
    labelled += buffers.stamps()[i] == buffers.open_stamp() ||
                buffers.stamps()[i] == buffers.closed_stamp();
  EXPECT_EQ(listener.generations, labelled);
  EXPECT_GE(listener.generations, turned.expanded);
  EXPECT_LE(listener.generations, listener.relaxations + 1);
  trace_cells(buffers, grid, goal, cells);
  EXPECT_EQ(cells.back(), goal);
}

}  // namespace
}  // namespace agv
