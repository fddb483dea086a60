#include "engine/plan/sweep_plan.h"

#include <algorithm>
#include <cstdio>
#include <string>

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
  return only.maps_in(maps_per_cell);
}

std::int64_t scheduled_runs(const SweepConfig& config, const SweepPlan& plan) {
  std::int64_t runs = 0;
  for (const auto& cell : plan.cells)
    for (const auto& p : config.planners) runs += scoped_maps(p, cell);
  return runs;
}

Rng map_rng(std::uint64_t seed, const std::string& cell_key, int map_index) {
  return Rng::for_run(seed, static_cast<std::uint64_t>(map_index), "map|" + cell_key);
}

Rng run_rng(std::uint64_t seed, const std::string& cell_key, int map_index,
            const std::string& label) {
  return Rng::for_run(seed, static_cast<std::uint64_t>(map_index), "run|" + cell_key + "|" + label);
}

std::string task_id(const std::string& config_hash, const SweepCell& cell, int map_index,
                    const std::string& label) {
  const std::uint64_t h =
      stable_hash(config_hash + "|" + cell.key + "|" + std::to_string(map_index) + "|" + label);
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace agv
