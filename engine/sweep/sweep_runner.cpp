#include "engine/sweep/sweep_runner.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>

#include "core/input_error.h"
#include "core/json_text.h"
#include "core/printable.h"
#include "engine/outputs/journal.h"
#include "engine/outputs/journal_sink.h"
#include "engine/outputs/report.h"
#include "engine/outputs/sweep_identity.h"
#include "engine/sweep/map_task.h"
#include "engine/system/phase_clock.h"

namespace agv {

namespace {

void check_shard(const SweepOptions& options) {
  if (options.shard_count < 1 || options.shard_index < 0 ||
      options.shard_index >= options.shard_count)
    throw InputError("--shard: index must be in [0, count)");
}

// The map tasks of this call's shard with a planner still to run, and how many runs they hold
// (progress counts runs: map tasks differ in planners, by scopes and resumes).
struct Todo {
  std::vector<std::int64_t> tasks;
  std::int64_t runs = 0;
};

Todo pending_tasks(const SweepResults& res, const SweepOptions& options) {
  Todo todo;
  for (std::int64_t t = 0; t < res.plan.map_tasks(); ++t) {
    if (t % options.shard_count != options.shard_index) continue;
    const std::size_t pending = res.pending_planners(t).size();
    if (pending == 0) continue;
    todo.tasks.push_back(t);
    todo.runs += static_cast<std::int64_t>(pending);
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
  nlohmann::json first = {{"config", config_as_run(config)}, {"base_dir", config.base_dir}};
  // A folder named in bytes that are not UTF-8 would reach the worker as U+FFFD: sent as hex.
  if (!is_utf8(config.base_dir)) first["base_dir_hex"] = to_hex(config.base_dir);
  // So would a plugin's path (a plugin in that folder): the config's "plugins" in hex, in order.
  const bool odd_plugin_path = std::any_of(config.plugins.begin(), config.plugins.end(),
                                           [](const PluginRecord& p) { return !is_utf8(p.path); });
  if (odd_plugin_path) {
    nlohmann::json paths = nlohmann::json::array();
    for (const PluginRecord& p : config.plugins) paths.push_back(to_hex(p.path));
    first["plugin_paths_hex"] = std::move(paths);
  }
  launch.config_line = json_text(first);
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
  SweepState(const MapTaskContext& task_context, SweepResults& sweep_results)
      : context(task_context),
        results(sweep_results),
        restorer(sweep_results),
        header(journal_header(task_context.config_hash, task_context.config, task_context.plan,
                              sweep_results.sweep_id)) {}

  const MapTaskContext& context;
  SweepResults& results;
  RecordRestorer restorer;  // worker records into slots
  std::string header;       // this sweep's journal header: worker replies are decoded under it
  std::atomic<std::int64_t> executed{0};
  std::atomic<bool> cut{false};  // an interruption cut runs short: they are not recorded
};

// A map task's runs, done, as the sinks get them.
struct TaskDone {
  MapFacts facts;
  std::vector<RecordedRun> runs;
};

// Runs the task's pending `planners` in this thread.
TaskDone run_task_in_process(SweepState& s, MapTaskWorkspace& workspace, std::int64_t task,
                             const std::vector<std::size_t>& planners) {
  TaskDone done;
  done.facts = run_map_task(s.context, task, planners, workspace, [&](const MapTaskRun& run) {
    RunSlot slot = run_slot_of(run.output);
    done.runs.push_back({run.planner, slot, run.output.message});
    s.results.store(task, run.planner, std::move(slot), run.map);
    ++s.executed;
  });
  return done;
}

// A worker's reply decoded, or nullopt when its lines are not records (the worker is stopped and
// the run recorded as a crash, as when it dies: whatever garbled them was in that process).
std::optional<std::pair<DecodedRecord, DecodedRecord>> decode_reply(JournalDecoder& decoder,
                                                                    WorkerProcess::Reply& reply,
                                                                    WorkerProcess& process) {
  try {
    DecodedRecord map = decoder.decode_line(reply.map_line, "worker record");
    DecodedRecord run = decoder.decode_line(reply.run_line, "worker record");
    return std::make_pair(std::move(map), std::move(run));
  } catch (const InputError& e) {
    process.stop();
    reply.outcome = Outcome::crash;
    reply.message = std::string("worker sent a malformed record: ") + e.what();
    return std::nullopt;
  }
}

// A lost run's message: why, and the parent's wall-clock wait beside the CPU time its slot
// holds (the CPU time unknown when the worker's clock could not be read).
std::string lost_run_message(const WorkerProcess::Reply& reply) {
  char clocks[96];
  if (reply.cpu_ns >= 0)
    std::snprintf(clocks, sizeof clocks, " (wall %.3f s, CPU %.3f s)",
                  static_cast<double>(reply.wall_ns) * 1e-9,
                  static_cast<double>(reply.cpu_ns) * 1e-9);
  else
    std::snprintf(clocks, sizeof clocks, " (wall %.3f s, CPU time unknown)",
                  static_cast<double>(reply.wall_ns) * 1e-9);
  return reply.message + clocks;
}

// Runs the task's pending planners in this thread's worker process. A run the worker does not
// answer (it hung, died or sent garbage) is recorded here with its outcome, and a fresh worker
// takes the task's remaining planners. A run an interruption cut short is not recorded: the task's
// remaining planners stay pending for a resume.
TaskDone run_task_isolated(SweepState& s, WorkerProcess& process, double hard_limit_s,
                           std::int64_t task, const std::vector<std::size_t>& planners) {
  TaskDone done;
  std::vector<RecordedRun>& recorded = done.runs;
  MapFacts& facts = done.facts;
  JournalDecoder decoder;  // this task's: its map's facts accumulate over the replies
  decoder.decode_line(s.header, "journal header");
  std::size_t next = 0;
  while (next < planners.size()) {
    process.start_task(task, std::span(planners).subspan(next));
    bool alive = true;
    while (alive && next < planners.size()) {
      const std::size_t p = planners[next++];
      WorkerProcess::Reply reply = process.next_run(hard_limit_s);
      if (reply.cut) {
        s.cut = true;
        return done;
      }
      std::optional<std::pair<DecodedRecord, DecodedRecord>> records;
      if (reply.ok) records = decode_reply(decoder, reply, process);
      alive = records.has_value();
      if (records) {
        auto& [map, run] = *records;
        if (map.kind != DecodedRecord::Kind::map || run.kind != DecodedRecord::Kind::run ||
            run.planner != s.results.labels.at(p) || map.cell != s.context.plan.cell_of(task).key ||
            map.map_index != s.context.plan.map_index_of(task) || run.map_index != map.map_index)
          throw std::runtime_error("worker answered with the record of another run");
        facts = map.map;
        s.restorer.restore(run, "worker record");
        recorded.push_back({p, std::move(run.run), std::move(run.message)});
      } else {
        MapSlot& ms = s.results.map(task);
        if (!ms.done) ms = regenerate_map_slot(s.context, task);
        if (!facts.slot.done) facts.slot = ms;
        RunSlot slot = lost_run_slot(reply.outcome, reply.cpu_ns);
        recorded.push_back({p, slot, lost_run_message(reply)});
        s.results.store(task, p, std::move(slot), ms);
      }
      ++s.executed;
    }
  }
  return done;
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
  // A sink's failure (a journal write) stops the sweep too, but is no error of a map task: the
  // report is still written (incomplete) and the message names only the sink's file.
  void record_sink(const SinkError& e) {
    std::lock_guard lock(mutex_);
    if (sink_error_.empty()) sink_error_ = e.what();
    failed_ = true;
  }
  std::string sink_error() {
    std::lock_guard lock(mutex_);
    return sink_error_;
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
  std::string sink_error_;
  std::atomic<bool> failed_{false};
};

// The sweep's sinks (engine/outputs/sweep_sink.h), called one at a time, in list order; counts the
// map tasks each cell has still to finish.
class SinkCalls {
 public:
  // release: a finished cell's run slots are freed once the sinks had it, its digest kept.
  // journal: the sweep has a journal sink, whose lines are then made before the lock.
  SinkCalls(std::vector<SweepSink*> sinks, const SweepConfig& config, SweepResults& results,
            const Todo& todo, bool release, bool journal)
      : sinks_(std::move(sinks)),
        config_(config),
        results_(results),
        tasks_left_(results.plan.cells.size(), 0),
        release_(release),
        journal_(journal) {
    for (const std::int64_t t : todo.tasks) ++tasks_left_[cell_index(t)];
  }

  void start(const SweepStart& start) {
    for (SweepSink* sink : sinks_) sink->start(start);
  }
  // The task's runs to every sink, then its cell when `whole` made it the cell's last task.
  // Throws SinkError.
  void task_done(std::int64_t task, const TaskDone& done, bool whole) {
    // The journal's lines need nothing the lock guards: made by this thread, only their write
    // waits for the others (perf/README.md "Thread scaling beyond two cores").
    std::string lines;
    if (journal_ && !done.runs.empty()) {
      const PhaseScope timed(EnginePhase::record);
      lines = journal_lines(results_.plan, task, done.facts, done.runs);
    }
    std::lock_guard lock(mutex_);
    const PhaseScope timed(EnginePhase::sinks);  // after the lock: its wait is no CPU of ours
    const TaskRuns runs{task, done.facts, done.runs, journal_ ? &lines : nullptr};
    for (SweepSink* sink : sinks_) sink->task_done(runs);
    if (!whole || --tasks_left_[cell_index(task)] > 0) return;
    const SweepCell& cell = results_.plan.cell_of(task);
    for (SweepSink* sink : sinks_) sink->cell_done(cell, results_);
    if (release_) results_.release(cell, digest_cell(config_, results_, cell));
  }
  // Every sink's end of the runs, also after a failure; returns the first SinkError's message.
  std::string end_runs() {
    std::string error;
    for (SweepSink* sink : sinks_) {
      try {
        sink->end_runs();
      } catch (const SinkError& e) {
        if (error.empty()) error = e.what();
      }
    }
    return error;
  }
  void finish(const SweepResults& results) {
    for (SweepSink* sink : sinks_) sink->finish(results);
  }

 private:
  std::size_t cell_index(std::int64_t task) const {
    return static_cast<std::size_t>(results_.plan.cell_of(task).index);
  }

  std::vector<SweepSink*> sinks_;
  const SweepConfig& config_;
  SweepResults& results_;
  std::vector<std::int64_t> tasks_left_;  // by cell index
  bool release_;
  bool journal_;
  std::mutex mutex_;
};

// Runs `todo` over oneTBB until every task is done, a task fails or a stop is requested (runs
// in flight finish unless cut short). Returns whether an interruption left runs undone.
bool run_tasks(SweepState& state, const Todo& todo, const SweepOptions& options, SinkCalls& sinks,
               FirstFailure& failure) {
  const bool isolated = options.isolation.enabled;
  const WorkerLaunch launch = worker_launch(state.context.config, options.isolation);
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
  const auto run_task = [&](std::int64_t task) {
    // Worked out once here (no other thread writes this task's slots) and handed on.
    const std::vector<std::size_t> planners = state.results.pending_planners(task);
    try {
      Worker& w = workers.local();  // may start an isolation worker, which may fail
      const TaskDone done =
          isolated ? run_task_isolated(state, *w.process, launch.hard_limit_s, task, planners)
                   : run_task_in_process(state, w.workspace, task, planners);
      try {
        sinks.task_done(task, done, done.runs.size() == planners.size());
      } catch (const SinkError& e) {
        // A sink lost the task's runs: not done, so the report is incomplete and a resume runs
        // them again.
        for (const std::size_t p : planners) state.results.run(task, p).done = false;
        failure.record_sink(e);
      }
    } catch (const RunsCut&) {
      state.cut = true;  // a worker not yet ready when the cut came: no run to record
    } catch (const std::exception& e) {
      failure.record(state.results.plan, task, e);
    }
  };
  // Every thread takes the next task in plan order as it becomes free (rather than oneTBB
  // splitting the range, which starts the second thread half-way through the sweep): a cell's
  // tasks run together and the cells finish one after another, at most one task per thread in
  // flight, so each finished cell can be summarised and released.
  std::atomic<std::size_t> next{0};
  // A cell's run slots are allocated as its first task is taken, before any thread reads them.
  std::mutex allocation;
  const auto allocate_cell = [&](std::int64_t task) {
    std::lock_guard lock(allocation);
    state.results.allocate(state.results.plan.cell_of(task));
  };
  tbb::parallel_for(
      0, state.results.threads,
      [&](int) {
        for (std::size_t i; (i = next++) < todo.tasks.size();) {
          if (failure.failed()) return;
          if ((options.stop != nullptr && options.stop->load()) || state.cut.load()) {
            stopped = true;
            return;
          }
          allocate_cell(todo.tasks[i]);
          run_task(todo.tasks[i]);
        }
      },
      tbb::simple_partitioner());
  return stopped.load() || state.cut.load();
}

}  // namespace

std::string journal_path_of(const SweepOptions& options) {
  if (options.resume_path.empty()) return options.runs_path;
  if (!options.runs_path.empty() && options.runs_path != options.resume_path)
    throw InputError(
        "--resume: the journal is appended to; --runs-out must be empty or the same file");
  return options.resume_path;
}

void run_sweep(const SweepConfig& config, SweepResults& res, const SweepOptions& options) {
  check_shard(options);
  res.shard_index = options.shard_index;
  res.shard_count = options.shard_count;
  const MapTaskContext context(config, res.plan, res.config_hash);

  const bool resume = !options.resume_path.empty();
  const std::string journal_path = journal_path_of(options);
  JournalStats restored;
  RunMessages restored_messages;
  // With release_cells, the cells the journal completes are released as they are read.
  if (resume)
    restored = restore_journal_to_resume(options.resume_path, res, &restored_messages,
                                         options.release_cells ? &config : nullptr);
  res.restored_runs = restored.records;
  // A resume goes on with its journal's last sweep; anything else is a sweep of its own.
  res.sweep_id = restored.has_header ? restored.sweep_id : new_sweep_id();
  res.add_sweep(res.sweep_id);
  // The journal is the first sink: what the others are handed is on disk first.
  std::optional<JournalSink> journal;
  if (!journal_path.empty()) journal.emplace(journal_path, resume);
  std::vector<SweepSink*> sinks;
  if (journal) sinks.push_back(&*journal);
  sinks.insert(sinks.end(), options.sinks.begin(), options.sinks.end());

  res.threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            static_cast<std::size_t>(res.threads));

  const Todo todo = pending_tasks(res, options);
  SinkCalls calls(std::move(sinks), config, res, todo, options.release_cells, journal.has_value());
  calls.start({config, res, todo.runs, restored, restored_messages});
  SweepState state(context, res);
  FirstFailure failure;
  const auto t0 = std::chrono::steady_clock::now();
  res.interrupted = run_tasks(state, todo, options, calls, failure);
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.executed_runs = state.executed.load();
  res.sink_error = failure.sink_error();
  const std::string end_error = calls.end_runs();
  if (res.sink_error.empty()) res.sink_error = end_error;
  update_completeness(res);
  // Runs whose records may not have reached the disk: the sweep's record is not complete.
  if (!res.sink_error.empty()) res.complete = false;
  failure.rethrow();
  calls.finish(res);
}

SweepResults run_sweep(const SweepConfig& config, const SweepOptions& options) {
  SweepResults res = empty_results(config);
  run_sweep(config, res, options);
  return res;
}

}  // namespace agv
