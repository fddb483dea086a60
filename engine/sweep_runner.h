#pragma once
// The parallel sweep: oneTBB over map tasks; each task generates its map once and runs every
// planner on it in config order (engine/map_task.h), so all planners see the same maps (paired
// comparisons). Only a few scalars per run are kept (engine/sweep_results.h), indexed by cell and
// task, so every statistic is computed afterwards in task order and is identical on any thread
// count; paths and per-run records stream out.

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "engine/isolated_worker.h"
#include "engine/sweep_results.h"

namespace agv {

// done, total: the runs of this call (a resume's restored runs are not among them).
using SweepProgress = std::function<void(std::int64_t done, std::int64_t total)>;

struct SweepOptions {
  int threads = 0;  // 0 = all hardware threads
  // Progress, in runs: called once with done = 0 before the first task, then after each map task
  // with the runs done so far, from the worker threads but one call at a time (done never
  // decreases). Empty = none. The command line draws its meter from it (cli/progress.h).
  SweepProgress progress;
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

// Runs the sweep into `results` (empty_results of the config, whose plan and hash it uses).
// Throws InputError for bad configs and std::runtime_error for failures such as a generator that
// cannot produce a solvable map.
void run_sweep(const SweepConfig& config, SweepResults& results, const SweepOptions& options);
// The same into fresh results.
SweepResults run_sweep(const SweepConfig& config, const SweepOptions& options);

}  // namespace agv
