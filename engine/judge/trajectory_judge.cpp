#include "engine/judge/trajectory_judge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "algos/local/unicycle.h"
#include "core/cell_geometry.h"
#include "core/distance_transform.h"
#include "core/numbers.h"

namespace agv {

namespace {

constexpr double kContactTolerance = 1e-12;  // cells
constexpr double kStartTolerance = 1e-9;     // cells
constexpr double kPositionTolerance = 1e-6;  // cells, kinematic replay
constexpr double kHeadingTolerance = 1e-9;   // rad

// Minimum over s in [0, 1] of |(a0 + s (a1 - a0)) - (b0 + s (b1 - b0))|: two points moving
// linearly over the same interval.
double relative_min(Point a0, Point a1, Point b0, Point b1) {
  const double dx = a0.x - b0.x, dy = a0.y - b0.y;
  const double ex = (a1.x - b1.x) - dx, ey = (a1.y - b1.y) - dy;
  const double e2 = ex * ex + ey * ey;
  double s = 0.0;
  if (e2 > 0.0) s = std::clamp(-(dx * ex + dy * ey) / e2, 0.0, 1.0);
  return std::hypot(dx + s * ex, dy + s * ey);
}

bool finite(Point p) { return std::isfinite(p.x) && std::isfinite(p.y); }

std::string text(const char* format, double a, double b = 0.0, double c = 0.0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, format, a, b, c);
  return buf;
}

// Shape and kinematics; empty when sound.
std::string check_shape(const Grid& grid, Cell start, const Trajectory& tr) {
  const std::size_t n = tr.position.size();
  if (n == 0) return "trajectory: no samples";
  if (tr.t.size() != n || tr.heading.size() != n)
    return "trajectory: t/position/heading sizes differ";
  if (tr.v.size() != n - 1 || tr.w.size() != n - 1)
    return "trajectory: expected one (v, w) command per interval";
  if (!(tr.robot_radius > 0.0) || !std::isfinite(tr.robot_radius))
    return "trajectory: robot_radius must be positive";
  if (!(tr.goal_tolerance >= 0.0) || !std::isfinite(tr.goal_tolerance))
    return "trajectory: goal_tolerance must be non-negative";
  if (!(tr.cell_edge > 0.0) || !std::isfinite(tr.cell_edge))
    return "trajectory: cell_edge must be positive";
  if (tr.t[0] != 0.0) return "trajectory: t[0] must be 0";
  for (std::size_t i = 0; i < n; ++i) {
    if (!finite(tr.position[i]) || !std::isfinite(tr.heading[i]) || !std::isfinite(tr.t[i]))
      return "trajectory: non-finite sample " + std::to_string(i);
    if (i > 0 && !(tr.t[i] > tr.t[i - 1])) return "trajectory: times must increase";
  }
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (!std::isfinite(tr.v[i]) || !std::isfinite(tr.w[i]))
      return "trajectory: non-finite command " + std::to_string(i);
  if (point_distance(tr.position[0], centre(start)) > kStartTolerance)
    return "trajectory: does not start at the start cell's centre";
  for (const auto& ob : tr.obstacles) {
    if (ob.centre.size() != n) return "trajectory: a moving obstacle track has the wrong length";
    if (!(ob.radius > 0.0) || !std::isfinite(ob.radius))
      return "trajectory: moving obstacle radius must be positive";
    for (const Point& p : ob.centre)
      if (!finite(p)) return "trajectory: non-finite moving obstacle position";
  }
  for (const Cell& c : tr.unknown_cells)
    if (!grid.in_bounds(c) || grid.blocked(c))
      return "trajectory: an unknown cell is outside the grid or already an obstacle";
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const Pose a{tr.position[i].x, tr.position[i].y, tr.heading[i]};
    const Pose b = unicycle_step(a, tr.v[i] / tr.cell_edge, tr.w[i], tr.t[i + 1] - tr.t[i]);
    if (point_distance({b.x, b.y}, tr.position[i + 1]) > kPositionTolerance ||
        std::abs(b.theta - tr.heading[i + 1]) > kHeadingTolerance)
      return "trajectory: sample " + std::to_string(i + 1) +
             " does not follow from the previous one under its (v, w) command";
  }
  return {};
}

// The verdict of a run without contact: the planner's end reason, confirmed.
void judge_end(const Trajectory& tr, Cell goal, TrajectoryVerdict& out) {
  const double to_goal = point_distance(tr.position.back(), centre(goal));
  if (tr.end_reason == "reached") {
    if (to_goal <= tr.goal_tolerance + kStartTolerance) {
      out.outcome = Outcome::success;
    } else {
      out.outcome = Outcome::invalid_path;
      out.message = text(
          "trajectory claims to reach the goal but ends %.3f cells from it "
          "(tolerance %.3f)",
          to_goal, tr.goal_tolerance);
    }
  } else if (tr.end_reason == "timeout") {
    out.outcome = Outcome::sim_timeout;
    out.message = text("simulated time limit reached at t = %.1f s, %.2f cells from the goal",
                       tr.t.back(), to_goal);
  } else if (tr.end_reason == "stuck") {
    out.outcome = Outcome::stuck;
    out.message = text(
        "no admissible moving velocity for too long at t = %.1f s, %.2f cells "
        "from the goal",
        tr.t.back(), to_goal);
  } else if (tr.end_reason == "contact") {
    out.outcome = Outcome::invalid_path;
    out.message = "the planner reported a contact that the engine's judge does not confirm";
  } else {
    out.outcome = Outcome::invalid_path;
    out.message = "trajectory: unknown end reason \"" + tr.end_reason + "\"";
  }
}

