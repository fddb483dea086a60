// The A* family of issue 3 (MA*, improved A* internal/full, alternative A*, kinematic A*,
// bidirectional A*) and the shared post-processing, against truth on many random maps
// (docs/ARCHITECTURE.md "Style" item 11): every path validates under its planner's own corner rule;
// smoothed paths are collision-free at a sampling of 0.05 cells; shortcuts never lengthen and never
// collide; each paper's defining property is checked as a paired comparison; bidirectional A* is
// optimal. Where a paper's claim is not a property that must hold, the test prints the measured
// figure
// ("[measured]") and asserts only what must hold.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "algos/postprocess/path_curves.h"
#include "algos/postprocess/path_simplify.h"
#include "algos/postprocess/postprocess_params.h"
#include "algos/registry.h"
#include "algos/search/dijkstra.h"
#include "algos/search/heuristics.h"
#include "algos/search/kin_astar.h"
#include "algos/search/search_core.h"
#include "core/cell_geometry.h"
#include "core/line_of_sight.h"
#include "engine/judge/metrics.h"
#include "engine/judge/validator.h"
#include "engine/plan/sweep_plan.h"
#include "generators/map_generators.h"
#include "generators/registry.h"

namespace agv {
namespace {

constexpr int kMaps = 600;  // >= 500 per planner and per paired property

// A fixed, varied set of solvable random maps: uniform, blocks, maze and rooms, sides 16-48,
// densities 0.1-0.35, corner and random endpoints; solvable under no_corner_cut (the strictest
// rule, so every planner has a path).
MapInstance random_map(int i, double density_scale = 1.0) {
  static const int kSides[] = {16, 20, 24, 32, 40, 48};
  static const double kDensities[] = {0.1, 0.2, 0.25, 0.3, 0.35};
  MapSpec spec;
  static const char* const kGenerators[] = {"uniform", "blocks", "uniform", "maze", "rooms"};
  spec.generator = kGenerators[i % 5];
  spec.width = kSides[i % 6];
  spec.height = kSides[(i / 6) % 6];
  spec.density = kDensities[(i / 2) % 5] * density_scale;
  spec.endpoints = (i % 2 == 0) ? EndpointMode::corners : EndpointMode::random;
  spec.min_distance = 6.0;
  spec.require_solvable = true;
  spec.solvable_rule = CornerRule::no_corner_cut;
  Rng rng(20240603, static_cast<std::uint64_t>(i));
  return make_map(spec, rng);
}

const std::vector<MapInstance>& maps() {
  static const std::vector<MapInstance> all = [] {
    std::vector<MapInstance> v;
    for (int i = 0; i < kMaps; ++i) v.push_back(random_map(i));
    return v;
  }();
  return all;
}

ConfiguredPlanner make(const std::string& name, const nlohmann::json& params = {}) {
  return configure_planner(name, params.is_null() ? nlohmann::json::object() : params, "test");
}

PlanResult run(const ConfiguredPlanner& p, const MapInstance& m, Scratch& scratch) {
  Rng rng(1, 2);
  return p.planner->plan(PlanRequest{m.grid, m.start, m.goal, rng, scratch});
}

// Independent of line_of_sight.cpp: every sample, at most `step` apart along each segment, lies
// in no blocked cell's open interior. A sample on a grid line (within the line of sight's
// documented 1e-9 tolerance) touches cells only at their boundary, which the validator judges
// with the corner rule (under `allow` a path may pass exactly through a vertex between two
// diagonal obstacles).
bool samples_free(const Grid& grid, const std::vector<Point>& path, double step = 0.05) {
  auto point_free = [&](Point p) {
    if (p.x < 0 || p.y < 0 || p.x > grid.width() || p.y > grid.height()) return false;
    const double fx = std::floor(p.x), fy = std::floor(p.y);
    if (p.x - fx <= kSightEpsilon || fx + 1 - p.x <= kSightEpsilon || p.y - fy <= kSightEpsilon ||
        fy + 1 - p.y <= kSightEpsilon)
      return true;
    return !grid.blocked(static_cast<int>(fx), static_cast<int>(fy));
  };
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const Point a = path[i], b = path[i + 1];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
    for (int k = 0; k <= n; ++k) {
      const double t = static_cast<double>(k) / n;
      if (!point_free({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)})) return false;
    }
  }
  return path.size() != 1 || point_free(path[0]);
}

double length(const std::vector<Point>& path) { return polyline_length(path); }

// Does segment a-b run along `input` (a and b on it, only straight-through vertices between)?
// Such a segment collides exactly where the input does, so a step may leave it.
bool along_input(const std::vector<Point>& input, Point a, Point b) {
  auto on = [](Point p, Point s, Point t) {
    const double cross = (t.x - s.x) * (p.y - s.y) - (t.y - s.y) * (p.x - s.x);
    const double dot = (p.x - s.x) * (t.x - s.x) + (p.y - s.y) * (t.y - s.y);
    const double len2 = (t.x - s.x) * (t.x - s.x) + (t.y - s.y) * (t.y - s.y);
    return std::abs(cross) <= 1e-9 && dot >= -1e-9 && dot <= len2 + 1e-9;
  };
  for (std::size_t ka = 0; ka + 1 < input.size(); ++ka) {
    if (!on(a, input[ka], input[ka + 1])) continue;
    for (std::size_t kb = ka; kb + 1 < input.size(); ++kb) {
      if (kb > ka && !goes_straight(input[kb - 1], input[kb], input[kb + 1])) break;
      if (on(b, input[kb], input[kb + 1])) return true;
    }
  }
  return false;
}

std::int64_t turns(const Grid& grid, const std::vector<Point>& path) {
  return compute_path_metrics(grid, path).turns;
}

// --- the pieces ------------------------------------------------------------------------------

