#pragma once
// Alternative A* of paper 003 section 2 (docs/PLANNERS.md "Alternative A*").

#include "algos/planner_info.h"

namespace agv {

PlannerInfo alt_astar_planner();

}  // namespace agv
