// The shared line-of-sight test: hand cases for every corner rule, the equivalence with grid
// move legality, and thousands of random segments against an independent exact reference
// (Liang-Barsky clipping in 128-bit rational arithmetic, cell by cell).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "core/corner_rule.h"
#include "core/grid.h"
#include "core/line_of_sight.h"

namespace agv {
namespace {

constexpr CornerRule kRules[] = {CornerRule::allow, CornerRule::no_squeeze,
                                 CornerRule::no_corner_cut};

Grid grid_with(int w, int h, std::initializer_list<Cell> obstacles) {
  Grid g(w, h);
  for (Cell c : obstacles) g.set_blocked(c, true);
  return g;
}

bool free_under(const Grid& g, Point a, Point b, CornerRule rule) {
  return segment_free(g, a, b, SightRule::cells(rule));
}

// ---------------------------------------------------------------------------------------------
// Hand cases.

TEST(LineOfSight, EmptyGridStraightAndDiagonal) {
  const Grid g(6, 5);
  for (CornerRule rule : kRules) {
    EXPECT_TRUE(free_under(g, {0.5, 0.5}, {5.5, 0.5}, rule));
    EXPECT_TRUE(free_under(g, {0.5, 0.5}, {4.5, 4.5}, rule));
    EXPECT_TRUE(free_under(g, {5.5, 0.5}, {0.5, 4.5}, rule));
    EXPECT_TRUE(free_under(g, {2.5, 2.5}, {2.5, 2.5}, rule));  // a point
  }
}

TEST(LineOfSight, CornerGrazingUnderEachRule) {
  // Diagonal move (1,1) -> (2,2) through vertex (2,2); side cells (2,1) and (1,2).
  const Point a{1.5, 1.5};
  const Point b{2.5, 2.5};
  const Grid one = grid_with(5, 5, {{2, 1}});
  EXPECT_TRUE(free_under(one, a, b, CornerRule::allow));
  EXPECT_TRUE(free_under(one, a, b, CornerRule::no_squeeze));
  EXPECT_FALSE(free_under(one, a, b, CornerRule::no_corner_cut));
  const SightHit hit = check_segment(one, a, b, SightRule::cells());
  EXPECT_EQ(hit.kind, SightHit::Kind::corner);
  EXPECT_EQ(hit.cell, (Cell{2, 1}));

  const Grid both = grid_with(5, 5, {{2, 1}, {1, 2}});
  EXPECT_TRUE(free_under(both, a, b, CornerRule::allow));
  EXPECT_FALSE(free_under(both, a, b, CornerRule::no_squeeze));
  EXPECT_FALSE(free_under(both, a, b, CornerRule::no_corner_cut));
  // Reversed direction, same verdicts.
  EXPECT_TRUE(free_under(both, b, a, CornerRule::allow));
  EXPECT_FALSE(free_under(both, b, a, CornerRule::no_squeeze));

  // The other diagonal: (2,1) -> (1,2) through vertex (2,2); sides (1,1) and (2,2).
  const Grid anti = grid_with(5, 5, {{1, 1}});
  EXPECT_TRUE(free_under(anti, {2.5, 1.5}, {1.5, 2.5}, CornerRule::no_squeeze));
  EXPECT_FALSE(free_under(anti, {2.5, 1.5}, {1.5, 2.5}, CornerRule::no_corner_cut));
}

TEST(LineOfSight, LongShallowSegmentThroughTwoVertices) {
  // (0.5,0.5) -> (6.5,2.5), slope 1/3: y(2) = 1 and y(5) = 2, so it passes vertex (2,1) (from
  // cell (1,0) to (2,1), sides (2,0) and (1,1)) and vertex (5,2) (from (4,1) to (5,2), sides
  // (5,1) and (4,2)); everywhere else it crosses edge interiors.
  const Point a{0.5, 0.5};
  const Point b{6.5, 2.5};
  const Grid side = grid_with(8, 4, {{1, 1}});
  EXPECT_TRUE(free_under(side, a, b, CornerRule::allow));
  EXPECT_TRUE(free_under(side, a, b, CornerRule::no_squeeze));
  EXPECT_FALSE(free_under(side, a, b, CornerRule::no_corner_cut));
  const Grid pair = grid_with(8, 4, {{1, 1}, {2, 0}});
  EXPECT_TRUE(free_under(pair, a, b, CornerRule::allow));
  EXPECT_FALSE(free_under(pair, a, b, CornerRule::no_squeeze));
  // One side cell at each vertex: no squeeze anywhere.
  const Grid spread = grid_with(8, 4, {{1, 1}, {4, 2}});
  EXPECT_TRUE(free_under(spread, a, b, CornerRule::no_squeeze));
  EXPECT_FALSE(free_under(spread, a, b, CornerRule::no_corner_cut));
  // Cells it crosses, then cells it misses.
  for (Cell c :
       {Cell{0, 0}, Cell{1, 0}, Cell{2, 1}, Cell{3, 1}, Cell{4, 1}, Cell{5, 2}, Cell{6, 2}}) {
    const Grid g = grid_with(8, 4, {c});
    for (CornerRule rule : kRules) EXPECT_FALSE(free_under(g, a, b, rule)) << c.x << "," << c.y;
  }
  for (Cell c : {Cell{0, 1}, Cell{3, 0}, Cell{3, 2}, Cell{6, 1}, Cell{7, 2}}) {
    const Grid g = grid_with(8, 4, {c});
    for (CornerRule rule : kRules) EXPECT_TRUE(free_under(g, a, b, rule)) << c.x << "," << c.y;
  }
}

TEST(LineOfSight, SteepSegmentThroughVertex) {
  // (1.5,0.5) -> (2.5,3.5): at y = 2, x = 2: vertex (2,2), from (1,1) to (2,2); sides (2,1), (1,2).
  const Point a{1.5, 0.5};
  const Point b{2.5, 3.5};
  const Grid g = grid_with(5, 5, {{1, 2}});
  EXPECT_TRUE(free_under(g, a, b, CornerRule::allow));
  EXPECT_TRUE(free_under(g, a, b, CornerRule::no_squeeze));
  EXPECT_FALSE(free_under(g, a, b, CornerRule::no_corner_cut));
  EXPECT_FALSE(free_under(grid_with(5, 5, {{1, 1}}), a, b, CornerRule::allow));
}

TEST(LineOfSight, AlongAnEdgeTouchesBothSides) {
  // Along y = 1 from x = 1 to x = 4: rows 0 and 1, columns 0..4 (the endpoints on the line
  // x = 1 and x = 4 touch columns 0 and 4 too).
  const Point a{1.0, 1.0};
  const Point b{4.0, 1.0};
  for (CornerRule rule : kRules) {
    EXPECT_FALSE(free_under(grid_with(6, 4, {{2, 0}}), a, b, rule));
    EXPECT_FALSE(free_under(grid_with(6, 4, {{2, 1}}), a, b, rule));
    EXPECT_FALSE(free_under(grid_with(6, 4, {{0, 1}}), a, b, rule));
    EXPECT_FALSE(free_under(grid_with(6, 4, {{4, 0}}), a, b, rule));
    EXPECT_TRUE(free_under(grid_with(6, 4, {{2, 2}}), a, b, rule));
    EXPECT_TRUE(free_under(grid_with(6, 4, {{5, 1}}), a, b, rule));
  }
  // Vertical, along x = 3.
  EXPECT_FALSE(free_under(grid_with(6, 4, {{2, 1}}), {3.0, 0.5}, {3.0, 2.5}, CornerRule::allow));
  EXPECT_FALSE(free_under(grid_with(6, 4, {{3, 1}}), {3.0, 0.5}, {3.0, 2.5}, CornerRule::allow));
  EXPECT_TRUE(free_under(grid_with(6, 4, {{4, 1}}), {3.0, 0.5}, {3.0, 2.5}, CornerRule::allow));
}

TEST(LineOfSight, EndpointsInsideAndOnBoundaries) {
  const Grid g = grid_with(5, 5, {{2, 1}});
  for (CornerRule rule : kRules) {
    // Inside a free cell right next to the obstacle: fine.
    EXPECT_TRUE(free_under(g, {1.9, 1.5}, {1.1, 1.5}, rule));
    EXPECT_TRUE(free_under(g, {1.999, 1.5}, {1.999, 1.5}, rule));
    // Ending exactly on the obstacle's edge touches it.
    EXPECT_FALSE(free_under(g, {0.5, 1.5}, {2.0, 1.5}, rule));
    EXPECT_FALSE(free_under(g, {2.0, 1.5}, {2.0, 1.5}, rule));
    // Ending on its corner vertex touches it too (an endpoint never "passes through").
    EXPECT_FALSE(free_under(g, {1.5, 2.5}, {2.0, 2.0}, rule));
  }
  // Within the documented tolerance counts as on the edge.
  EXPECT_FALSE(free_under(g, {0.5, 1.5}, {2.0 - 1e-11, 1.5}, CornerRule::allow));
}

TEST(LineOfSight, OutsideAndBorder) {
  const Grid g(5, 4);
  EXPECT_EQ(check_segment(g, {-0.5, 1.0}, {1.5, 1.5}, {}).kind, SightHit::Kind::outside);
  EXPECT_EQ(check_segment(g, {1.5, 1.5}, {1.5, 4.5}, {}).kind, SightHit::Kind::outside);
  EXPECT_EQ(check_segment(g, {NAN, 1.0}, {1.5, 1.5}, {}).kind, SightHit::Kind::outside);
  // Touching the outer boundary touches the border wall.
  const SightHit hit = check_segment(g, {0.0, 1.5}, {1.5, 1.5}, {});
  EXPECT_EQ(hit.kind, SightHit::Kind::cell);
  EXPECT_EQ(hit.cell, (Cell{-1, 1}));
  EXPECT_FALSE(segment_free(g, {0.5, 0.0}, {4.5, 0.0}));
  EXPECT_TRUE(segment_free(g, {0.01, 0.01}, {4.99, 3.99}));
}

TEST(LineOfSight, ClearanceMode) {
  // 12 x 12; the border centres are at -0.5 and 12.5.
  const Grid g = grid_with(12, 12, {{5, 5}});  // centre (5.5, 5.5)
  const Point a{3.5, 3.5};
  const Point b{8.5, 3.5};  // 2 from the obstacle centre, 4 from the top and left border
  EXPECT_TRUE(segment_free(g, a, b, SightRule::circles(2.0)));  // equality is free
  const SightHit hit = check_segment(g, a, b, SightRule::circles(2.01));
  EXPECT_EQ(hit.kind, SightHit::Kind::clearance);
  EXPECT_EQ(hit.cell, (Cell{5, 5}));
  EXPECT_TRUE(segment_free(g, a, b, SightRule::margin(1.5)));
  EXPECT_FALSE(segment_free(g, a, b, SightRule::margin(1.6)));
  // The border wall counts.
  const Grid empty(12, 12);
  EXPECT_TRUE(segment_free(empty, a, b, SightRule::circles(4.0)));
  EXPECT_FALSE(segment_free(empty, a, b, SightRule::circles(4.1)));
  // Closest to an endpoint: obstacle centre (5.5,8.5), segment ending at (5.5, 5.5): 3 away.
  const Grid below = grid_with(12, 12, {{5, 8}});
  EXPECT_TRUE(segment_free(below, {5.5, 4.5}, {5.5, 5.5}, SightRule::circles(3.0)));
  EXPECT_FALSE(segment_free(below, {5.5, 4.5}, {5.5, 5.5}, SightRule::circles(3.1)));
  EXPECT_FALSE(segment_free(below, {5.5, 5.5}, {5.5, 5.5}, SightRule::circles(3.1)));
  // margin 0 == cells, including corner cuts.
  const Grid corner = grid_with(5, 5, {{2, 1}});
  EXPECT_TRUE(
      segment_free(corner, {1.5, 1.5}, {2.5, 2.5}, SightRule::margin(0.0, CornerRule::allow)));
  EXPECT_FALSE(segment_free(corner, {1.5, 1.5}, {2.5, 2.5}, SightRule::margin(0.0)));
  // Paper 000's r_obs = half a cell diagonal: a 45-degree corner pass is exactly at r_obs.
  EXPECT_TRUE(segment_free(corner, {1.5, 1.5}, {2.5, 2.5},
                           SightRule::circles(std::sqrt(0.5), CornerRule::allow)));
  EXPECT_FALSE(segment_free(corner, {1.5, 1.5}, {2.5, 2.5},
                            SightRule::circles(std::sqrt(0.5) + 1e-6, CornerRule::allow)));
}

TEST(LineOfSight, Polyline) {
  const Grid g = grid_with(5, 5, {{2, 2}});
  const std::vector<Point> around = {{1.5, 1.5}, {3.5, 1.5}, {3.5, 3.5}};
  const std::vector<Point> through = {{1.5, 1.5}, {3.5, 3.5}};
  EXPECT_TRUE(polyline_free(g, around));
  EXPECT_FALSE(polyline_free(g, through));
  EXPECT_TRUE(polyline_free(g, std::vector<Point>{}));
  EXPECT_FALSE(polyline_free(g, std::vector<Point>{{2.5, 2.5}}));
  EXPECT_TRUE(polyline_free(g, std::vector<Point>{{1.5, 2.5}}));
}

// ---------------------------------------------------------------------------------------------
// Move legality: a move between adjacent cell centres is free under cells(rule) exactly when
// move_allowed() accepts it.

std::uint64_t next(std::mt19937_64& rng, std::uint64_t n) { return rng() % n; }

Grid random_grid(std::mt19937_64& rng, int w, int h, int percent_blocked) {
  Grid g(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (static_cast<int>(next(rng, 100)) < percent_blocked) g.set_blocked(x, y, true);
  return g;
}

TEST(LineOfSight, MatchesMoveLegality) {
  std::mt19937_64 rng(7);
  for (int map = 0; map < 20; ++map) {
    const Grid g = random_grid(rng, 12, 9, 35);
    const auto blocked = [&g](int x, int y) { return g.blocked(x, y); };
    for (int y = 0; y < g.height(); ++y)
      for (int x = 0; x < g.width(); ++x) {
        if (g.blocked(x, y)) continue;
        for (int d = 0; d < 8; ++d)
          for (CornerRule rule : kRules) {
            const Point to{x + kDx[d] + 0.5, y + kDy[d] + 0.5};
            const bool in = g.in_bounds(x + kDx[d], y + kDy[d]);
            const bool legal = in && move_allowed(blocked, x, y, d, rule);
            EXPECT_EQ(free_under(g, centre({x, y}), to, rule), legal)
                << "map " << map << " cell " << x << "," << y << " d " << d << " rule "
                << to_string(rule);
          }
      }
  }
}

// ---------------------------------------------------------------------------------------------
// Independent exact reference. Every coordinate is an integer multiple of 2^-40 (the random
// generator below makes sure), so scaled coordinates are exact integers and all clipping
// arithmetic is exact in 128 bits. For each cell, clip the closed segment to the closed
// square (Liang-Barsky): empty -> untouched; a single point that is a square vertex, interior
// to the segment -> a side cell of a vertex pass; anything else -> the cell must be free.

__extension__ typedef __int128 Int;
constexpr int kScaleBits = 40;
constexpr Int kScale = Int{1} << kScaleBits;

Int scaled(double v) { return static_cast<Int>(std::llround(std::ldexp(v, kScaleBits))); }

struct Frac {
  Int num;
  Int den;  // > 0
};
bool less(Frac a, Frac b) { return a.num * b.den < b.num * a.den; }
bool equal(Frac a, Frac b) { return a.num * b.den == b.num * a.den; }

enum class Touch { none, full, side };

// Clip along one axis: lo <= p + t d <= hi.
bool clip(Int p, Int d, Int lo, Int hi, Frac& t0, Frac& t1) {
  if (d == 0) return lo <= p && p <= hi;
  Frac a{lo - p, d};
  Frac b{hi - p, d};
  if (d < 0) {
    a = {p - lo, -d};
    b = {p - hi, -d};
    std::swap(a, b);
  }
  if (less(t0, a)) t0 = a;
  if (less(b, t1)) t1 = b;
  return true;
}

Touch touch(Int ax, Int ay, Int dx, Int dy, int cx, int cy, Int& vx, Int& vy) {
  Frac t0{0, 1};
  Frac t1{1, 1};
  if (!clip(ax, dx, cx * kScale, (cx + 1) * kScale, t0, t1)) return Touch::none;
  if (!clip(ay, dy, cy * kScale, (cy + 1) * kScale, t0, t1)) return Touch::none;
  if (less(t1, t0)) return Touch::none;
  if (!equal(t0, t1) || t0.num == 0 || t0.num == t0.den) return Touch::full;
  const Int px = ax * t0.den + t0.num * dx;  // point * den
  const Int py = ay * t0.den + t0.num * dy;
  const Int unit = kScale * t0.den;
  if (px % unit != 0 || py % unit != 0) return Touch::full;  // cannot happen; be strict
  vx = px / unit;
  vy = py / unit;
  return Touch::side;
}

double squared_distance(Point p, Point a, Point b) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
  t = std::fmax(0.0, std::fmin(1.0, t));
  const double ex = p.x - (a.x + t * dx);
  const double ey = p.y - (a.y + t * dy);
  return ex * ex + ey * ey;
}

bool reference_free(const Grid& g, Point a, Point b, const SightRule& rule) {
  const Int ax = scaled(a.x);
  const Int ay = scaled(a.y);
  const Int dx = scaled(b.x) - ax;
  const Int dy = scaled(b.y) - ay;
  const auto blocked = [&g](int x, int y) { return !g.in_bounds(x, y) || g.blocked(x, y); };
  std::map<std::pair<long long, long long>, std::pair<int, int>> sides;  // vertex -> (n, blocked)
  for (int cy = -3; cy <= g.height() + 2; ++cy)
    for (int cx = -3; cx <= g.width() + 2; ++cx) {
      Int vx = 0;
      Int vy = 0;
      const Touch t = touch(ax, ay, dx, dy, cx, cy, vx, vy);
      if (t == Touch::full && blocked(cx, cy)) return false;
      if (t == Touch::side) {
        auto& s = sides[{static_cast<long long>(vx), static_cast<long long>(vy)}];
        ++s.first;
        s.second += blocked(cx, cy) ? 1 : 0;
      }
    }
  for (const auto& [vertex, s] : sides) {
    EXPECT_EQ(s.first, 2);  // a vertex pass grazes exactly two cells
    if (rule.corners == CornerRule::no_squeeze && s.second == 2) return false;
    if (rule.corners == CornerRule::no_corner_cut && s.second > 0) return false;
  }
  if (rule.kind == SightRule::Kind::clearance) {
    for (int cy = -3; cy <= g.height() + 2; ++cy)
      for (int cx = -3; cx <= g.width() + 2; ++cx)
        if (blocked(cx, cy) &&
            squared_distance({cx + 0.5, cy + 0.5}, a, b) < rule.radius * rule.radius - 1e-9)
          return false;
  }
  return true;
}

// Coordinates on grid lines, half cells, quarters, sixteenths and generic 2^-40 multiples, in
// [-0.5, size + 0.5] so some segments leave the grid.
double random_coordinate(std::mt19937_64& rng, int size) {
  static constexpr int kDenominators[] = {1, 2, 2, 4, 16, 1 << 20};
  const int den = kDenominators[next(rng, std::size(kDenominators))];
  const std::uint64_t span = static_cast<std::uint64_t>(size + 1) * den;
  const double v = static_cast<double>(next(rng, span + 1)) / den - 0.5;
  if (den < (1 << 20)) return v;
  // Generic: add random low bits down to 2^-40.
  return v + std::ldexp(static_cast<double>(next(rng, std::uint64_t{1} << 20)), -kScaleBits);
}

Point random_point(std::mt19937_64& rng, const Grid& g) {
  if (next(rng, 4) == 0)  // a cell centre, the most common waypoint
    return centre({static_cast<int>(next(rng, static_cast<std::uint64_t>(g.width()))),
                   static_cast<int>(next(rng, static_cast<std::uint64_t>(g.height())))});
  return {random_coordinate(rng, g.width()), random_coordinate(rng, g.height())};
}

TEST(LineOfSight, RandomSegmentsAgreeWithExactReference) {
  std::mt19937_64 rng(2024);
  const SightRule rules[] = {
      SightRule::cells(CornerRule::allow),
      SightRule::cells(CornerRule::no_squeeze),
      SightRule::cells(CornerRule::no_corner_cut),
      SightRule::margin(0.5),
      SightRule::circles(std::sqrt(0.5), CornerRule::allow),
      SightRule::circles(1.3),
  };
  int checked = 0;
  int free_count = 0;
  int rule_matters = 0;  // segments whose verdict differs between allow and no_corner_cut
  for (int map = 0; map < 24; ++map) {
    const int w = map % 3 == 0 ? 40 : 10 + map % 5;
    const int h = map % 3 == 0 ? 23 : 7 + map % 4;
    const Grid g = random_grid(rng, w, h, 5 + 5 * (map % 6));
    for (int s = 0; s < 400; ++s) {
      Point a = random_point(rng, g);
      Point b = random_point(rng, g);
      if (next(rng, 5) == 0) {  // short centre-to-centre hops (knight moves and friends)
        const Cell c{static_cast<int>(next(rng, static_cast<std::uint64_t>(w))),
                     static_cast<int>(next(rng, static_cast<std::uint64_t>(h)))};
        a = centre(c);
        b = centre(
            {c.x + static_cast<int>(next(rng, 7)) - 3, c.y + static_cast<int>(next(rng, 7)) - 3});
      }
      rule_matters += reference_free(g, a, b, rules[0]) != reference_free(g, a, b, rules[2]);
      for (const SightRule& rule : rules) {
        const bool expected = reference_free(g, a, b, rule);
        ASSERT_EQ(segment_free(g, a, b, rule), expected)
            << "map " << map << " (" << a.x << "," << a.y << ")-(" << b.x << "," << b.y << ") rule "
            << to_string(rule.corners) << " radius " << rule.radius;
        ASSERT_EQ(segment_free(g, b, a, rule), expected) << "reversed";
        ++checked;
        free_count += expected ? 1 : 0;
      }
    }
  }
  // Both verdicts well represented, so the comparison means something.
  EXPECT_GT(free_count, checked / 10);
  EXPECT_LT(free_count, checked * 9 / 10);
  EXPECT_GT(rule_matters, 100);
}

}  // namespace
}  // namespace agv