TEST(PathSimplify, CollinearUsesCrossProductsNotSlopes) {
  // Vertical moves (the printed slopes of eq. 5.1a divide by zero there) and a reversal.
  EXPECT_TRUE(goes_straight({0.5, 0.5}, {0.5, 1.5}, {0.5, 4.5}));
  EXPECT_FALSE(goes_straight({0.5, 0.5}, {0.5, 1.5}, {1.5, 2.5}));
  EXPECT_FALSE(goes_straight({0.5, 0.5}, {0.5, 1.5}, {0.5, 0.5}));  // back the same way
  EXPECT_TRUE(goes_straight({0.1, 0.1}, {0.2, 0.2}, {0.7, 0.7}));   // continuous, tolerance
  std::vector<Point> p = {{0.5, 0.5}, {1.5, 0.5}, {2.5, 0.5}, {2.5, 0.5},
                          {3.5, 1.5}, {4.5, 2.5}, {4.5, 3.5}};
  remove_collinear(p);
  const std::vector<Point> want = {{0.5, 0.5}, {2.5, 0.5}, {4.5, 2.5}, {4.5, 3.5}};
  EXPECT_EQ(p, want);
}

TEST(PathSimplify, MidpointsForwardKeysAndGreedyOnAnOpenMap) {
  const Grid grid(10, 10);
  std::vector<Point> p = {{0.5, 0.5}, {1.5, 1.5}, {2.5, 1.5}, {3.5, 2.5}};
  std::vector<Point> mid = p;
  insert_midpoints(mid);
  ASSERT_EQ(mid.size(), 7u);
  EXPECT_EQ(mid[1], (Point{1.0, 1.0}));
  EXPECT_DOUBLE_EQ(length(mid), length(p));
  std::vector<Point> f = mid;
  forward_key_points(grid, f, SightRule::cells());
  EXPECT_EQ(f, (std::vector<Point>{{0.5, 0.5}, {3.5, 2.5}}));
  std::vector<Point> g = p;
  shortcut_greedy(grid, g, SightRule::cells());
  EXPECT_EQ(g, (std::vector<Point>{{0.5, 0.5}, {3.5, 2.5}}));
  std::vector<Point> r = p;
  remove_redundant_from_goal(grid, r, SightRule::cells());
  EXPECT_EQ(r, g);
}

TEST(PathCurves, BsplineIsTheAppendixMatrixFormAndClamped) {
  // Paper 004 appendix A basis functions, evaluated directly.
  const Point c[4] = {{0, 0}, {1, 3}, {4, 3}, {5, 0}};
  auto basis_point = [&](double t) {
    const double b0 = (-t * t * t + 3 * t * t - 3 * t + 1) / 6;
    const double b1 = (3 * t * t * t - 6 * t * t + 4) / 6;
    const double b2 = (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6;
    const double b3 = t * t * t / 6;
    return Point{b0 * c[0].x + b1 * c[1].x + b2 * c[2].x + b3 * c[3].x,
                 b0 * c[0].y + b1 * c[1].y + b2 * c[2].y + b3 * c[3].y};
  };
  std::vector<int> segment;
  const std::vector<Point> s = sample_bspline(c, 0.05, &segment);
  ASSERT_EQ(s.size(), segment.size());
  EXPECT_EQ(s.front(), c[0]);  // clamped: starts at the first control point
  EXPECT_EQ(s.back(), c[3]);   // and ends at the last
  // The middle segment (clamped controls q[2..5] = c[0..3]) is the textbook one.
  bool checked = false;
  const auto first = std::find(segment.begin(), segment.end(), 2);
  if (first != segment.end()) {
    const Point p = s[static_cast<std::size_t>(first - segment.begin())];
    const Point want = basis_point(0.0);
    EXPECT_NEAR(p.x, want.x, 1e-12);
    EXPECT_NEAR(p.y, want.y, 1e-12);
    checked = true;
  }
  EXPECT_TRUE(checked);
  for (std::size_t i = 1; i < s.size(); ++i)
    EXPECT_LE(std::hypot(s[i].x - s[i - 1].x, s[i].y - s[i - 1].y), 0.05 + 1e-12);
}

TEST(PathCurves, QuadraticBezierEq14) {
  const auto b = sample_quadratic_bezier({0, 0}, {1, 1}, {2, 0}, 3);
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b[0], (Point{0, 0}));
  EXPECT_DOUBLE_EQ(b[1].x, 1.0);  // t = 1/2: (P0 + 2 P1 + P2) / 4
  EXPECT_DOUBLE_EQ(b[1].y, 0.5);
  EXPECT_EQ(b[2], (Point{2, 0}));
}

TEST(KinAStar, FiveDirectionsAreTable1) {
  // Goal due east: keep 000, 045, 090, 270, 315 (E, the two easterly diagonals, N and S).
  const std::uint8_t east = five_direction_mask(7, 0);
  EXPECT_EQ(east, (1 << 0) | (1 << 4) | (1 << 7) | (1 << 1) | (1 << 3));
  for (int dx = -9; dx <= 9; ++dx) {
    for (int dy = -9; dy <= 9; ++dy) {
      if (dx == 0 && dy == 0) continue;
      const std::uint8_t m = five_direction_mask(dx, dy);
      EXPECT_EQ(std::popcount(static_cast<unsigned>(m)), 5);
      // Every kept direction is within 90 degrees + half a sector of the goal direction, and the
      // move straight toward the goal's sector is always kept.
      const double theta = std::atan2(dy, dx);
      for (int d = 0; d < 8; ++d) {
        if (!(m & (1 << d))) continue;
        double diff = std::abs(std::atan2(kDy[d], kDx[d]) - theta);
        if (diff > std::numbers::pi) diff = 2 * std::numbers::pi - diff;
        EXPECT_LE(diff, std::numbers::pi * 5 / 8 + 1e-12) << dx << "," << dy << " dir " << d;
      }
    }
  }
}

