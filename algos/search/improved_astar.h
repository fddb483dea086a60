#pragma once
// Improved A* of paper 002 (docs/PLANNERS.md "Improved A*"), registered twice: the internal part
// alone
// (`improved_astar_internal`, the planner of the paper's Table 4) and with the external part
// (`improved_astar`, Table 5).

#include "algos/planner_info.h"

namespace agv {

PlannerInfo improved_astar_internal_planner();
PlannerInfo improved_astar_planner();

}  // namespace agv