// What the judge sums and minimises over the intervals, in cells and radians.
struct TrajectoryTotals {
  double travelled, heading_sum, abs_w, min_static, min_dynamic;
};

void add_metrics(const Trajectory& tr, const TrajectoryTotals& t, TrajectoryVerdict& out) {
  const double edge = tr.cell_edge;
  const std::size_t n = tr.position.size();
  out.metrics.emplace_back("travelled_length", t.travelled * edge);
  out.metrics.emplace_back("sim_time_s", tr.t.back());
  out.metrics.emplace_back("control_steps", static_cast<double>(n - 1));
  out.metrics.emplace_back("min_clearance_static", t.min_static * edge);
  if (!tr.obstacles.empty())
    out.metrics.emplace_back("min_clearance_dynamic", t.min_dynamic * edge);
  out.metrics.emplace_back("heading_change_sum", t.heading_sum);
  if (n > 1) out.metrics.emplace_back("mean_abs_w", t.abs_w / static_cast<double>(n - 1));
}

}  // namespace

TrajectoryVerdict judge_trajectory(const Grid& grid, Cell start, Cell goal, const Trajectory& tr) {
  TrajectoryVerdict out;
  if (std::string bad = check_shape(grid, start, tr); !bad.empty()) {
    out.outcome = Outcome::invalid_path;
    out.message = std::move(bad);
    return out;
  }
  const DistanceTransform& dt = grid.distance_transform();
  const std::size_t n = tr.position.size();
  const double r = tr.robot_radius;
  const auto& pos = tr.position;

  // Static clearance at the samples, then exact chord minima only where a chord can go lower
  // than both its ends (1-Lipschitz: never below the nearer end's clearance - length / 2).
  std::vector<double> point_clear(n);
  for (std::size_t i = 0; i < n; ++i) point_clear[i] = dt.clearance(pos[i]);
  double min_static = *std::min_element(point_clear.begin(), point_clear.end());
  double min_dynamic = kInf;
  double travelled = 0.0, heading_sum = 0.0, abs_w = 0.0;
  bool collided = false;

  auto collide = [&](Outcome what, std::string message) {
    if (collided) return;
    collided = true;
    out.outcome = what;
    out.message = std::move(message);
  };

  const std::size_t intervals = n > 1 ? n - 1 : 1;
  for (std::size_t i = 0; i < intervals; ++i) {
    const std::size_t j = std::min(i + 1, n - 1);
    const Point a = pos[i], b = pos[j];
    const double len = point_distance(a, b);
    const double time = tr.t[j];
    // Static cells. The chord's clearance is at least its endpoints' minus half its length; the
    // exact value is needed where that bound could fall below the radius (a contact) or below
    // the minimum so far (the metric).
    double s = std::min(point_clear[i], point_clear[j]);
    if (s - 0.5 * len < std::max(min_static, r)) s = dt.segment_clearance(a, b);
    min_static = std::min(min_static, s);
    if (s < r - kContactTolerance)
      collide(Outcome::collision_static,
              text("robot disc meets a static cell by t = %.2f s (clearance %.4f < radius %.4f)",
                   time, s, r));
    // Unknown cells.
    for (const Cell& c : tr.unknown_cells) {
      const double u = segment_cell_distance(a, b, c);
      min_static = std::min(min_static, u);
      if (u < r - kContactTolerance)
        collide(
            Outcome::collision_unknown,
            text("robot disc meets an unknown cell by t = %.2f s (clearance %.4f < radius %.4f)",
                 time, u, r));
    }
    // Moving discs.
    for (const auto& ob : tr.obstacles) {
      const double d = relative_min(a, b, ob.centre[i], ob.centre[j]) - ob.radius;
      min_dynamic = std::min(min_dynamic, d);
      if (d < r - kContactTolerance)
        collide(Outcome::collision_dynamic,
                text("robot disc meets a moving obstacle by t = %.2f s (gap %.4f < radius %.4f)",
                     time, d, r));
    }
    if (n > 1) {
      travelled += len;
      heading_sum += std::abs(wrap_angle(tr.heading[j] - tr.heading[i]));
      abs_w += std::abs(tr.w[i]);
    }
  }

  if (!collided) judge_end(tr, goal, out);
  out.min_clearance = min_static;
  out.sim_time_s = tr.t.back();
  add_metrics(tr, {travelled, heading_sum, abs_w, min_static, min_dynamic}, out);
  return out;
}

void apply_trajectory_verdict(const TrajectoryVerdict& verdict, double cell_edge, PathMetrics& m) {
  m.min_clearance = verdict.min_clearance;
  m.min_clearance_m = verdict.min_clearance * cell_edge;
  m.motion_time_s = verdict.sim_time_s;
}

}  // namespace agv
