// The distance transform against brute force: squared centre distances and the feature
// transform on random grids, and the exact clearance of points and segments against a search
// over every obstacle square.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/distance_transform.h"
#include "core/grid.h"
#include "core/rng.h"
#include "tests/core/random_grid.h"

namespace agv {
namespace {

using test::random_grid;

// Every obstacle cell of the padded grid (border included).
std::vector<Cell> obstacles(const Grid& g) {
  std::vector<Cell> out;
  for (int y = -1; y <= g.height(); ++y) {
    for (int x = -1; x <= g.width(); ++x) {
      if (g.blocked(x, y)) out.push_back({x, y});
    }
  }
  return out;
}

double point_square(Point p, Cell o) {
  const double dx = std::max({o.x - p.x, 0.0, p.x - (o.x + 1.0)});
  const double dy = std::max({o.y - p.y, 0.0, p.y - (o.y + 1.0)});
  return std::sqrt(dx * dx + dy * dy);
}

double brute_clearance(const std::vector<Cell>& obs, Point p) {
  double best = std::numeric_limits<double>::infinity();
  for (Cell o : obs) best = std::min(best, point_square(p, o));
  return best;
}

Point lerp(Point a, Point b, double t) { return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; }

// The distance from a + t (b - a) to a square is convex in t: golden-section search finds its
// minimum to rounding precision, independently of the library's closed form.
double brute_segment_square(Point a, Point b, Cell o) {
  const double phi = (std::sqrt(5.0) - 1.0) / 2.0;
  double lo = 0.0;
  double hi = 1.0;
  for (int i = 0; i < 80; ++i) {
    const double m1 = hi - phi * (hi - lo);
    const double m2 = lo + phi * (hi - lo);
    if (point_square(lerp(a, b, m1), o) <= point_square(lerp(a, b, m2), o)) {
      hi = m2;
    } else {
      lo = m1;
    }
  }
  return std::min(
      {point_square(lerp(a, b, 0.5 * (lo + hi)), o), point_square(a, o), point_square(b, o)});
}

double brute_segment(const std::vector<Cell>& obs, Point a, Point b) {
  double best = std::numeric_limits<double>::infinity();
  for (Cell o : obs) best = std::min(best, brute_segment_square(a, b, o));
  return best;
}

// A random point in [0, W] x [0, H], often on cell boundaries or centres.
Point random_point(const Grid& g, Rng& rng) {
  auto coord = [&](int size) {
    switch (rng.below(4)) {
      case 0:
        return static_cast<double>(rng.between(0, size));
      case 1:
        return rng.between(0, size - 1) + 0.5;
      default:
        return rng.uniform(0.0, size);
    }
  };
  return {coord(g.width()), coord(g.height())};
}

TEST(DistanceTransform, SquaredDistancesAndFeaturesEqualBruteForce) {
  Rng rng(1, 5);
  for (int trial = 0; trial < 60; ++trial) {
    const int w = rng.between(1, 30);
    const int h = rng.between(1, 30);
    const Grid g = random_grid(w, h, rng.uniform(0.0, 0.5), rng);
    const DistanceTransform dt(g);
    const std::vector<Cell> obs = obstacles(g);
    for (int y = -1; y <= h; ++y) {
      for (int x = -1; x <= w; ++x) {
        std::int64_t best = std::numeric_limits<std::int64_t>::max();
        for (Cell o : obs) {
          const std::int64_t dx = o.x - x;
          const std::int64_t dy = o.y - y;
          best = std::min(best, dx * dx + dy * dy);
        }
        ASSERT_EQ(dt.squared_centre_distance(x, y), best) << w << "x" << h << " " << x << "," << y;
        ASSERT_DOUBLE_EQ(dt.centre_distance(x, y), std::sqrt(static_cast<double>(best)));
        const Cell f = g.cell_of(dt.nearest_obstacle(x, y));
        ASSERT_TRUE(g.blocked(f));
        const std::int64_t fx = f.x - x;
        const std::int64_t fy = f.y - y;
        ASSERT_EQ(fx * fx + fy * fy, best);
      }
    }
  }
}

TEST(DistanceTransform, EmptyGridDistancesAreToTheBorder) {
  const Grid g(300, 7);
  const DistanceTransform& dt = g.distance_transform();
  EXPECT_EQ(dt.squared_centre_distance(150, 3), 16);
  EXPECT_EQ(dt.squared_centre_distance(0, 3), 1);
  EXPECT_EQ(dt.squared_centre_distance(-1, 3), 0);
  EXPECT_DOUBLE_EQ(dt.clearance({150.0, 3.5}), 3.5);
}

TEST(DistanceTransform, PointClearanceEqualsBruteForce) {
  Rng rng(2, 6);
  for (int trial = 0; trial < 60; ++trial) {
    const Grid g = random_grid(rng.between(1, 25), rng.between(1, 25), rng.uniform(0.0, 0.4), rng);
    const DistanceTransform dt(g);
    const std::vector<Cell> obs = obstacles(g);
    for (int k = 0; k < 200; ++k) {
      const Point p = random_point(g, rng);
      ASSERT_NEAR(dt.clearance(p), brute_clearance(obs, p), 1e-12) << p.x << "," << p.y;
    }
  }
}

TEST(DistanceTransform, ClearanceIsZeroOnObstaclesAndOutside) {
  Grid g(10, 10);
  g.set_blocked(4, 4, true);
  const DistanceTransform dt(g);
  EXPECT_EQ(dt.clearance({4.5, 4.5}), 0.0);
  EXPECT_EQ(dt.clearance({4.0, 5.0}), 0.0);  // on the square's corner
  EXPECT_EQ(dt.clearance({0.0, 3.0}), 0.0);  // on the border wall
  EXPECT_EQ(dt.clearance({-0.5, 3.0}), 0.0);
  EXPECT_EQ(dt.clearance({11.0, 3.0}), 0.0);
  EXPECT_EQ(dt.clearance({std::nan(""), 3.0}), 0.0);
  EXPECT_DOUBLE_EQ(dt.clearance({0.5, 0.5}), 0.5);
  EXPECT_DOUBLE_EQ(dt.clearance({3.0, 3.0}), std::sqrt(2.0));  // to the corner (4, 4)
  EXPECT_DOUBLE_EQ(dt.clearance({4.5, 6.5}), 1.5);             // straight below the square
}

TEST(DistanceTransform, SegmentClearanceEqualsBruteForce) {
  Rng rng(3, 7);
  for (int trial = 0; trial < 40; ++trial) {
    const Grid g = random_grid(rng.between(1, 22), rng.between(1, 22), rng.uniform(0.0, 0.3), rng);
    const DistanceTransform dt(g);
    const std::vector<Cell> obs = obstacles(g);
    for (int k = 0; k < 40; ++k) {
      const Point a = random_point(g, rng);
      const Point b = random_point(g, rng);
      const double exact = dt.segment_clearance(a, b);
      ASSERT_NEAR(exact, brute_segment(obs, a, b), 1e-9)
          << "(" << a.x << "," << a.y << ")-(" << b.x << "," << b.y << ")";
      // Dense sampling can only over-estimate the minimum, and by at most half a step
      // (clearance is 1-Lipschitz).
      const double length = std::hypot(b.x - a.x, b.y - a.y);
      const int samples = 400;
      double sampled = std::numeric_limits<double>::infinity();
      for (int i = 0; i <= samples; ++i) {
        sampled = std::min(sampled, brute_clearance(obs, lerp(a, b, i / double(samples))));
      }
      ASSERT_GE(sampled, exact - 1e-12);
      ASSERT_LE(sampled, exact + 0.5 * length / samples + 1e-12);
      // The minimum over the segment is at most the clearance of either end.
      ASSERT_LE(exact, dt.clearance(a) + 1e-12);
      ASSERT_LE(exact, dt.clearance(b) + 1e-12);
    }
  }
}

// With a bound: the same double below it, at least the bound otherwise, so a polyline's running
// minimum is bit for bit the unbounded one (engine/judge/metrics.cpp min_clearance).
TEST(DistanceTransform, BoundedSegmentClearanceIsExactBelowTheBound) {
  Rng rng(8, 3);
  for (int trial = 0; trial < 40; ++trial) {
    const Grid g = random_grid(rng.between(1, 30), rng.between(1, 30), rng.uniform(0.0, 0.4), rng);
    const DistanceTransform dt(g);
    double running = std::numeric_limits<double>::infinity();
    double bounded = running;
    Point prev = random_point(g, rng);
    for (int k = 0; k < 60; ++k) {
      const Point next = random_point(g, rng);
      const double exact = dt.segment_clearance(prev, next);
      const double below = rng.uniform(0.0, 3.0);
      const double got = dt.segment_clearance(prev, next, below);
      if (exact < below) {
        ASSERT_EQ(got, exact);
      } else {
        ASSERT_GE(got, below);
      }
      running = std::min(running, exact);
      bounded = std::min(bounded, dt.segment_clearance(prev, next, bounded));
      ASSERT_EQ(bounded, running);
      prev = next;
    }
  }
}

// Short steps under a small bound (a sampled curve's segments once its least clearance is
// tight) take the scan of the bound's box instead of the transform's candidates: the same
// doubles as the unbounded search, down to the bit.
TEST(DistanceTransform, ShortSegmentsUnderASmallBoundAreExact) {
  Rng rng(5, 11);
  for (int trial = 0; trial < 60; ++trial) {
    const Grid g = random_grid(rng.between(2, 30), rng.between(2, 30), rng.uniform(0.0, 0.5), rng);
    const DistanceTransform dt(g);
    const std::vector<Cell> obs = obstacles(g);
    Point prev = random_point(g, rng);
    for (int k = 0; k < 200; ++k) {
      const double step = rng.uniform(0.0, 1.5);
      const double angle = rng.uniform(0.0, 6.283185307179586);
      Point next{prev.x + step * std::cos(angle), prev.y + step * std::sin(angle)};
      next.x = std::clamp(next.x, 0.0, 1.0 * g.width());
      next.y = std::clamp(next.y, 0.0, 1.0 * g.height());
      if (k % 7 == 0) next = Point{std::floor(next.x), next.y};  // on a cell edge
      const double exact = dt.segment_clearance(prev, next);
      ASSERT_NEAR(exact, brute_segment(obs, prev, next), 1e-9);
      const double below = k % 5 == 0 ? exact : rng.uniform(0.0, 3.9);
      const double got = dt.segment_clearance(prev, next, below);
      if (exact < below) {
        ASSERT_EQ(got, exact) << trial << " " << k;
      } else {
        ASSERT_GE(got, below) << trial << " " << k;
      }
      prev = next;
    }
  }
}

TEST(DistanceTransform, SegmentClearanceExactCases) {
  Grid g(12, 10);
  g.set_blocked(6, 2, true);  // square [6, 7] x [2, 3]
  const DistanceTransform dt(g);
  // Horizontal at y = 5: the square is 2 above, the left wall 2 away from x = 2.
  EXPECT_DOUBLE_EQ(dt.segment_clearance({2.0, 5.0}, {9.0, 5.0}), 2.0);
  // Horizontal at y = 4.5 from x = 3: 1.5 below the square, 3 from the left wall.
  EXPECT_DOUBLE_EQ(dt.segment_clearance({3.0, 4.5}, {8.0, 4.5}), 1.5);
  // Vertical at x = 8.25 from y = 1.5 to 6: 1.5 from the wall above, 1.25 right of the square.
  EXPECT_DOUBLE_EQ(dt.segment_clearance({8.25, 1.5}, {8.25, 6.0}), 1.25);
  // Grazing the square's corner (6, 3) diagonally counts as touching.
  EXPECT_EQ(dt.segment_clearance({5.0, 4.0}, {7.0, 2.0}), 0.0);
  EXPECT_EQ(dt.segment_clearance({5.0, 2.5}, {8.0, 2.5}), 0.0);  // through it
  // A degenerate segment is a point.
  EXPECT_DOUBLE_EQ(dt.segment_clearance({4.5, 6.5}, {4.5, 6.5}), dt.clearance({4.5, 6.5}));
  // Diagonals: starting on the square's corner (7, 2), and starting 0.5 right of its edge
  // heading away (the start is the closest point).
  EXPECT_EQ(dt.segment_clearance({7.0, 2.0}, {9.0, 4.0}), 0.0);
  EXPECT_DOUBLE_EQ(dt.segment_clearance({7.5, 2.5}, {9.0, 4.0}), 0.5);
  // Along the line x + y = 11, passing the square's corner (7, 3) at 1 / sqrt(2).
  EXPECT_NEAR(dt.segment_clearance({6.5, 4.5}, {9.5, 1.5}), 1.0 / std::sqrt(2.0), 1e-12);
  // Outside the grid: inside the wall.
  EXPECT_EQ(dt.segment_clearance({-1.0, 5.0}, {5.0, 5.0}), 0.0);
}

TEST(DistanceTransform, LongSegmentsInOpenSpace) {
  const Grid g(400, 300);
  const DistanceTransform& dt = g.distance_transform();
  EXPECT_DOUBLE_EQ(dt.segment_clearance({100.0, 150.0}, {300.0, 150.0}), 100.0);
  EXPECT_DOUBLE_EQ(dt.segment_clearance({50.0, 50.0}, {350.0, 250.0}), 50.0);
  EXPECT_DOUBLE_EQ(dt.clearance({200.0, 150.0}), 150.0);
}

}  // namespace
}  // namespace agv
