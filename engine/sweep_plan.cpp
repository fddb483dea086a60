#include "engine/sweep_plan.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <set>
#include <string>

#include "engine/sweep_runner.h"

namespace agv {

std::string density_text(double density) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", density);
  return buf;
}

std::string cell_key(const std::string& generator, GridSize size, double density) {
  return generator + "/" + std::to_string(size.width) + "x" + std::to_string(size.height) + "/" +
         density_text(density);
}

SweepPlan plan_sweep(const SweepConfig& config) {
  SweepPlan plan;
  for (const auto& entry : config.generators) {
    const std::string& generator = entry.name;
    if (entry.files) {
      // One cell per file, named by it.
      for (const MapFile& file : entry.files->files) {
        SweepCell cell;
        cell.index = static_cast<int>(plan.cells.size());
        cell.generator = generator;
        cell.size = {file.grid.width(), file.grid.height()};
        cell.density = static_cast<double>(file.grid.obstacle_count()) /
                       (static_cast<double>(file.grid.width()) * file.grid.height());
        cell.key = generator + "/" + file.name;
        cell.spec = config.map;
        cell.spec.generator = generator;
        cell.spec.width = cell.size.width;
        cell.spec.height = cell.size.height;
        cell.spec.cell_edge = file.grid.cell_edge();
        cell.file = &file;
        cell.queries = entry.files->queries;
        cell.first_task = plan.tasks;
        cell.maps = cell.queries == QuerySource::scen ? static_cast<int>(file.queries.size())
                                                      : config.maps_per_cell;
        plan.tasks += cell.maps;
        plan.cells.push_back(std::move(cell));
      }
      continue;
    }
    for (const auto& size : config.sizes) {
      for (double density : config.densities) {
        SweepCell cell;
        cell.index = static_cast<int>(plan.cells.size());
        cell.generator = generator;
        cell.size = size;
        cell.density = density;
        cell.key = cell_key(generator, size, density);
        cell.spec = config.map;
        cell.spec.generator = generator;
        cell.spec.params = entry.resolved;
        cell.spec.width = size.width;
        cell.spec.height = size.height;
        cell.spec.density = density;
        cell.first_task = plan.tasks;
        cell.maps = config.maps_per_cell;
        plan.tasks += cell.maps;
        plan.cells.push_back(std::move(cell));
      }
    }
  }
  return plan;
}

int scoped_maps(const PlannerEntry& planner, const SweepCell& cell) {
  const int maps_per_cell = cell.maps;
  const PlannerScope& only = planner.only;
  const auto listed = [](const auto& list, const auto& value) {
    if (list.empty()) return true;
    for (const auto& v : list)
      if (v == value) return true;
    return false;
  };
  if (!listed(only.generators, cell.generator) || !listed(only.sizes, cell.size) ||
      !listed(only.densities, cell.density))
    return 0;
  return only.maps_per_cell > 0 ? std::min(only.maps_per_cell, maps_per_cell) : maps_per_cell;
}

std::int64_t scheduled_runs(const SweepConfig& config, const SweepPlan& plan) {
  std::int64_t runs = 0;
  for (const auto& cell : plan.cells)
    for (const auto& p : config.planners) runs += scoped_maps(p, cell);
  return runs;
}

Rng map_rng(std::uint64_t seed, const SweepCell& cell, int map_index) {
  return Rng::for_run(seed, static_cast<std::uint64_t>(map_index), "map|" + cell.key);
}

Rng run_rng(std::uint64_t seed, const SweepCell& cell, int map_index, const std::string& label) {
  return Rng::for_run(seed, static_cast<std::uint64_t>(map_index), "run|" + cell.key + "|" + label);
}

