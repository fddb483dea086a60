#pragma once
// One map and one run as a sweep makes them, outside a sweep: the map a cell with this spec and
// key makes for (seed, map index), and a planner's run on a map with the random stream the sweep
// gives that run. The sweep's map tasks (engine/sweep/map_task.h) go through these, and so do
// `agvbench plan` and the Python module, so any run record can be replayed exactly.

#include <cstdint>
#include <string>

#include "engine/judge/run_executor.h"
#include "generators/map_generators.h"

namespace agv {

// Throws what the generator throws (std::invalid_argument naming the field, std::runtime_error
// when no solvable map was found).
MapInstance make_cell_map(const MapSpec& spec, const std::string& cell_key, std::uint64_t seed,
                          int map_index);

// The sweep's run of planner `label` on map `map_index` of the cell `cell_key`.
RunOutput run_on_map(const Planner& planner, MapReference& map, std::uint64_t seed,
                     const std::string& cell_key, int map_index, const std::string& label,
                     Scratch& scratch, Deadline deadline, const MotionTimeParams& motion);

}  // namespace agv
