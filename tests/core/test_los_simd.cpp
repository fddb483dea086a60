// The word-parallel line of sight (core/line_of_sight_batch.h), at every instruction-set level
// this machine runs (core/simd_path.h), against the reference walk (segment_free_reference): the
// same verdict on every segment, for every corner rule and
// clearance radius, over grids of many sizes (widths across the 64-bit word boundaries) and
// densities, with endpoints on vertices, grid lines, half and quarter cells, just off integers
// (either side of the snapping tolerance) and anywhere.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "core/corner_rule.h"
#include "core/grid.h"
#include "core/line_of_sight.h"
#include "core/line_of_sight_batch.h"
#include "core/line_of_sight_kernel.h"
#include "core/simd_path.h"

namespace agv {
namespace {

constexpr CornerRule kRules[] = {CornerRule::allow, CornerRule::no_squeeze,
                                 CornerRule::no_corner_cut};

// Every margin mode under every corner rule: cells; radius 0.5 (clearance implied by cells);
// paper 000's r_obs (half a cell diagonal); margin 0.5 (radius 1); wider circles.
std::vector<SightRule> all_rules() {
  std::vector<SightRule> rules;
  for (CornerRule c : kRules) {
    rules.push_back(SightRule::cells(c));
    rules.push_back(SightRule::circles(0.5, c));
    rules.push_back(SightRule::circles(std::sqrt(0.5), c));
    rules.push_back(SightRule::margin(0.5, c));
    rules.push_back(SightRule::circles(1.3, c));
    rules.push_back(SightRule::margin(2.2, c));
  }
  return rules;
}

std::string describe(const SightRule& r) {
  return std::string(to_string(r.corners)) +
         (r.kind == SightRule::Kind::cells ? " cells" : " radius " + std::to_string(r.radius));
}

class Generator {
 public:
  explicit Generator(std::uint64_t seed) : rng_(seed) {}
  std::uint64_t below(std::uint64_t n) { return rng_() % n; }
  double unit() { return static_cast<double>(rng_() >> 11) * 0x1.0p-53; }

