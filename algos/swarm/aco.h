#pragma once
// Ant colony optimisation on the 8-connected grid (Ant System, Dorigo et al. 1996), the "ant
// colony" baseline of paper 002 section 5 with its Table 2 parameters as defaults (docs/PLANNERS.md
// "Baselines"). Raw cell-centre path, no post-processing.

#include "algos/planner_info.h"

namespace agv {

PlannerInfo aco_planner();

}  // namespace agv
