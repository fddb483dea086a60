#pragma once
// Classic A* (docs/PLANNERS.md "A* (classic)"): the "traditional A*" column of every paper.

#include "algos/planner_info.h"

namespace agv {

PlannerInfo astar_planner();

}  // namespace agv
