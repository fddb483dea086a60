#include "engine/judge/validator.h"

#include <cmath>
#include <cstdio>
#include <utility>

#include "core/line_of_sight.h"

namespace agv {

namespace {

std::string fmt(Point p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.10g,%.10g)", p.x, p.y);
  return buf;
}

// snprintf, not "(" + std::to_string(...): the latter trips GCC 12's false -Wrestrict.
std::string fmt(Cell c) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "(%d,%d)", c.x, c.y);
  return buf;
}

bool near(Point a, Point b) {
  return std::abs(a.x - b.x) <= kEndpointTolerance && std::abs(a.y - b.y) <= kEndpointTolerance;
}

ValidationResult fail(std::string reason) { return {false, std::move(reason)}; }

}  // namespace

ValidationResult validate_path(const Grid& grid, Cell start, Cell goal, std::span<const Point> path,
                               CornerRule rule) {
  return validate_path(grid, start, goal, path, SightRule::cells(rule));
}

ValidationResult validate_path(const Grid& grid, Cell start, Cell goal, std::span<const Point> path,
                               const SightRule& sight) {
  if (path.empty()) return fail("empty path");
  for (std::size_t i = 0; i < path.size(); ++i) {
    const Point p = path[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      return fail("point " + std::to_string(i) + " is not finite " + fmt(p));
    if (p.x < 0.0 || p.y < 0.0 || p.x > grid.width() || p.y > grid.height())
      return fail("point " + std::to_string(i) + " " + fmt(p) + " is outside the grid");
  }
  if (!near(path.front(), centre(start)))
    return fail("starts at " + fmt(path.front()) + " not at start " + fmt(centre(start)));
  if (!near(path.back(), centre(goal)))
    return fail("ends at " + fmt(path.back()) + " not at goal " + fmt(centre(goal)));

  const std::size_t segments = path.size() == 1 ? 1 : path.size() - 1;
  for (std::size_t s = 0; s < segments; ++s) {
    const Point a = path[s];
    const Point b = path.size() == 1 ? a : path[s + 1];
    const SightHit hit = check_segment(grid, a, b, sight);
    if (!hit) continue;
    const std::string what = "segment " + std::to_string(s) + " " + fmt(a) + "-" + fmt(b);
    switch (hit.kind) {
      case SightHit::Kind::corner:
        return fail(what + " cuts a corner of obstacle cell " + fmt(hit.cell) + " under " +
                    std::string(to_string(sight.corners)));
      case SightHit::Kind::cell:
        return fail(what +
                    (grid.in_bounds(hit.cell) ? " touches obstacle cell "
                                              : " touches the border at cell ") +
                    fmt(hit.cell));
      case SightHit::Kind::clearance: {
        char buf[96];
        std::snprintf(buf, sizeof buf, " passes closer than %.6g to the centre of obstacle cell ",
                      sight.radius);
        return fail(what + buf + fmt(hit.cell));
      }
      default:
        return fail(what + " leaves the grid");
    }
  }
  return {true, {}};
}

}  // namespace agv
