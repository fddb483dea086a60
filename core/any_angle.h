#pragma once
// The any-angle reference (docs/METRICS.md "Any-angle reference"): the length of the shortest
// path from centre(start) to centre(goal) that is not bound to grid moves, the lower bound
// every planner's path is compared with (any_angle_ratio = path length / this).
//
// Geometry (core/line_of_sight.h): cell (x, y) is the closed square [x, x+1] x [y, y+1] and
// outside the grid is obstacle. A path valid under segment_free(..., SightRule::cells(rule)), or
// under any stricter rule, lies in the CLOSURE of free space (the union of the closed free
// squares), and under no_squeeze / no_corner_cut it never crosses a "pinch" (a grid vertex whose
// only blocked cells are two diagonally opposite ones) from one free cell to the other; under
// allow it may. The reference is the shortest path in that closure under that pinch rule: a
// lower bound of every valid path, and their infimum (each bend can be pushed off its vertex
// into free space by an arbitrarily small amount), so no_squeeze and no_corner_cut give the same
// value and only allow differs.
//
// Method: A* with the Euclidean heuristic over the visibility graph of start, goal and the
// possible bend points (convex obstacle corners: vertices with exactly one blocked cell around
// them; under allow also the pinch vertices), edges generated lazily with the taut-path
// conditions and, on large maps, the 8-connected optimum as an upper bound; visibility decided
// exactly in integers (coordinates doubled, so vertices and cell centres are integers). This
// visibility ("every point in some closed free square, no pinch crossed unless allow") is NOT
// segment_free's test, which asks the closed segment to stay off every obstacle square: a
// segment may touch an obstacle corner here.

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/connectivity.h"
#include "core/corner_rule.h"
#include "core/grid.h"

namespace agv {

// A point with doubled coordinates: grid vertex (i, j) is (2i, 2j), cell (x, y)'s centre is
// (2x + 1, 2y + 1).
struct HalfPoint {
  int x = 0;
  int y = 0;
  friend bool operator==(const HalfPoint&, const HalfPoint&) = default;
};

// Reusable per-thread buffers: a caller asking many queries allocates nothing once the largest
// map has been seen.
struct AnyAngleScratch {
  ConnectivityScratch component;  // the start's component (core/connectivity.h flood_fill)
  // Graph nodes: 0 = start, 1 = goal, then the bend points of the start's component.
  std::vector<HalfPoint> node;
  std::vector<std::int8_t> block_x, block_y;  // a blocked quadrant's direction from the node
  std::vector<std::uint8_t> pinch;            // the node is a pinch (both diagonals blocked)
  // Bend nodes in tile order: tile (tx, ty)'s are [tile_begin[t], tile_begin[t + 1]) for
  // t = ty * tiles_x + tx.
  std::vector<int> tile_begin;
  int tiles_x = 0;
  int tiles_y = 0;
  std::vector<std::uint8_t> closed;
  std::vector<double> g, h;
  std::vector<int> parent;
  struct Entry {
    double f;
    double g;
    int node;
  };
  std::vector<Entry> heap;
  // The 8-connected optimum under the same connectivity: an upper bound that prunes the search.
  std::vector<double> grid_g;
  std::vector<std::pair<double, int>> grid_open;
  double upper = 0.0;
};

// Length in cells of the shortest path from centre(start) to centre(goal) in the closure of
// free space under the pinch rule of `rule` (see above); 0 when start == goal; nullopt when
// start or goal is outside the grid or blocked, or they are not connected under `rule` (the
// same connectivity as the 8-connected grid search under `rule`).
std::optional<double> any_angle_length(const Grid& grid, Cell start, Cell goal, CornerRule rule,
                                       AnyAngleScratch& scratch);

// The same search; also sets `vertices` to its path: centre(start), the bend vertices in order,
// centre(goal) (one point when start == goal; empty for nullopt).
std::optional<double> any_angle_path(const Grid& grid, Cell start, Cell goal, CornerRule rule,
                                     AnyAngleScratch& scratch, std::vector<Point>& vertices);

// The visibility of the search, for tests: every point of segment a-b lies in a closed free
// square, and unless `rule` is allow the segment passes through no pinch vertex (other than at
// an endpoint). Exact.
bool closure_visible(const Grid& grid, HalfPoint a, HalfPoint b, CornerRule rule);

// The vertex kinds of the visibility graph, for tests: how many of the four cells around grid
// vertex (i, j) are blocked (1: a convex obstacle corner), and whether they form a pinch.
// Vertex coordinates in [0, width] x [0, height].
int blocked_around_vertex(const Grid& grid, int i, int j);
bool is_pinch_vertex(const Grid& grid, int i, int j);

}  // namespace agv
