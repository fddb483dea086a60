#pragma once
// Probabilistic roadmap (Kavraki et al. 1996), the "PRM" baseline of paper 000 Tables III-XIII
// (docs/PLANNERS.md "Baselines"): uniform free samples plus the start and goal centres, each joined
// to its k nearest neighbours (a nanoflann k-d tree) when the shared line-of-sight test holds, then
// Dijkstra on the roadmap from the start to the goal. Single-query: the roadmap is built per plan.

#include "algos/planner_info.h"

namespace agv {

PlannerInfo prm_planner();

}  // namespace agv
