// The any-angle reference (core/any_angle.h, docs/METRICS.md "Any-angle reference"): hand cases
// with known lengths; on thousands of random maps, per corner rule, that it lies between the
// Euclidean distance and the grid optimum, that every valid path found by other means is at
// least as long (lower bound) and that its own vertex path, pushed off its corners by 1e-6,
// is valid under the shared line of sight and as long up to a few 1e-6 (tightness); the
// MovingAI optima are never below it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "algos/planner.h"
#include "algos/registry.h"
#include "algos/search/dijkstra.h"
#include "core/any_angle.h"
#include "core/corner_rule.h"
#include "core/grid.h"
#include "core/line_of_sight.h"
#include "core/rng.h"
#include "generators/map_generators.h"
#include "generators/movingai.h"
#include "tests/movingai_data.h"

namespace agv {
namespace {

constexpr CornerRule kRules[] = {CornerRule::allow, CornerRule::no_squeeze,
                                 CornerRule::no_corner_cut};
constexpr double kPush = 1e-6;
constexpr int kMaxBucket = 8;  // MovingAI buckets used: lengths below 4 * kMaxBucket cells

Grid grid_with(int w, int h, std::initializer_list<Cell> obstacles) {
  Grid g(w, h);
  for (Cell c : obstacles) g.set_blocked(c, true);
  return g;
}

double length_of(const std::vector<Point>& path) {
  double sum = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i)
    sum += std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
  return sum;
}

bool valid_under(const Grid& grid, const std::vector<Point>& path, CornerRule rule) {
  return polyline_free(grid, path, SightRule::cells(rule));
}

// The centre-to-centre distance as the search computes it (doubled coordinates, halved).
double euclid(Cell a, Cell b) {
  const double dx = 2.0 * (b.x - a.x);
  const double dy = 2.0 * (b.y - a.y);
  return std::sqrt(dx * dx + dy * dy) * 0.5;
}

std::optional<double> reference(const Grid& g, Cell a, Cell b, CornerRule rule) {
  AnyAngleScratch scratch;
  return any_angle_length(g, a, b, rule, scratch);
}

int sign(double v) { return (v > 0) - (v < 0); }

// The free quadrant around vertex v (doubled coordinates) that direction d leaves v into: the
// quadrant (sign dx, sign dy), or for an axis-parallel d the free one of the two beside it.
HalfPoint free_quadrant(const Grid& g, HalfPoint v, double dx, double dy) {
  const int i = v.x / 2;
  const int j = v.y / 2;
  auto free_q = [&](int qx, int qy) { return !g.blocked(qx > 0 ? i : i - 1, qy > 0 ? j : j - 1); };
  const int sx = sign(dx);
  const int sy = sign(dy);
  if (sx != 0 && sy != 0) return {sx, sy};
  if (sx == 0) return free_q(1, sy) ? HalfPoint{1, sy} : HalfPoint{-1, sy};
  return free_q(sx, 1) ? HalfPoint{sx, 1} : HalfPoint{sx, -1};
}

// The reference's vertex path made valid: every bend point lying on a segment is made a vertex
// (the search passes straight through some), each convex corner is pushed kPush diagonally away
// from its blocked cell and each pinch (allow) becomes two points kPush into its two free cells,
// on the diagonal through it.
std::vector<Point> pushed_path(const Grid& g, const std::vector<Point>& vertices) {
  std::vector<HalfPoint> v;
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const HalfPoint b{static_cast<int>(vertices[k].x * 2), static_cast<int>(vertices[k].y * 2)};
    if (k > 0) {
      const HalfPoint a = v.back();
      const int steps = std::gcd(std::abs(b.x - a.x), std::abs(b.y - a.y));
      for (int s = 1; s < steps; ++s) {
        const HalfPoint p{a.x + (b.x - a.x) / steps * s, a.y + (b.y - a.y) / steps * s};
        if (p.x % 2 != 0 || p.y % 2 != 0) continue;
        if (blocked_around_vertex(g, p.x / 2, p.y / 2) == 1 || is_pinch_vertex(g, p.x / 2, p.y / 2))
          v.push_back(p);
      }
    }
    v.push_back(b);
  }
  std::vector<Point> out{{v.front().x * 0.5, v.front().y * 0.5}};
  for (std::size_t k = 1; k + 1 < v.size(); ++k) {
    const HalfPoint p = v[k];
    const int i = p.x / 2;
    const int j = p.y / 2;
    const Point at{p.x * 0.5, p.y * 0.5};
    if (is_pinch_vertex(g, i, j)) {
      const HalfPoint in = free_quadrant(g, p, v[k - 1].x - p.x, v[k - 1].y - p.y);
      const HalfPoint leave = free_quadrant(g, p, v[k + 1].x - p.x, v[k + 1].y - p.y);
      out.push_back({at.x + kPush * in.x, at.y + kPush * in.y});
      out.push_back({at.x + kPush * leave.x, at.y + kPush * leave.y});
      continue;
    }
    EXPECT_EQ(blocked_around_vertex(g, i, j), 1) << "bend at (" << i << ", " << j << ")";
    const int bx = g.blocked(i, j - 1) || g.blocked(i, j) ? 1 : -1;
    const int by = g.blocked(i - 1, j) || g.blocked(i, j) ? 1 : -1;
    out.push_back({at.x - kPush * bx, at.y - kPush * by});
  }
  out.push_back({v.back().x * 0.5, v.back().y * 0.5});
  return out;
}

