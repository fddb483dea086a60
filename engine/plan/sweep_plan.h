#pragma once
// A sweep expanded into its cells (generator x size x density, and one per file of a map source)
// and map tasks (cell x map index).
// Every id here is a pure function of the config, so a task can be named in a journal, skipped on
// resume, or assigned to a shard.

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/plan/sweep_config.h"

namespace agv {

struct SweepCell {
  int index = 0;
  std::string generator;
  GridSize size;
  double density = 0.0;
  std::string key;  // "uniform/64x64/0.2": names the cell in records and seeds its maps
  MapSpec spec;     // the config's map options with this cell's generator, size and density
  // Its map tasks: first_task ... first_task + maps - 1 (maps_per_cell, or a file's .scen
  // queries).
  std::int64_t first_task = 0;
  int maps = 0;
  // A map source's cell: its file (owned by the config's GeneratorEntry) and how its queries are
  // made; size is the file's grid and density its obstacle fraction. nullptr for a generator.
  const MapFile* file = nullptr;
  QuerySource queries = QuerySource::endpoints;
};

struct SweepPlan {
  std::vector<SweepCell> cells;
  std::int64_t tasks = 0;
  std::int64_t map_tasks() const { return tasks; }
  // The cell whose task range holds `task`.
  const SweepCell& cell_of(std::int64_t task) const {
    const auto it =
        std::upper_bound(cells.begin(), cells.end(), task,
                         [](std::int64_t t, const SweepCell& c) { return t < c.first_task; });
    return *(it - 1);
  }
  int map_index_of(std::int64_t task) const {
    return static_cast<int>(task - cell_of(task).first_task);
  }
  std::int64_t task_of(const SweepCell& cell, int map_index) const {
    return cell.first_task + map_index;
  }
};

SweepPlan plan_sweep(const SweepConfig& config);

// How many maps of `cell` the planner runs: its first N (all, 0 or its scope's maps_per_cell).
int scoped_maps(const PlannerEntry& planner, const SweepCell& cell);
// The runs a sweep schedules: over planners and cells, their scoped map counts.
std::int64_t scheduled_runs(const SweepConfig& config, const SweepPlan& plan);

// Short text of a density ("0.2", "0.35"): ten significant digits, so two densities closer
// than that share one text, and the config refuses them (they would share one cell key).
std::string density_text(double density);
// "uniform/64x64/0.2": names a cell in records and seeds its maps.
std::string cell_key(const std::string& generator, GridSize size, double density);

// The random stream of a cell's map `map_index` and of one planner's run on it, by the cell or
// its key.
Rng map_rng(std::uint64_t seed, const std::string& cell_key, int map_index);
Rng run_rng(std::uint64_t seed, const std::string& cell_key, int map_index,
            const std::string& label);
inline Rng map_rng(std::uint64_t seed, const SweepCell& cell, int map_index) {
  return map_rng(seed, cell.key, map_index);
}
inline Rng run_rng(std::uint64_t seed, const SweepCell& cell, int map_index,
                   const std::string& label) {
  return run_rng(seed, cell.key, map_index, label);
}

// Deterministic id of one run: config hash, cell, map index, planner label.
std::string task_id(const std::string& config_hash, const SweepCell& cell, int map_index,
                    const std::string& label);

}  // namespace agv
