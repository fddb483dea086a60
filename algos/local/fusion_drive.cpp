#include "algos/local/fusion_drive.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "algos/local/unicycle.h"
#include "core/cell_geometry.h"
#include "core/distance_transform.h"

namespace agv {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kDeadlineCheckSteps = 32;
constexpr double kStandStill = 1e-3;  // cells per control step
// Key points a rollout may pass within one horizon (T v_max = 6 m at the defaults).
constexpr std::size_t kLookaheadGoals = 8;

struct DriveScratch {
  DwaScratch dwa;
  std::vector<char> seen;  // per unknown cell
  std::vector<Cell> seen_cells;
  std::vector<Disc> visible;
  std::vector<Point> last_seen;  // per moving disc: its centre at the previous control step
  std::vector<char> was_seen;
  Grid replan_grid;
};

// Does the polyline pos -> keys[from..] pass within `r` of unknown cell c's square?
bool path_near_cell(Point pos, const std::vector<Point>& keys, std::size_t from, Cell c, double r) {
  Point a = pos;
  for (std::size_t i = from; i < keys.size(); ++i) {
    if (segment_cell_distance(a, keys[i], c) < r) return true;
    a = keys[i];
  }
  return false;
}

// The turn speed limit: turning by phi at w_max within `reach_m` metres of travel allows
// v_turn = reach_m w_max / phi, reached by braking at acc_v over `room_m`.
double turn_speed(double phi, double room_m, double reach_m, const DwaParams& p) {
  if (phi < 1e-6) return kInf;
  const double v_turn = reach_m * p.w_max / phi;
  return std::sqrt(v_turn * v_turn + 2.0 * p.acc_v * std::max(0.0, room_m));
}

// The cap for the turn in progress (heading against the direction to the aim point) and for
// the turns at the next key points.
double turn_speed_cap(const FusionOptions& o, const std::vector<Point>& keys, std::size_t key,
                      const Pose& pose, Point aim, double edge) {
  const double reach = o.turn_distance * edge;
  const Point pos = position(pose);
  double cap = turn_speed(
      std::abs(wrap_angle(std::atan2(aim.y - pos.y, aim.x - pos.x) - pose.theta)), 0.0, reach,
      o.dwa);
  double distance = point_distance(pos, keys[key]);
  for (std::size_t k = key; k + 1 < keys.size() && k < key + 3; ++k) {
    const double a = std::atan2(keys[k].y - keys[k - 1].y, keys[k].x - keys[k - 1].x);
    const double b = std::atan2(keys[k + 1].y - keys[k].y, keys[k + 1].x - keys[k].x);
    const double room = std::max(0.0, distance - o.waypoint_tolerance) * edge;
    cap = std::min(cap, turn_speed(std::abs(wrap_angle(b - a)), room, reach, o.dwa));
    distance += point_distance(keys[k], keys[k + 1]);
  }
  return cap;
}

}  // namespace

std::vector<Point> fusion_key_points(std::span<const Point> path, double tolerance) {
  const std::size_t n = path.size();
  if (n <= 2) return {path.begin(), path.end()};
  std::vector<char> keep(n, 0);
  keep.front() = keep.back() = 1;
  // Iterative Ramer-Douglas-Peucker: split a span at its farthest point while that point lies
  // farther than `tolerance` from the chord.
  std::vector<std::pair<std::size_t, std::size_t>> stack = {{0, n - 1}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    double far = -1.0;
    std::size_t at = a;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = point_segment_distance(path[i], path[a], path[b]);
      if (d > far) {
        far = d;
        at = i;
      }
    }
    if (at > a && far > tolerance) {
      keep[at] = 1;
      stack.push_back({a, at});
      stack.push_back({at, b});
    }
  }
  std::vector<Point> out;
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i] && (out.empty() || !(out.back() == path[i]))) out.push_back(path[i]);
  if (out.size() == 1) out.push_back(path.back());
  return out;
}

