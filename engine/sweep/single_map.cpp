#include "engine/sweep/single_map.h"

#include <string>

#include "engine/plan/sweep_plan.h"
#include "engine/system/exit_guard.h"

namespace agv {

MapInstance make_cell_map(const MapSpec& spec, const std::string& cell_key, std::uint64_t seed,
                          int map_index) {
  Rng rng = map_rng(seed, cell_key, map_index);
  return make_map(spec, rng);
}

RunOutput run_on_map(const Planner& planner, MapReference& map, std::uint64_t seed,
                     const std::string& cell_key, int map_index, const std::string& label,
                     Scratch& scratch, Deadline deadline, const MotionTimeParams& motion) {
  Rng rng = run_rng(seed, cell_key, map_index, label);
  const std::string who = "planner \"" + label + "\", in the middle of its run on map " +
                          std::to_string(map_index) + " of cell " + cell_key + ",";
  const ForeignCodeScope foreign(who.c_str());
  return execute_run(planner, map, rng, scratch, deadline, motion);
}

}  // namespace agv
