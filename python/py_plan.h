#pragma once
// agvbench._core.plan: one planner on one map, validated and measured as a sweep's run
// (engine/sweep/single_map.h), the random stream the sweep gives run (cell, map index, label).

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <string>

namespace agv::py_bind {

struct PlanCall {
  std::string planner;
  nlohmann::json params = nlohmann::json::object();
  nlohmann::json collision;     // a config's "collision" object; null = the default model
  nlohmann::json time_limit_s;  // seconds; null = none (as `agvbench plan`)
  nlohmann::json seed = 0;
  std::string cell;  // the cell key naming the run's random stream
  int map_index = 0;
  double cell_edge = 1.0;
};

// A dict: outcome, message, rule, path (N x 2 float array, cell coordinates), metrics, phases
// (ns), plan_time_ns. InputError naming the argument for bad input.
pybind11::dict plan(const pybind11::handle& grid, const pybind11::handle& start,
                    const pybind11::handle& goal, const PlanCall& call);

}  // namespace agv::py_bind
