#include "engine/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

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

struct Vertex {
  double turn;  // signed, wrapped to (-pi, pi]
  double at;    // arc length from the start, cells
};

struct TurnSummary {
  std::int64_t count = 0;
  double max = 0.0;
};

// docs/METRICS.md "turns": same-sign vertices less than kTurnMergeLength apart form one turn.
TurnSummary merged_turns(std::span<const Vertex> vertices) {
  TurnSummary t;
  double sum = 0.0;
  double sign = 0.0;  // of the open merged turn; 0 when none is open
  double last_at = 0.0;
  const auto close = [&] {
    if (sign != 0.0 && sum > kTurnThreshold) ++t.count;
    t.max = std::max(t.max, sum);
  };
  for (const Vertex& v : vertices) {
    if (std::abs(v.turn) <= kStraightTolerance) continue;
    const double s = v.turn > 0.0 ? 1.0 : -1.0;
    if (s != sign || v.at - last_at >= kTurnMergeLength) {
      close();
      sign = s;
      sum = 0.0;
    }
    sum += std::abs(v.turn);
    last_at = v.at;
  }
  close();
  return t;
}

// docs/METRICS.md "smoothness_max": each vertex's |turn| spread evenly over the arc within
// kTurnSpread of it (at most to the middle of either adjacent segment), a curvature density;
// the largest integral of that density over a kSmoothnessWindow of arc, per cell. A window
// with an end at a box edge is a largest one. The spread makes a curve sampled every h score
// its curvature, not one sample's turn more (a point mass per vertex would count floor(W / h)
// or that plus one of them, 10 % apart at h = 0.1).
struct TurnBox {
  double lo;
  double hi;
  double turn;  // |turn|, spread over [lo, hi]
};

double window_integral(std::span<const TurnBox> boxes, double from) {
  const double to = from + kSmoothnessWindow;
  double sum = 0.0;
  for (const TurnBox& b : boxes) {
    if (b.lo >= to) break;
    const double overlap = std::min(b.hi, to) - std::max(b.lo, from);
    if (overlap > 0.0) sum += b.turn * std::min(1.0, overlap / (b.hi - b.lo));
  }
  return sum;
}

double max_window_turn(std::span<const TurnBox> boxes) {
  double best = 0.0;
  std::size_t first = 0;  // the first box that ends after the window starts
  const auto from_box = [&](double from) {
    while (first < boxes.size() && boxes[first].hi <= from) ++first;
    return window_integral(boxes.subspan(first), from);
  };
  // Windows starting at a box's start, then windows ending at a box's end (both in increasing
  // order of their start, so `first` only moves forward within each pass).
  for (const TurnBox& b : boxes) best = std::max(best, from_box(b.lo));
  first = 0;
  for (const TurnBox& b : boxes) best = std::max(best, from_box(b.hi - kSmoothnessWindow));
  return best / kSmoothnessWindow;
}

}  // namespace

PathMetrics compute_path_metrics(const Grid& grid, std::span<const Point> path,
                                 const MotionTimeParams& motion, std::int64_t plan_time_ns,
                                 std::int64_t waypoints) {
  PathMetrics m;
  m.waypoints = waypoints >= 0 ? waypoints : static_cast<std::int64_t>(path.size());
  if (path.empty()) return m;

  CompensatedSum length;
  CompensatedSum turn_sum;
  std::vector<Vertex> vertices;
  std::vector<TurnBox> boxes;
  bool have_previous = false;
  double previous_heading = 0.0;
  double previous_length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double dx = path[i].x - path[i - 1].x;
    const double dy = path[i].y - path[i - 1].y;
    const double l = std::hypot(dx, dy);
    if (l == 0.0) continue;  // duplicate waypoint: no heading
    const double heading = std::atan2(dy, dx);
    if (have_previous) {
      const double turn = wrapped_turn(previous_heading, heading);
      turn_sum.add(std::abs(turn));
      const double at = length.value();
      vertices.push_back({turn, at});
      if (std::abs(turn) > 0.0)
        boxes.push_back({at - std::min(kTurnSpread, previous_length / 2.0),
                         at + std::min(kTurnSpread, l / 2.0), std::abs(turn)});
    }
    length.add(l);
    have_previous = true;
    previous_heading = heading;
    previous_length = l;
  }
  m.path_length = length.value();
  m.path_length_m = m.path_length * grid.cell_edge();
  m.turn_angle_rad = turn_sum.value();
  const TurnSummary turns = merged_turns(vertices);
  m.turns = turns.count;
  m.max_turn_rad = turns.max;
  if (m.path_length > 0.0) m.smoothness_mean = m.turn_angle_rad / m.path_length;
  m.smoothness_max = max_window_turn(boxes);

  const DistanceTransform& dt = grid.distance_transform();
  double clearance =
      path.size() == 1 ? dt.clearance(path[0]) : std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < path.size(); ++i)
    clearance = std::min(clearance, dt.segment_clearance(path[i - 1], path[i]));
  m.min_clearance = clearance;
  m.min_clearance_m = clearance * grid.cell_edge();

  // Paper 000 eq. 5.2e.
  m.motion_time_s = m.path_length_m / motion.line_speed_mps +
                    static_cast<double>(m.waypoints) * motion.node_time_s +
                    m.turn_angle_rad / motion.turn_speed_radps;
  if (motion.include_plan_time) m.motion_time_s += static_cast<double>(plan_time_ns) * 1e-9;
  return m;
}

std::array<std::pair<std::string_view, double>, kPathMetricCount> metric_values(
    const PathMetrics& m) {
  return {{
      {"path_length", m.path_length},
      {"path_length_m", m.path_length_m},
      {"waypoints", static_cast<double>(m.waypoints)},
      {"turns", static_cast<double>(m.turns)},
      {"turn_angle_rad", m.turn_angle_rad},
      {"max_turn_rad", m.max_turn_rad},
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
