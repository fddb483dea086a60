// Path metrics on hand-computed paths, smoothness_max against every window scanned, the same values
// for a curve whatever its sampling step, and the clearance metric against brute force over every
// obstacle cell.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string_view>
#include <vector>

#include "algos/postprocess/path_curves.h"
#include "engine/judge/metrics.h"
#include "engine/judge/statistics.h"

namespace agv {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Metrics, StraightPath) {
  const Grid g(10, 10, 2.0);  // 2 m cells
  const std::vector<Point> path = {{0.5, 0.5}, {4.5, 0.5}};
  const PathMetrics m = compute_path_metrics(g, path);
  EXPECT_DOUBLE_EQ(m.path_length, 4.0);
  EXPECT_DOUBLE_EQ(m.path_length_m, 8.0);
  EXPECT_EQ(m.waypoints, 2);
  EXPECT_EQ(m.turns, 0);
  EXPECT_EQ(m.turn_angle_rad, 0.0);
  EXPECT_EQ(m.max_turn_rad, 0.0);
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
  EXPECT_EQ(m.waypoints, 3);
  EXPECT_EQ(m.turns, 1);
  EXPECT_DOUBLE_EQ(m.turn_angle_rad, kPi / 2);
  EXPECT_DOUBLE_EQ(m.max_turn_rad, kPi / 2);
  // pi/2 over the 5 cells of path; the corner alone in a 1-cell window.
  EXPECT_DOUBLE_EQ(m.smoothness_mean, (kPi / 2) / 5.0);
  EXPECT_DOUBLE_EQ(m.smoothness_max, kPi / 2);
  EXPECT_DOUBLE_EQ(m.min_clearance, 1.5);  // (3.5, y) to the square [5,6]x[2,3]; walls 1.5 too
  // 5 + 3 * 0.1 + (pi/2) / pi.
  EXPECT_DOUBLE_EQ(m.motion_time_s, 5.0 + 0.3 + 0.5);
  MotionTimeParams slow;
  slow.line_speed_mps = 0.5;
  slow.node_time_s = 0.0;
  slow.turn_speed_radps = kPi / 4;
  EXPECT_DOUBLE_EQ(compute_path_metrics(g, path, slow).motion_time_s, 10.0 + 2.0);
}

TEST(Metrics, ZigZag) {
  const Grid g(6, 4);
  // Three diagonal segments of length sqrt(2), turning +-90 degrees twice.
  const std::vector<Point> path = {{0.5, 0.5}, {1.5, 1.5}, {2.5, 0.5}, {3.5, 1.5}};
  const PathMetrics m = compute_path_metrics(g, path);
  EXPECT_DOUBLE_EQ(m.path_length, 3 * std::sqrt(2.0));
  // Opposite signs never merge: two turns, although only sqrt(2) apart.
  EXPECT_EQ(m.turns, 2);
  EXPECT_DOUBLE_EQ(m.turn_angle_rad, kPi);
  EXPECT_DOUBLE_EQ(m.max_turn_rad, kPi / 2);
  EXPECT_DOUBLE_EQ(m.smoothness_mean, kPi / (3 * std::sqrt(2.0)));
  EXPECT_DOUBLE_EQ(m.smoothness_max, kPi / 2);  // the corners are sqrt(2) apart
  EXPECT_DOUBLE_EQ(m.min_clearance, 0.5);
}

