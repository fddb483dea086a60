#pragma once
// The static-planner metrics of docs/METRICS.md, computed by the engine from a validated path
// (never reported by the planner), so every planner is measured by one ruler. optimality_ratio
// needs the Dijkstra reference and is computed by the runner.

#include <array>
#include <cstdint>
#include <numbers>
#include <span>
#include <string_view>
#include <utility>

#include "core/grid.h"

namespace agv {

// Paper 000 eq. 5.2e parameters.
struct MotionTimeParams {
  double line_speed_mps = 1.0;                 // v_L
  double node_time_s = 0.1;                    // t_o, per waypoint
  double turn_speed_radps = std::numbers::pi;  // v_s
  // Paper 000's eq. 5.2e may add the planning time; this one never does: a time measured on the
  // machine inside a non-timing metric would make the report depend on more than its seed.
};

// Every metric is defined on the geometry of the path, so a polyline and a densely sampled curve
// of the same shape score alike (docs/METRICS.md "Path metrics"). Headings come from segments of
// non-zero length only (duplicate waypoints are skipped, never a NaN heading); a vertex is the
// joint of two consecutive non-zero segments, its turn the atan2 heading difference wrapped to
// (-pi, pi], its position the arc length from the start to it.
struct PathMetrics {
  double path_length = 0.0;      // cells: sum of segment lengths (paper 000 eq. 5.2a)
  double path_length_m = 0.0;    // x cell_edge
  std::int64_t waypoints = 0;    // vertices before curve sampling (eq. 5.2b "Node No.")
  std::int64_t turns = 0;        // merged turns above kTurnThreshold
  double turn_angle_rad = 0.0;   // sum of |turn| over every vertex (eq. 5.2c, computed robustly)
  double max_turn_rad = 0.0;     // the largest merged turn
  double smoothness_mean = 0.0;  // turn_angle_rad / path_length: rad per cell (0 if no length)
  // The largest heading change within any kSmoothnessWindow of arc, each vertex's |turn|
  // spread over kTurnSpread either side of it, divided by the window: rad per cell.
  double smoothness_max = 0.0;
  // Exact minimum distance, in cells, from the path to any obstacle cell (closed squares,
  // border included): DistanceTransform::segment_clearance. And in metres.
  double min_clearance = 0.0;
  double min_clearance_m = 0.0;
  // Paper 000 eq. 5.2e: path_length_m / v_L + waypoints * t_o + turn_angle_rad / v_s.
  double motion_time_s = 0.0;
};

// docs/METRICS.md "turns": a turn is one lobe of the path's curvature. Each vertex's |turn| is
// spread over kTurnSpread either side of it (at most half way to the neighbouring turning
// vertex), a curvature density; vertices of one sign whose spreads touch form a run (so polyline
// corners more than 2 kTurnSpread apart never merge); a run is cut at every valley where the
// density falls to kTurnValleyRatio of the peaks on both sides (two rounded corners), and a lobe
// longer than kTurnMaxExtent cells of arc is cut into ceil(extent / kTurnMaxExtent) equal
// pieces (a U-turn rounded as one bend). A turn counts when its angle exceeds kTurnThreshold.
// Vertices within kStraightTolerance of 0 are collinear joints: they neither join nor split.
inline constexpr double kTurnThreshold = 0.05;      // rad (about 2.9 degrees)
inline constexpr double kTurnValleyRatio = 0.75;    // valley density / the lower adjacent peak
inline constexpr double kTurnMaxExtent = 3.0;       // cells of arc, first to last vertex
inline constexpr double kStraightTolerance = 1e-9;  // rad
// docs/METRICS.md "smoothness_max".
inline constexpr double kSmoothnessWindow = 1.0;  // cells
inline constexpr double kTurnSpread = 0.25;       // cells either side of a vertex

// Precondition: the path passed validate_path (non-empty, finite, inside the grid).
// `waypoints` >= 0 overrides the point count as PathMetrics::waypoints (and its motion-time
// term) for a path that is a sampled curve: docs/METRICS.md counts waypoints before sampling.
PathMetrics compute_path_metrics(const Grid& grid, std::span<const Point> path,
                                 const MotionTimeParams& motion = {}, std::int64_t waypoints = -1);

// Sum of segment lengths in cells, compensated: the same length compute_path_metrics reports.
double polyline_length(std::span<const Point> path);

// (name, value) in a fixed order, for the aggregator and the per-run records.
inline constexpr std::size_t kPathMetricCount = 11;
std::array<std::pair<std::string_view, double>, kPathMetricCount> metric_values(
    const PathMetrics& m);

}  // namespace agv
