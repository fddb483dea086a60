#include "python/py_run.h"

#include <pybind11/numpy.h>
#include <tbb/info.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <optional>
#include <pybind11_json/pybind11_json.hpp>
#include <sstream>
#include <thread>

#include "core/input_error.h"
#include "core/json_reader.h"
#include "engine/outputs/journal.h"
#include "engine/outputs/journal_table.h"
#include "engine/outputs/report.h"
#include "engine/outputs/report_sink.h"
#include "engine/outputs/run_table.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/files_read.h"
#include "engine/plan/output_paths.h"
#include "engine/plan/sweep_size.h"
#include "engine/sweep/sweep_runner.h"

namespace py = pybind11;
using nlohmann::json;

namespace agv::py_bind {

namespace {

// Counts the runs as they finish, for the progress callback on the Python thread.
class RunCounter : public SweepSink {
 public:
  void start(const SweepStart& s) override { total_ = s.runs_to_do; }
  void task_done(const TaskRuns& t) override { done_ += static_cast<std::int64_t>(t.runs.size()); }
  std::int64_t done() const { return done_; }
  std::int64_t total() const { return total_; }

 private:
  std::atomic<std::int64_t> done_{0};
  std::atomic<std::int64_t> total_{0};
};

SweepConfig call_config(const RunCall& call) {
  SweepConfig config =
      call.config_path.empty() ? parse_config(call.config) : load_config(call.config_path);
  if (!call.threads.is_null())
    config.threads =
        static_cast<int>(ObjectReader::check_integer(call.threads, "threads", kThreadsRange));
  // oneTBB runs at most its default concurrency, whatever is asked (as `agvbench run`).
  config.threads = std::min(config.threads, tbb::info::default_concurrency());
  if (!call.out.empty()) config.report_path = call.out;
  if (!call.runs_out.empty()) config.runs_path = call.runs_out;
  return config;
}

SweepOptions call_options(const RunCall& call, const SweepConfig& config) {
  SweepOptions options;
  options.threads = config.threads;
  options.runs_path = config.runs_path;
  // A journal with records already is this call's earlier, interrupted run: resume it (a
  // journal of another config is refused, naming it, as `agvbench run --resume`).
  std::error_code ec;
  const bool resume =
      !options.runs_path.empty() && std::filesystem::file_size(options.runs_path, ec) > 0 && !ec;
  if (resume) options.resume_path = options.runs_path;
  if (!call.shard.is_null()) {
    if (!call.shard.is_array() || call.shard.size() != 2)
      throw InputError("shard: expected (i, n) with 0 <= i < n, got " + call.shard.dump());
    const auto n = ObjectReader::check_integer(call.shard[1], "shard[1]", 1, 1 << 30);
    options.shard_index =
        static_cast<int>(ObjectReader::check_integer(call.shard[0], "shard[0]", 0, n - 1));
    options.shard_count = static_cast<int>(n);
  }
  // Nothing the sweep reads or the user wrote is overwritten (engine/plan/output_paths.h).
  std::vector<InputPath> inputs = files_read(config, call.config_path);
  std::erase_if(inputs, [](const InputPath& p) { return p.path.empty(); });
  check_paths(inputs, {{"out", call.out},
                       {"runs_out", options.runs_path,
                        resume ? OutputKind::appended : OutputKind::new_journal}});
  return options;
}

// The column as a numpy array that owns it (no copy: a table of 100,000 runs is tens of MB).
template <class T>
py::array_t<T> array_of(std::vector<T>&& v) {
  auto* owned = new std::vector<T>(std::move(v));
  const py::capsule free_it(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(static_cast<py::ssize_t>(owned->size()), owned->data(), free_it);
}

py::dict column_arrays(RunColumns& c) {
  py::dict columns;
  columns["cell"] = array_of(std::move(c.cell));
  columns["map_index"] = array_of(std::move(c.map_index));
  columns["planner"] = array_of(std::move(c.planner));
  columns["outcome"] = array_of(std::move(c.outcome));
  columns["plan_time_ns"] = array_of(std::move(c.plan_time_ns));
  return columns;
}

py::list metric_arrays(RunColumns& c) {
  py::list metrics;
  for (std::size_t k = 0; k < c.metric_names.size(); ++k)
    metrics.append(py::make_tuple(c.metric_names[k], array_of(std::move(c.metrics[k]))));
  return metrics;
}

py::list label_list(const std::vector<std::string>& labels) {
  py::list out;
  for (const std::string& label : labels) out.append(label);
  return out;
}

// The runs as the package's runs_frame reads them: numpy columns, and the cells, planners and
// outcomes their codes index.
py::dict runs_payload(RunColumns& c, py::list cells, const std::vector<std::string>& planners,
                      py::object seed) {
  py::dict out;
  out["columns"] = column_arrays(c);
  out["metrics"] = metric_arrays(c);
  out["cells"] = std::move(cells);
  out["planners"] = label_list(planners);
  out["outcomes"] = outcome_names();
  out["seed"] = std::move(seed);
  return out;
}

py::dict runs_dict(RunColumns c, const SweepConfig& config, const SweepResults& results) {
  py::list cells;
  for (const SweepCell& cell : results.plan.cells) {
    py::dict d;
    d["key"] = cell.key;
    d["generator"] = cell.generator;
    d["width"] = cell.size.width;
    d["height"] = cell.size.height;
    d["density"] = cell.density;
    cells.append(d);
  }
  return runs_payload(c, std::move(cells), results.labels, py::int_(config.seed));
}

// What run() and merge() return: the report, the runs (keep_runs) and completeness.
py::dict sweep_result(const json& report, RunTable& table, const RunCall& call,
                      const SweepConfig& config, const SweepResults& results) {
  py::dict out;
  out["report"] = pyjson::from_json(report);
  out["runs"] = call.keep_runs ? py::object(runs_dict(table.take(), config, results)) : py::none();
  out["complete"] = results.complete;
  return out;
}

// A journal's cell: a generator's key "uniform/64x64/0.2" read back into its parts (cell_key()
// of engine/plan/sweep_plan.h); a map file's cell, or a key of another shape, by its key alone.
py::dict journal_cell(const JournalHeader::Cell& c) {
  py::dict d;
  d["key"] = c.key;
  for (const char* unknown : {"generator", "width", "height", "density"}) d[unknown] = py::none();
  const auto a = c.key.find('/');
  const auto b = c.key.rfind('/');
  if (!c.map_file.empty() || a == std::string::npos || a == b) return d;
  int width = 0, height = 0;
  char x = 0;
  double density = 0.0;
  std::istringstream size(c.key.substr(a + 1, b - a - 1));
  std::istringstream dens(c.key.substr(b + 1));
  if (!(size >> width >> x >> height) || x != 'x' || !(size >> std::ws).eof() ||
      !(dens >> density) || !(dens >> std::ws).eof())
    return d;
  d["generator"] = c.key.substr(0, a);
  d["width"] = width;
  d["height"] = height;
  d["density"] = density;
  return d;
}

// Runs the sweep on a thread of its own while this, the Python thread, calls `progress` about
// ten times a second and watches for Ctrl-C: then (or when `progress` raises) the sweep stops
// taking map tasks and cuts the runs in flight short (their records are not written, so the same
// call with the same runs_out resumes them). Throws the Python error once the sweep is over and
// its journal flushed, else the sweep's own.
void sweep_beside_python(const SweepConfig& config, SweepResults& results, SweepOptions& options,
                         const RunCounter& counter, const py::object& progress) {
  std::atomic<bool> stop{false}, cut{false};
  options.stop = &stop;
  options.cut_short = &cut;
  std::optional<py::error_already_set> raised;
  std::exception_ptr failed;
  {
    std::mutex m;
    std::condition_variable cv;
    bool over = false;
    const py::gil_scoped_release released;
    std::thread sweep([&] {
      try {
        run_sweep(config, results, options);
      } catch (...) {
        failed = std::current_exception();
      }
      const std::lock_guard<std::mutex> lock(m);
      over = true;
      cv.notify_all();
    });
    for (bool last = false; !last;) {
      {
        std::unique_lock<std::mutex> lock(m);
        last = cv.wait_for(lock, std::chrono::milliseconds(100), [&] { return over; });
      }
      const py::gil_scoped_acquire gil;
      try {
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        if (!progress.is_none() && !raised) progress(counter.done(), counter.total());
      } catch (py::error_already_set& e) {
        if (!raised) raised = std::move(e);
        stop = true;
        cut = true;
      }
    }
    sweep.join();
  }
  options.stop = options.cut_short = nullptr;
  if (raised) throw *raised;
  if (failed) std::rethrow_exception(failed);
}

}  // namespace

py::dict run(const RunCall& call, const py::object& progress) {
  const SweepConfig config = call_config(call);
  SweepOptions options = call_options(call, config);
  SweepResults results = empty_results(config);
  std::optional<ReportSink> report_sink;
  if (!call.out.empty()) options.sinks.push_back(&report_sink.emplace(config, call.out, true));
  RunTable table;
  if (call.keep_runs) options.sinks.push_back(&table);
  RunCounter counter;
  options.sinks.push_back(&counter);
  sweep_beside_python(config, results, options, counter, progress);
  if (!results.sink_error.empty()) throw std::runtime_error(results.sink_error);
  return sweep_result(report_sink ? report_sink->report() : build_report(config, results), table,
                      call, config, results);
}

py::dict merge(const RunCall& call, const std::vector<std::string>& journals) {
  const SweepConfig config = call_config(call);
  check_sweep_size(config, true);  // every run's slot is restored
  std::vector<InputPath> inputs = files_read(config, call.config_path);
  std::erase_if(inputs, [](const InputPath& p) { return p.path.empty(); });
  for (const auto& j : journals) inputs.push_back({"journal", j});
  check_paths(inputs, {{"out", call.out}});
  SweepResults results = empty_results(config);
  {
    const py::gil_scoped_release released;
    restore_journals(journals, results);
    update_completeness(results);
  }
  // One document, kept and written (as ReportSink writes a kept one), not built twice.
  const json report = build_report(config, results);
  if (!call.out.empty()) write_json_atomic(report, call.out);
  RunTable table;
  if (call.keep_runs) table.finish(results);
  return sweep_result(report, table, call, config, results);
}

py::dict read_journal(const std::string& path) {
  JournalTable table;
  {
    const py::gil_scoped_release released;
    table = read_journal_table(path);
  }
  py::list cells;
  for (const auto& c : table.cells) cells.append(journal_cell(c));
  py::dict out = runs_payload(table.runs, std::move(cells), table.planners, py::none());
  out["duplicates"] = table.duplicates;
  out["torn_lines"] = table.torn_lines;
  return out;
}

py::list outcome_names() {
  py::list outcomes;
  for (int k = 0; k < kOutcomeCount; ++k)
    outcomes.append(std::string(to_string(static_cast<Outcome>(k))));
  return outcomes;
}

}  // namespace agv::py_bind
