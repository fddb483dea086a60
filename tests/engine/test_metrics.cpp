// Path metrics on hand-computed paths, and the clearance metric against brute force over every
// obstacle cell.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string_view>
#include <vector>

#include "engine/metrics.h"

namespace agv {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Metrics, StraightPath) {
  const Grid g(10, 10, 2.0);  // 2 m cells
  const std::vector<Point> path = {{0.5, 0.5}, {4.5, 0.5}};
  const PathMetrics m = compute_path_metrics(g, path);
  EXPECT_DOUBLE_EQ(m.path_length, 4.0);
  EXPECT_DOUBLE_EQ(m.path_length_m, 8.0);
  EXPECT_EQ(m.path_nodes, 2);
  EXPECT_EQ(m.turns, 0);
  EXPECT_EQ(m.turn_angle_rad, 0.0);
  EXPECT_EQ(m.smoothness_mean, 0.0);
  EXPECT_EQ(m.smoothness_max, 0.0);
  EXPECT_DOUBLE_EQ(m.min_clearance, 0.5);  // to the top border wall at y = 0
  EXPECT_DOUBLE_EQ(m.min_clearance_m, 1.0);
  // Eq. 5.2e: 8 m / 1 m/s + 2 * 0.1 s + 0.
  EXPECT_DOUBLE_EQ(m.motion_time_s, 8.2);
}

TEST(Metrics, LShapedPath) {
  Grid g(10, 10);
  g.set_blocked(5, 2, true);  // the corner (3.5,0.5)-(3.5,4.5) runs 1.5 from its square
  const std::vector<Point> path = {{1.5, 1.5}, {3.5, 1.5}, {3.5, 4.5}};
  const PathMetrics m = compute_path_metrics(g, path);
  EXPECT_DOUBLE_EQ(m.path_length, 5.0);
  EXPECT_EQ(m.path_nodes, 3);
  EXPECT_EQ(m.turns, 1);
  EXPECT_DOUBLE_EQ(m.turn_angle_rad, kPi / 2);
  // pi/2 over the mean of the adjacent lengths (2 + 3) / 2.
  EXPECT_DOUBLE_EQ(m.smoothness_mean, (kPi / 2) / 2.5);
  EXPECT_DOUBLE_EQ(m.smoothness_max, (kPi / 2) / 2.5);
  EXPECT_DOUBLE_EQ(m.min_clearance, 1.5);  // (3.5, y) to the square [5,6]x[2,3]; walls 1.5 too
  // 5 + 3 * 0.1 + (pi/2) / pi.
  EXPECT_DOUBLE_EQ(m.motion_time_s, 5.0 + 0.3 + 0.5);
  MotionTimeParams slow;
  slow.line_speed_mps = 0.5;
  slow.node_time_s = 0.0;
  slow.turn_speed_radps = kPi / 4;
  slow.include_plan_time = true;
  EXPECT_DOUBLE_EQ(compute_path_metrics(g, path, slow, 250'000'000).motion_time_s,
                   10.0 + 2.0 + 0.25);
}

