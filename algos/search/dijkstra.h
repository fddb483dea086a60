#pragma once
// Dijkstra = A* with the zero heuristic (docs/PLANNERS.md "Dijkstra, bidirectional A*"; paper 002's
// baseline), and the engine's optimal-length reference.

#include <optional>

#include "algos/planner.h"
#include "algos/planner_info.h"
#include "core/corner_rule.h"
#include "core/grid.h"

namespace agv {

PlannerInfo dijkstra_planner();

// Optimal 8-connected path length from start to goal in cells (straight 1, diagonal sqrt 2)
// under `rule`, or nullopt when the goal is unreachable (or start/goal is blocked or outside).
// The optimality reference of the engine and the proof that a planner's no_path is true.
// Computed by A* with the octile heuristic, which is consistent for every corner rule and so
// returns Dijkstra's length while expanding far fewer cells (tests check both against each
// other and against the MovingAI optima). Uses scratch's grid-search buffers.
std::optional<double> shortest_length(const Grid& grid, Cell start, Cell goal, CornerRule rule,
                                      Scratch& scratch);

}  // namespace agv