TEST(FamilyParams, DeclaredWithPaperDefaults) {
  EXPECT_EQ(make("ma_star").params.choice("g_mode"), "euclid_from_start");
  EXPECT_NEAR(make("ma_star").params.number("r_obs"), std::sqrt(0.5), 1e-15);
  const auto inner = make("improved_astar_internal");
  // Every corner rule defaults to the collision model's (paper 002's no_squeeze is its config's
  // model, configs/paper-002.json).
  EXPECT_EQ(inner.params.choice("corner_rule"), "no_corner_cut");
  EXPECT_EQ(inner.params.choice("heuristic"), "octile");
  EXPECT_DOUBLE_EQ(inner.params.number("diagonal_cost"), 1.4);
  EXPECT_DOUBLE_EQ(inner.params.number("turn_weight"), 1.2);
  EXPECT_EQ(make("improved_astar").params.choice("smoothing"), "bezier");
  const auto alt = make("alt_astar");
  EXPECT_EQ(alt.params.choice("weight_mode"), "inverse_rate");
  EXPECT_EQ(alt.params.choice("rate_scope"), "node");
  EXPECT_DOUBLE_EQ(alt.params.number("max_weight"), 5.0);
  EXPECT_EQ(alt.params.choice("corner_rule"), "no_corner_cut");
  const auto kin = make("kin_astar");
  EXPECT_EQ(kin.params.choice("directions"), "five");
  // Paper 004: obstacle centre points more than one cell edge from the segment (margin + 0.5).
  EXPECT_DOUBLE_EQ(kin.params.number("shortcut_margin"), 0.5);
  EXPECT_DOUBLE_EQ(alt.params.number("shortcut_margin"), 0.0);
  // One name per meaning: the old spellings are gone, not aliases.
  EXPECT_THROW(make("kin_astar", {{"d_safe", 1.0}}), InputError);
  EXPECT_THROW(make("alt_astar", {{"margin", 0.5}}), InputError);
  EXPECT_EQ(kin.params.choice("smoothing"), "bspline");
  EXPECT_EQ(make("bidir_astar").params.choice("meet"), "optimal");
  EXPECT_THROW(make("kin_astar", {{"directions", "six"}}), InputError);
  EXPECT_THROW(make("alt_astar", {{"max_weight", 0.5}}), InputError);
}

// --- every planner on every map -----------------------------------------------------------------

struct Case {
  const char* name;
  const char* params;  // JSON
  bool curved;         // returns sampled curves
};
const Case kCases[] = {
    {"ma_star", "{}", false},
    {"ma_star", R"({"g_mode": "path"})", false},
    {"improved_astar_internal", "{}", false},
    {"improved_astar", "{}", true},
    {"alt_astar", "{}", false},
    {"alt_astar", R"({"rate_scope": "query", "shortcut_margin": 0.5})", false},
    {"kin_astar", "{}", true},
    {"kin_astar", R"({"directions": "eight"})", true},
    {"bidir_astar", "{}", false},
    {"astar", "{}", false},  // + generic post-processing below
    {"astar", R"({"corner_rule": "no_corner_cut", "shortcut": "greedy", "smoothing": "bspline"})",
     true},
    {"dijkstra", R"({"shortcut": "turning_points", "smoothing": "bezier"})", true},
};

class FamilyPaths : public ::testing::TestWithParam<int> {};

