#pragma once
// The parallel sweep: oneTBB over map tasks; each task generates its map once and runs every
// planner on it in config order (engine/sweep/map_task.h), so all planners see the same maps
// (paired comparisons). Only a few scalars per run are kept (engine/plan/sweep_results.h), indexed
// by cell and task, so every statistic is computed afterwards in task order and is identical on any
// thread count; paths and per-run records stream out.

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "engine/outputs/sweep_sink.h"
#include "engine/plan/sweep_results.h"
#include "engine/sweep/isolated_worker.h"

namespace agv {

struct SweepOptions {
  int threads = 0;  // 0 = all hardware threads
  // Where the results go besides the journal (engine/outputs/sweep_sink.h), in this order: the
  // report, the database, the progress display, a test's probe. Not owned.
  std::vector<SweepSink*> sinks;
  // The journal (JSON Lines of per-run records), the first sink, which run_sweep makes itself
  // because a resume reads it too; empty = none.
  std::string runs_path;
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
  // Once a cell's tasks of this call are done and the sinks had it, keep its digest (report
  // entry, coverage, summary tallies: engine/outputs/report.h digest_cell) and free its run slots,
  // so memory stays bounded however many cells the sweep has. The results' slots of such a cell are
  // then gone: set it only when nothing reads them afterwards (`run` sets it unless --db).
  bool release_cells = false;
};

// The journal a sweep with these options writes ("" = none): a resumed sweep appends to the one
// it restores. Throws InputError when runs_path names another file.
std::string journal_path_of(const SweepOptions& options);

// Runs the sweep into `results` (empty_results of the config, whose plan and hash it uses),
// handing it to the journal and options.sinks as it goes. Throws InputError for bad configs and
// std::runtime_error for failures such as a generator that cannot produce a solvable map (then
// no sink's finish is called), and what a sink's finish throws (a report that cannot be
// written). A sink's failure during the runs is not thrown: results.sink_error names it.
void run_sweep(const SweepConfig& config, SweepResults& results, const SweepOptions& options);
// The same into fresh results.
SweepResults run_sweep(const SweepConfig& config, const SweepOptions& options);

}  // namespace agv
