#pragma once
// RRT (LaValle 1998), the "RRT" baseline of paper 000 Tables III-XIII (docs/PLANNERS.md
// "Baselines"): one tree from the start, grown by fixed steps towards uniform samples of the map
// (the goal with probability goal_bias), every edge checked with the shared line-of-sight test.

#include "algos/planner_info.h"

namespace agv {

PlannerInfo rrt_planner();

}  // namespace agv
