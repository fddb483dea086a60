#pragma once
// Where a sweep's results go as they are made: the runner hands its plan, each finished map
// task's runs, each finished cell and the end of the sweep to a list of sinks, in that order (the
// shape of Google Benchmark's reporters). The journal, the report, the SQLite database and the
// progress display are sinks (engine/outputs/journal_sink.h, engine/outputs/report_sink.h,
// engine/outputs/database_sink.h, cli/progress.h); the front-end picks them (SweepOptions::sinks).
//
// The runner calls the sinks one call at a time (never two at once, from whichever thread
// finished the task), each call on every sink in list order. A sink that cannot keep what it is
// handed (a full disk) throws SinkError (engine/outputs/sink_error.h): the sweep stops taking
// tasks, the task's runs count as not done (a resume runs them again), later sinks are not handed
// that task, and the results say the sweep is incomplete, naming the failure (sink_error).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/outputs/journal.h"
#include "engine/outputs/run_record.h"
#include "engine/outputs/sink_error.h"
#include "engine/plan/sweep_config.h"
#include "engine/plan/sweep_results.h"

namespace agv {

// What a sweep starts from.
struct SweepStart {
  const SweepConfig& config;
  const SweepResults& results;           // the plan, and the slots a resume restored
  std::int64_t runs_to_do = 0;           // the runs this call executes (its shard's, not restored)
  const JournalStats& restored;          // what a resume read from its journal
  const RunMessages& restored_messages;  // the restored runs' failure messages
};

// One finished run as the sinks get it.
struct RecordedRun {
  std::size_t planner;  // config index
  RunSlot slot;
  std::string message;  // a failure's, if any
};

// A map task's runs, done: all of them, or those an interruption left done.
struct TaskRuns {
  std::int64_t task = 0;
  const MapFacts& facts;                 // the map and the references its runs computed
  const std::vector<RecordedRun>& runs;  // in the order they ran
  // The task's journal lines (engine/outputs/journal_sink.h journal_lines), when the runner made
  // them before taking the sinks' lock; null otherwise.
  const std::string* journal_lines = nullptr;
};

class SweepSink {
 public:
  virtual ~SweepSink() = default;
  // Before the first task.
  virtual void start(const SweepStart&) {}
  // After each map task, its runs in their slots.
  virtual void task_done(const TaskRuns&) {}
  // After the last map task of a cell that this call runs: the cell's slots are complete (for
  // this shard).
  virtual void cell_done(const SweepCell&, const SweepResults&) {}
  // The runs are over (all done, interrupted, or stopped by a failure): make them durable.
  virtual void end_runs() {}
  // The results are final, completeness known. Not called when a map task failed: the sweep
  // throws that failure and writes nothing more.
  virtual void finish(const SweepResults&) {}
};

}  // namespace agv
