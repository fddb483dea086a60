#pragma once
// The one line-of-sight test of the project (docs/PLANNERS.md "Line of sight and clearance"): every
// shortcut pass, every sampling/swarm planner and the validator ask "is segment a-b free?" here.
// The word-parallel and batched forms (core/line_of_sight_batch.h) agree with this scalar walk.
//
// Geometry: points are continuous cell coordinates; cell (x, y) is the closed square
// [x, x+1] x [y, y+1]; cells outside [0, width) x [0, height) are obstacles (the border wall).
//
// `cells` mode. A segment is free when every cell its closed form touches is free, except the
// two "side" cells at a grid vertex the segment passes THROUGH (the vertex is an interior point
// of the segment and the segment is not axis-parallel): it goes diagonally from one cell to the
// opposite one and only grazes the two others at their corner. Those are judged by the rule:
//   allow          no requirement;
//   no_squeeze     not both blocked;
//   no_corner_cut  both free (so no_corner_cut == "the closed segment touches no obstacle cell").
// So: a segment running along a cell edge touches the cells on both sides; an endpoint lying
// on an edge or vertex touches every cell around it (an endpoint is never "passing through");
// an endpoint strictly inside a free cell is fine. A move between adjacent cell centres is free
// under cells(rule) exactly when move_allowed() says it is legal under the rule.
//
// `clearance` mode: the cells test AND every obstacle cell CENTRE at distance >= radius from
// the segment (docs/PLANNERS.md "margin d": radius = d + 0.5; paper 000 eq. 5.1b: obstacles as
// circles of radius r_obs around their centres).
//
// Tolerance: a coordinate within kSightEpsilon (1e-9 cells) of an integer is taken as on that
// grid line, both for the endpoints and where the segment meets a column (row) line, so
// x + 0.5-style waypoints that should hit a vertex exactly do. Near-misses within 1e-9 are thus
// judged as exact hits. Clearance compares squared distances with the same tolerance in favour
// of "free" (distance == radius is free).

#include <cstdint>
#include <span>

#include "core/corner_rule.h"
#include "core/grid.h"

namespace agv {

inline constexpr double kSightEpsilon = 1e-9;

struct SightRule {
  enum class Kind { cells, clearance };
  Kind kind = Kind::cells;
  // cells test: how a pass exactly through a vertex between two diagonal cells is judged.
  CornerRule corners = CornerRule::no_corner_cut;
  // clearance only: minimum distance, in cells, from every obstacle cell centre to the segment.
  double radius = 0.0;

  static SightRule cells(CornerRule rule = CornerRule::no_corner_cut);
  // docs/PLANNERS.md "margin d": radius d + 0.5 (margin 0 is the same as cells).
  static SightRule margin(double d, CornerRule rule = CornerRule::no_corner_cut);
  // Paper 000 eq. 5.1b: obstacles are circles of radius r_obs around cell centres.
  static SightRule circles(double r_obs, CornerRule rule = CornerRule::no_corner_cut);
};

// Why a segment is not free; the first problem found along the walk.
struct SightHit {
  enum class Kind {
    none,       // free
    outside,    // an endpoint is not finite or lies outside [0, width] x [0, height]
    cell,       // touches blocked `cell` (a border cell when it runs along the grid's edge)
    corner,     // passes through a vertex whose side cells fail the corner rule; `cell` is one
    clearance,  // obstacle `cell`'s centre is closer than the radius
  };
  Kind kind = Kind::none;
  Cell cell;
  explicit operator bool() const { return kind != Kind::none; }
};

// Full diagnosis (the validator's reasons): the reference walk, cell by cell along the major
// axis; same verdict as segment_free.
SightHit check_segment(const Grid& grid, Point a, Point b, const SightRule& rule);

// The verdict alone (core/line_of_sight_batch.cpp): blocks of columns screened by word tests on
// the bit-packed rows, the reference's column walk only where a screen finds an obstacle; the
// same answer as segment_free_reference, bit for bit. Many segments at once: segments_free()
// and friends in core/line_of_sight_batch.h.
bool segment_free(const Grid& grid, Point a, Point b, const SightRule& rule = {});

// The reference verdict (the walk of check_segment), kept for tests and benchmarks.
inline bool segment_free_reference(const Grid& grid, Point a, Point b, const SightRule& rule = {}) {
  return !check_segment(grid, a, b, rule);
}

// Every consecutive segment free; a single point is checked as the segment p-p; an empty
// polyline is free.
bool polyline_free(const Grid& grid, std::span<const Point> points, const SightRule& rule = {});

// The collision_checks work counter (docs/METRICS.md "Work counters"): a running total per
// thread. Every test above adds one per segment or point it judges (check_segment, segment_free
// and each element of the batched forms), so no caller can forget to count; a planner adds its
// own cell-occupancy tests with count_collision_checks(). plan_checked() reports the difference
// over one plan call. Thread-local: a worker's count is its own plan's alone.
namespace sight_detail {
inline constinit thread_local std::int64_t collision_checks = 0;
}
inline void count_collision_checks(std::int64_t n) { sight_detail::collision_checks += n; }
inline std::int64_t collision_checks_on_thread() { return sight_detail::collision_checks; }

}  // namespace agv
