#pragma once
// One map task, the unit of work of a sweep: the task's map is generated once and every planner
// asked for runs on it in the order given, each run measured by execute_run and recorded. The
// sweep runner does it in process (engine/sweep/sweep_runner.h); under --isolate a worker process
// does it (engine/sweep/isolated_worker.h). Both share this one function, so the runs, their random
// streams and their records cannot drift apart between the two modes.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "engine/outputs/run_record.h"
#include "engine/plan/sweep_plan.h"
#include "engine/plan/sweep_results.h"

namespace agv {

// What every map task of one sweep shares: the config, its plan and hash (made once, by the
// sweep's results or the worker process), the run budget.
struct MapTaskContext {
  MapTaskContext(const SweepConfig& config, const SweepPlan& plan, const std::string& config_hash);

  const SweepConfig& config;
  const SweepPlan& plan;
  const std::string& config_hash;
  std::chrono::nanoseconds budget;  // per run: the config's time_limit_s
};

// Per worker thread or worker process: its own planner objects (planners keep no shared state)
// and scratch buffers.
struct MapTaskWorkspace {
  std::vector<ConfiguredPlanner> planners;  // config order
  Scratch scratch;
};

// Every planner of the config, configured: one set per worker thread or worker process.
std::vector<ConfiguredPlanner> configure_planners(const SweepConfig& config);
// What is kept of a generated map.
MapSlot map_slot_of(const MapInstance& inst);
// The map slot of a task, its map generated anew (the parent of a worker that died before it
// recorded any run of the task). Throws what the generator throws.
MapSlot regenerate_map_slot(const MapTaskContext& context, std::int64_t task);

// One finished run of a map task, as handed to the caller.
struct MapTaskRun {
  const MapTaskContext& context;
  std::int64_t task;
  std::size_t planner;  // config index
  const MapSlot& map;
  const RunOutput& output;
  const MapReference& reference;  // the task's map and the references its runs computed

  // The map's facts as far as the runs so far computed them.
  MapFacts facts() const { return map_facts_of(map, reference); }
};

// A run as a journal records it.
// The slot of a run that produced none itself: its worker process died or was killed.
// `cpu_ns` is the worker's CPU time while the run was awaited (WorkerProcess::Reply), so its
// planning time is on the clock of every other run's; 0 when it could not be read (-1).
RunSlot lost_run_slot(Outcome outcome, std::int64_t cpu_ns);

// Generates the map of `task`, runs `planners` (config indices) on it in the order given and
// hands each run to `on_run` as soon as it is done. Returns the map's facts (its slot and the
// references the runs computed). Throws what the generator throws (a map that cannot be made
// fails the sweep, not a run).
MapFacts run_map_task(const MapTaskContext& context, std::int64_t task,
                      std::span<const std::size_t> planners, MapTaskWorkspace& workspace,
                      const std::function<void(const MapTaskRun&)>& on_run);

}  // namespace agv