  Grid grid(int w, int h, double density) {
    Grid g(w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (unit() < density) g.set_blocked(x, y, true);
    return g;
  }

  // A coordinate in [-0.3, size + 0.3] (some endpoints outside the grid): on a grid line, a
  // half or quarter cell, within 1e-10 of an integer (snapped onto it), 2e-9 off one (not
  // snapped), or any double.
  double coordinate(int size) {
    const double whole = static_cast<double>(below(static_cast<std::uint64_t>(size) + 1));
    switch (below(8)) {
      case 0:
        return whole;
      case 1:
        return whole + 0.5;
      case 2:
        return whole + 0.25 * static_cast<double>(below(4));
      case 3:
        return whole + (below(2) ? 1e-10 : -1e-10);
      case 4:
        return whole + (below(2) ? 2e-9 : -2e-9);
      case 5:
        return -0.3 + unit() * (size + 0.6);
      default:
        return unit() * size;
    }
  }

  Point point(const Grid& g) {
    if (below(4) == 0)  // a cell centre, the most common waypoint
      return centre({static_cast<int>(below(static_cast<std::uint64_t>(g.width()))),
                     static_cast<int>(below(static_cast<std::uint64_t>(g.height())))});
    return {coordinate(g.width()), coordinate(g.height())};
  }

  // The second endpoint: any point, a lattice step (rational slopes through vertices), or a
  // segment of a chosen length in a random direction (0 to the whole map).
  Point partner(const Grid& g, Point a) {
    switch (below(4)) {
      case 0:
        return point(g);
      case 1: {
        const int k = 1 + static_cast<int>(below(6));
        const double step = below(3) == 0 ? 0.5 : 1.0;
        return {a.x + step * static_cast<double>(static_cast<int>(below(7)) - 3) * k,
                a.y + step * static_cast<double>(static_cast<int>(below(7)) - 3) * k};
      }
      default: {
        static constexpr double kLengths[] = {0.0, 1e-12, 0.3, 1.0, 2.0, 8.0, 32.0, 128.0, 1e9};
        double len = kLengths[below(std::size(kLengths))];
        len = std::min(len, std::hypot(g.width(), g.height()));
        const double angle = unit() * 6.283185307179586;
        return {a.x + len * std::cos(angle), a.y + len * std::sin(angle)};
      }
    }
  }

 private:
  std::mt19937_64 rng_;
};

struct Size {
  int w, h;
};
constexpr Size kSizes[] = {{1, 1},     {2, 3},    {7, 5},     {20, 20}, {31, 9},   {62, 4},
                           {63, 17},   {64, 64},  {65, 33},   {100, 7}, {127, 40}, {128, 3},
                           {129, 129}, {191, 12}, {200, 200}, {300, 50}};
constexpr double kDensities[] = {0.0, 0.05, 0.2, 0.35, 0.5, 0.8};

// Every level of the kernel this build has and this CPU runs (core/simd_path.h), each called
// directly: the comparisons hold for each one, whichever the process would pick.
class LosSimd : public ::testing::TestWithParam<SimdPath> {
 protected:
  const SightKernel& kernel() const { return *sight_kernel(GetParam()); }
};

std::vector<SimdPath> supported_levels() {
  std::vector<SimdPath> levels;
  for (SimdPath path : kSimdPaths)
    if (simd_path_supported(path)) levels.push_back(path);
  return levels;
}

std::string level_name(const ::testing::TestParamInfo<SimdPath>& info) {
  return std::string(simd_path_name(info.param));
}

TEST_P(LosSimd, RandomSegmentsAgreeWithReference) {
  Generator gen(20240613);
  const std::vector<SightRule> rules = all_rules();
  constexpr int kSegments = 200000;  // x 18 rules x 4 forms: 14.4 million verdicts compared
  constexpr int kPerGrid = 500;
  std::vector<Point> as, bs;
  std::vector<std::uint8_t> out, out_from;
  std::int64_t free_count = 0, checks = 0;
  for (int start = 0; start < kSegments; start += kPerGrid) {
    const int m = start / kPerGrid;
    const Size size = kSizes[m % std::size(kSizes)];
    const Grid g = gen.grid(size.w, size.h, kDensities[(m / 3) % std::size(kDensities)]);
    as.clear();
    bs.clear();
    for (int s = 0; s < kPerGrid; ++s) {
      as.push_back(gen.point(g));
      bs.push_back(gen.partner(g, as.back()));
    }
    out.assign(as.size(), 2);
    out_from.assign(as.size(), 2);
    for (const SightRule& rule : rules) {
      kernel().segments(g, as, bs, rule, out);
      kernel().segments_from(g, as[0], bs, rule, out_from);
      for (std::size_t s = 0; s < as.size(); ++s) {
        const bool expected = segment_free_reference(g, as[s], bs[s], rule);
        const auto where = [&] {
          char buf[200];
          std::snprintf(buf, sizeof buf, "grid %dx%d map %d (%.17g,%.17g)-(%.17g,%.17g) ", size.w,
                        size.h, m, as[s].x, as[s].y, bs[s].x, bs[s].y);
          return std::string(buf) + describe(rule);
        };
        ASSERT_EQ(kernel().segment(g, as[s], bs[s], rule), expected) << where();
        ASSERT_EQ(kernel().segment(g, bs[s], as[s], rule), expected) << where() << " reversed";
        ASSERT_EQ(out[s] == 1, expected) << where() << " batched";
        ASSERT_EQ(out_from[s] == 1, segment_free_reference(g, as[0], bs[s], rule))
            << where() << " from as[0]";
        free_count += expected;
        ++checks;
      }
    }
  }
  // Both verdicts well represented, so the agreement means something.
  EXPECT_GT(free_count, checks / 10);
  EXPECT_LT(free_count, checks * 9 / 10);
}

TEST_P(LosSimd, PointsAgreeWithReference) {
  Generator gen(7);
  const std::vector<SightRule> rules = all_rules();
  for (int m = 0; m < 40; ++m) {
    const Size size = kSizes[m % std::size(kSizes)];
    const Grid g = gen.grid(size.w, size.h, kDensities[m % std::size(kDensities)]);
    std::vector<Point> ps;
    for (int s = 0; s < 500; ++s) ps.push_back(gen.point(g));
    std::vector<std::uint8_t> out(ps.size(), 2);
    for (const SightRule& rule : rules) {
      kernel().points(g, ps, rule, out);
      for (std::size_t s = 0; s < ps.size(); ++s)
        ASSERT_EQ(out[s] == 1, segment_free_reference(g, ps[s], ps[s], rule))
            << ps[s].x << "," << ps[s].y << " " << describe(rule);
    }
  }
}

// Endpoints in blocked cells: well inside one (the check ends there), and within snapping distance
// of a cell edge or vertex, where the reference may leave the cell to the corner rule (an endpoint
// snapped onto a vertex pass: (85 - 1e-10, 1 - 2e-9) to (84.22, 2.84) is free under `allow` with
// only cell (84, 0) blocked, found by RandomSegmentsAgreeWithReference).
TEST_P(LosSimd, EndpointsInBlockedCellsNearEdgesAndVertices) {
  Grid g(100, 7);
  for (const Cell c : {Cell{84, 0}, Cell{86, 1}, Cell{84, 2}, Cell{10, 3}})
    g.set_blocked(c.x, c.y, true);
  const double offsets[] = {0.0, 1e-10, -1e-10, 2e-9, -2e-9, 1e-6, -1e-6, 2e-6, -2e-6, 0.5};
  const std::vector<SightRule> rules = all_rules();
  for (double ox : offsets)
    for (double oy : offsets)
      for (const Point b : {Point{84.221672676504625, 2.8423372574767178}, Point{80.5, 0.5},
                            Point{85.5, 6.5}, Point{90.0, 1.0}, Point{85.0, 1.0}}) {
        const Point a{85.0 + ox, 1.0 + oy};
        for (const SightRule& rule : rules) {
          ASSERT_EQ(kernel().segment(g, a, b, rule), segment_free_reference(g, a, b, rule))
              << a.x << "," << a.y << " " << b.x << "," << b.y << " " << describe(rule);
          ASSERT_EQ(kernel().segment(g, b, a, rule), segment_free_reference(g, b, a, rule))
              << b.x << "," << b.y << " " << a.x << "," << a.y << " " << describe(rule);
        }
      }
  // The counterexample itself, with only (84, 0) blocked: free under `allow`, not under the
  // other rules (the side cell judged at the vertex is blocked).
  Grid one(100, 7);
  one.set_blocked(84, 0, true);
  const Point a{84.999999999899998, 0.99999999799999995};
  const Point b{84.221672676504625, 2.8423372574767178};
  EXPECT_TRUE(kernel().segment(one, a, b, SightRule::cells(CornerRule::allow)));
  EXPECT_FALSE(kernel().segment(one, a, b, SightRule::cells(CornerRule::no_corner_cut)));
  for (const SightRule& rule : rules)
    EXPECT_EQ(kernel().segment(one, a, b, rule), segment_free_reference(one, a, b, rule))
        << describe(rule);
}

// The clearance screens: one obstacle on open ground, segments passing it at every distance
// around each radius, in every direction, so that a screen box one cell too small would call a
// segment free that the scan finds too close.
TEST_P(LosSimd, ClearanceScreensAroundOneObstacle) {
  Generator gen(7);
  Grid g(120, 120);
  g.set_blocked(60, 60, true);
  const std::vector<SightRule> rules = all_rules();
  for (int s = 0; s < 20000; ++s) {
    const double angle = gen.unit() * 6.283185307179586;
    const double offset = (gen.unit() - 0.5) * 8.0;  // distance of the line from the centre
    const double along = (gen.unit() - 0.5) * 40.0;
    const double length = 1.0 + gen.unit() * 50.0;
    const double cx = 60.5 - offset * std::sin(angle) + along * std::cos(angle);
    const double cy = 60.5 + offset * std::cos(angle) + along * std::sin(angle);
    const Point a{cx - length * std::cos(angle), cy - length * std::sin(angle)};
    const Point b{cx + length * std::cos(angle), cy + length * std::sin(angle)};
    for (const SightRule& rule : rules)
      ASSERT_EQ(kernel().segment(g, a, b, rule), segment_free_reference(g, a, b, rule))
          << a.x << "," << a.y << " " << b.x << "," << b.y << " " << describe(rule);
  }
}

// Degenerate slopes: long, almost flat segments whose crossings snap onto a row line over many
// columns, and exact vertex runs, across word boundaries.
TEST_P(LosSimd, NearlyFlatAndVertexRuns) {
  Generator gen(99);
  const std::vector<SightRule> rules = all_rules();
  for (int m = 0; m < 30; ++m) {
    const Grid g = gen.grid(150, 12, 0.03 * (m % 5));
    for (int s = 0; s < 300; ++s) {
      const double y = static_cast<double>(1 + gen.below(10));
      const double off[] = {0.0, 1e-10, -1e-10, 5e-10, 2e-9, 1e-7, 0.5};
      const Point a{gen.unit() * 10.0, y + off[gen.below(std::size(off))]};
      const Point b{140.0 + gen.unit() * 10.0, y + off[gen.below(std::size(off))]};
      const Point c{static_cast<double>(gen.below(40)), static_cast<double>(gen.below(12))};
      const Point d{c.x + 110.0,
                    c.y + (gen.below(2) ? 1.0 : -1.0) * static_cast<double>(gen.below(3))};
      for (const SightRule& rule : rules) {
        ASSERT_EQ(kernel().segment(g, a, b, rule), segment_free_reference(g, a, b, rule))
            << a.x << "," << a.y << " " << b.x << "," << b.y << " " << describe(rule);
        ASSERT_EQ(kernel().segment(g, c, d, rule), segment_free_reference(g, c, d, rule))
            << c.x << "," << c.y << " " << d.x << "," << d.y << " " << describe(rule);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Levels, LosSimd, ::testing::ValuesIn(supported_levels()), level_name);

// The public checks run the active level and count one collision check per verdict.
TEST(LosSimdDispatch, PublicChecksCountAndRunTheActiveLevel) {
  EXPECT_TRUE(simd_path_supported(SimdPath::baseline));
  EXPECT_TRUE(simd_path_supported(active_simd_path()));
  EXPECT_EQ(&active_sight_kernel(), sight_kernel(active_simd_path()));
  Generator gen(5);
  const Grid g = gen.grid(90, 70, 0.2);
  std::vector<Point> as, bs;
  for (int s = 0; s < 300; ++s) {
    as.push_back(gen.point(g));
    bs.push_back(gen.partner(g, as.back()));
  }
  std::vector<std::uint8_t> out(as.size()), from(as.size()), points(as.size());
  const SightRule rule = SightRule::circles(0.7);
  const std::int64_t before = collision_checks_on_thread();
  segments_free(g, as, bs, rule, out);
  segments_free_from(g, as[0], bs, rule, from);
  points_free(g, as, rule, points);
  for (std::size_t s = 0; s < as.size(); ++s) {
    EXPECT_EQ(segment_free(g, as[s], bs[s], rule), segment_free_reference(g, as[s], bs[s], rule));
    EXPECT_EQ(out[s] == 1, segment_free_reference(g, as[s], bs[s], rule));
    EXPECT_EQ(from[s] == 1, segment_free_reference(g, as[0], bs[s], rule));
    EXPECT_EQ(points[s] == 1, segment_free_reference(g, as[s], as[s], rule));
  }
  // Per segment: three batched verdicts, one single, and the four reference walks (they count too).
  EXPECT_EQ(collision_checks_on_thread() - before, 300 * (3 + 1 + 4));
}

}  // namespace
}  // namespace agv
