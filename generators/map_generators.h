#pragma once
// Random maps for sweeps, each a pure function of its spec and the RNG handed in, plus the
// start/goal protocols. (Interface fixed; implementation in map_generators.cpp.)

#include <string>
#include <vector>

#include "core/rng.h"
#include "core/corner_rule.h"
#include "core/grid.h"

namespace agv {

enum class EndpointMode {
  corners,  // the papers' protocol: bottom-left cell (0, height-1) to top-right cell (width-1, 0),
            // both kept free (the generator never places obstacles there)
  random,   // uniform free cells at least min_distance (Euclidean, cells) apart
};

struct MapSpec {
  std::string generator = "uniform";  // uniform | blocks | maze | rooms
  int width = 64;
  int height = 64;
  double density = 0.2;  // obstacle fraction in [0, 1); see map_generators.cpp per generator
  double cell_edge = 1.0;
  EndpointMode endpoints = EndpointMode::corners;
  double min_distance = 0.0;  // random endpoints only
  bool require_solvable = false;
  CornerRule solvable_rule = CornerRule::no_corner_cut;  // the run's strictest corner rule
  int max_attempts = 1000;  // require_solvable: regenerations before giving up
  // Generator shape parameters (documented in map_generators.cpp).
  int block_min = 2;  // blocks: side range of rectangular obstacles
  int block_max = 5;
  int corridor = 1;   // maze: corridor and wall width in cells
  int room_size = 8;  // rooms: room side in cells
  int door_width = 2; // rooms: opening width in cells
};

struct MapInstance {
  Grid grid;
  Cell start;
  Cell goal;
  int rejections = 0;  // maps thrown away by require_solvable before this one
};

// The generator names, for config validation.
const std::vector<std::string>& generator_names();

// Throws std::invalid_argument naming the field for an impossible spec, and
// std::runtime_error when require_solvable fails max_attempts times.
MapInstance make_map(const MapSpec& spec, Rng& rng);

}  // namespace agv
