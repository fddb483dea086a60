#include "engine/sweep/map_task.h"

#include <algorithm>
#include <limits>

#include "engine/sweep/single_map.h"
#include "engine/system/phase_clock.h"

namespace agv {

MapTaskContext::MapTaskContext(const SweepConfig& sweep_config, const SweepPlan& sweep_plan,
                               const std::string& hash)
    : config(sweep_config),
      plan(sweep_plan),
      config_hash(hash),
      budget(std::chrono::duration_cast<std::chrono::nanoseconds>(
          std::chrono::duration<double>(sweep_config.time_limit_s))) {}

std::vector<ConfiguredPlanner> configure_planners(const SweepConfig& config) {
  std::vector<ConfiguredPlanner> planners;
  for (std::size_t i = 0; i < config.planners.size(); ++i) {
    const auto& p = config.planners[i];
    planners.push_back(configure_planner(p.name, p.params, "planners[" + std::to_string(i) + "]",
                                         config.collision));
  }
  return planners;
}

MapSlot map_slot_of(const MapInstance& inst) {
  MapSlot ms;
  ms.rejections = inst.rejections;
  ms.obstacle_fraction = static_cast<double>(inst.grid.obstacle_count()) /
                         (static_cast<double>(inst.grid.width()) * inst.grid.height());
  ms.done = true;
  return ms;
}

namespace {

// A task's map: generated, or a map source's file grid (shared by the cell's tasks, never
// copied) with one query.
struct TaskMap {
  MapInstance generated;
  const Grid* grid = nullptr;
  Cell start;
  Cell goal;
  double scen_optimum = -1.0;  // negative: none
  MapSlot slot;
};

TaskMap make_task_map(const MapTaskContext& context, std::int64_t task) {
  const SweepCell& cell = context.plan.cell_of(task);
  const int map_index = context.plan.map_index_of(task);
  TaskMap out;
  if (cell.file != nullptr) {
    Rng rng = map_rng(context.config.seed, cell, map_index);
    const FileQuery q = file_query(*cell.file, cell.queries, map_index, cell.spec, rng);
    out.grid = &cell.file->grid;
    out.start = q.start;
    out.goal = q.goal;
    out.scen_optimum = q.scen_optimum;
    out.slot.rejections = q.rejections;
    out.slot.obstacle_fraction = cell.density;
    out.slot.done = true;
    return out;
  }
  out.generated = make_cell_map(cell.spec, cell.key, context.config.seed, map_index);
  out.grid = &out.generated.grid;
  out.start = out.generated.start;
  out.goal = out.generated.goal;
  out.slot = map_slot_of(out.generated);
  return out;
}

}  // namespace

MapSlot regenerate_map_slot(const MapTaskContext& context, std::int64_t task) {
  return make_task_map(context, task).slot;
}

RunSlot lost_run_slot(Outcome outcome, std::int64_t cpu_ns) {
  RunSlot slot;
  slot.metrics.fill(std::numeric_limits<double>::quiet_NaN());
  slot.outcome = outcome;
  slot.plan_time_ns = std::max<std::int64_t>(cpu_ns, 0);
  return slot;
}

MapFacts run_map_task(const MapTaskContext& context, std::int64_t task,
                      std::span<const std::size_t> planners, MapTaskWorkspace& workspace,
                      const std::function<void(const MapTaskRun&)>& on_run) {
  const SweepCell& cell = context.plan.cell_of(task);
  const int map_index = context.plan.map_index_of(task);
  const TaskMap map = [&] {
    const PhaseScope timed(EnginePhase::map);
    return make_task_map(context, task);
  }();
  const MapSlot& slot = map.slot;
  // Shared by the task's runs: the optimal lengths are computed once per corner rule.
  MapReference ref(*map.grid, map.start, map.goal, context.config.collision);
  if (map.scen_optimum >= 0.0) ref.set_scenario_optimum(map.scen_optimum);
  if (!context.config.any_angle_reference) ref.skip_any_angle();
  for (const std::size_t p : planners) {
    const PlannerEntry& entry = context.config.planners.at(p);
    const RunOutput out = run_on_map(*workspace.planners.at(p).planner, ref, context.config.seed,
                                     cell.key, map_index, entry.label, workspace.scratch,
                                     Deadline::after(context.budget), context.config.motion);
    const PhaseScope timed(EnginePhase::record);
    on_run(MapTaskRun{context, task, p, slot, out, ref});
  }
  return map_facts_of(slot, ref);
}

}  // namespace agv