TEST_P(FamilyPaths, ValidateUnderOwnRuleAndSmoothedAreCollisionFree) {
  const Case& c = kCases[GetParam()];
  const auto planner = make(c.name, nlohmann::json::parse(c.params));
  Scratch scratch;
  int failures = 0;
  for (int i = 0; i < kMaps && failures < 5; ++i) {
    const MapInstance& m = maps()[static_cast<std::size_t>(i)];
    const PlanResult r = run(planner, m, scratch);
    if (!r.ok()) {
      ++failures;
      ADD_FAILURE() << c.name << " map " << i << ": " << r.message;
      continue;
    }
    const ValidationResult v = validate_path(m.grid, m.start, m.goal, r.path, r.rule);
    if (!v.ok) {
      ++failures;
      ADD_FAILURE() << c.name << " map " << i << ": " << v.reason;
    }
    if (!samples_free(m.grid, r.path)) {
      ++failures;
      ADD_FAILURE() << c.name << " map " << i << ": a sample lies inside an obstacle";
    }
    EXPECT_GT(r.work.search_expansions.value_or(-1), 0);
    // Deterministic: the same query again gives the same path.
    if (i % 50 == 0) {
      EXPECT_EQ(run(planner, m, scratch).path, r.path) << c.name << " map " << i;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Planners, FamilyPaths,
                         ::testing::Range(0, static_cast<int>(std::size(kCases))),
                         [](const auto& test) {
                           return std::string(kCases[test.param].name) + "_" +
                                  std::to_string(test.param);
                         });

// --- post-processing through parameters (any planner) ----------------------------------------

TEST(Postprocess, ShortcutsNeverLengthenNeverCollideAndSmoothingStaysFree) {
  const auto astar = make("astar");
  Scratch scratch;
  const ShortcutMode modes[] = {ShortcutMode::collinear, ShortcutMode::turning_points,
                                ShortcutMode::greedy,    ShortcutMode::forward,
                                ShortcutMode::from_goal, ShortcutMode::direct_midpoint};
  const char* names[] = {"collinear", "turning_points", "greedy",
                         "forward",   "from_goal",      "direct_midpoint"};
  int failures = 0;
  int curve_fallbacks[2] = {0, 0};
  int curve_cases[2] = {0, 0};
  for (int i = 0; i < kMaps && failures < 10; ++i) {
    const MapInstance& m = maps()[static_cast<std::size_t>(i)];
    const PlanResult base = run(astar, m, scratch);
    ASSERT_TRUE(base.ok());
    for (std::size_t k = 0; k < std::size(modes); ++k) {
      for (double margin : {0.0, 0.5}) {
        const SightRule sight = sight_rule(base.rule, margin);
        WorkingPath path(base.path);
        apply_shortcut(m.grid, modes[k], sight, path);
        const std::string what = std::string(names[k]) + " margin " + std::to_string(margin) +
                                 " map " + std::to_string(i);
        // Never longer than the input.
        if (!(length(path.points) <= length(base.path) + 1e-9)) {
          ++failures;
          ADD_FAILURE() << what << ": " << length(path.points) << " > " << length(base.path);
        }
        // Removes no node whose removal would collide: every segment is free under the step's
        // rule, or runs along the input path (collides exactly where the input does).
        for (std::size_t s = 0; s + 1 < path.points.size(); ++s) {
          const Point a = path.points[s], b = path.points[s + 1];
          if (!segment_free(m.grid, a, b, sight) && !along_input(base.path, a, b)) {
            ++failures;
            ADD_FAILURE() << what << ": segment " << s << " collides";
          }
        }
        const ValidationResult v = validate_path(m.grid, m.start, m.goal, path.points, base.rule);
        if (!v.ok) {
          ++failures;
          ADD_FAILURE() << what << ": " << v.reason;
        }
        // Subsequence steps keep a subsequence of the search path.
        if (!path.kept.empty()) {
          for (std::size_t s = 0; s < path.kept.size(); ++s)
            EXPECT_EQ(path.points[s], base.path[static_cast<std::size_t>(path.kept[s])]);
        }
        if (margin > 0.0) continue;
        // Smoothing on top, as `smoothing: bezier | bspline` does for any planner.
        for (SmoothingMode smooth : {SmoothingMode::bezier, SmoothingMode::bspline}) {
          PostprocessOptions options;
          options.smoothing = smooth;
          WorkingPath curve = path;
          apply_smoothing(m.grid, options, SightRule::cells(base.rule), curve);
          const ValidationResult cv =
              validate_path(m.grid, m.start, m.goal, curve.points, base.rule);
          if (!cv.ok || !samples_free(m.grid, curve.points)) {
            ++failures;
            ADD_FAILURE() << what << (smooth == SmoothingMode::bezier ? " bezier" : " bspline")
                          << ": " << (cv.ok ? "sample in an obstacle" : cv.reason);
          }
          if (path.points.size() >= 3 && curve.points == path.points)
            ++curve_fallbacks[smooth == SmoothingMode::bezier ? 0 : 1];
          ++curve_cases[smooth == SmoothingMode::bezier ? 0 : 1];
        }
      }
    }
  }
  std::printf(
      "[measured] polylines of >= 3 points returned unsmoothed (no corner fitted, or "
      "the fallback): bezier %d of %d, bspline %d of %d\n",
      curve_fallbacks[0], curve_cases[0], curve_fallbacks[1], curve_cases[1]);
}

TEST(Postprocess, AStarAndDijkstraTakeThePostprocessingParameters) {
  // A user's "classic A* + shortcut + B-spline", configured by parameters: the same path as the
  // generic options applied to the plain planner's result, and the shortcut alone never
  // lengthens the optimal path it refines.
  PostprocessOptions options;
  options.shortcut = ShortcutMode::greedy;
  options.smoothing = SmoothingMode::bspline;
  Scratch scratch;
  for (const char* name : {"astar", "dijkstra"}) {
    const auto plain = make(name);
    const auto post = make(name, {{"shortcut", "greedy"}, {"smoothing", "bspline"}});
    const auto cut = make(name, {{"shortcut", "greedy"}});
    int shorter = 0;
    for (int i = 0; i < 100; ++i) {
      const MapInstance& m = maps()[static_cast<std::size_t>(i)];
      const PlanResult base = run(plain, m, scratch);
      ASSERT_TRUE(base.ok()) << name << " map " << i;
      PlanResult expected = base;
      apply_postprocessing(m.grid, options, expected, Deadline::never());
      const PlanResult r = run(post, m, scratch);
      ASSERT_TRUE(r.ok()) << name << " map " << i;
      EXPECT_EQ(r.path, expected.path) << name << " map " << i;
      EXPECT_TRUE(validate_path(m.grid, m.start, m.goal, r.path, r.rule).ok) << name << " " << i;
      EXPECT_TRUE(samples_free(m.grid, r.path)) << name << " map " << i;
      bool timed = false;
      for (const auto& phase : r.phases) timed = timed || phase.name == "smoothing";
      EXPECT_TRUE(timed) << name;
      const PlanResult c = run(cut, m, scratch);
      ASSERT_TRUE(c.ok());
      EXPECT_LE(length(c.path), length(base.path) + 1e-9) << name << " map " << i;
      EXPECT_TRUE(validate_path(m.grid, m.start, m.goal, c.path, c.rule).ok) << name << " " << i;
      shorter += length(c.path) < length(base.path) - 1e-9 ? 1 : 0;
    }
    // Any-angle shortcuts beat 8-connected optimal paths on most random maps.
    EXPECT_GT(shorter, 50) << name;
    std::printf("[measured] %s + greedy shortcut shorter than %s on %d/100 maps\n", name, name,
                shorter);
  }
}

// --- the papers' defining properties, paired over the same maps ------------------------------

struct Pair {
  int wins = 0, ties = 0, losses = 0;  // candidate smaller / equal / larger
  double log_ratio_sum = 0.0;
  int ratios = 0;
  void add(double candidate, double baseline) {
    if (candidate < baseline)
      ++wins;
    else if (candidate > baseline)
      ++losses;
    else
      ++ties;
    if (candidate > 0 && baseline > 0) {
      log_ratio_sum += std::log(candidate / baseline);
      ++ratios;
    }
  }
  double geo_ratio() const { return ratios ? std::exp(log_ratio_sum / ratios) : 1.0; }
  void print(const char* what) const {
    std::printf(
        "[measured] %s: candidate smaller on %d, equal on %d, larger on %d maps; "
        "geometric-mean ratio %.4f\n",
        what, wins, ties, losses, geo_ratio());
  }
};

TEST(PaperProperties, ImprovedInternalTurnsLessThanClassicAStar) {
  const auto astar = make("astar");
  const auto inner = make("improved_astar_internal");
  Scratch scratch;
  Pair turn_count, turn_angle;
  for (const MapInstance& m : maps()) {
    const PlanResult a = run(astar, m, scratch);
    const PlanResult b = run(inner, m, scratch);
    ASSERT_TRUE(a.ok() && b.ok());
    turn_count.add(static_cast<double>(turns(m.grid, b.path)),
                   static_cast<double>(turns(m.grid, a.path)));
    turn_angle.add(compute_path_metrics(m.grid, b.path).turn_angle_rad,
                   compute_path_metrics(m.grid, a.path).turn_angle_rad);
  }
  turn_count.print("paper 002: improved_astar_internal vs astar, turns");
  turn_angle.print("paper 002: improved_astar_internal vs astar, turn angle");
  // Fewer turns on most maps (the turning weight's purpose), and more often fewer than more.
  EXPECT_GT(turn_count.wins, kMaps / 2);
  EXPECT_GT(turn_count.wins, 2 * turn_count.losses);
}

TEST(PaperProperties, NoSqueezeNeverPassesBetweenDiagonalObstacles) {
  Scratch scratch;
  int squeezes_allowed = 0;
  for (const char* name : {"improved_astar_internal", "improved_astar"}) {
    // Paper 002's rule (its config's collision model).
    const auto planner = make(name, {{"corner_rule", "no_squeeze"}});
    const auto classic = make("astar", {{"corner_rule", "allow"}});
    for (const MapInstance& m : maps()) {
      const PlanResult r = run(planner, m, scratch);
      ASSERT_TRUE(r.ok());
      ASSERT_EQ(r.rule, CornerRule::no_squeeze);
      // The whole polyline, exactly: no segment passes through a vertex whose two side cells are
      // both obstacles (cells mode under no_squeeze; the validator's test).
      EXPECT_TRUE(polyline_free(m.grid, r.path, SightRule::cells(CornerRule::no_squeeze))) << name;
      // Cell by cell, for the search path: no diagonal move with both cardinals blocked.
      if (std::string(name) == "improved_astar_internal") {
        for (std::size_t i = 1; i < r.path.size(); ++i) {
          const int x = static_cast<int>(r.path[i - 1].x), y = static_cast<int>(r.path[i - 1].y);
          const int dx = static_cast<int>(r.path[i].x) - x, dy = static_cast<int>(r.path[i].y) - y;
          if (dx != 0 && dy != 0) {
            EXPECT_FALSE(m.grid.blocked(x + dx, y) && m.grid.blocked(x, y + dy));
          }
        }
      }
      const PlanResult a = run(classic, m, scratch);
      if (!polyline_free(m.grid, a.path, SightRule::cells(CornerRule::no_squeeze)))
        ++squeezes_allowed;
    }
  }
  std::printf(
      "[measured] classic A* (allow) squeezes between diagonal obstacles on %d of %d "
      "maps\n",
      squeezes_allowed / 2, kMaps);
}

TEST(PaperProperties, KinFiveDirectionsExpandFewerThanEight) {
  const auto five = make("kin_astar");
  const auto eight = make("kin_astar", {{"directions", "eight"}});
  Scratch scratch;
  auto generated = [](const PlanResult& r) {
    for (const auto& [name, value] : r.extra)
      if (name == "generated_nodes") return value;
    return -1.0;
  };
  Pair expanded, children;
  std::int64_t total_five = 0, total_eight = 0;
  for (const MapInstance& m : maps()) {
    const PlanResult a = run(five, m, scratch);
    const PlanResult b = run(eight, m, scratch);
    ASSERT_TRUE(a.ok() && b.ok());
    expanded.add(static_cast<double>(a.work.search_expansions.value_or(-1)),
                 static_cast<double>(b.work.search_expansions.value_or(-1)));
    children.add(generated(a), generated(b));
    ASSERT_GT(generated(a), 0.0);
    total_five += a.work.search_expansions.value_or(-1);
    total_eight += b.work.search_expansions.value_or(-1);
  }
  expanded.print("paper 004: kin_astar five vs eight directions, expanded nodes");
  children.print("paper 004: kin_astar five vs eight directions, generated (searched) children");
  std::printf("[measured] expanded in total: five %lld, eight %lld\n",
              static_cast<long long>(total_five), static_cast<long long>(total_eight));
  // The five-direction rule removes moves, so it generates fewer children wherever it applies
  // (the paper's Figure 6 counts these). The expansions (popped nodes) barely move under the
  // strongly weighted heuristic, either way: measured and printed, not asserted (the claim
  // "expands fewer nodes" does not hold in our measurement).
  EXPECT_GT(children.wins, 10 * children.losses);
  EXPECT_LT(children.geo_ratio(), 1.0);
}

TEST(PaperProperties, AltInverseRateExpandsNoMoreOnLowDensity) {
  const auto inverse = make("alt_astar");
  const auto admissible = make("alt_astar", {{"weight_mode", "admissible"}});
  Scratch scratch;
  Pair expanded, path_len;
  for (int i = 0; i < kMaps; ++i) {
    const MapInstance m = random_map(i, 0.5);  // densities 0.05-0.175
    const PlanResult a = run(inverse, m, scratch);
    const PlanResult b = run(admissible, m, scratch);
    ASSERT_TRUE(a.ok() && b.ok());
    expanded.add(static_cast<double>(a.work.search_expansions.value_or(-1)),
                 static_cast<double>(b.work.search_expansions.value_or(-1)));
    path_len.add(length(a.path), length(b.path));
  }
  expanded.print("paper 003: alt_astar inverse_rate vs admissible (low density), expanded");
  path_len.print("paper 003: alt_astar inverse_rate vs admissible (low density), length");
  // In distribution, not map by map: a weighted search occasionally wanders (printed above).
  EXPECT_GT(expanded.wins + expanded.ties, 10 * expanded.losses);
  EXPECT_LT(expanded.geo_ratio(), 1.0);
}

TEST(PaperProperties, MaStarPrintedGExpandsFewerThanAStar) {
  const auto astar = make("astar");
  const auto ma = make("ma_star");
  const auto ma_path = make("ma_star", {{"g_mode", "path"}});
  Scratch scratch;
  Pair expanded, path_len;
  for (const MapInstance& m : maps()) {
    const PlanResult a = run(astar, m, scratch);
    const PlanResult b = run(ma, m, scratch);
    const PlanResult c = run(ma_path, m, scratch);
    ASSERT_TRUE(a.ok() && b.ok() && c.ok());
    // g_mode path is A*: the same search, node for node.
    EXPECT_EQ(c.work.search_expansions.value_or(-1), a.work.search_expansions.value_or(-1));
    // The removals never lengthen A*'s path.
    EXPECT_LE(length(c.path), length(a.path) + 1e-9);
    expanded.add(static_cast<double>(b.work.search_expansions.value_or(-1)),
                 static_cast<double>(a.work.search_expansions.value_or(-1)));
    path_len.add(length(b.path), length(a.path));
  }
  expanded.print("paper 000: ma_star vs astar, expanded nodes");
  path_len.print("paper 000: ma_star vs astar, path length");
}

TEST(PaperProperties, BidirectionalAStarIsOptimal) {
  // 1,000 maps: the 600 of the suite and 400 more; several corner rules and diagonal costs.
  Scratch scratch;
  const std::pair<const char*, double> settings[] = {
      {"allow", kSqrt2}, {"no_corner_cut", kSqrt2}, {"no_squeeze", 1.4}, {"allow", 1.4}};
  int checked = 0;
  std::int64_t bidir_expanded = 0, dijkstra_expanded = 0;
  for (int i = 0; i < 1000; ++i) {
    const MapInstance m = i < kMaps ? maps()[static_cast<std::size_t>(i)] : random_map(i);
    // Named copies, not a structured binding: the cost lambda below captures `diagonal`, which
    // clang 14 (the fuzz and ASan tree's compiler) refuses for a binding.
    const char* const rule = settings[i % 4].first;
    const double diagonal = settings[i % 4].second;
    const nlohmann::json params = {{"corner_rule", rule}, {"diagonal_cost", diagonal}};
    const PlanResult b = run(make("bidir_astar", params), m, scratch);
    const PlanResult d = run(make("dijkstra", params), m, scratch);
    ASSERT_TRUE(b.ok() && d.ok()) << i;
    ASSERT_TRUE(validate_path(m.grid, m.start, m.goal, b.path, b.rule).ok) << i;
    // Compare costs under the run's own diagonal cost.
    auto cost = [&](const std::vector<Point>& p) {
      double c = 0;
      for (std::size_t k = 1; k < p.size(); ++k)
        c += (p[k].x != p[k - 1].x && p[k].y != p[k - 1].y) ? diagonal : 1.0;
      return c;
    };
    EXPECT_NEAR(cost(b.path), cost(d.path), 1e-9) << "map " << i << " rule " << rule;
    bidir_expanded += b.work.search_expansions.value_or(-1);
    dijkstra_expanded += d.work.search_expansions.value_or(-1);
    ++checked;
  }
  EXPECT_EQ(checked, 1000);
  // No fixed total: expansion counts depend on floating-point tie-breaks, which differ between
  // the Release and sanitizer builds. That the shared expansion changed no search is shown by
  // the reports (search_expansions per run), equal before and after (scripts/report_set.sh).
  EXPECT_LT(bidir_expanded, dijkstra_expanded);
  std::printf("[measured] expanded over 1000 maps: bidir_astar %lld, dijkstra %lld\n",
              static_cast<long long>(bidir_expanded), static_cast<long long>(dijkstra_expanded));
}

// Largest |heading change| over the joints of consecutive non-zero segments, in [0, pi];
// computed here, not by the library.
double largest_heading_change(const std::vector<Point>& path) {
  double worst = 0.0;
  double previous = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double dx = path[i + 1].x - path[i].x, dy = path[i + 1].y - path[i].y;
    if (std::hypot(dx, dy) <= 1e-9) continue;
    const double heading = std::atan2(dy, dx);
    if (!std::isnan(previous)) {
      double d = std::fmod(std::abs(heading - previous), 2.0 * std::numbers::pi);
      worst = std::max(worst, std::min(d, 2.0 * std::numbers::pi - d));
    }
    previous = heading;
  }
  return worst;
}

TEST(ImprovedAStar, AdjustmentNeverReversesNorLengthensBeyondTheSearchPath) {
  // The 600 maps of the suite, then 200 denser ones (densities 0.13-0.46; the doubled-back
  // paths were mostly at 0.4). The external part refines the internal search path: steps 1-2
  // (midpoints, forward key points) only shorten it, step 3 (eq. 12-13) bends the key polyline
  // around obstacles, a detour that may make it longer than the pre-adjustment polyline (the
  // paper's own design), and step 4's Bezier corners only shorten (a convex arc inside the
  // corner's triangle). So what must hold under `avoid_cap: search_path`: the adjusted polyline
  // is never longer than the search path, nor the final curve longer than the adjusted
  // polyline. Under both caps: no point inserted twice, no heading change above 150 degrees.
  const auto inner = make("improved_astar_internal");
  const auto capped = make("improved_astar");
  const auto uncapped = make("improved_astar", {{"avoid_cap", "none"}});
  EXPECT_EQ(capped.params.choice("avoid_cap"), "search_path");
  Scratch scratch;
  int checked = 0, lengthened = 0, bent = 0, uncapped_longer = 0;
  double worst_turn = 0.0;
  for (int i = 0; i < kMaps + 200; ++i) {
    const MapInstance m = i < kMaps ? maps()[static_cast<std::size_t>(i)] : random_map(i, 1.3);
    const PlanResult search = run(inner, m, scratch);
    ASSERT_TRUE(search.ok()) << i;
    // The pipeline's pieces, to see the polyline before and after the adjustment.
    const SightRule sight = SightRule::cells(search.rule);
    WorkingPath keys(search.path);
    apply_shortcut(m.grid, ShortcutMode::forward, sight, keys);
    const std::vector<Point> before = keys.points;
    EXPECT_LE(length(before), length(search.path) + 1e-9) << "map " << i;
    EXPECT_LE(largest_heading_change(before), kReversalAngle) << "map " << i;
    for (const bool cap : {true, false}) {
      SCOPED_TRACE(std::string("map ") + std::to_string(i) + (cap ? " capped" : " uncapped"));
      const PlanResult r = run(cap ? capped : uncapped, m, scratch);
      ASSERT_TRUE(r.ok());
      ASSERT_TRUE(validate_path(m.grid, m.start, m.goal, r.path, r.rule).ok);
      std::vector<Point> adjusted = before;
      avoid_obstacles(m.grid, adjusted, sight, 0.5, 1.0,
                      cap ? length(search.path) : std::numeric_limits<double>::infinity());
      ASSERT_EQ(bezier_corners(m.grid, adjusted, sight), r.path);
      EXPECT_EQ(r.waypoints_before_sampling, static_cast<std::int64_t>(adjusted.size()));
      for (std::size_t a = 0; a < adjusted.size(); ++a)
        for (std::size_t b = a + 1; b < adjusted.size(); ++b)
          EXPECT_GT(point_distance(adjusted[a], adjusted[b]), 1e-9) << a << " " << b;
      EXPECT_LE(largest_heading_change(adjusted), kReversalAngle);
      const double turn = largest_heading_change(r.path);
      EXPECT_LE(turn, kReversalAngle);
      worst_turn = std::max(worst_turn, turn);
      EXPECT_LE(length(r.path), length(adjusted) + 1e-9);
      if (cap) {
        EXPECT_LE(length(adjusted), length(search.path) + 1e-9);
        EXPECT_LE(length(r.path), length(search.path) + 1e-9);
        lengthened += length(adjusted) > length(before) + 1e-9;
        bent += adjusted != before;
      } else {
        uncapped_longer += length(r.path) > length(search.path) + 1e-9;
      }
    }
    ++checked;
  }
  EXPECT_EQ(checked, kMaps + 200);
  // The capped adjustment still does its work: without moves or insertions this checks nothing.
  EXPECT_GT(bent, (kMaps + 200) / 4);
  std::printf(
      "[measured] improved_astar over %d maps: the capped adjustment changed %d polylines and "
      "lengthened %d; uncapped, the path is longer than the search path on %d; largest heading "
      "change %.3f rad\n",
      checked, bent, lengthened, uncapped_longer, worst_turn);
}

// The map `agvbench plan --generator G --size S --density D --seed SEED --map-index I` draws.
MapInstance plan_command_map(const std::string& generator, int side, double density,
                             std::uint64_t seed, int map_index) {
  SweepCell cell;
  cell.key = generator + "/" + std::to_string(side) + "x" + std::to_string(side) + "/" +
             density_text(density);
  cell.spec.generator = generator;
  cell.spec.params = resolve_generator_params(generator_or_throw(generator, "test"),
                                              nlohmann::json::object(), "test", side, side)
                         .values();
  cell.spec.width = cell.spec.height = side;
  cell.spec.density = density;
  cell.spec.require_solvable = true;
  Rng rng = map_rng(seed, cell, map_index);
  return make_map(cell.spec, rng);
}

TEST(ImprovedAStar, IssueExamplesNoLongerDoubleBack) {
  // Issue 14: on the first map the full path turned 9.18 rad against the internal one's 2.36,
  // passing the same pushed vertex twice; on the second it reversed by exactly 180 degrees.
  struct Example {
    const char* generator;
    double density;
    std::uint64_t seed;
    int map_index;
    double internal_length;  // as `agvbench plan` reports it: the map is the issue's
  };
  const Example examples[] = {{"blocks", 0.2, 2002, 2, 28.6274}, {"maze", 0.4, 1, 9, 34.3848}};
  Scratch scratch;
  for (const Example& e : examples) {
    SCOPED_TRACE(e.generator);
    const MapInstance m = plan_command_map(e.generator, 20, e.density, e.seed, e.map_index);
    // Under paper 002's no_squeeze, the rule `agvbench plan` used when the issue was filed.
    const nlohmann::json rule = {{"corner_rule", "no_squeeze"}};
    const PlanResult inner = run(make("improved_astar_internal", rule), m, scratch);
    const PlanResult full = run(make("improved_astar", rule), m, scratch);
    ASSERT_TRUE(inner.ok() && full.ok());
    ASSERT_NEAR(length(inner.path), e.internal_length, 1e-4);
    EXPECT_LE(largest_heading_change(full.path), kReversalAngle);
    EXPECT_LE(length(full.path), length(inner.path) + 1e-9);
    std::printf("[measured] %s: turn angle full %.3f, internal %.3f rad\n", e.generator,
                compute_path_metrics(m.grid, full.path).turn_angle_rad,
                compute_path_metrics(m.grid, inner.path).turn_angle_rad);
  }
}

TEST(PaperProperties, BidirectionalMeetFirstIsNeverShorterThanOptimal) {
  // Paper 002's bidirectional A* stops when the searches meet (its Table 5 lengths exceed its
  // A*'s); ours stops on the optimal test, the length of A* under the same rule and costs.
  Scratch scratch;
  int longer = 0;
  for (int i = 0; i < kMaps; ++i) {
    const MapInstance& m = maps()[static_cast<std::size_t>(i)];
    const nlohmann::json rule = {{"corner_rule", i % 2 ? "allow" : "no_corner_cut"}};
    nlohmann::json first = rule;
    first["meet"] = "first";
    const PlanResult a = run(make("astar", rule), m, scratch);
    const PlanResult opt = run(make("bidir_astar", rule), m, scratch);
    const PlanResult f = run(make("bidir_astar", first), m, scratch);
    ASSERT_TRUE(a.ok() && opt.ok() && f.ok()) << i;
    ASSERT_TRUE(validate_path(m.grid, m.start, m.goal, f.path, f.rule).ok) << i;
    EXPECT_NEAR(length(opt.path), length(a.path), 1e-9) << "map " << i;
    EXPECT_GE(length(f.path), length(opt.path) - 1e-9) << "map " << i;
    longer += length(f.path) > length(opt.path) + 1e-9;
  }
  // The variant differs from the optimal one somewhere, or it would be no reading of its own.
  EXPECT_GT(longer, 0);
  std::printf("[measured] bidir_astar meet first longer than optimal on %d of %d maps\n", longer,
              kMaps);
}

// Minimum distance from the segment a-b to the centre of any blocked cell near it.
double centre_distance(const Grid& grid, Point a, Point b) {
  double best = std::numeric_limits<double>::infinity();
  const int x0 = static_cast<int>(std::floor(std::min(a.x, b.x))) - 3;
  const int x1 = static_cast<int>(std::floor(std::max(a.x, b.x))) + 3;
  const int y0 = static_cast<int>(std::floor(std::min(a.y, b.y))) - 3;
  const int y1 = static_cast<int>(std::floor(std::max(a.y, b.y))) + 3;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      if (!grid.in_bounds(Cell{x, y}) || !grid.blocked(x, y)) continue;
      const double px = x + 0.5 - a.x, py = y + 0.5 - a.y, dx = b.x - a.x, dy = b.y - a.y;
      const double len2 = dx * dx + dy * dy;
      const double t = len2 > 0 ? std::clamp((px * dx + py * dy) / len2, 0.0, 1.0) : 0.0;
      best = std::min(best, std::hypot(px - t * dx, py - t * dy));
    }
  return best;
}

