#pragma once
// Bidirectional A* (paper 002's baseline; docs/PLANNERS.md "Dijkstra, bidirectional A*").

#include "algos/planner_info.h"

namespace agv {

PlannerInfo bidir_astar_planner();

}  // namespace agv
