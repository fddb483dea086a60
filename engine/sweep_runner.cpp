#include "engine/sweep_runner.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>

#include "engine/journal.h"
#include "engine/progress.h"
#include "engine/run_record.h"

namespace agv {

namespace {

// Per worker thread: scratch buffers and its own planner objects (planners keep no shared
// state), or, isolated, its own worker process.
struct Worker {
  Scratch scratch;
  std::vector<ConfiguredPlanner> planners;
  std::unique_ptr<WorkerProcess> process;
};


void fill_run_slot(RunSlot& slot, const RunOutput& out) {
  slot.outcome = out.outcome;
  slot.metrics = out.metrics;
  slot.plan_time_ns = out.plan_time_ns;
  slot.phases = out.result.phases;
  slot.extra = out.result.extra;
  slot.done = true;
}

}  // namespace

std::vector<ConfiguredPlanner> configure_planners(const SweepConfig& config) {
  std::vector<ConfiguredPlanner> planners;
  for (std::size_t i = 0; i < config.planners.size(); ++i) {
    const auto& p = config.planners[i];
    planners.push_back(configure_planner(p.name, p.params, "planners[" + std::to_string(i) + "]"));
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

SweepResults empty_results(const SweepConfig& config) {
  SweepResults res;
  res.plan = plan_sweep(config);
  for (const auto& p : config.planners) res.labels.push_back(p.label);
  const std::int64_t tasks = res.plan.map_tasks();
  res.maps.resize(static_cast<std::size_t>(tasks));
  res.runs.resize(static_cast<std::size_t>(tasks) * res.labels.size());
  for (auto& r : res.runs) r.metrics.fill(std::numeric_limits<double>::quiet_NaN());
  for (const auto& cell : res.plan.cells)
    for (const auto& p : config.planners)
      res.scoped_maps.push_back(scoped_maps(p, cell, res.plan.maps_per_cell));
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

SweepResults run_sweep(const SweepConfig& config, const SweepOptions& options) {
  if (options.shard_count < 1 || options.shard_index < 0 ||
      options.shard_index >= options.shard_count)
    throw InputError("--shard: index must be in [0, count)");
  SweepResults res = empty_results(config);
  res.shard_index = options.shard_index;
  res.shard_count = options.shard_count;
  const std::int64_t tasks = res.plan.map_tasks();
  const std::string hash = config_hash(config);

  std::string journal_path = options.runs_path;
  if (!options.resume_path.empty()) {
    if (!journal_path.empty() && journal_path != options.resume_path)
      throw InputError("--resume: the journal is appended to; --runs-out must be empty or the same file");
    journal_path = options.resume_path;
    res.restored_runs = restore_journal(options.resume_path, hash, res).records;
  }
  JournalWriter journal(journal_path, !options.resume_path.empty());

  const int hw = tbb::info::default_concurrency();
  res.threads = options.threads > 0 ? options.threads : hw;
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            static_cast<std::size_t>(res.threads));

  // The map tasks this call must (still) run.
  std::vector<std::int64_t> todo;
  for (std::int64_t t = 0; t < tasks; ++t) {
    if (t % options.shard_count != options.shard_index) continue;
    bool pending = false;
    for (std::size_t p = 0; p < res.labels.size(); ++p)
      pending = pending || (res.scheduled(t, p) && !res.run(t, p).done);
    if (pending) todo.push_back(t);
  }

  const IsolationOptions& iso = options.isolation;
  const double hard_limit = iso.hard_limit_s > 0 ? iso.hard_limit_s : 2.0 * config.time_limit_s + 1.0;
  std::vector<std::string> worker_command = iso.command;
  if (worker_command.empty()) worker_command = {"/proc/self/exe", "worker"};
  const std::string config_line = nlohmann::json{{"config", config_as_run(config)}}.dump();

  ProgressMeter progress(static_cast<std::int64_t>(todo.size()), options.progress);
  tbb::enumerable_thread_specific<Worker> workers([&] {
    Worker w;
    if (iso.enabled) {
      w.process = std::make_unique<WorkerProcess>(worker_command, iso.memory_mb, config_line);
    } else {
      w.planners = configure_planners(config);
    }
    return w;
  });

  // Restores worker records into slots; each task's slots are written by one thread only.
  RecordRestorer restorer(hash, res);
  std::mutex error_mutex;
  std::optional<std::string> error;
  bool error_is_input = false;
  std::atomic<bool> failed{false};
  std::atomic<bool> stopped{false};
  std::atomic<std::int64_t> executed{0};
  const auto budget = std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::duration<double>(config.time_limit_s));
  const auto t0 = std::chrono::steady_clock::now();

  tbb::parallel_for(std::size_t{0}, todo.size(), [&](std::size_t i) {
    if (failed.load(std::memory_order_relaxed)) return;
    if (options.stop != nullptr && options.stop->load()) {
      stopped = true;
      return;
    }
    const std::int64_t task = todo[i];
    const SweepCell& cell = res.plan.cell_of(task);
    const int map_index = res.plan.map_index_of(task);
    MapSlot& ms = res.maps[static_cast<std::size_t>(task)];
    std::string lines;
    try {
      Worker& w = workers.local();  // may start an isolation worker, which may fail
      if (!iso.enabled) {
        Rng rng = map_rng(config.seed, cell, map_index);
        const MapInstance inst = make_map(cell.spec, rng);
        ms = map_slot_of(inst);
        MapReference ref(inst.grid, inst.start, inst.goal);
        for (std::size_t p = 0; p < config.planners.size(); ++p) {
          RunSlot& slot = res.run(task, p);
          if (slot.done || !res.scheduled(task, p)) continue;
          Rng prng = run_rng(config.seed, cell, map_index, config.planners[p].label);
          const RunOutput out = execute_run(*w.planners[p].planner, ref, prng, w.scratch,
                                            Deadline::after(budget), config.motion);
          fill_run_slot(slot, out);
          ++executed;
          if (journal.enabled())
            lines += run_record(hash, config.seed, cell, map_index, config.planners[p], ms, out)
                         .dump() + '\n';
        }
      } else {
        for (std::size_t p = 0; p < config.planners.size(); ++p) {
          if (res.run(task, p).done || !res.scheduled(task, p)) continue;
          WorkerProcess::Reply reply = w.process->run(task, p, hard_limit);
          nlohmann::json record;
          if (reply.ok) {
            record = std::move(reply.record);
          } else {
            // The worker died or was killed: the parent writes the run's record itself.
            if (!ms.done) {
              Rng rng = map_rng(config.seed, cell, map_index);
              ms = map_slot_of(make_map(cell.spec, rng));
            }
            RunOutput out;
            out.metrics.fill(std::numeric_limits<double>::quiet_NaN());
            out.outcome = reply.outcome;
            out.message = reply.message;
            out.plan_time_ns = reply.wall_ns;
            record = run_record(hash, config.seed, cell, map_index, config.planners[p], ms, out);
          }
          restorer.restore(record, "worker record");
          ++executed;
          if (journal.enabled()) lines += record.dump() + '\n';
        }
      }
      if (journal.enabled() && !lines.empty()) journal.write(lines);
    } catch (const std::exception& e) {
      std::lock_guard lock(error_mutex);
      if (!error) {
        error = "cell " + cell.key + ", map " + std::to_string(map_index) + ": " + e.what();
        error_is_input = dynamic_cast<const std::invalid_argument*>(&e) != nullptr ||
                         dynamic_cast<const InputError*>(&e) != nullptr;
      }
      failed = true;
    }
    progress.advance();
  });
  progress.finish();
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.executed_runs = executed.load();
  res.interrupted = stopped.load();
  update_completeness(res);
  if (error) {
    if (error_is_input) throw InputError(*error);
    throw std::runtime_error(*error);
  }
  return res;
}

}  // namespace agv