TEST(KinAStar, SafetyDistanceIsOneCellFromObstacleCentres) {
  // Paper 004 section 2.3: a node is redundant when the segment replacing it keeps every
  // obstacle's centre point beyond the safety distance, one cell edge. The default reading
  // (shortcut_margin 0.5) keeps exactly that on every segment of the de-redundant path; the
  // former 1.0 demanded 1.5 and kept more nodes.
  const auto paper = make("kin_astar", {{"smoothing", "none"}});
  const auto wide = make("kin_astar", {{"smoothing", "none"}, {"shortcut_margin", 1.0}});
  Scratch scratch;
  std::size_t paper_nodes = 0, wide_nodes = 0;
  for (const MapInstance& m : maps()) {
    const PlanResult r = run(paper, m, scratch);
    const PlanResult w = run(wide, m, scratch);
    ASSERT_TRUE(r.ok() && w.ok());
    for (std::size_t k = 0; k + 1 < r.path.size(); ++k)
      EXPECT_GE(centre_distance(m.grid, r.path[k], r.path[k + 1]), 1.0 - 1e-9) << k;
    paper_nodes += r.path.size();
    wide_nodes += w.path.size();
  }
  EXPECT_LT(paper_nodes, wide_nodes);
  std::printf("[measured] kin_astar nodes over %d maps: margin 0.5 %zu, margin 1.0 %zu\n", kMaps,
              paper_nodes, wide_nodes);
}