DriveResult drive(const FusionOptions& o, const PlanRequest& req, DwaWorld& world,
                  std::vector<Point> keys, const Planner* global) {
  const Grid& grid = req.grid;
  DriveScratch& fs = req.scratch.get<DriveScratch>();
  const double edge = grid.cell_edge();
  const Point start = centre(req.start), goal = centre(req.goal);
  if (keys.size() < 2) keys = {start, goal};
  DwaParams dp = o.dwa;
  dp.cell_edge = edge;
  const auto max_steps = static_cast<long long>(std::ceil(o.sim_time_limit / dp.dt - 1e-9));
  const double keep_out = dp.robot_radius + dp.safety_margin;
  const GoalPassing passing{o.waypoint_tolerance, o.pass_radius};
  const double horizon_cells = dp.v_max * dp.predict_time / edge + o.waypoint_tolerance;

  DriveResult out;
  auto tr = std::make_shared<Trajectory>();
  tr->robot_radius = dp.robot_radius;
  tr->goal_tolerance = o.goal_tolerance;
  tr->cell_edge = edge;
  tr->unknown_cells.assign(world.unknown_cells().begin(), world.unknown_cells().end());
  tr->key_points = keys;
  for (const MovingDisc& m : world.moving()) tr->obstacles.push_back({m.radius, {}});
  // The robot starts at rest, facing its first local goal.
  Pose pose{start.x, start.y, std::atan2(keys[1].y - start.y, keys[1].x - start.x)};
  double v = 0.0, w = 0.0;
  auto record = [&] {
    tr->t.push_back(static_cast<double>(out.steps) * dp.dt);
    tr->position.push_back(position(pose));
    tr->heading.push_back(pose.theta);
    for (std::size_t j = 0; j < world.moving().size(); ++j)
      tr->obstacles[j].centre.push_back(world.moving()[j].centre);
  };
  record();

  fs.seen.assign(world.unknown_cells().size(), 0);
  fs.seen_cells.clear();
  fs.last_seen.assign(world.moving().size(), Point{});
  fs.was_seen.assign(world.moving().size(), 0);
  std::size_t key = 1;
  int stuck = 0;
  std::string end;
  while (true) {
    const Point pos = position(pose);
    if (point_distance(pos, goal) <= o.goal_tolerance) {
      end = "reached";
      break;
    }
    // Sense: unknown cells within range are seen (and remembered); moving discs within range.
    bool replan = false;
    for (std::size_t j = 0; j < fs.seen.size(); ++j) {
      const Cell c = world.unknown_cells()[j];
      if (fs.seen[j] || point_distance(pos, centre(c)) > o.sensor_range) continue;
      fs.seen[j] = 1;
      fs.seen_cells.push_back(c);
      replan = replan || (global != nullptr && o.replan && path_near_cell(pos, keys, key, c, keep_out));
    }
    if (replan) {
      // Replan on the grid as now known, from the robot's cell.
      fs.replan_grid = grid;
      for (const Cell& c : fs.seen_cells) fs.replan_grid.set_blocked(c, true);
      const Cell here{static_cast<int>(pos.x), static_cast<int>(pos.y)};
      if (fs.replan_grid.in_bounds(here) && !fs.replan_grid.blocked(here)) {
        const PlanRequest sub{fs.replan_grid, here, req.goal, req.rng, req.scratch, req.deadline};
        const PlanResult g = global->plan(sub);
        out.expanded_nodes += g.expanded_nodes;
        if (g.ok()) {
          keys = fusion_key_points(g.path, o.key_point_tolerance);
          if (keys.size() < 2) keys.push_back(goal);
          key = 1;
          ++out.replans;
        }
      }
    }
    // Advance the local goal past key points passed or made unreachable by an unknown cell.
    while (key + 1 < keys.size()) {
      const Point k = keys[key];
      double clear = kInf;
      for (const Cell& c : fs.seen_cells) clear = std::min(clear, point_cell_distance(k, c));
      if (clear >= keep_out && !passes_goal(pos, keys[key - 1], k, passing)) break;
      ++key;
    }
    fs.visible.clear();
    for (std::size_t j = 0; j < world.moving().size(); ++j) {
      const MovingDisc& m = world.moving()[j];
      const bool seen = point_distance(pos, m.centre) - m.radius <= o.sensor_range;
      Point velocity;  // observed: the displacement since the previous control step
      if (seen && o.predict_moving && fs.was_seen[j])
        velocity = {(m.centre.x - fs.last_seen[j].x) / dp.dt,
                    (m.centre.y - fs.last_seen[j].y) / dp.dt};
      if (seen) fs.visible.push_back({m.centre, m.radius, velocity});
      fs.was_seen[j] = seen;
      fs.last_seen[j] = m.centre;
    }

    // The local goal and the key points after it (rollouts that pass one aim at the next), or
    // the final goal alone.
    DwaTarget target;
    // Only key points a rollout can reach within the horizon (at most v_max T along the path).
    std::size_t reach = 1;
    for (double along = point_distance(pos, keys[key]); key + reach < keys.size() && reach < kLookaheadGoals;
         ++reach) {
      if (along > horizon_cells) break;
      along += point_distance(keys[key + reach - 1], keys[key + reach]);
    }
    target.goals = std::span<const Point>(keys.data() + key, reach);
    target.passing = passing;
    target.from = keys[key - 1];
    target.aim_segment = o.aim_segment;
    target.lookahead = o.lookahead;
    if (o.heading_final) {
      target.goals = std::span<const Point>(&goal, 1);
      target.from = pos;
      target.aim_segment = false;
    } else if (o.turn_speed_limit) {
      target.speed_cap = turn_speed_cap(
          o, keys, key, pose, aim_point(keys[key - 1], keys[key], pos, o.lookahead), edge);
    }
    const DwaView view{grid, fs.seen_cells, fs.visible};
    const DwaDecision d = dwa_step(dp, pose, v, w, target, view, fs.dwa);
    v = d.v;
    w = d.w;
    pose = unicycle_step(pose, v / edge, w, dp.dt);
    const Point robot = position(pose);
    world.advance(dp.dt, o.moving_yield ? &robot : nullptr, dp.robot_radius);
    ++out.steps;
    tr->v.push_back(v);
    tr->w.push_back(w);
    record();
    if (world.contact(position(pose), dp.robot_radius) != DwaWorld::Contact::none) {
      end = "contact";
      break;
    }
    // Stuck: no admissible velocity that moves the robot, or one the DWA does not take (the
    // classic local minimum: every forward rollout ends at an obstacle, standing scores best).
    const bool moved = d.any_moving && point_distance(position(pose), pos) >= kStandStill;
    stuck = moved ? 0 : stuck + 1;
    if (stuck >= o.stuck_steps) {
      end = "stuck";
      break;
    }
    if (out.steps >= max_steps && point_distance(position(pose), goal) > o.goal_tolerance) {
      end = "timeout";
      break;
    }
    if (out.steps % kDeadlineCheckSteps == 0 && req.deadline.expired()) {
      out.deadline_hit = true;
      end = "timeout";
      break;
    }
  }
  tr->end_reason = end;
  out.trajectory = std::move(tr);
  return out;
}

}  // namespace agv
