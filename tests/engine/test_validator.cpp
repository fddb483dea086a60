// The independent path validator: hand-made bad paths are rejected with a reason naming the
// problem, legal ones accepted under each corner rule.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "engine/judge/validator.h"

namespace agv {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// 6 x 5, obstacles at (2,1) and (3,3):
//   ......
//   ..#...
//   ......
//   ...#..
//   ......
Grid test_grid() {
  Grid g(6, 5);
  g.set_blocked(2, 1, true);
  g.set_blocked(3, 3, true);
  return g;
}

TEST(Validator, AcceptsLegalPathsUnderEveryRule) {
  const Grid g = test_grid();
  const std::vector<Point> cells = {{0.5, 0.5}, {1.5, 0.5}, {2.5, 0.5}, {3.5, 0.5},
                                    {4.5, 1.5}, {4.5, 2.5}, {4.5, 3.5}, {5.5, 4.5}};
  const std::vector<Point> any_angle = {{0.5, 0.5}, {3.5, 0.5}, {5.5, 4.5}};
  for (CornerRule rule : {CornerRule::allow, CornerRule::no_squeeze, CornerRule::no_corner_cut}) {
    EXPECT_TRUE(validate_path(g, {0, 0}, {5, 4}, cells, rule).ok) << to_string(rule);
    const ValidationResult r = validate_path(g, {0, 0}, {5, 4}, any_angle, rule);
    EXPECT_TRUE(r.ok) << r.reason;
  }
  // Start == goal: the one-point path.
  EXPECT_TRUE(
      validate_path(g, {1, 1}, {1, 1}, std::vector<Point>{{1.5, 1.5}}, CornerRule::no_corner_cut)
          .ok);
  // Within the endpoint tolerance.
  EXPECT_TRUE(validate_path(g, {0, 0}, {0, 2}, std::vector<Point>{{0.5 + 1e-12, 0.5}, {0.5, 2.5}},
                            CornerRule::allow)
                  .ok);
}

TEST(Validator, CornerCutDependsOnRule) {
  const Grid g = test_grid();
  // Diagonal (1,1) -> (2,2) grazes (2,1) at vertex (2,2): legal under allow and no_squeeze,
  // a corner cut under no_corner_cut.
  const std::vector<Point> path = {{0.5, 1.5}, {1.5, 1.5}, {2.5, 2.5}, {2.5, 4.5}};
  EXPECT_TRUE(validate_path(g, {0, 1}, {2, 4}, path, CornerRule::allow).ok);
  EXPECT_TRUE(validate_path(g, {0, 1}, {2, 4}, path, CornerRule::no_squeeze).ok);
  const ValidationResult r = validate_path(g, {0, 1}, {2, 4}, path, CornerRule::no_corner_cut);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(contains(r.reason, "segment 1 (1.5,1.5)-(2.5,2.5) cuts a corner")) << r.reason;
  EXPECT_TRUE(contains(r.reason, "no_corner_cut")) << r.reason;

  // Squeezing between two diagonal obstacles: only allow accepts it.
  Grid squeeze(4, 4);
  squeeze.set_blocked(2, 1, true);
  squeeze.set_blocked(1, 2, true);
  const std::vector<Point> between = {{1.5, 1.5}, {2.5, 2.5}};
  EXPECT_TRUE(validate_path(squeeze, {1, 1}, {2, 2}, between, CornerRule::allow).ok);
  const ValidationResult s =
      validate_path(squeeze, {1, 1}, {2, 2}, between, CornerRule::no_squeeze);
  EXPECT_FALSE(s.ok);
  EXPECT_TRUE(contains(s.reason, "segment 0")) << s.reason;
}

TEST(Validator, RejectsBadPaths) {
  const Grid g = test_grid();
  const CornerRule rule = CornerRule::allow;

  ValidationResult r = validate_path(g, {0, 0}, {5, 4}, std::vector<Point>{}, rule);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.reason, "empty path");

  // Through an obstacle.
  r = validate_path(g, {0, 1}, {5, 1}, std::vector<Point>{{0.5, 1.5}, {5.5, 1.5}}, rule);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(contains(r.reason, "segment 0")) << r.reason;
  EXPECT_TRUE(contains(r.reason, "obstacle cell (2,1)")) << r.reason;

  // Wrong start, wrong end.
  r = validate_path(g, {0, 0}, {1, 0}, std::vector<Point>{{0.6, 0.5}, {1.5, 0.5}}, rule);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(contains(r.reason, "starts at (0.6,0.5)")) << r.reason;
  r = validate_path(g, {0, 0}, {1, 0}, std::vector<Point>{{0.5, 0.5}, {1.5, 2.5}}, rule);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(contains(r.reason, "ends at (1.5,2.5) not at goal (1.5,0.5)")) << r.reason;

  // Off the grid, and on its very edge (touching the border wall).
  r = validate_path(g, {0, 0}, {1, 0}, std::vector<Point>{{0.5, 0.5}, {0.5, -0.5}, {1.5, 0.5}},
                    rule);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(contains(r.reason, "point 1")) << r.reason;
  EXPECT_TRUE(contains(r.reason, "outside the grid")) << r.reason;
  r = validate_path(g, {0, 0}, {1, 0}, std::vector<Point>{{0.5, 0.5}, {1.0, 0.0}, {1.5, 0.5}},
                    rule);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(contains(r.reason, "border")) << r.reason;

  // NaN and infinity.
  r = validate_path(g, {0, 0}, {1, 0}, std::vector<Point>{{0.5, 0.5}, {NAN, 0.5}, {1.5, 0.5}},
                    rule);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(contains(r.reason, "point 1 is not finite")) << r.reason;
  r = validate_path(g, {0, 0}, {1, 0}, std::vector<Point>{{0.5, 0.5}, {1.5, INFINITY}}, rule);
  EXPECT_FALSE(r.ok);

  // A one-point path on an obstacle (start == goal given wrongly).
  r = validate_path(g, {2, 1}, {2, 1}, std::vector<Point>{{2.5, 1.5}}, rule);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(contains(r.reason, "obstacle cell (2,1)")) << r.reason;
}

}  // namespace
}  // namespace agv
