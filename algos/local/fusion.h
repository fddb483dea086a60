#pragma once
// Global grid planner + DWA fusion (paper 003 section 4, paper 004 section 3.4; docs/PLANNERS.md
// "DWA local planner and the fusion planners"), and pure DWA.
//
// A run: (1) a world is generated for the map (algos/local/dwa_world.h): unknown static cells on or
// near the map's reference path (classic A*, no_corner_cut, the same for every planner) and
// moving discs; (2) the global planner, any registered grid planner chosen by name, plans on
// the known grid (its corner rule forced to no_corner_cut by default: a disc robot cannot pass
// between diagonal obstacles); its key points (Ramer-Douglas-Peucker with key_point_tolerance,
// on cell-centre paths exactly the turning points after collinear removal) are the DWA's
// successive local goals, taken by default (`local_goals: key_nodes`) from its path before any
// curve fitting, the planner then running with `smoothing: none`; (3) the robot drives through them
// (algos/local/fusion_drive.h, which lists our additions to the papers' loop). The planner reports
// the executed trajectory, the moving obstacles' tracks and the unknown cells
// (PlanResult::trajectory) and the engine judges it (engine/judge/trajectory_judge.h). `path` is
// the executed positions, so the path metrics apply.
//
// Pure DWA (`dwa`): the same world and loop with start and goal as the only key points,
// Fox's heading toward the goal, no turn speed limit.

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "algos/local/fusion_drive.h"
#include "algos/planner_info.h"
#include "core/corner_rule.h"

namespace agv {

// What a fusion planner asks of the registry when it is made: the reference A* and its global
// planner, by name. The registry hands over its own lookup as it builds the fusion entries
// (algos/registry.cpp): fusion includes no registry, which includes every planner.
struct PlannerLookup {
  const PlannerInfo* (*find)(std::string_view name) = nullptr;
  // A planner with these parameters (validated; InputError naming `where`).
  std::unique_ptr<Planner> (*make)(const std::string& name, const nlohmann::json& params,
                                   const std::string& where) = nullptr;
};

// Registered as dwa, fusion_astar_dwa, fusion_alt_dwa, fusion_kin_dwa (algos/registry.cpp).
// `grid_planners`: the names a fusion's `global_planner` may choose, in registry order: the
// registered planners of kind grid_search, which the registry hands over as it builds itself,
// with its lookup (the same for every entry).
struct FusionRegistry {
  std::vector<std::string> grid_planners;
  PlannerLookup lookup;
};
PlannerInfo dwa_planner(const FusionRegistry& registry);  // pure DWA toward the goal
// classic A* + classic DWA (the papers' baseline)
PlannerInfo fusion_astar_dwa_planner(const FusionRegistry& registry);
// alternative A* + improved DWA (paper 003)
PlannerInfo fusion_alt_dwa_planner(const FusionRegistry& registry);
// kinematic A* + following DWA (paper 004)
PlannerInfo fusion_kin_dwa_planner(const FusionRegistry& registry);

// The parameters a fusion run gives its global planner `global`: `corner_rule` = `rule` when
// given and declared; `shortcut_margin` = max(its default, `margin`) when declared and margin >= 0
// (global_margin is a floor, so a planner with a wider clearance of its own keeps it).
nlohmann::json global_planner_params(const PlannerInfo& global, std::optional<CornerRule> rule,
                                     double margin);

// The control-loop options the registered planner `planner` (dwa or a fusion_*_dwa) runs with
// under the parameters `given`, its global planner one of `grid_planners` (tests drive
// hand-made worlds with them, algos/local/fusion_drive.h). Throws InputError naming `planner`
// for a bad value.
FusionOptions fusion_options(const std::string& planner, const nlohmann::json& given,
                             const std::vector<std::string>& grid_planners);

}  // namespace agv
