#pragma once
// OMPL's geometric planners (docs/PLANNERS.md "OMPL planners"), each a thin entry of one adapter
// (algos/ompl/ompl_adapter.h): ompl_rrt, ompl_rrtconnect, ompl_rrtstar, ompl_informed_rrtstar,
// ompl_bitstar, ompl_prm, ompl_prmstar, ompl_lazyprmstar.

#include <cstddef>
#include <vector>

#include "algos/planner_info.h"

namespace agv {

inline constexpr std::size_t kOmplPlanners = 8;

// Their registry entries, in `list` order.
std::vector<PlannerInfo> ompl_planners();

}  // namespace agv
