#pragma once
// The results model of a sweep: what is kept of each run and map, grouped by cell, and how much
// of the sweep is present. Filled by the runner (engine/sweep/sweep_runner.h), by resume and merge
// from journals (engine/outputs/journal.h), and read by the report, compare and the SQLite writer.
// Every run reaches its slot one way, SweepResults::store: a run in process as its RunOutput made a
// slot (engine/outputs/run_record.h run_slot_of), an isolated worker's run and a journal's as the
// record decoded (engine/outputs/journal.h RecordRestorer), so the two modes cannot fill a slot
// differently.
//
// Cells are the unit: a cell's map tasks are contiguous in the plan (engine/plan/sweep_plan.h), and
// its slots live in a CellResults of their own, so a cell can be summarised and released once
// its runs are complete.

#include <algorithm>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "algos/planner.h"
#include "engine/judge/outcome.h"
#include "engine/judge/run_metrics.h"
#include "engine/plan/sweep_plan.h"

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

// What the terminal's summary table takes of one planner's runs in a cell (engine/outputs/report.h
// summary_table), in map order.
struct PlannerTally {
  std::int64_t runs = 0;
  std::int64_t successes = 0;
  std::vector<double> plan_time_us;  // every run
  // Over the successful runs, compensated (the table prints their means: 8 bytes a run less
  // than the values, which a released cell would keep to the end).
  double turns_sum = 0.0;
  double checks_sum = 0.0;
  // Successful runs whose map's baseline run succeeded too: both path lengths.
  std::vector<double> length;
  std::vector<double> baseline_length;
};

// What stays of a cell once it is finished and released (SweepResults::release): its report
// entry, its coverage and the summary table's tallies, made from its slots by digest_cell
// (engine/outputs/report.h) exactly as the end of the sweep would make them.
struct CellDigest {
  // The report's entry for the cell as CBOR (nlohmann::json::to_cbor), a tenth of the size of
  // the parsed document, which holds a std::map node per key.
  std::vector<std::uint8_t> report_cbor;
  std::int64_t runs_present = 0;
  std::int64_t maps_missing = 0;
  std::vector<PlannerTally> tallies;  // by planner
};

// One cell's slots.
struct CellResults {
  std::vector<MapSlot> maps;  // by map index
  // By map index * planners + planner. Allocated when a run is first stored (until then every
  // slot reads as not done), freed when the cell is released.
  std::vector<RunSlot> runs;
  // By planner: it runs on the cell's first N maps (its scope).
  std::vector<int> scoped_maps;
  std::shared_ptr<const CellDigest> digest;  // once released
};

struct SweepResults {
  SweepPlan plan;
  std::string config_hash;          // engine/plan/sweep_config.h config_hash, computed once
  std::vector<std::string> labels;  // planner labels, config order
  std::vector<CellResults> cells;   // by cell index
  double wall_s = 0.0;
  int threads = 0;
  bool complete = true;      // every scheduled run of the sweep is present
  bool interrupted = false;  // stopped before its tasks were done
  std::int64_t restored_runs = 0;
  std::int64_t executed_runs = 0;
  int shard_index = 0;
  int shard_count = 1;
  // Set when a sink failed (a journal write: engine/outputs/sweep_sink.h): the sweep stopped taking
  // tasks, the runs the sink lost are not counted as done and `complete` is false (the message
  // names the sink's file and the OS error).
  std::string sink_error;
  // This run's sweep (engine/outputs/sweep_identity.h): drawn fresh, or the resumed journal's.
  std::string sweep_id;
  // Every sweep whose runs these results hold (sorted): this run's and a resume's or a merge's.
  std::vector<std::string> sweep_ids;
  void add_sweep(const std::string& id) {
    const auto at = std::lower_bound(sweep_ids.begin(), sweep_ids.end(), id);
    if (!id.empty() && (at == sweep_ids.end() || *at != id)) sweep_ids.insert(at, id);
  }

