#include "engine/sweep_runner.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>

#include "core/input_error.h"
#include "engine/journal.h"
#include "engine/json_text.h"
#include "engine/map_task.h"
#include "engine/progress.h"

namespace agv {

namespace {

void fill_run_slot(RunSlot& slot, const RunOutput& out) {
  slot.outcome = out.outcome;
  slot.metrics = out.metrics;
  slot.plan_time_ns = out.plan_time_ns;
  slot.phases = out.result.phases;
  slot.extra = out.result.extra;
  slot.done = true;
}

}  // namespace

SweepResults empty_results(const SweepConfig& config) {
  SweepResults res;
  res.plan = plan_sweep(config);
  for (const auto& p : config.planners) res.labels.push_back(p.label);
  const std::int64_t tasks = res.plan.map_tasks();
  res.maps.resize(static_cast<std::size_t>(tasks));
  res.runs.resize(static_cast<std::size_t>(tasks) * res.labels.size());
  for (auto& r : res.runs) r.metrics.fill(std::numeric_limits<double>::quiet_NaN());
  for (const auto& cell : res.plan.cells)
    for (const auto& p : config.planners) res.scoped_maps.push_back(scoped_maps(p, cell));
  return res;
}

Coverage coverage_of(const SweepResults& r) {
  Coverage c;
  for (const int maps : r.scoped_maps) c.runs_expected += maps;
  for (std::int64_t t = 0; t < r.plan.map_tasks(); ++t) {
    bool any = false;
    for (std::size_t p = 0; p < r.labels.size(); ++p) any = any || r.run(t, p).done;
    c.maps_missing += any ? 0 : 1;
  }
  for (const auto& s : r.runs) c.runs_present += s.done ? 1 : 0;
  return c;
}

void update_completeness(SweepResults& results) {
  // Only scheduled runs can be done: the runner skips the others and the journal refuses them.
  const Coverage c = coverage_of(results);
  results.complete = c.runs_present == c.runs_expected;
}

namespace {

void check_shard(const SweepOptions& options) {
  if (options.shard_count < 1 || options.shard_index < 0 ||
      options.shard_index >= options.shard_count)
    throw InputError("--shard: index must be in [0, count)");
}

// The journal this call writes: a resumed sweep appends to the one it restores.
std::string journal_path_of(const SweepOptions& options) {
  if (options.resume_path.empty()) return options.runs_path;
  if (!options.runs_path.empty() && options.runs_path != options.resume_path)
    throw InputError(
        "--resume: the journal is appended to; --runs-out must be empty or the same file");
  return options.resume_path;
}

// The planners of `task` still to run: scheduled there and not restored, in config order.
std::vector<std::size_t> pending_planners(const SweepResults& res, std::int64_t task) {
  std::vector<std::size_t> pending;
  for (std::size_t p = 0; p < res.labels.size(); ++p)
    if (res.scheduled(task, p) && !res.run(task, p).done) pending.push_back(p);
  return pending;
}

// The map tasks of this call's shard with a planner still to run.
std::vector<std::int64_t> pending_tasks(const SweepResults& res, const SweepOptions& options) {
  std::vector<std::int64_t> todo;
  for (std::int64_t t = 0; t < res.plan.map_tasks(); ++t) {
    if (t % options.shard_count != options.shard_index) continue;
    if (!pending_planners(res, t).empty()) todo.push_back(t);
  }
  return todo;
}

// How an isolated sweep starts its worker processes and bounds their runs.
struct WorkerLaunch {
  std::vector<std::string> command;
  std::string config_line;
  double hard_limit_s = 0.0;
};

WorkerLaunch worker_launch(const SweepConfig& config, const IsolationOptions& iso) {
  WorkerLaunch launch;
  launch.command = iso.command;
  if (launch.command.empty()) launch.command = {"/proc/self/exe", "worker"};
  launch.config_line =
      nlohmann::json{{"config", config_as_run(config)}, {"base_dir", config.base_dir}}.dump();
  launch.hard_limit_s = iso.hard_limit_s > 0 ? iso.hard_limit_s : 2.0 * config.time_limit_s + 1.0;
  return launch;
}

// Per worker thread: in process, its own planners and scratch; isolated, its own worker process.
struct Worker {
  MapTaskWorkspace workspace;
  std::unique_ptr<WorkerProcess> process;
};

// What the map tasks of one run_sweep call share. Each task's slots are written by the one
// thread that runs it.
struct SweepState {
  SweepState(const MapTaskContext& task_context, SweepResults& sweep_results, bool journaled)
      : context(task_context),
        results(sweep_results),
        restorer(task_context.config_hash, sweep_results),
        keep_lines(journaled) {}

