#pragma once
// Curve steps shared by every planner: quadratic Bezier corners (paper 002 eq. 14), the clamped
// cubic uniform B-spline in the matrix form of paper 004 appendix A, curve sampling, and paper
// 002's obstacle-avoidance adjustment of key points (eq. 12-13).
//
// Every curve is returned as the polyline of its samples, and every sample polyline is checked
// segment by segment with the shared line of sight (core/line_of_sight.h), under the rule the
// caller passes (the planner's SightRule::cells(corner rule), or a margin). A sampled polyline
// that passes is free at every point of every segment, so it is also free when checked at any
// finer sampling, and it passes the engine's validator under the same corner rule.
//
// Fallbacks keep that guarantee: a Bezier corner that still hits after shrinking stays a sharp
// corner; a B-spline that still hits after its refits gives back its control polygon; a result
// that fails the final check gives back the input polyline (free by precondition).
//
// Deadline: the curve steps poll `poll` (algos/planner.h DeadlinePoller) once per corner or
// sight test and, once it has expired, give back their input, which the caller (seeing
// poll->has_expired()) discards.

#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include "algos/planner.h"
#include "core/grid.h"
#include "core/line_of_sight.h"

namespace agv {

// B(t) = (1-t)^2 p0 + 2t(1-t) p1 + t^2 p2 at `points` parameters t = 0, 1/(points-1), ..., 1
// (paper 002 eq. 14); points >= 2.
std::vector<Point> sample_quadratic_bezier(Point p0, Point p1, Point p2, int points);

// The clamped cubic uniform B-spline with control points `controls` (each end repeated three
// times, so the curve starts at the first and ends at the last control point), segment j being
// P(t) = 1/6 [1 t t^2 t^3] M [Q_j .. Q_j+3] with M the basis matrix of paper 004 appendix A;
// sampled so consecutive samples are at most about `step` cells apart. `segment_of` (optional)
// receives, per sample, the curve segment it belongs to.
std::vector<Point> sample_bspline(std::span<const Point> controls, double step,
                                  std::vector<int>* segment_of = nullptr);

struct BezierOptions {
  double corner_distance = 1.0;  // L: P0 and P2 this far from the corner (clamped to half of
                                 // each adjacent segment), cells
  int points_per_curve = 10;     // samples per corner, P0 and P2 included
  int shrink_steps = 3;          // halvings of the distance tried when a curve hits
};

// Paper 002 section 4.2 step 4: a quadratic Bezier at every interior point of `keys` (a free
// polyline under `sight`), with P1 = the key point and P0, P2 on the incoming and outgoing
// segments; a curve that hits is shrunk, and the corner stays sharp if it still hits.
std::vector<Point> bezier_corners(const Grid& grid, std::span<const Point> keys,
                                  const SightRule& sight, const BezierOptions& options = {},
                                  DeadlinePoller* poll = nullptr);

struct BsplineOptions {
  double sample_step = 0.1;  // cells between samples
  int max_refits = 64;       // control-point insertions tried before giving up
};

// Paper 004 section 2.4: the B-spline whose control points are dense[kept[0]], dense[kept[1]],
// ... (kept increasing, dense[kept] a free polyline under `sight`). Where the sampled curve
// hits, the removed dense point between the hit segment's control points that lies nearest the
// hit is re-inserted and the curve refitted (docs/PLANNERS.md); with no removed point left there,
// the control point nearest the hit is tripled (the curve then runs along the control polygon
// through it). After max_refits, the control polygon dense[kept] itself is returned.
std::vector<Point> bspline_smooth(const Grid& grid, std::span<const Point> dense,
                                  std::vector<int> kept, const SightRule& sight,
                                  const BsplineOptions& options = {},
                                  DeadlinePoller* poll = nullptr);

// Sum of the segment lengths, cells.
double polyline_length_cells(std::span<const Point> path);

// A heading change above this (150 degrees) is a reversal: the path turns back on itself.
// avoid_obstacles refuses an adjustment that makes one (docs/PLANNERS.md "Improved A*").
inline constexpr double kReversalAngle = 150.0 * std::numbers::pi / 180.0;

// Paper 002 eq. 12-13 (section 4.2 "obstacle avoidance adjustment"), resolved in docs/PLANNERS.md:
// 1. each interior key point with an obstacle among its cell's 8 neighbours is moved `offset`
//    (L/2) away from them: k - offset * a / |a|, a = sum of the unit vectors from k to those
//    obstacle centres (eq. 12 direction, eq. 13 move);
// 2. where a segment then passes closer than `near` (L) to an obstacle cell centre, the vertex of
//    that cell nearest the segment, moved `offset` away from the cell centre, is inserted, unless
//    that point is already on the polyline.
// A move or insertion is kept only when the segments it creates are free under `sight`, no
// vertex it changes turns by more than kReversalAngle, and the polyline stays no longer than
// `max_length` (the improved A* passes its search path's length). So a free polyline stays free,
// and the adjustment makes no reversal the input did not have.
void avoid_obstacles(const Grid& grid, std::vector<Point>& keys, const SightRule& sight,
                     double offset = 0.5, double near = 1.0,
                     double max_length = std::numeric_limits<double>::infinity(),
                     DeadlinePoller* poll = nullptr);

}  // namespace agv
