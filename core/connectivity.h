#pragma once
// Reachability between two cells under a corner rule (8-connected moves filtered by the rule of
// corner_rule.h). Used by the map generators' require_solvable check and by tests; a BFS flood
// fill over the padded occupancy array, so it needs no bounds checks.

#include <cstdint>
#include <vector>

#include "core/corner_rule.h"
#include "core/grid.h"

namespace agv {

// Reusable buffers: a caller checking many maps (require_solvable regenerations) keeps one so the
// check allocates nothing after the first map of a given size.
struct ConnectivityScratch {
  std::vector<std::uint32_t> stamp;  // visited when stamp[i] == generation
  std::vector<int> queue;
  std::uint32_t generation = 0;
};

// Stamps every free cell reachable from `from` (which must be free) with the returned generation
// in scratch.stamp, stopping as soon as `stop` is stamped (-1: the whole component). The one
// flood fill of the project: connected() and the any-angle reference's component
// (core/any_angle.cpp) both stand on it.
std::uint32_t flood_fill(const std::uint8_t* occupancy, int stride, int padded_size, int from,
                         int stop, CornerRule rule, ConnectivityScratch& scratch);

// `occupancy` is a padded row-major array (row length `stride`, a blocked one-cell border), as
// Grid::occupancy(); `from` and `to` are padded indices. False when either cell is blocked.
bool connected(const std::uint8_t* occupancy, int stride, int padded_size, int from, int to,
               CornerRule rule, ConnectivityScratch& scratch);

bool connected(const Grid& grid, Cell a, Cell b, CornerRule rule, ConnectivityScratch& scratch);
bool connected(const Grid& grid, Cell a, Cell b, CornerRule rule);

}  // namespace agv