  const MapTaskContext& context;
  SweepResults& results;
  RecordRestorer restorer;  // worker records into slots
  bool keep_lines;          // whether the runs' records become journal lines
  std::atomic<std::int64_t> executed{0};
  std::atomic<bool> cut{false};  // an interruption cut runs short: they are not recorded
};

// Runs the task's pending planners in this thread; returns their journal lines.
std::string run_task_in_process(SweepState& s, MapTaskWorkspace& workspace, std::int64_t task) {
  std::string lines;
  const std::vector<std::size_t> planners = pending_planners(s.results, task);
  s.results.maps[static_cast<std::size_t>(task)] =
      run_map_task(s.context, task, planners, workspace, [&](const MapTaskRun& run) {
        fill_run_slot(s.results.run(task, run.planner), run.output);
        ++s.executed;
        if (s.keep_lines) lines += json_text(run.record()) + '\n';
      });
  return lines;
}

// Runs the task's pending planners in this thread's worker process; returns their journal
// lines. A run the worker does not answer (it hung, died or sent garbage) is recorded here with
// its outcome, and a fresh worker takes the task's remaining planners. A run an interruption cut
// short is not recorded: the task's remaining planners stay pending for a resume.
std::string run_task_isolated(SweepState& s, WorkerProcess& process, double hard_limit_s,
                              std::int64_t task) {
  std::string lines;
  const std::vector<std::size_t> planners = pending_planners(s.results, task);
  std::size_t next = 0;
  while (next < planners.size()) {
    process.start_task(task, std::span(planners).subspan(next));
    bool alive = true;
    while (alive && next < planners.size()) {
      const std::size_t p = planners[next++];
      WorkerProcess::Reply reply = process.next_run(hard_limit_s);
      if (reply.cut) {
        s.cut = true;
        return lines;
      }
      alive = reply.ok;
      nlohmann::json record;
      if (reply.ok) {
        record = std::move(reply.record);
      } else {
        MapSlot& ms = s.results.maps[static_cast<std::size_t>(task)];
        if (!ms.done) ms = regenerate_map_slot(s.context, task);
        record =
            lost_run_record(s.context, task, p, ms, reply.outcome, reply.message, reply.wall_ns);
      }
      s.restorer.restore(record, "worker record");
      ++s.executed;
      if (s.keep_lines) lines += json_text(record) + '\n';
    }
  }
  return lines;
}

// The first failure of any map task: the sweep stops taking tasks and throws it at the end,
// as an InputError when the config or a map's input caused it.
class FirstFailure {
 public:
  void record(const SweepPlan& plan, std::int64_t task, const std::exception& e) {
    std::lock_guard lock(mutex_);
    if (!message_) {
      message_ = "cell " + plan.cell_of(task).key + ", map " +
                 std::to_string(plan.map_index_of(task)) + ": " + e.what();
      is_input_ = dynamic_cast<const std::invalid_argument*>(&e) != nullptr ||
                  dynamic_cast<const InputError*>(&e) != nullptr;
    }
    failed_ = true;
  }
  // A journal write failure stops the sweep too, but is no error of a map task: the report is
  // still written (incomplete) and the message names only the journal.
  void record_journal(const JournalError& e) {
    std::lock_guard lock(mutex_);
    if (journal_error_.empty()) journal_error_ = e.what();
    failed_ = true;
  }
  std::string journal_error() {
    std::lock_guard lock(mutex_);
    return journal_error_;
  }
  bool failed() const { return failed_.load(std::memory_order_relaxed); }
  void rethrow() const {
    if (!message_) return;
    if (is_input_) throw InputError(*message_);
    throw std::runtime_error(*message_);
  }

