#pragma once
// The independent path validator (docs/METRICS.md "success"): every returned path is re-checked
// against the map with the shared line-of-sight test, whatever the planner claimed. It knows
// nothing of any planner.

#include <span>
#include <string>

#include "core/corner_rule.h"
#include "core/grid.h"
#include "core/line_of_sight.h"

namespace agv {

struct ValidationResult {
  bool ok = false;
  std::string reason;  // empty when ok; otherwise names the problem and the point/segment index
};

// Tolerance, in cells, for "the path starts (ends) at the start (goal) cell's centre".
inline constexpr double kEndpointTolerance = 1e-9;

// Checks, in order: non-empty; every point finite and inside [0, width] x [0, height]; first
// point == centre(start) and last point == centre(goal) within kEndpointTolerance per
// coordinate; every segment free under SightRule::cells(rule) (a one-point path: the point).
ValidationResult validate_path(const Grid& grid, Cell start, Cell goal, std::span<const Point> path,
                               CornerRule rule);
// The same under any sight rule: a sweep's collision model (CollisionModel::sight()), whose
// clearance adds "every obstacle cell centre at least clearance + 0.5 from every segment".
ValidationResult validate_path(const Grid& grid, Cell start, Cell goal, std::span<const Point> path,
                               const SightRule& sight);

}  // namespace agv