// generated_nodes comes from the search listener; it must equal what kin_astar used to count by
// scanning the grid's search stamps after the search: every cell open or closed when it stopped.
std::int64_t labelled_cells(Scratch& scratch, const Grid& grid) {
  GridSearchBuffers& buffers = scratch.get<GridSearchBuffers>();
  const std::uint8_t* stamp = buffers.stamps();
  std::int64_t seen = 0;
  for (int i = 0; i < grid.padded_size(); ++i)
    seen += (stamp[i] == buffers.open_stamp() || stamp[i] == buffers.closed_stamp()) ? 1 : 0;
  return seen;
}

double generated_nodes(const PlanResult& r) {
  for (const auto& [name, value] : r.extra)
    if (name == "generated_nodes") return value;
  return -1.0;
}

TEST(KinAStar, GeneratedNodesAreTheCellsTheSearchLabelled) {
  Scratch scratch;
  int checked = 0;
  for (const char* directions : {"five", "eight"}) {
    const auto kin = make("kin_astar", {{"directions", directions}});
    for (int i = 0; i < 2 * kMaps; ++i) {
      // The suite's maps, then as many more (the walled grid below covers no_path).
      const MapInstance m = i < kMaps ? maps()[static_cast<std::size_t>(i)] : random_map(i);
      Rng rng(1, 2);
      const PlanResult r = kin.planner->plan(PlanRequest{m.grid, m.start, m.goal, rng, scratch});
      ASSERT_NE(r.failure, Failure::invalid_input) << i;
      EXPECT_EQ(generated_nodes(r), static_cast<double>(labelled_cells(scratch, m.grid)))
          << directions << " map " << i;
      ++checked;
    }
  }
  Grid walled(12, 12);
  for (int y = 0; y < 12; ++y) walled.set_blocked(6, y, true);
  Rng rng(1, 2);
  const PlanResult none =
      make("kin_astar").planner->plan(PlanRequest{walled, {1, 1}, {10, 10}, rng, scratch});
  EXPECT_EQ(none.failure, Failure::no_path);
  EXPECT_EQ(generated_nodes(none), 6.0 * 12.0);  // the whole left half
  EXPECT_EQ(generated_nodes(none), static_cast<double>(labelled_cells(scratch, walled)));
  const PlanResult same =
      make("kin_astar").planner->plan(PlanRequest{walled, {2, 2}, {2, 2}, rng, scratch});
  EXPECT_EQ(generated_nodes(same), 1.0);
  EXPECT_EQ(checked, 4 * kMaps);
}