// Longest valid jump first: from each point, the farthest later point it sees.
std::vector<Point> greedy_shortcut(const Grid& g, const std::vector<Point>& path, CornerRule rule) {
  std::vector<Point> out{path.front()};
  std::size_t i = 0;
  while (i + 1 < path.size()) {
    std::size_t j = path.size() - 1;
    while (j > i + 1 && !segment_free(g, path[i], path[j], SightRule::cells(rule))) --j;
    out.push_back(path[j]);
    i = j;
  }
  return out;
}

// The grid path with every waypoint moved to a random point inside its cell (endpoints kept).
std::vector<Point> jittered(const std::vector<Point>& path, Rng& rng) {
  std::vector<Point> out = path;
  for (std::size_t k = 1; k + 1 < out.size(); ++k) {
    out[k].x += rng.uniform(-0.49, 0.49);
    out[k].y += rng.uniform(-0.49, 0.49);
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Hand cases.

TEST(AnyAngle, EmptyGridIsTheStraightLine) {
  const Grid g(9, 6);
  for (CornerRule rule : kRules) {
    EXPECT_EQ(reference(g, {0, 5}, {8, 0}, rule), euclid({0, 5}, {8, 0}));
    EXPECT_EQ(reference(g, {1, 1}, {7, 1}, rule), 6.0);
  }
}

TEST(AnyAngle, StartEqualsGoalAndRefusedEndpoints) {
  const Grid g = grid_with(4, 4, {{2, 2}});
  AnyAngleScratch scratch;
  std::vector<Point> path;
  for (CornerRule rule : kRules) {
    EXPECT_EQ(any_angle_path(g, {1, 1}, {1, 1}, rule, scratch, path), 0.0);
    EXPECT_EQ(path, (std::vector<Point>{{1.5, 1.5}}));
    EXPECT_FALSE(any_angle_path(g, {2, 2}, {0, 0}, rule, scratch, path));
    EXPECT_TRUE(path.empty());
    EXPECT_FALSE(any_angle_length(g, {0, 0}, {2, 2}, rule, scratch));
    EXPECT_FALSE(any_angle_length(g, {0, 0}, {4, 0}, rule, scratch));
    EXPECT_FALSE(any_angle_length(g, {-1, 0}, {0, 0}, rule, scratch));
  }
}

TEST(AnyAngle, AroundASingleObstacleOverItsCorners) {
  // Centre row blocked at (2, 2): over the top corners (2, 2) and (3, 2) or under the bottom ones.
  const Grid g = grid_with(5, 5, {{2, 2}});
  AnyAngleScratch scratch;
  std::vector<Point> path;
  for (CornerRule rule : kRules) {
    const auto len = any_angle_path(g, {0, 2}, {4, 2}, rule, scratch, path);
    ASSERT_TRUE(len);
    EXPECT_NEAR(*len, 1.0 + 2.0 * std::sqrt(2.5), 1e-12);
    ASSERT_EQ(path.size(), 4U);
    EXPECT_EQ(path[1].x, 2.0);
    EXPECT_EQ(path[2].x, 3.0);
    EXPECT_EQ(path[1].y, path[2].y);
    EXPECT_NEAR(length_of(path), *len, 1e-12);
  }
}

TEST(AnyAngle, LShapedCorridorBendsAtItsInnerCorner) {
  // Free: row 0 and column 4 of a 5x5 grid; the path bends at vertex (4, 1).
  Grid g(5, 5);
  for (int y = 1; y < 5; ++y)
    for (int x = 0; x < 4; ++x) g.set_blocked(x, y, true);
  AnyAngleScratch scratch;
  std::vector<Point> path;
  for (CornerRule rule : kRules) {
    const auto len = any_angle_path(g, {0, 0}, {4, 4}, rule, scratch, path);
    ASSERT_TRUE(len);
    EXPECT_NEAR(*len, 2.0 * std::sqrt(12.5), 1e-12);
    EXPECT_EQ(path, (std::vector<Point>{{0.5, 0.5}, {4.0, 1.0}, {4.5, 4.5}}));
  }
  // A straight corridor one cell wide: its centre line.
  const Grid corridor = grid_with(6, 3,
                                  {{0, 0},
                                   {1, 0},
                                   {2, 0},
                                   {3, 0},
                                   {4, 0},
                                   {5, 0},
                                   {0, 2},
                                   {1, 2},
                                   {2, 2},
                                   {3, 2},
                                   {4, 2},
                                   {5, 2}});
  for (CornerRule rule : kRules) EXPECT_EQ(reference(corridor, {0, 1}, {5, 1}, rule), 5.0);
}

TEST(AnyAngle, PinchIsPassableOnlyUnderAllow) {
  // (0, 0) is walled in but for the pinch at vertex (1, 1).
  const Grid closed = grid_with(4, 3, {{1, 0}, {0, 1}});
  EXPECT_EQ(reference(closed, {0, 0}, {1, 1}, CornerRule::allow), std::sqrt(8.0) * 0.5);
  EXPECT_FALSE(reference(closed, {0, 0}, {1, 1}, CornerRule::no_squeeze));
  EXPECT_FALSE(reference(closed, {0, 0}, {1, 1}, CornerRule::no_corner_cut));

  // The diagonal of a 5x5 grid crosses the pinch at vertex (2, 2); without it the path goes
  // round (2, 1) by its corner (3, 1), or round (1, 2) by (1, 3).
  const Grid g = grid_with(5, 5, {{2, 1}, {1, 2}});
  EXPECT_EQ(reference(g, {0, 0}, {4, 4}, CornerRule::allow), euclid({0, 0}, {4, 4}));
  const double detour = std::sqrt(6.5) + std::sqrt(14.5);
  for (CornerRule rule : {CornerRule::no_squeeze, CornerRule::no_corner_cut}) {
    const auto len = reference(g, {0, 0}, {4, 4}, rule);
    ASSERT_TRUE(len);
    EXPECT_NEAR(*len, detour, 1e-12);
  }
  // A diagonal wall (x + y == 4) is crossable at its pinches only, which are then bend points:
  // (0.5, 2.5) -> (2, 3) -> (4.5, 3.5).
  const Grid wall = grid_with(5, 5, {{0, 4}, {1, 3}, {2, 2}, {3, 1}, {4, 0}});
  AnyAngleScratch scratch;
  std::vector<Point> path;
  const auto bent = any_angle_path(wall, {0, 2}, {4, 3}, CornerRule::allow, scratch, path);
  ASSERT_TRUE(bent);
  EXPECT_NEAR(*bent, std::sqrt(2.5) + std::sqrt(6.5), 1e-12);
  EXPECT_EQ(path, (std::vector<Point>{{0.5, 2.5}, {2.0, 3.0}, {4.5, 3.5}}));
  EXPECT_FALSE(reference(wall, {0, 2}, {4, 3}, CornerRule::no_squeeze));
  EXPECT_FALSE(reference(wall, {0, 2}, {4, 3}, CornerRule::no_corner_cut));
}

TEST(AnyAngle, TouchingACornerCountsAsFreeForEveryRule) {
  // The straight line (0.5, 0.5) -> (2.5, 2.5) touches blocked (2, 1) at vertex (2, 2) only:
  // not free under no_corner_cut, but the infimum of valid paths all the same.
  const Grid g = grid_with(3, 3, {{2, 1}});
  EXPECT_FALSE(
      segment_free(g, {0.5, 0.5}, {2.5, 2.5}, SightRule::cells(CornerRule::no_corner_cut)));
  for (CornerRule rule : kRules)
    EXPECT_EQ(reference(g, {0, 0}, {2, 2}, rule), euclid({0, 0}, {2, 2}));
}

TEST(AnyAngle, ScratchIsReusableAcrossMapSizes) {
  AnyAngleScratch scratch;
  const Grid big = grid_with(30, 20, {{10, 5}, {11, 5}, {12, 6}});
  const Grid small = grid_with(5, 5, {{2, 2}});
  for (int round = 0; round < 3; ++round) {
    EXPECT_NEAR(*any_angle_length(small, {0, 2}, {4, 2}, CornerRule::allow, scratch),
                1.0 + 2.0 * std::sqrt(2.5), 1e-12);
    EXPECT_EQ(any_angle_length(big, {0, 0}, {0, 19}, CornerRule::allow, scratch), 19.0);
  }
}

// ---------------------------------------------------------------------------------------------
// Visibility against the shared line of sight: between cell centres, closure visibility is
// segment_free under allow (allow) or no_squeeze (the others: a touched corner is fine, a pinch
// is not).

TEST(AnyAngle, CentreToCentreVisibilityIsSegmentFreeUnderTheLenientRule) {
  Rng rng(14, 2);
  int checked = 0;
  for (int m = 0; m < 200; ++m) {
    Grid g(12, 10);
    const double density = rng.uniform(0.1, 0.5);
    for (int y = 0; y < g.height(); ++y)
      for (int x = 0; x < g.width(); ++x) g.set_blocked(x, y, rng.uniform01() < density);
    for (int q = 0; q < 50; ++q) {
      const Cell a{static_cast<int>(rng.below(12)), static_cast<int>(rng.below(10))};
      const Cell b{static_cast<int>(rng.below(12)), static_cast<int>(rng.below(10))};
      if (g.blocked(a) || g.blocked(b)) continue;
      for (CornerRule rule : kRules) {
        const CornerRule lenient = rule == CornerRule::allow ? rule : CornerRule::no_squeeze;
        EXPECT_EQ(closure_visible(g, {2 * a.x + 1, 2 * a.y + 1}, {2 * b.x + 1, 2 * b.y + 1}, rule),
                  segment_free(g, centre(a), centre(b), SightRule::cells(lenient)))
            << "map " << m << " (" << a.x << "," << a.y << ")-(" << b.x << "," << b.y << ")";
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 10000);
}

TEST(AnyAngle, VisibilityAlongGridLinesAndThroughVertices) {
  // Along the top edge of blocked (1, 1): free (the cells above are free); along the line
  // between two blocked rows: not free.
  const Grid g = grid_with(4, 4, {{1, 1}, {2, 1}, {1, 2}, {2, 2}});
  EXPECT_TRUE(closure_visible(g, {2, 2}, {6, 2}, CornerRule::no_corner_cut));
  EXPECT_FALSE(closure_visible(g, {2, 4}, {6, 4}, CornerRule::allow));
  EXPECT_TRUE(closure_visible(g, {2, 2}, {2, 6}, CornerRule::no_corner_cut));
  EXPECT_FALSE(closure_visible(g, {4, 2}, {4, 6}, CornerRule::allow));
  // The grid's border edges are in the closure of the cells inside.
  EXPECT_TRUE(closure_visible(g, {0, 0}, {8, 0}, CornerRule::no_corner_cut));
  // Vertical line x = 2 through the pinch at vertex (2, 2) of (1, 1) and (2, 2).
  const Grid pinch = grid_with(4, 4, {{1, 1}, {2, 2}});
  EXPECT_TRUE(closure_visible(pinch, {4, 0}, {4, 8}, CornerRule::allow));
  EXPECT_FALSE(closure_visible(pinch, {4, 0}, {4, 8}, CornerRule::no_squeeze));
  EXPECT_TRUE(closure_visible(pinch, {4, 0}, {4, 4}, CornerRule::no_squeeze));  // ends on it
  EXPECT_TRUE(closure_visible(pinch, {1, 7}, {7, 1}, CornerRule::allow));
  EXPECT_FALSE(closure_visible(pinch, {1, 7}, {7, 1}, CornerRule::no_corner_cut));
  EXPECT_FALSE(closure_visible(pinch, {1, 1}, {7, 7}, CornerRule::allow));  // through (1, 1)
}

// ---------------------------------------------------------------------------------------------
// Random maps.

struct Tally {
  int maps = 0;
  int connected = 0;
  int straight = 0;
  int jitter_paths = 0;
  int pushed_vertices = 0;
};

void check_map(const Grid& g, Cell s, Cell t, CornerRule rule, Rng& rng, Scratch& scratch,
               AnyAngleScratch& any, Tally& tally, const std::string& what) {
  SCOPED_TRACE(what + " rule " + std::string(to_string(rule)));
  std::vector<Point> vertices;
  const auto bound = any_angle_path(g, s, t, rule, any, vertices);
  EXPECT_EQ(bound, any_angle_length(g, s, t, rule, any));
  const auto grid_opt = shortest_length(g, s, t, rule, scratch);
  ++tally.maps;
  ASSERT_EQ(bound.has_value(), grid_opt.has_value());
  if (!bound) return;
  ++tally.connected;

  // Between the Euclidean distance and the grid optimum; the Euclidean distance itself exactly
  // when the straight segment is visible.
  const double e = euclid(s, t);
  EXPECT_GE(*bound, e);
  EXPECT_LE(*bound, *grid_opt * (1 + 1e-12));
  const bool straight =
      closure_visible(g, {2 * s.x + 1, 2 * s.y + 1}, {2 * t.x + 1, 2 * t.y + 1}, rule);
  EXPECT_EQ(*bound == e, straight);
  if (segment_free(g, centre(s), centre(t), SightRule::cells(rule))) {
    EXPECT_EQ(*bound, e);
  }
  tally.straight += straight ? 1 : 0;

  // Its own path: as long as the bound, and valid once pushed off its corners.
  EXPECT_NEAR(length_of(vertices), *bound, 1e-9 * std::max(1.0, *bound));
  const std::vector<Point> pushed = pushed_path(g, vertices);
  tally.pushed_vertices += static_cast<int>(pushed.size()) - 2;
  EXPECT_TRUE(valid_under(g, pushed, rule));
  EXPECT_NEAR(length_of(pushed), *bound, 4 * kPush * static_cast<double>(pushed.size()));

  // Lower bound of valid paths made by other means.
  const auto lower_than = [&](const std::vector<Point>& p, const char* kind) {
    ASSERT_TRUE(valid_under(g, p, rule)) << kind;
    EXPECT_GE(length_of(p), *bound * (1 - 1e-9)) << kind;
  };
  const ConfiguredPlanner dijkstra =
      configure_planner("dijkstra", {{"corner_rule", std::string(to_string(rule))}}, "test");
  Rng plan_rng(1, 2);
  const PlanResult r = dijkstra.planner->plan(PlanRequest{g, s, t, plan_rng, scratch});
  ASSERT_TRUE(r.ok());
  lower_than(r.path, "grid optimum");
  lower_than(greedy_shortcut(g, r.path, rule), "shortcut grid optimum");
  for (int k = 0; k < 4; ++k) {
    const std::vector<Point> j = jittered(r.path, rng);
    if (!valid_under(g, j, rule)) continue;
    ++tally.jitter_paths;
    lower_than(j, "jittered");
    lower_than(greedy_shortcut(g, j, rule), "shortcut jittered");
  }
}

TEST(AnyAngle, RandomMapsEveryGeneratorAndRule) {
  const char* const kGenerators[] = {"uniform", "blocks", "maze", "rooms"};
  Rng rng(2026, 14);
  Scratch scratch;
  AnyAngleScratch any;
  Tally tally;
  for (const char* generator : kGenerators) {
    for (int m = 0; m < 300; ++m) {
      MapSpec spec;
      spec.generator = generator;
      spec.width = 8 + static_cast<int>(rng.below(33));
      spec.height = 8 + static_cast<int>(rng.below(33));
      spec.density = rng.uniform(0.1, 0.4);
      spec.endpoints = m % 3 == 0 ? EndpointMode::corners : EndpointMode::random;
      Rng map_rng(static_cast<std::uint64_t>(m), 7);
      const MapInstance map = make_map(spec, map_rng);
      const std::string what = std::string(generator) + " map " + std::to_string(m) + " " +
                               std::to_string(spec.width) + "x" + std::to_string(spec.height);
      for (CornerRule rule : kRules)
        check_map(map.grid, map.start, map.goal, rule, rng, scratch, any, tally, what);
    }
  }
  // The sample exercises every branch: disconnected, straight, bent and pushed paths.
  EXPECT_EQ(tally.maps, 4 * 300 * 3);
  EXPECT_GT(tally.connected, tally.maps / 2);
  EXPECT_LT(tally.connected, tally.maps);
  EXPECT_GT(tally.straight, 20);
  EXPECT_LT(tally.straight, tally.connected / 2);
  EXPECT_GT(tally.jitter_paths, 1000);
  EXPECT_GT(tally.pushed_vertices, 3000);
}

TEST(AnyAngle, CheckerboardPinchesUnderAllow) {
  // Dense diagonal pinches: 80 % of the odd cells of a checkerboard blocked. Under allow every
  // free cell connects through the pinches; the other rules mostly cannot cross.
  Rng rng(3, 3);
  Scratch scratch;
  AnyAngleScratch any;
  Tally allow;
  Tally strict;
  for (int m = 0; m < 100; ++m) {
    Grid g(8 + static_cast<int>(rng.below(17)), 8 + static_cast<int>(rng.below(17)));
    for (int y = 0; y < g.height(); ++y)
      for (int x = 0; x < g.width(); ++x)
        g.set_blocked(x, y, (x + y) % 2 == 1 && rng.uniform01() < 0.8);
    const Cell s{0, 0};
    const Cell t{g.width() - 1, g.height() - 1};
    g.set_blocked(t, false);
    const std::string what = "checkerboard " + std::to_string(m);
    check_map(g, s, t, CornerRule::allow, rng, scratch, any, allow, what);
    for (CornerRule rule : {CornerRule::no_squeeze, CornerRule::no_corner_cut})
      check_map(g, s, t, rule, rng, scratch, any, strict, what);
  }
  EXPECT_EQ(allow.maps, 100);
  EXPECT_EQ(allow.connected, allow.maps);
  EXPECT_GT(allow.pushed_vertices, 100);
  EXPECT_LT(strict.connected, strict.maps / 2);
}

// ---------------------------------------------------------------------------------------------
// MovingAI: the scenario optima (no_corner_cut grid paths) are never below the bound.

// The shorter buckets (the search's cost grows with the bend points it must look at, tens of
// thousands on these maps), 60 queries a map spread over them; returns how many were checked.
int check_bound_below_optima(const std::string& dir, const std::vector<const char*>& maps) {
  AnyAngleScratch any;
  int checked = 0;
  for (const char* name : maps) {
    const Grid grid = read_map(dir + name);
    std::vector<ScenarioQuery> queries = read_scen(dir + name + ".scen");
    std::erase_if(queries, [](const ScenarioQuery& q) { return q.bucket >= kMaxBucket; });
    const std::size_t stride = std::max<std::size_t>(1, queries.size() / 60);
    for (std::size_t q = 0; q < queries.size(); q += stride) {
      const ScenarioQuery& s = queries[q];
      for (CornerRule rule : {CornerRule::allow, CornerRule::no_corner_cut}) {
        const auto bound = any_angle_length(grid, s.start, s.goal, rule, any);
        EXPECT_TRUE(bound) << name << " line " << s.line;
        if (!bound) return checked;
        EXPECT_GE(*bound, euclid(s.start, s.goal) * (1 - 1e-12)) << name << " line " << s.line;
        // The files print the optimum to 8 decimals.
        EXPECT_LE(*bound, s.optimal_length + 1e-8) << name << " line " << s.line;
        ++checked;
      }
    }
  }
  return checked;
}

TEST(AnyAngle, FullSetsOptimaAreNeverBelowTheBound) {
  AGV_MOVINGAI_SETS_OR_SKIP(sets);
  const int checked = check_bound_below_optima(
      sets + "/",
      {"arena2.map", "random512-10-0.map", "maze512-1-0.map", "8room_000.map", "Berlin_0_512.map"});
  EXPECT_GT(checked, 500);
}

}  // namespace
}  // namespace agv
