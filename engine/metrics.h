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
  bool include_plan_time = false;              // add the planning CPU time
};

// Headings come from segments of non-zero length only (duplicate waypoints are skipped, never a
// NaN heading); an interior "vertex" is the joint of two consecutive non-zero segments, and its
// turn is the atan2 heading difference wrapped to (-pi, pi].
struct PathMetrics {
  double path_length = 0.0;     // cells: sum of segment lengths (paper 000 eq. 5.2a)
  double path_length_m = 0.0;   // x cell_edge
  std::int64_t path_nodes = 0;  // waypoints, duplicates included (eq. 5.2b)
  std::int64_t turns = 0;       // vertices whose |turn| > kTurnThreshold
  double turn_angle_rad = 0.0;  // sum of |turn| (eq. 5.2c, computed robustly)
  // Curvature proxy at a vertex: |turn| / ((l_in + l_out) / 2), l the two segment lengths in
  // cells, i.e. rad per cell. Mean over ALL vertices (collinear ones count 0) and max; 0 when
  // the path has no vertex.
  double smoothness_mean = 0.0;
  double smoothness_max = 0.0;
  // Exact minimum distance, in cells, from the path to any obstacle cell (closed squares,
  // border included): DistanceTransform::segment_clearance. And in metres.
  double min_clearance = 0.0;
  double min_clearance_m = 0.0;
  // Paper 000 eq. 5.2e: path_length_m / v_L + path_nodes * t_o + turn_angle_rad / v_s
  // (+ plan time in seconds if include_plan_time).
  double motion_time_s = 0.0;
};

inline constexpr double kTurnThreshold = 1e-9;  // rad, docs/METRICS.md "turns"

// Precondition: the path passed validate_path (non-empty, finite, inside the grid).
// `waypoints` >= 0 overrides path_nodes (and its motion-time term) for a path that is a sampled
// curve: docs/METRICS.md counts waypoints before sampling.
PathMetrics compute_path_metrics(const Grid& grid, std::span<const Point> path,
                                 const MotionTimeParams& motion = {}, std::int64_t plan_time_ns = 0,
                                 std::int64_t waypoints = -1);

// (name, value) in a fixed order, for the aggregator and the per-run records.
// Sum of segment lengths in cells, compensated: the same length compute_path_metrics reports.
double polyline_length(std::span<const Point> path);

inline constexpr std::size_t kPathMetricCount = 10;
std::array<std::pair<std::string_view, double>, kPathMetricCount> metric_values(
    const PathMetrics& m);

}  // namespace agv
