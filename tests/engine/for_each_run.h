#pragma once
// Test helper: every run of a sweep, in process and in task order, with the run's full output
// (path included), through the same run_map_task the sweep uses.
#include <cstddef>
#include <string>
#include <vector>

#include "engine/plan/sweep_config.h"
#include "engine/sweep/map_task.h"

namespace agv {

template <class Check>
void for_each_run(const SweepConfig& config, Check&& check) {
  const SweepPlan plan = plan_sweep(config);
  const std::string hash = config_hash(config);
  const MapTaskContext context(config, plan, hash);
  MapTaskWorkspace workspace;
  workspace.planners = configure_planners(config);
  std::vector<std::size_t> all(config.planners.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  for (std::int64_t task = 0; task < context.plan.map_tasks(); ++task)
    run_map_task(context, task, all, workspace, [&](const MapTaskRun& run) { check(run); });
}

}  // namespace agv
