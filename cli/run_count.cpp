#include "cli/run_count.h"

namespace agv {

std::string run_count_text(const SweepConfig& config, const SweepPlan& plan) {
  const long long full = plan.map_tasks() * static_cast<long long>(config.planners.size());
  const long long runs = scheduled_runs(config, plan);
  bool uniform = true;  // map sources' cells hold as many maps as their files have queries
  for (const auto& cell : plan.cells) uniform = uniform && cell.maps == plan.cells.front().maps;
  std::string text =
      uniform ? std::to_string(plan.cells.size()) + " cells x " +
                    std::to_string(plan.cells.empty() ? 0 : plan.cells.front().maps) + " maps x "
              : std::to_string(plan.cells.size()) + " cells, " + std::to_string(plan.map_tasks()) +
                    " maps x ";
  text += std::to_string(config.planners.size()) + " planners = ";
  if (runs == full) return text + std::to_string(runs) + " runs";
  return text + std::to_string(full) + ", of which " + std::to_string(runs) +
         " runs are scheduled (planners with an \"only\" scope)";
}

}  // namespace agv
