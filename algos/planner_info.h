#pragma once
// What a planner declares about itself: its name, family, parameters and factory. Each planner's
// header returns its PlannerInfo; the registry (algos/registry.h) lists them.

#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "algos/planner.h"
#include "core/params.h"

namespace agv {

// The family a planner belongs to (its folder under algos/). Code that needs "the grid
// planners" (a fusion planner's global planner, the family tests) asks the registry for a kind.
enum class PlannerKind { grid_search, sampling, swarm, local };
const char* to_string(PlannerKind kind);

struct PlannerInfo {
  std::string name;  // stable public name, e.g. "astar"
  PlannerKind kind = PlannerKind::grid_search;
  std::string summary;  // one line for `agvbench list`
  std::string source;   // where it comes from, e.g. "paper 000 section 4.1"
  // The work counters it reports (docs/METRICS.md "Work counters"), each with what it counts
  // for this planner; collision_checks is every planner's.
  std::vector<std::pair<std::string, std::string>> counters;
  bool stochastic = false;  // draws from the run's RNG
  // Whether the planner proves that there is no path: where the goal cannot be reached it
  // answers no_path (and the engine checks every no_path claim: missed_path). A planner that
  // searches within a budget of samples, iterations or simulated time cannot tell "none" from
  // "not found yet", sets false and gives up with limit (the planner contract, checked by
  // tests/algos/test_contract.cpp).
  bool proves_no_path = true;
  std::vector<ParamSpec> params;
  // Builds a planner from a validated parameter set.
  std::unique_ptr<Planner> (*make)(const Params& params) = nullptr;
  // Empty for a built-in planner; else the name of the plugin it came from (algos/plugin.h).
  std::string plugin;
};

// The names of the planners of one kind, in the order of `planners`.
std::vector<std::string> planner_names(std::span<const PlannerInfo> planners, PlannerKind kind);

}  // namespace agv
