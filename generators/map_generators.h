#pragma once
// Random maps for sweeps, each a pure function of its spec and the RNG handed in, plus the
// start/goal protocols. The generators themselves and their shape parameters are in
// generators/registry.h.

#include <nlohmann/json.hpp>
#include <string>

#include "core/corner_rule.h"
#include "core/grid.h"
#include "core/rng.h"

namespace agv {

enum class EndpointMode {
  corners,  // the papers' protocol: bottom-left cell (0, height-1) to top-right cell (width-1, 0),
            // both kept free (the generator never places obstacles there)
  random,   // uniform free cells at least min_distance (Euclidean, cells) apart
  fixed,    // MapSpec::start and goal (0-based cells), reserved free as the corners are; a map
            // whose generator still blocks one (a maze wall) is redrawn like an unsolvable one
};

struct MapSpec {
  std::string generator = "uniform";  // a generator_registry() name
  // The generator's shape parameters; missing ones take their defaults (generators/registry.h).
  nlohmann::json params = nlohmann::json::object();
  int width = 64;
  int height = 64;
  double density = 0.2;  // obstacle fraction in [0, 1); what it means: each generator's file
  double cell_edge = 1.0;
  EndpointMode endpoints = EndpointMode::corners;
  double min_distance = 0.0;  // random endpoints only
  Cell start;                 // fixed endpoints only: 0-based cells, x right, y down
  Cell goal;
  bool require_solvable = false;
  CornerRule solvable_rule = CornerRule::no_corner_cut;  // the run's strictest corner rule
  int max_attempts = 1000;  // require_solvable: regenerations before giving up
};

struct MapInstance {
  Grid grid;
  Cell start;
  Cell goal;
  int rejections = 0;  // maps thrown away by require_solvable before this one
};

// The checks make_map makes before drawing anything: std::invalid_argument naming the field
// ("min_distance: ...", a shape parameter as "params.<name>: ..."). A sweep config runs them on
// every cell at load, so nothing make_map refuses can pass `agvbench validate`.
void check_map_spec(const MapSpec& spec);

// Throws std::invalid_argument naming the field for an impossible spec (a shape parameter as
// "params.<name>"), and std::runtime_error when require_solvable fails max_attempts times.
MapInstance make_map(const MapSpec& spec, Rng& rng);

}  // namespace agv
