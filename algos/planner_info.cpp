#include "algos/planner_info.h"

namespace agv {

const char* to_string(PlannerKind kind) {
  switch (kind) {
    case PlannerKind::grid_search:
      return "grid_search";
    case PlannerKind::sampling:
      return "sampling";
    case PlannerKind::swarm:
      return "swarm";
    case PlannerKind::local:
      return "local";
  }
  return "?";
}

std::vector<std::string> planner_names(std::span<const PlannerInfo> planners, PlannerKind kind) {
  std::vector<std::string> names;
  for (const auto& info : planners)
    if (info.kind == kind) names.push_back(info.name);
  return names;
}

}  // namespace agv