  int maps_of(const SweepCell& cell, std::size_t planner) const {
    return cells[static_cast<std::size_t>(cell.index)].scoped_maps[planner];
  }
  // Whether the sweep runs this planner on this map task at all.
  bool scheduled(std::int64_t task, std::size_t planner) const {
    return plan.map_index_of(task) < maps_of(plan.cell_of(task), planner);
  }
  // A slot of a cell not yet allocated is allocated first; two threads must not do that to one
  // cell at once (the runner allocates each cell before its tasks run: allocate()). Throws
  // std::logic_error for a released cell (read its digest).
  RunSlot& run(const SweepCell& cell, int map_index, std::size_t planner) {
    CellResults& c = cells_of(cell);
    if (c.runs.empty()) allocate(cell);
    return c.runs[static_cast<std::size_t>(map_index) * labels.size() + planner];
  }
  // A slot of a cell not yet allocated reads as a run not done. Throws std::logic_error for a
  // released cell.
  const RunSlot& run(const SweepCell& cell, int map_index, std::size_t planner) const {
    const CellResults& c = cells_of(cell);
    if (c.runs.empty()) return unallocated_slot(cell);
    return c.runs[static_cast<std::size_t>(map_index) * labels.size() + planner];
  }
  RunSlot& run(std::int64_t task, std::size_t planner) {
    const SweepCell& cell = plan.cell_of(task);
    return run(cell, static_cast<int>(task - cell.first_task), planner);
  }
  const RunSlot& run(std::int64_t task, std::size_t planner) const {
    const SweepCell& cell = plan.cell_of(task);
    return run(cell, static_cast<int>(task - cell.first_task), planner);
  }
  MapSlot& map(std::int64_t task) {
    const SweepCell& cell = plan.cell_of(task);
    return cells[static_cast<std::size_t>(cell.index)]
        .maps[static_cast<std::size_t>(task - cell.first_task)];
  }
  const MapSlot& map(std::int64_t task) const {
    const SweepCell& cell = plan.cell_of(task);
    return cells[static_cast<std::size_t>(cell.index)]
        .maps[static_cast<std::size_t>(task - cell.first_task)];
  }
  // Allocates the cell's run slots (none done) unless they are; throws std::logic_error for a
  // released cell.
  void allocate(const SweepCell& cell);
  // Keeps the cell's digest and frees its run slots.
  void release(const SweepCell& cell, CellDigest digest);
  bool released(const SweepCell& cell) const { return cells_of(cell).digest != nullptr; }
  // Puts a finished run and its map into their slots (the map's only when it is not there yet:
  // every run of a task shares one map).
  void store(std::int64_t task, std::size_t planner, RunSlot slot, const MapSlot& map_slot);
  // The planners of `task` still to run: scheduled there and not done, in config order.
  std::vector<std::size_t> pending_planners(std::int64_t task) const;

 private:
  CellResults& cells_of(const SweepCell& cell) {
    return cells[static_cast<std::size_t>(cell.index)];
  }
  const CellResults& cells_of(const SweepCell& cell) const {
    return cells[static_cast<std::size_t>(cell.index)];
  }
  const RunSlot& unallocated_slot(const SweepCell& cell) const;
};

// How much of a sweep's results are present: the report's `coverage`.
struct Coverage {
  std::int64_t runs_expected = 0;  // scheduled runs (planner scopes counted)
  std::int64_t runs_present = 0;
  std::int64_t maps_missing = 0;  // map tasks with no run at all
};
Coverage coverage_of(const SweepResults& results);
// The same of one cell (its digest's once released).
Coverage cell_coverage_of(const SweepResults& results, const SweepCell& cell);

// Empty results shaped for the config: its plan and hash, made once here, no run done (the
// runner, resume and merge fill them).
SweepResults empty_results(const SweepConfig& config);
// Recomputes `complete` (every scheduled run present) from the slots.
void update_completeness(SweepResults& results);

}  // namespace agv