TEST(Metrics, DuplicatesCollinearPointsReversalAndWrap) {
  const Grid g(8, 8);
  // Duplicates carry no heading: one 90-degree turn, 5 waypoints, no NaN.
  const std::vector<Point> dup = {{0.5, 0.5}, {0.5, 0.5}, {2.5, 0.5}, {2.5, 0.5}, {2.5, 2.5}};
  PathMetrics m = compute_path_metrics(g, dup);
  EXPECT_EQ(m.waypoints, 5);
  EXPECT_DOUBLE_EQ(m.path_length, 4.0);
  EXPECT_EQ(m.turns, 1);
  EXPECT_DOUBLE_EQ(m.turn_angle_rad, kPi / 2);
  EXPECT_DOUBLE_EQ(m.smoothness_max, kPi / 2);
  // A collinear waypoint changes nothing (the metrics are the geometry's, not the sampling's).
  const std::vector<Point> collinear = {{0.5, 0.5}, {1.5, 0.5}, {2.5, 0.5}, {2.5, 1.5}};
  m = compute_path_metrics(g, collinear);
  EXPECT_EQ(m.turns, 1);
  EXPECT_DOUBLE_EQ(m.smoothness_max, kPi / 2);
  EXPECT_DOUBLE_EQ(m.smoothness_mean, (kPi / 2) / 3.0);
  // A full reversal turns by pi (wrapped to +pi): the broken path max_turn_rad flags.
  m = compute_path_metrics(g, std::vector<Point>{{0.5, 0.5}, {2.5, 0.5}, {1.5, 0.5}});
  EXPECT_DOUBLE_EQ(m.turn_angle_rad, kPi);
  EXPECT_DOUBLE_EQ(m.max_turn_rad, kPi);
  EXPECT_EQ(m.turns, 1);
  // Headings either side of the -x axis (near -pi and +pi): the turn is 2 atan(1/2), not
  // 2 pi minus it.
  m = compute_path_metrics(g, std::vector<Point>{{5.5, 5.5}, {3.5, 4.5}, {1.5, 5.5}});
  EXPECT_NEAR(m.turn_angle_rad, 2 * std::atan(0.5), 1e-15);
  // A kink below kTurnThreshold is no turn (but still adds its angle).
  m = compute_path_metrics(g, std::vector<Point>{{0.5, 0.5}, {3.5, 0.5}, {6.5, 0.6}});
  EXPECT_EQ(m.turns, 0);
  EXPECT_NEAR(m.turn_angle_rad, std::atan(0.1 / 3.0), 1e-15);
  // A one-point path.
  m = compute_path_metrics(g, std::vector<Point>{{3.5, 3.5}});
  EXPECT_EQ(m.waypoints, 1);
  EXPECT_EQ(m.turns, 0);
  EXPECT_EQ(m.smoothness_mean, 0.0);
  EXPECT_EQ(m.smoothness_max, 0.0);
  EXPECT_EQ(m.path_length, 0.0);
  EXPECT_DOUBLE_EQ(m.min_clearance, 3.5);
}

TEST(Metrics, NamesInFixedOrder) {
  const PathMetrics m =
      compute_path_metrics(Grid(4, 4), std::vector<Point>{{0.5, 0.5}, {2.5, 0.5}});
  const auto values = metric_values(m);
  const std::string_view expected[] = {"path_length",     "path_length_m",  "waypoints",
                                       "turns",           "turn_angle_rad", "max_turn_rad",
                                       "smoothness_mean", "smoothness_max", "min_clearance",
                                       "min_clearance_m", "motion_time_s"};
  ASSERT_EQ(values.size(), std::size(expected));
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(values[i].first, expected[i]);
  EXPECT_EQ(values[0].second, 2.0);
  EXPECT_EQ(values[2].second, 2.0);
}