TEST(FamilyEdges, StartEqualsGoalAndUnreachableAndDeadline) {
  Grid grid(12, 12);
  for (int y = 0; y < 12; ++y) grid.set_blocked(6, y, true);  // a wall: right half unreachable
  Scratch scratch;
  Rng rng(1, 1);
  for (const auto& info : planner_registry()) {
    if (info.kind != PlannerKind::grid_search) continue;
    const std::string name = info.name;
    const auto p = make(name);
    const PlanResult same = p.planner->plan(PlanRequest{grid, {2, 2}, {2, 2}, rng, scratch});
    ASSERT_TRUE(same.ok()) << name;
    EXPECT_TRUE(validate_path(grid, {2, 2}, {2, 2}, same.path, same.rule).ok) << name;
    const PlanResult none = p.planner->plan(PlanRequest{grid, {1, 1}, {10, 10}, rng, scratch});
    EXPECT_FALSE(none.ok()) << name;
    EXPECT_EQ(none.failure, Failure::no_path) << name;
    const PlanResult bad = p.planner->plan(PlanRequest{grid, {6, 3}, {1, 1}, rng, scratch});
    EXPECT_EQ(bad.failure, Failure::invalid_input) << name;
    Grid big(300, 300);
    const PlanResult late = p.planner->plan(PlanRequest{
        big, {0, 0}, {299, 299}, rng, scratch, Deadline::after(std::chrono::nanoseconds(0))});
    EXPECT_EQ(late.failure, Failure::limit) << name;
  }
}

}  // namespace
}  // namespace agv
