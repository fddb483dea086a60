#pragma once
// RRT-Connect (Kuffner & LaValle 2000), the "Bi-RRT" baseline of paper 000 Tables III-XIII
// (docs/PLANNERS.md "Baselines"): a tree from the start and one from the goal alternate; one
// EXTENDs towards a sample, the other CONNECTs (extends repeatedly) towards the new node until it
// reaches it or is trapped.

#include "algos/planner_info.h"

namespace agv {

PlannerInfo birrt_planner();

}  // namespace agv
