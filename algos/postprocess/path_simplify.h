#pragma once
// Path simplification steps shared by every planner (docs/PLANNERS.md "Line of sight and clearance"
// and the A* family sections): one implementation of each, every collision test through
// core/line_of_sight.h.
//
// Guarantees, tested on many random maps (tests/algos/test_family.cpp):
// - Subsequence steps (collinear removal, turning-point removal, greedy shortcuts, forward key
//   points, redundancy removal from the goal) keep the first and the last point and only drop
//   points; a point is dropped only when the segment that replaces it is free under the given
//   SightRule, so the result is free wherever the input was, and, by the triangle inequality,
//   never longer than the input.
// - insert_midpoints() changes neither the shape nor the length.
// - shortcut_direct_midpoint() moves a corner to the midpoint of one of its segments only when
//   both new segments are free; the triangle inequality again makes it never longer.
//
// The *_keep() forms return the indices of the kept points (increasing, first 0, last n - 1),
// so a later step (the B-spline refit, algos/postprocess/path_curves.h) can re-insert removed
// points.
//
// Deadline: the steps that test sight in a loop poll `poll` (algos/planner.h DeadlinePoller) once
// per sight test or point, and stop when it has expired, returning a valid but unfinished
// result that the caller, which sees poll->has_expired(), discards.

#include <span>
#include <vector>

#include "algos/planner.h"
#include "core/grid.h"
#include "core/line_of_sight.h"

namespace agv {

// True when b lies on the straight continuation a -> b -> c (same direction, or a zero-length
// segment). Points on the half-cell lattice (cell centres, their midpoints) are compared with an
// exact integer cross product of doubled coordinates (paper 000 eq. 5.1a without its slopes,
// which divide by zero on vertical moves); other points with a relative tolerance of 1e-12.
bool goes_straight(Point a, Point b, Point c);

// Paper 000 step 2 / eq. 5.1a, paper 003 section 2.4 first step: drops duplicate points and
// points where the path goes straight on. No collision test is needed: the merged segment is
// the union of the two it replaces.
std::vector<int> collinear_keep(std::span<const Point> path);
void remove_collinear(std::vector<Point>& path);

// Paper 000 step 3 / eq. 5.1b: repeatedly drops an interior point whose two neighbours see each
// other under `sight` (MA*: SightRule::circles(r_obs)), until no point can be dropped.
std::vector<int> turning_point_keep(const Grid& grid, std::span<const Point> path,
                                    const SightRule& sight, DeadlinePoller* poll = nullptr);
void remove_turning_points(const Grid& grid, std::vector<Point>& path, const SightRule& sight,
                           DeadlinePoller* poll = nullptr);

// Greedy shortcutting: from the start, jump to the FARTHEST later point in sight, repeat from
// there. from_goal = true runs the same walk from the goal backwards (paper 004 section 2.3
// "secondary redundancy removal": the goal connects to the earliest node it sees under the
// safety margin, then that node does the same, down to the start).
std::vector<int> greedy_keep(const Grid& grid, std::span<const Point> path, const SightRule& sight,
                             bool from_goal = false, DeadlinePoller* poll = nullptr);
void shortcut_greedy(const Grid& grid, std::vector<Point>& path, const SightRule& sight);
void remove_redundant_from_goal(const Grid& grid, std::vector<Point>& path, const SightRule& sight);

// Paper 002 Algorithm 2, its intent (the printed condition is garbled, docs/PLANNERS.md): from the
// current key point the next key point is the last path point still in sight before the first
// one that is not; repeat to the goal.
std::vector<int> forward_keep(const Grid& grid, std::span<const Point> path, const SightRule& sight,
                              DeadlinePoller* poll = nullptr);
void forward_key_points(const Grid& grid, std::vector<Point>& path, const SightRule& sight);

// Paper 002 Algorithm 2 lines 1-12 (eq. 11 read as the midpoint): a point halfway between every
// two consecutive points.
void insert_midpoints(std::vector<Point>& path);

// Paper 003 section 2.4: drop collinear points; then, walking forward, for each turning point
// B between its predecessor S and successor G: the direct connection S-G when it is free;
// failing that the midpoint shortcut S-C-G with C the midpoint of S-B (Figure 5), or else with
// C the midpoint of B-G; otherwise B stays.
void shortcut_direct_midpoint(const Grid& grid, std::vector<Point>& path, const SightRule& sight,
                              DeadlinePoller* poll = nullptr);

// The points of `path` at `keep`.
std::vector<Point> select_points(std::span<const Point> path, std::span<const int> keep);

}  // namespace agv