TEST(Metrics, MergedTurns) {
  const Grid g(20, 20);
  // Two 0.03 rad bends of one sign 0.5 cell apart: one merged turn of 0.06 > kTurnThreshold.
  const double a = 0.03;
  std::vector<Point> p = {{0.5, 5.5}, {5.5, 5.5}};
  p.push_back({p[1].x + 0.5 * std::cos(a), p[1].y + 0.5 * std::sin(a)});
  p.push_back({p[2].x + 5 * std::cos(2 * a), p[2].y + 5 * std::sin(2 * a)});
  PathMetrics m = compute_path_metrics(g, p);
  EXPECT_EQ(m.turns, 1);
  EXPECT_NEAR(m.max_turn_rad, 2 * a, 1e-12);
  // The same bends 2 cells apart are two turns, each below the threshold: none counts.
  p[2] = {p[1].x + 2 * std::cos(a), p[1].y + 2 * std::sin(a)};
  p[3] = {p[2].x + 5 * std::cos(2 * a), p[2].y + 5 * std::sin(2 * a)};
  m = compute_path_metrics(g, p);
  EXPECT_EQ(m.turns, 0);
  EXPECT_NEAR(m.max_turn_rad, a, 1e-12);
  EXPECT_NEAR(m.turn_angle_rad, 2 * a, 1e-12);
  // A U-turn around a wall end: two 90-degree corners of one sign 2 cells apart are two turns;
  // a full cell apart, still two (their spreads of kTurnSpread do not touch); half a cell apart,
  // one turn of pi.
  m = compute_path_metrics(g, std::vector<Point>{{2.5, 0.5}, {2.5, 6.5}, {4.5, 6.5}, {4.5, 0.5}});
  EXPECT_EQ(m.turns, 2);
  EXPECT_DOUBLE_EQ(m.max_turn_rad, kPi / 2);
  EXPECT_DOUBLE_EQ(m.smoothness_max, kPi / 2);
  m = compute_path_metrics(g, std::vector<Point>{{2.5, 0.5}, {2.5, 6.5}, {3.5, 6.5}, {3.5, 0.5}});
  EXPECT_EQ(m.turns, 2);
  EXPECT_DOUBLE_EQ(m.max_turn_rad, kPi / 2);
  // Each corner's turn is spread over half a cell: a 1-cell window holds one corner's worth.
  EXPECT_DOUBLE_EQ(m.smoothness_max, kPi / 2);
  // A diagonal move then a straight one: the corners are 1 cell apart, though sqrt(2) + 1 minus
  // sqrt(2) rounds below 1 (an `apart < 1` merge joined them): two turns of 45 degrees.
  m = compute_path_metrics(g, std::vector<Point>{{0.5, 0.5}, {1.5, 1.5}, {2.5, 1.5}, {3.5, 0.5}});
  EXPECT_EQ(m.turns, 2);
  EXPECT_DOUBLE_EQ(m.max_turn_rad, kPi / 4);
  // Half a cell apart, one window holds both.
  m = compute_path_metrics(g, std::vector<Point>{{2.5, 0.5}, {2.5, 6.5}, {3.0, 6.5}, {3.0, 0.5}});
  EXPECT_EQ(m.turns, 1);
  EXPECT_DOUBLE_EQ(m.max_turn_rad, kPi);
  EXPECT_DOUBLE_EQ(m.smoothness_max, kPi);
}

// A 90-degree corner at (10.5, 2.5), and the same corner rounded by a quarter circle of radius
// r, sampled every `step` cells of arc.
std::vector<Point> rounded_corner(double r, double step) {
  std::vector<Point> p = {{2.5, 2.5}};
  const int n = static_cast<int>(std::ceil((kPi / 2) * r / step));
  for (int i = 0; i <= n; ++i) {
    const double t = (kPi / 2) * i / n;  // centre (10.5 - r, 2.5 + r)
    p.push_back({10.5 - r + r * std::sin(t), 2.5 + r - r * std::cos(t)});
  }
  p.push_back({10.5, 12.5});
  return p;
}

