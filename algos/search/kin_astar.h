#pragma once
// Kinematic-constraint A* of paper 004 section 2 (docs/PLANNERS.md "Kinematic-constraint A*").

#include <cstdint>

#include "algos/planner_info.h"

namespace agv {

PlannerInfo kin_astar_planner();

// Paper 004 eq. 1 / Table 1: the five directions (corner_rule.h numbering, bit d = direction d)
// kept for a node whose goal lies at offset (dx, dy) cells: the 45-degree sector of
// atan2(dy, dx) picks a centre direction, and the five directions within 90 degrees of it are
// kept. (dx, dy) = (0, 0) counts as east.
std::uint8_t five_direction_mask(int dx, int dy);

}  // namespace agv
