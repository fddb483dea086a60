#include "engine/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/distance_transform.h"
#include "engine/statistics.h"

namespace agv {

namespace {

// Difference of two headings wrapped to (-pi, pi].
double wrapped_turn(double from, double to) {
  constexpr double kPi = std::numbers::pi;
  double d = to - from;  // in (-2 pi, 2 pi)
  if (d > kPi) d -= 2.0 * kPi;
  if (d <= -kPi) d += 2.0 * kPi;
  return d;
}

}  // namespace

PathMetrics compute_path_metrics(const Grid& grid, std::span<const Point> path,
                                 const MotionTimeParams& motion, std::int64_t plan_time_ns,
                                 std::int64_t waypoints) {
  PathMetrics m;
  m.path_nodes = waypoints >= 0 ? waypoints : static_cast<std::int64_t>(path.size());
  if (path.empty()) return m;

  CompensatedSum length;
  CompensatedSum turn_sum;
  CompensatedSum curvature_sum;
  std::size_t vertices = 0;
  bool have_previous = false;
  double previous_heading = 0.0;
  double previous_length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double dx = path[i].x - path[i - 1].x;
    const double dy = path[i].y - path[i - 1].y;
    const double l = std::hypot(dx, dy);
    if (l == 0.0) continue;  // duplicate waypoint: no heading
    length.add(l);
    const double heading = std::atan2(dy, dx);
    if (have_previous) {
      const double turn = std::abs(wrapped_turn(previous_heading, heading));
      if (turn > kTurnThreshold) ++m.turns;
      turn_sum.add(turn);
      const double curvature = turn / ((previous_length + l) / 2.0);
      curvature_sum.add(curvature);
      m.smoothness_max = std::max(m.smoothness_max, curvature);
      ++vertices;
    }
    have_previous = true;
    previous_heading = heading;
    previous_length = l;
  }
  m.path_length = length.value();
  m.path_length_m = m.path_length * grid.cell_edge();
  m.turn_angle_rad = turn_sum.value();
  if (vertices > 0) m.smoothness_mean = curvature_sum.value() / static_cast<double>(vertices);

  const DistanceTransform& dt = grid.distance_transform();
  double clearance =
      path.size() == 1 ? dt.clearance(path[0]) : std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < path.size(); ++i)
    clearance = std::min(clearance, dt.segment_clearance(path[i - 1], path[i]));
  m.min_clearance = clearance;
  m.min_clearance_m = clearance * grid.cell_edge();

  // Paper 000 eq. 5.2e.
  m.motion_time_s = m.path_length_m / motion.line_speed_mps +
                    static_cast<double>(m.path_nodes) * motion.node_time_s +
                    m.turn_angle_rad / motion.turn_speed_radps;
  if (motion.include_plan_time) m.motion_time_s += static_cast<double>(plan_time_ns) * 1e-9;
  return m;
}

std::array<std::pair<std::string_view, double>, kPathMetricCount> metric_values(
    const PathMetrics& m) {
  return {{
      {"path_length", m.path_length},
      {"path_length_m", m.path_length_m},
      {"path_nodes", static_cast<double>(m.path_nodes)},
      {"turns", static_cast<double>(m.turns)},
      {"turn_angle_rad", m.turn_angle_rad},
      {"smoothness_mean", m.smoothness_mean},
      {"smoothness_max", m.smoothness_max},
      {"min_clearance", m.min_clearance},
      {"min_clearance_m", m.min_clearance_m},
      {"motion_time_s", m.motion_time_s},
  }};
}

double polyline_length(std::span<const Point> path) {
  CompensatedSum length;
  for (std::size_t i = 1; i < path.size(); ++i)
    length.add(std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y));
  return length.value();
}

}  // namespace agv