TEST(Metrics, SampledCurveScoresLikeItsGeometry) {
  const Grid g(16, 16);
  const std::vector<Point> corner = {{2.5, 2.5}, {10.5, 2.5}, {10.5, 12.5}};
  const PathMetrics sharp = compute_path_metrics(g, corner);
  // (A quarter circle shorter than the 1-cell window, r < 2 / pi, scores pi/2 like the corner.)
  for (double r : {1.0, 2.0, 4.0}) {
    const PathMetrics coarse = compute_path_metrics(g, rounded_corner(r, 0.1));
    const PathMetrics fine = compute_path_metrics(g, rounded_corner(r, 0.02));
    // One turn, like the corner it rounds, of the same angle, while the arc (pi/2) r is within
    // kTurnMaxExtent; a longer arc (r = 2, 4) is that many turns of equal arc (docs/METRICS.md
    // "turns"), the same at either step.
    const int pieces = static_cast<int>(std::ceil((kPi / 2) * r / kTurnMaxExtent));
    for (const PathMetrics* m : {&coarse, &fine}) {
      EXPECT_EQ(m->turns, pieces) << "r " << r;
      EXPECT_NEAR(m->max_turn_rad, kPi / 2 / pieces, 0.05) << "r " << r;  // a sample apart
      EXPECT_NEAR(m->turn_angle_rad, kPi / 2, 1e-9) << "r " << r;
      // The rounded corner is smoother than the sharp one where it matters: its sharpest cell.
      EXPECT_LT(m->smoothness_max, sharp.smoothness_max) << "r " << r;
    }
    // Independent of the sampling step: within a few per cent.
    EXPECT_NEAR(coarse.smoothness_max, fine.smoothness_max, 0.05 * fine.smoothness_max) << r;
    EXPECT_NEAR(coarse.smoothness_mean, fine.smoothness_mean, 0.01 * fine.smoothness_mean) << r;
    // A circle of radius r turns 1/r rad per cell, so a 1-cell window holds min(1/r, pi/2).
    EXPECT_NEAR(fine.smoothness_max, std::min(1.0 / r, kPi / 2), 0.03 * std::min(1.0 / r, kPi / 2))
        << r;
  }
}

// The polygon's edges cut at unit steps, as a grid path's cells are: the B-spline refit's
// control points (docs/PLANNERS.md "Common ground").
std::vector<Point> cells_along(const std::vector<Point>& polygon) {
  std::vector<Point> out = {polygon[0]};
  for (std::size_t i = 1; i < polygon.size(); ++i) {
    const Point a = polygon[i - 1];
    const Point b = polygon[i];
    const int steps = static_cast<int>(std::ceil(std::hypot(b.x - a.x, b.y - a.y) - 1e-9));
    for (int k = 1; k <= steps; ++k)
      out.push_back({a.x + (b.x - a.x) * k / steps, a.y + (b.y - a.y) * k / steps});
  }
  return out;
}

TEST(Metrics, BsplineAgreesWithItsPolyline) {
  // The pipeline's own curve (a clamped cubic B-spline) over a staircase of 90-degree corners
  // of alternating signs, an L, and four same-sign 45-degree corners: as many turns as the
  // polyline, at either sampling step.
  const Grid g(40, 40);
  const std::vector<std::vector<Point>> shapes = {
      {{1.5, 1.5}, {11.5, 1.5}, {11.5, 11.5}, {21.5, 11.5}, {21.5, 21.5}},
      {{1.5, 1.5}, {15.5, 1.5}, {15.5, 15.5}},
      {{1.5, 1.5}, {9.5, 1.5}, {17.5, 9.5}, {17.5, 25.5}, {9.5, 33.5}, {1.5, 33.5}}};
  for (const auto& polygon : shapes) {
    const PathMetrics poly = compute_path_metrics(g, polygon);
    const std::vector<Point> controls = cells_along(polygon);
    const PathMetrics coarse = compute_path_metrics(g, sample_bspline(controls, 0.1));
    const PathMetrics fine = compute_path_metrics(g, sample_bspline(controls, 0.02));
    EXPECT_EQ(coarse.turns, poly.turns);
    EXPECT_EQ(fine.turns, poly.turns);
    EXPECT_LT(coarse.smoothness_max, poly.smoothness_max);
    EXPECT_NEAR(coarse.smoothness_max, fine.smoothness_max, 0.05 * fine.smoothness_max);
    EXPECT_NEAR(coarse.smoothness_mean, fine.smoothness_mean, 0.02 * fine.smoothness_mean);
    EXPECT_NEAR(coarse.turn_angle_rad, fine.turn_angle_rad, 1e-3);
    EXPECT_NEAR(coarse.max_turn_rad, fine.max_turn_rad, 1e-3);
    EXPECT_NEAR(fine.max_turn_rad, poly.max_turn_rad, 0.02);
  }
  // With the corners alone as control points, the spline over the same-sign polygon bends one
  // way all along its length, with no valley between its corners deep enough to cut it: it is
  // cut into pieces of at most kTurnMaxExtent of arc (docs/METRICS.md "turns"), the same at
  // either sampling step, none turning the polygon's whole 180 degrees.
  const PathMetrics sparse = compute_path_metrics(g, sample_bspline(shapes[2], 0.1));
  const PathMetrics sparse_fine = compute_path_metrics(g, sample_bspline(shapes[2], 0.02));
  EXPECT_GE(sparse.turns, 2);
  EXPECT_EQ(sparse.turns, sparse_fine.turns);
  EXPECT_LT(sparse.max_turn_rad, kPi / 2);
  EXPECT_NEAR(sparse.turn_angle_rad, kPi, 1e-6);
}