std::string task_id(const std::string& config_hash, const SweepCell& cell, int map_index,
                    const std::string& label) {
  const std::uint64_t h =
      stable_hash(config_hash + "|" + cell.key + "|" + std::to_string(map_index) + "|" + label);
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

namespace {

// What a finished run holds beyond its slots: the phase times and extra metrics in its RunSlot
// (40 bytes each, plus the allocator's header) and its share of the report's statistics inputs.
// Measured (maximum resident set of `agvbench run`, 2,000 against 200,000 maps of astar on
// 16x16, one thread): 461 bytes more per run, of which the slots' sizeof is 192 (RunSlot 168,
// MapSlot and the to-do entry 24); the rest, about 270, is rounded up here for planners with
// more phases or extra metrics.
constexpr double kRunHeapBytes = 320.0;
// A SweepCell with its key and the map spec's parameters on the heap.
constexpr double kCellBytes = sizeof(SweepCell) + 256.0;
// A map task's MapSlot and its entry in the to-do list.
constexpr double kMapTaskBytes = sizeof(MapSlot) + sizeof(std::int64_t);
// Above this share of the memory the sweep is refused: the rest is for the maps, the planners'
// scratch, the report being built and whatever else the machine runs.
constexpr double kMemoryShare = 0.5;

}  // namespace

SweepSize sweep_size(const SweepConfig& config) {
  SweepSize size;
  // Map sources: a cell per file, a map per query (scen) or maps_per_cell; counted apart, and
  // every planner counted on all of their maps (an upper bound under "only" scopes).
  double generated = 0.0, file_cells = 0.0, file_maps = 0.0;
  for (const auto& g : config.generators) {
    if (!g.files) {
      ++generated;
      continue;
    }
    for (const auto& f : g.files->files) {
      ++file_cells;
      file_maps += g.files->queries == QuerySource::scen ? static_cast<double>(f.queries.size())
                                                         : config.maps_per_cell;
    }
  }
  size.cells = generated * static_cast<double>(config.sizes.size()) *
               static_cast<double>(config.densities.size());
  size.map_tasks = size.cells * config.maps_per_cell + file_maps;
  size.scheduled_runs = file_maps * static_cast<double>(config.planners.size());
  size.cells += file_cells;
  size.run_slots = size.map_tasks * static_cast<double>(config.planners.size());
  // A scoped planner runs on the cells its lists leave (each a subset of the sweep's axis, so
  // their product) and on the first maps of each, as scoped_maps counts them.
  const auto listed = [](const auto& only, std::size_t all) {
    return only.empty() ? static_cast<double>(all)
                        : static_cast<double>(std::set(only.begin(), only.end()).size());
  };
  for (const auto& p : config.planners) {
    const int maps = p.only.maps_per_cell > 0 ? std::min(p.only.maps_per_cell, config.maps_per_cell)
                                              : config.maps_per_cell;
    size.scheduled_runs += listed(p.only.generators, static_cast<std::size_t>(generated)) *
                           listed(p.only.sizes, config.sizes.size()) *
                           listed(p.only.densities, config.densities.size()) * maps;
  }
  size.bytes = size.cells * kCellBytes + size.map_tasks * kMapTaskBytes +
               size.run_slots * static_cast<double>(sizeof(RunSlot)) +
               size.scheduled_runs * kRunHeapBytes;
  return size;
}

double usable_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  double bytes = pages > 0 && page_size > 0
                     ? static_cast<double>(pages) * static_cast<double>(page_size)
                     : 0.0;
  // A container's limit (cgroup v2); "max" when there is none.
  std::ifstream cgroup("/sys/fs/cgroup/memory.max");
  double limit = 0.0;
  if (cgroup >> limit && limit > 0 && (bytes == 0.0 || limit < bytes)) bytes = limit;
  return bytes;
}

std::string bytes_text(double bytes) {
  static constexpr const char* kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  std::size_t unit = 0;
  while (bytes >= 1024.0 && unit + 1 < std::size(kUnits)) {
    bytes /= 1024.0;
    ++unit;
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g %s", bytes, kUnits[unit]);
  return buf;
}

void check_sweep_size(const SweepConfig& config) {
  const SweepSize size = sweep_size(config);
  const double memory = usable_memory_bytes();
  if (memory <= 0.0 || size.bytes <= kMemoryShare * memory) return;
  char counts[160];
  std::snprintf(counts, sizeof counts,
                " maps in each of %.0f cells for %zu planners make %.4g run slots, about ",
                size.cells, config.planners.size(), size.run_slots);
  throw InputError("maps_per_cell: " + std::to_string(config.maps_per_cell) + counts +
                   bytes_text(size.bytes) + " held while the sweep runs; this machine has " +
                   bytes_text(memory) +
                   " and a sweep may use half of it: lower maps_per_cell (or "
                   "the number of sizes, densities, generators or planners)");
}

}  // namespace agv