TEST(Metrics, ZigZag) {
  const Grid g(6, 4);
  // Three diagonal segments of length sqrt(2), turning +-90 degrees twice.
  const std::vector<Point> path = {{0.5, 0.5}, {1.5, 1.5}, {2.5, 0.5}, {3.5, 1.5}};
  const PathMetrics m = compute_path_metrics(g, path);
  EXPECT_DOUBLE_EQ(m.path_length, 3 * std::sqrt(2.0));
  EXPECT_EQ(m.turns, 2);
  EXPECT_DOUBLE_EQ(m.turn_angle_rad, kPi);
  EXPECT_DOUBLE_EQ(m.smoothness_mean, (kPi / 2) / std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(m.smoothness_max, (kPi / 2) / std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(m.min_clearance, 0.5);
}

TEST(Metrics, DuplicatesCollinearPointsReversalAndWrap) {
  const Grid g(8, 8);
  // Duplicates carry no heading: one 90-degree turn, 5 nodes, no NaN.
  const std::vector<Point> dup = {{0.5, 0.5}, {0.5, 0.5}, {2.5, 0.5}, {2.5, 0.5}, {2.5, 2.5}};
  PathMetrics m = compute_path_metrics(g, dup);
  EXPECT_EQ(m.path_nodes, 5);
  EXPECT_DOUBLE_EQ(m.path_length, 4.0);
  EXPECT_EQ(m.turns, 1);
  EXPECT_DOUBLE_EQ(m.turn_angle_rad, kPi / 2);
  EXPECT_DOUBLE_EQ(m.smoothness_max, (kPi / 2) / 2.0);
  // A collinear waypoint is a vertex with zero curvature: it halves the mean, not the max.
  const std::vector<Point> collinear = {{0.5, 0.5}, {1.5, 0.5}, {2.5, 0.5}, {2.5, 1.5}};
  m = compute_path_metrics(g, collinear);
  EXPECT_EQ(m.turns, 1);
  EXPECT_DOUBLE_EQ(m.smoothness_max, kPi / 2);
  EXPECT_DOUBLE_EQ(m.smoothness_mean, kPi / 4);
  // A full reversal turns by pi (wrapped to +pi).
  m = compute_path_metrics(g, std::vector<Point>{{0.5, 0.5}, {2.5, 0.5}, {1.5, 0.5}});
  EXPECT_DOUBLE_EQ(m.turn_angle_rad, kPi);
  // Headings either side of the -x axis (near -pi and +pi): the turn is 2 atan(1/2), not
  // 2 pi minus it.
  m = compute_path_metrics(g, std::vector<Point>{{5.5, 5.5}, {3.5, 4.5}, {1.5, 5.5}});
  EXPECT_NEAR(m.turn_angle_rad, 2 * std::atan(0.5), 1e-15);
  // A tiny kink below the 1e-9 rad threshold is no turn (but still adds its angle).
  m = compute_path_metrics(g, std::vector<Point>{{0.5, 0.5}, {3.5, 0.5}, {6.5, 0.5 + 1e-12}});
  EXPECT_EQ(m.turns, 0);
  // A one-point path.
  m = compute_path_metrics(g, std::vector<Point>{{3.5, 3.5}});
  EXPECT_EQ(m.path_nodes, 1);
  EXPECT_EQ(m.path_length, 0.0);
  EXPECT_DOUBLE_EQ(m.min_clearance, 3.5);
}

TEST(Metrics, NamesInFixedOrder) {
  const PathMetrics m =
      compute_path_metrics(Grid(4, 4), std::vector<Point>{{0.5, 0.5}, {2.5, 0.5}});
  const auto values = metric_values(m);
  const std::string_view expected[] = {
      "path_length",     "path_length_m",  "path_nodes",    "turns",           "turn_angle_rad",
      "smoothness_mean", "smoothness_max", "min_clearance", "min_clearance_m", "motion_time_s"};
  ASSERT_EQ(values.size(), std::size(expected));
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(values[i].first, expected[i]);
  EXPECT_EQ(values[0].second, 2.0);
  EXPECT_EQ(values[2].second, 2.0);
}

// Brute force: the distance between a segment and a closed square is 0 if they meet, else the
// least of the endpoint-to-square and corner-to-segment distances (disjoint convex sets are
// closest at a vertex of one of them).
double point_segment(Point p, Point a, Point b) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

double point_square(Point p, int cx, int cy) {
  const double dx = std::max({cx - p.x, 0.0, p.x - (cx + 1)});
  const double dy = std::max({cy - p.y, 0.0, p.y - (cy + 1)});
  return std::hypot(dx, dy);
}

bool segment_meets_square(Point a, Point b, int cx, int cy) {
  double t0 = 0.0;
  double t1 = 1.0;
  const double d[2] = {b.x - a.x, b.y - a.y};
  const double p[2] = {a.x, a.y};
  const double lo[2] = {double(cx), double(cy)};
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0) {
      if (p[k] < lo[k] || p[k] > lo[k] + 1) return false;
      continue;
    }
    double ta = (lo[k] - p[k]) / d[k];
    double tb = (lo[k] + 1 - p[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 <= t1;
}

double brute_clearance(const Grid& g, const std::vector<Point>& path) {
  double best = std::numeric_limits<double>::infinity();
  for (int cy = -1; cy <= g.height(); ++cy)
    for (int cx = -1; cx <= g.width(); ++cx) {
      if (!g.blocked(cx, cy)) continue;
      for (std::size_t i = 0; i + 1 < path.size(); ++i) {
        const Point a = path[i];
        const Point b = path[i + 1];
        if (segment_meets_square(a, b, cx, cy)) return 0.0;
        best = std::min({best, point_square(a, cx, cy), point_square(b, cx, cy)});
        for (int k = 0; k < 4; ++k)
          best = std::min(best, point_segment({double(cx + k % 2), double(cy + k / 2)}, a, b));
      }
    }
  return best;
}

TEST(Metrics, ClearanceMatchesBruteForce) {
  std::mt19937_64 rng(99);
  for (int map = 0; map < 30; ++map) {
    Grid g(14, 11);
    for (int y = 0; y < g.height(); ++y)
      for (int x = 0; x < g.width(); ++x)
        if (rng() % 100 < 12) g.set_blocked(x, y, true);
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<Point> path;
      const int n = 2 + static_cast<int>(rng() % 4);
      for (int i = 0; i < n; ++i)
        path.push_back(
            {static_cast<double>(rng() % 1400) / 100.0, static_cast<double>(rng() % 1100) / 100.0});
      const PathMetrics m = compute_path_metrics(g, path);
      EXPECT_NEAR(m.min_clearance, brute_clearance(g, path), 1e-9) << "map " << map;
    }
  }
}

}  // namespace
}  // namespace agv