// Grid paths as a search returns them (one point per cell), for the B-spline over every cell.
std::vector<Point> grid_moves(Point start, const std::vector<std::array<int, 3>>& moves) {
  std::vector<Point> out = {start};
  for (const auto& [dx, dy, n] : moves)
    for (int k = 0; k < n; ++k) out.push_back({out.back().x + dx, out.back().y + dy});
  return out;
}

TEST(Metrics, UTurnsAreTwoTurns) {
  // Up a 1-cell corridor and down the next: around a 1-cell wall end (corners 2 cells apart,
  // the maze U-turn under no_corner_cut), between two adjacent columns (corners exactly 1 cell
  // apart), and around the wall end with diagonal moves (45, 90, 45 degrees). Neither the
  // polyline nor the B-spline over its cells, at either step, is one turn of 180 degrees.
  const Grid g(20, 20);
  const std::vector<std::vector<std::array<int, 3>>> uturns = {
      {{0, -1, 8}, {1, 0, 2}, {0, 1, 8}},
      {{0, -1, 8}, {1, 0, 1}, {0, 1, 8}},
      {{0, -1, 8}, {1, -1, 1}, {1, 1, 1}, {0, 1, 8}}};
  for (const auto& moves : uturns) {
    const std::vector<Point> cells = grid_moves({2.5, 12.5}, moves);
    const PathMetrics poly = compute_path_metrics(g, cells);
    EXPECT_EQ(poly.turns, static_cast<std::int64_t>(moves.size()) - 1);
    EXPECT_LE(poly.max_turn_rad, kPi / 2 + 1e-12);
    for (const double step : {0.1, 0.02}) {
      const PathMetrics curve = compute_path_metrics(g, sample_bspline(cells, step));
      EXPECT_GE(curve.turns, 2) << moves.size() << " step " << step;
      EXPECT_LT(curve.max_turn_rad, 3.0) << moves.size() << " step " << step;
      EXPECT_NEAR(curve.turn_angle_rad, kPi, 1e-6);
    }
  }
  // The two 90-degree corners half a cell apart are a hairpin: one turn of pi, flagged.
  const PathMetrics hairpin =
      compute_path_metrics(g, std::vector<Point>{{2.5, 12.5}, {2.5, 4.5}, {2.9, 4.5}, {2.9, 12.5}});
  EXPECT_EQ(hairpin.turns, 1);
  EXPECT_DOUBLE_EQ(hairpin.max_turn_rad, kPi);
  // One grid corner of every kind (90 between axes, 90 between diagonals, 45, 135), rounded by
  // the B-spline over its cells: one turn of the corner's angle, at either step.
  const std::vector<std::vector<std::array<int, 3>>> corners = {{{1, 0, 8}, {0, 1, 8}},
                                                                {{1, 1, 6}, {1, -1, 6}},
                                                                {{1, 0, 8}, {1, 1, 6}},
                                                                {{1, 0, 8}, {-1, 1, 6}}};
  for (const auto& moves : corners) {
    const std::vector<Point> cells = grid_moves({4.5, 8.5}, moves);
    const PathMetrics poly = compute_path_metrics(g, cells);
    for (const double step : {0.1, 0.02}) {
      const PathMetrics curve = compute_path_metrics(g, sample_bspline(cells, step));
      EXPECT_EQ(curve.turns, 1) << moves[1][0] << moves[1][1] << " step " << step;
      EXPECT_NEAR(curve.max_turn_rad, poly.max_turn_rad, 1e-3);
    }
  }
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

// docs/METRICS.md "smoothness_max" the plain way: every window starting at a turn box's start or
// ending at its end, each summed over all boxes in order. The metric prunes windows by a bound;
// the value must be this one to the bit.
double every_window_smoothness(const std::vector<Point>& path) {
  struct Box {
    double lo, hi, turn;
  };
  std::vector<Box> boxes;
  CompensatedSum length;
  double previous_heading = 0.0;
  double previous_length = 0.0;
  bool have_previous = false;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double dx = path[i].x - path[i - 1].x;
    const double dy = path[i].y - path[i - 1].y;
    const double l = std::hypot(dx, dy);
    if (l == 0.0) continue;
    const double heading = std::atan2(dy, dx);
    if (have_previous) {
      double turn = heading - previous_heading;
      if (turn > kPi) turn -= 2.0 * kPi;
      if (turn <= -kPi) turn += 2.0 * kPi;
      const double at = length.value();
      if (std::abs(turn) > 0.0)
        boxes.push_back({at - std::min(kTurnSpread, previous_length / 2.0),
                         at + std::min(kTurnSpread, l / 2.0), std::abs(turn)});
    }
    length.add(l);
    have_previous = true;
    previous_heading = heading;
    previous_length = l;
  }
  const auto integral = [&](double from) {
    const double to = from + kSmoothnessWindow;
    double sum = 0.0;
    for (const Box& b : boxes) {
      if (b.hi <= from) continue;
      if (b.lo >= to) break;
      const double overlap = std::min(b.hi, to) - std::max(b.lo, from);
      if (overlap > 0.0) sum += b.turn * std::min(1.0, overlap / (b.hi - b.lo));
    }
    return sum;
  };
  double best = 0.0;
  for (const Box& b : boxes) best = std::max(best, integral(b.lo));
  for (const Box& b : boxes) best = std::max(best, integral(b.hi - kSmoothnessWindow));
  return best / kSmoothnessWindow;
}

TEST(Metrics, SmoothnessMaxIsTheLargestOfEveryWindow) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Grid g(64, 64);
  for (int trial = 0; trial < 300; ++trial) {
    // Wiggles of random step, curvature and length, a kink now and then, some repeated points.
    std::vector<Point> path = {{32.0, 32.0}};
    double heading = unit(rng) * 2.0 * kPi;
    const double step = 0.02 + unit(rng) * (trial % 3 == 0 ? 2.0 : 0.3);
    const double curvature = (unit(rng) - 0.5) * 4.0;
    const int points = 2 + static_cast<int>(unit(rng) * 400.0);
    for (int i = 1; i < points; ++i) {
      heading += step * curvature * std::sin(0.05 * i) + (unit(rng) < 0.03 ? 1.5 : 0.0);
      const Point& p = path.back();
      path.push_back(unit(rng) < 0.02
                         ? p
                         : Point{p.x + step * std::cos(heading), p.y + step * std::sin(heading)});
    }
    const PathMetrics m = compute_path_metrics(g, path);
    ASSERT_EQ(m.smoothness_max, every_window_smoothness(path)) << "trial " << trial;
  }
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
