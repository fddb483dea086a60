#include "engine/sweep_runner.h"

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/enumerable_thread_specific.h>

#include <chrono>
#include <fstream>
#include <mutex>
#include <optional>
#include <stdexcept>

#include "engine/progress.h"
#include "engine/run_record.h"

namespace agv {

namespace {

// Appends records and flushes each one, so the file is a journal of finished runs.
class RecordStream {
 public:
  explicit RecordStream(const std::string& path) {
    if (path.empty()) return;
    out_.open(path, std::ios::out | std::ios::trunc);
    if (!out_) throw InputError("runs: cannot open \"" + path + "\" for writing");
  }
  bool enabled() const { return out_.is_open(); }
  void write(const std::string& lines) {
    std::lock_guard lock(mutex_);
    out_ << lines;
    out_.flush();
  }

 private:
  std::ofstream out_;
  std::mutex mutex_;
};

struct Worker {
  Scratch scratch;
  std::vector<ConfiguredPlanner> planners;  // per thread: planners keep no shared state
};

}  // namespace

SweepResults run_sweep(const SweepConfig& config, const SweepOptions& options) {
  SweepResults res;
  res.plan = plan_sweep(config);
  for (const auto& p : config.planners) res.labels.push_back(p.label);
  const std::int64_t tasks = res.plan.map_tasks();
  res.maps.resize(static_cast<std::size_t>(tasks));
  res.runs.resize(static_cast<std::size_t>(tasks) * res.labels.size());

  const int hw = tbb::info::default_concurrency();
  res.threads = options.threads > 0 ? options.threads : hw;
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            static_cast<std::size_t>(res.threads));

  const std::string hash = config_hash(config);
  RecordStream records(options.runs_path);
  ProgressMeter progress(tasks, options.progress);
  tbb::enumerable_thread_specific<Worker> workers([&config] {
    Worker w;
    for (std::size_t i = 0; i < config.planners.size(); ++i) {
      const auto& p = config.planners[i];
      w.planners.push_back(configure_planner(p.name, p.params, "planners[" + std::to_string(i) + "]"));
    }
    return w;
  });

  std::mutex error_mutex;
  std::optional<std::string> error;
  std::atomic<bool> failed{false};
  const auto budget = std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::duration<double>(config.time_limit_s));
  const auto t0 = std::chrono::steady_clock::now();

  tbb::parallel_for(std::int64_t{0}, tasks, [&](std::int64_t task) {
    if (failed.load(std::memory_order_relaxed)) return;
    Worker& w = workers.local();
    const SweepCell& cell = res.plan.cell_of(task);
    const int map_index = res.plan.map_index_of(task);
    try {
      Rng rng = map_rng(config.seed, cell, map_index);
      MapInstance inst = make_map(cell.spec, rng);
      MapSlot& ms = res.maps[static_cast<std::size_t>(task)];
      ms.rejections = inst.rejections;
      ms.obstacle_fraction = static_cast<double>(inst.grid.obstacle_count()) /
                             (static_cast<double>(inst.grid.width()) * inst.grid.height());
      ms.done = true;
      MapReference ref(inst.grid, inst.start, inst.goal);
      std::string lines;
      for (std::size_t p = 0; p < config.planners.size(); ++p) {
        Rng prng = run_rng(config.seed, cell, map_index, config.planners[p].label);
        RunOutput out = execute_run(*w.planners[p].planner, ref, prng, w.scratch,
                                    Deadline::after(budget), config.motion);
        RunSlot& slot = res.run(task, p);
        slot.outcome = out.outcome;
        slot.metrics = out.metrics;
        slot.plan_time_ns = out.plan_time_ns;
        slot.phases = out.result.phases;
        slot.extra = out.result.extra;
        slot.done = true;
        if (records.enabled()) {
          lines += run_record(hash, config.seed, cell, map_index, config.planners[p], ms, out).dump();
          lines += '\n';
        }
      }
      if (records.enabled()) records.write(lines);
    } catch (const std::exception& e) {
      std::lock_guard lock(error_mutex);
      if (!error) error = "cell " + cell.key + ", map " + std::to_string(map_index) + ": " + e.what();
      failed = true;
    }
    progress.advance();
  });
  progress.finish();
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (error) throw std::runtime_error(*error);
  return res;
}

}  // namespace agv