 private:
  std::mutex mutex_;
  std::optional<std::string> message_;
  bool is_input_ = false;
  std::string journal_error_;
  std::atomic<bool> failed_{false};
};

// Runs `todo` over oneTBB until every task is done, a task fails or a stop is requested (runs
// in flight finish unless cut short). Returns whether an interruption left runs undone.
bool run_tasks(SweepState& state, const std::vector<std::int64_t>& todo,
               const SweepOptions& options, JournalWriter& journal, FirstFailure& failure) {
  const bool isolated = options.isolation.enabled;
  const WorkerLaunch launch = worker_launch(state.context.config, options.isolation);
  std::int64_t runs_to_do = 0;  // the meter counts runs: map tasks differ in planners (scopes)
  for (const std::int64_t task : todo)
    runs_to_do += static_cast<std::int64_t>(pending_planners(state.results, task).size());
  ProgressMeter progress(runs_to_do, options.progress);
  tbb::enumerable_thread_specific<Worker> workers([&] {
    Worker w;
    if (isolated) {
      w.process = std::make_unique<WorkerProcess>(launch.command, options.isolation.memory_mb,
                                                  launch.config_line, options.cut_short);
    } else {
      w.workspace.planners = configure_planners(state.context.config);
    }
    return w;
  });
  std::atomic<bool> stopped{false};
  tbb::parallel_for(std::size_t{0}, todo.size(), [&](std::size_t i) {
    if (failure.failed()) return;
    if ((options.stop != nullptr && options.stop->load()) || state.cut.load()) {
      stopped = true;
      return;
    }
    const std::int64_t task = todo[i];
    const std::size_t planners_of_task = pending_planners(state.results, task).size();
    try {
      Worker& w = workers.local();  // may start an isolation worker, which may fail
      const std::vector<std::size_t> planners = pending_planners(state.results, task);
      const std::string lines =
          isolated ? run_task_isolated(state, *w.process, launch.hard_limit_s, task)
                   : run_task_in_process(state, w.workspace, task);
      if (journal.enabled() && !lines.empty()) {
        try {
          journal.write(lines);
        } catch (const JournalError& e) {
          // The task's runs are not in the journal: not done, so the report is incomplete and a
          // resume runs them again.
          for (const std::size_t p : planners) state.results.run(task, p).done = false;
          failure.record_journal(e);
        }
      }
    } catch (const RunsCut&) {
      state.cut = true;  // a worker not yet ready when the cut came: no run to record
    } catch (const std::exception& e) {
      failure.record(state.results.plan, task, e);
    }
    progress.advance(static_cast<std::int64_t>(planners_of_task));
  });
  progress.finish();
  return stopped.load() || state.cut.load();
}

}  // namespace

SweepResults run_sweep(const SweepConfig& config, const SweepOptions& options) {
  check_shard(options);
  SweepResults res = empty_results(config);
  res.shard_index = options.shard_index;
  res.shard_count = options.shard_count;
  const MapTaskContext context(config);

  const bool resume = !options.resume_path.empty();
  const std::string journal_path = journal_path_of(options);
  if (resume)
    res.restored_runs = restore_journal(options.resume_path, context.config_hash, res).records;
  JournalWriter journal(journal_path, resume);

  res.threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            static_cast<std::size_t>(res.threads));

  const std::vector<std::int64_t> todo = pending_tasks(res, options);
  SweepState state(context, res, journal.enabled());
  FirstFailure failure;
  const auto t0 = std::chrono::steady_clock::now();
  res.interrupted = run_tasks(state, todo, options, journal, failure);
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.executed_runs = state.executed.load();
  res.journal_error = failure.journal_error();
  if (res.journal_error.empty()) {
    try {
      journal.finish();
    } catch (const JournalError& e) {
      res.journal_error = e.what();
    }
  }
  update_completeness(res);
  // Runs whose records may not have reached the disk: the sweep's record is not complete.
  if (!res.journal_error.empty()) res.complete = false;
  failure.rethrow();
  return res;
}

}  // namespace agv
