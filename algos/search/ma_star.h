#pragma once
// MA*, the Modified A* of paper 000 section 4.1 and steps 2-3 (PLANNERS.md "MA*").

#include "algos/registry.h"

namespace agv {

PlannerInfo ma_star_planner();

}  // namespace agv
