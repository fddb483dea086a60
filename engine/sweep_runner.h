#pragma once
// The parallel sweep: oneTBB over map tasks; each task generates its map once and runs every
// planner on it in config order (engine/map_task.h), so all planners see the same maps (paired
// comparisons). Only a few scalars per run are kept, indexed by task, so every statistic is
// computed afterwards in task order and is identical on any thread count; paths and per-run
// records stream out.

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "engine/isolated_worker.h"
#include "engine/run_executor.h"
#include "engine/sweep_plan.h"

namespace agv {

// What is kept of one run after its record has been streamed.
struct RunSlot {
  bool done = false;
  Outcome outcome = Outcome::crash;
  RunMetrics metrics{};
  std::int64_t plan_time_ns = 0;
  std::vector<PhaseTime> phases;
  std::vector<std::pair<std::string, double>> extra;
};

// What is kept of one map.
struct MapSlot {
  bool done = false;
  int rejections = 0;
  double obstacle_fraction = 0.0;
};

struct SweepResults {
  SweepPlan plan;
  std::vector<std::string> labels;  // planner labels, config order
  std::vector<MapSlot> maps;        // by map task
  std::vector<RunSlot> runs;        // by map task * labels.size() + planner
  // By cell * labels.size() + planner: the planner runs on the cell's first N maps (scopes).
  std::vector<int> scoped_maps;
  double wall_s = 0.0;
  int threads = 0;
  bool complete = true;      // every scheduled run of the sweep is present
  bool interrupted = false;  // stopped before its tasks were done
  std::int64_t restored_runs = 0;
  std::int64_t executed_runs = 0;
  int shard_index = 0;
  int shard_count = 1;
  // Set when a journal write failed: the sweep stopped taking tasks, the runs the journal lost
  // are not counted as done and `complete` is false (the message names the journal and the OS
  // error).
  std::string journal_error;

  int maps_of(const SweepCell& cell, std::size_t planner) const {
    return scoped_maps[static_cast<std::size_t>(cell.index) * labels.size() + planner];
  }
  // Whether the sweep runs this planner on this map task at all.
  bool scheduled(std::int64_t task, std::size_t planner) const {
    return plan.map_index_of(task) < maps_of(plan.cell_of(task), planner);
  }
  RunSlot& run(std::int64_t task, std::size_t planner) {
    return runs[static_cast<std::size_t>(task) * labels.size() + planner];
  }
  const RunSlot& run(std::int64_t task, std::size_t planner) const {
    return runs[static_cast<std::size_t>(task) * labels.size() + planner];
  }
};

struct SweepOptions {
  int threads = 0;        // 0 = all hardware threads
  bool progress = false;  // progress line on stderr
  std::string runs_path;  // JSON Lines of per-run records (the journal); empty = none
  // Resume: restore the runs recorded in this journal, run only the others, and append their
  // records to it (runs_path must then be empty or the same file).
  std::string resume_path;
  // Sharding: run only map tasks t with t % shard_count == shard_index. Split by map, so every
  // planner of a map runs in the same shard and paired comparisons stay whole.
  int shard_index = 0;
  int shard_count = 1;
  // Set (by a signal handler, say) to stop taking new map tasks; runs in flight finish.
  const std::atomic<bool>* stop = nullptr;
  // Set as well to cut the runs in flight short: under isolation their workers are killed and
  // the runs are not recorded (a resume runs them); in process they end at their deadline.
  const std::atomic<bool>* cut_short = nullptr;
  IsolationOptions isolation;
};

// How much of a sweep's results are present: the report's `coverage`.
struct Coverage {
  std::int64_t runs_expected = 0;  // scheduled runs (planner scopes counted)
  std::int64_t runs_present = 0;
  std::int64_t maps_missing = 0;  // map tasks with no run at all
};
Coverage coverage_of(const SweepResults& results);

// Empty results shaped for the config: every slot present, none done (resume and merge fill them).
SweepResults empty_results(const SweepConfig& config);
// Recomputes `complete` (every scheduled run present) from the slots.
void update_completeness(SweepResults& results);

// Runs the sweep. Throws InputError for bad configs and std::runtime_error for failures such as
// a generator that cannot produce a solvable map.
SweepResults run_sweep(const SweepConfig& config, const SweepOptions& options);

}  // namespace agv
