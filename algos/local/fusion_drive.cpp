#include "algos/local/fusion_drive.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "algos/local/unicycle.h"
#include "core/cell_geometry.h"
#include "core/distance_transform.h"
#include "core/numbers.h"

namespace agv {

namespace {

constexpr int kDeadlineCheckSteps = 32;
constexpr std::int64_t kRolloutPointsPerPoll = 4096;
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
  double cap =
      turn_speed(std::abs(wrap_angle(std::atan2(aim.y - pos.y, aim.x - pos.x) - pose.theta)), 0.0,
                 reach, o.dwa);
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

namespace {

// One run of the control loop: the robot's state and what it has sensed, one method per step
// of a control period.
class Drive {
 public:
  Drive(const FusionOptions& o, const PlanRequest& req, DwaWorld& world, std::vector<Point> keys,
        const Planner* global)
      : o_(o),
        req_(req),
        grid_(req.grid),
        world_(world),
        global_(global),
        fs_(req.scratch.get<DriveScratch>()),
        edge_(grid_.cell_edge()),
        start_(centre(req.start)),
        goal_(centre(req.goal)),
        keys_(std::move(keys)),
        dp_(o.dwa),
        rollout_poll_(req.deadline, std::max<std::int64_t>(
                                        1, kRolloutPointsPerPoll /
                                               std::max(1, o.dwa.v_samples * o.dwa.w_samples))),
        tr_(std::make_shared<Trajectory>()) {
    if (keys_.size() < 2) keys_ = {start_, goal_};
    dp_.cell_edge = edge_;
    max_steps_ = static_cast<long long>(std::ceil(o_.sim_time_limit / dp_.dt - 1e-9));
    keep_out_ = dp_.robot_radius + dp_.safety_margin;
    passing_ = GoalPassing{o_.waypoint_tolerance, o_.pass_radius};
    horizon_cells_ = dp_.v_max * dp_.predict_time / edge_ + o_.waypoint_tolerance;

    tr_->robot_radius = dp_.robot_radius;
    tr_->goal_tolerance = o_.goal_tolerance;
    tr_->cell_edge = edge_;
    tr_->unknown_cells.assign(world_.unknown_cells().begin(), world_.unknown_cells().end());
    tr_->key_points = keys_;
    for (const MovingDisc& m : world_.moving()) tr_->obstacles.push_back({m.radius, {}});
    // The robot starts at rest, facing its first local goal.
    pose_ = Pose{start_.x, start_.y, std::atan2(keys_[1].y - start_.y, keys_[1].x - start_.x)};
    record();

    fs_.seen.assign(world_.unknown_cells().size(), 0);
    fs_.seen_cells.clear();
    fs_.last_seen.assign(world_.moving().size(), Point{});
    fs_.was_seen.assign(world_.moving().size(), 0);
  }

  DriveResult run() {
    std::string end;
    while (true) {
      const Point pos = position(pose_);
      if (point_distance(pos, goal_) <= o_.goal_tolerance) {
        end = "reached";
        break;
      }
      if (sense_unknown(pos)) replan(pos);
      advance_local_goal(pos);
      sense_moving(pos);
      const DwaView view{grid_, fs_.seen_cells, fs_.visible};
      const DwaDecision d =
          dwa_step(dp_, pose_, v_, w_, local_target(pos), view, fs_.dwa, &rollout_poll_);
      if (d.cut) {
        out_.deadline_hit = true;
        end = "timeout";
        break;
      }
      move(d);
      if (const char* reason = end_of_run(d, pos)) {
        end = reason;
        break;
      }
    }
    tr_->end_reason = end;
    out_.trajectory = std::move(tr_);
    return std::move(out_);
  }

 private:
  void record() {
    tr_->t.push_back(static_cast<double>(out_.steps) * dp_.dt);
    tr_->position.push_back(position(pose_));
    tr_->heading.push_back(pose_.theta);
    for (std::size_t j = 0; j < world_.moving().size(); ++j)
      tr_->obstacles[j].centre.push_back(world_.moving()[j].centre);
  }

  // Sense: unknown cells within range are seen (and remembered). True when one newly seen lies
  // on the remaining global path and the run replans.
  bool sense_unknown(Point pos) {
    bool replan = false;
    for (std::size_t j = 0; j < fs_.seen.size(); ++j) {
      const Cell c = world_.unknown_cells()[j];
      if (fs_.seen[j] || point_distance(pos, centre(c)) > o_.sensor_range) continue;
      fs_.seen[j] = 1;
      fs_.seen_cells.push_back(c);
      replan = replan ||
               (global_ != nullptr && o_.replan && path_near_cell(pos, keys_, key_, c, keep_out_));
    }
    return replan;
  }

  // Replan on the grid as now known, from the robot's cell.
  void replan(Point pos) {
    fs_.replan_grid = grid_;
    for (const Cell& c : fs_.seen_cells) fs_.replan_grid.set_blocked(c, true);
    const Cell here{static_cast<int>(pos.x), static_cast<int>(pos.y)};
    if (!fs_.replan_grid.in_bounds(here) || fs_.replan_grid.blocked(here)) return;
    const PlanRequest sub{fs_.replan_grid, here, req_.goal, req_.rng, req_.scratch, req_.deadline};
    const PlanResult g = global_->plan(sub);
    out_.expansions += g.work.search_expansions.value_or(0);
    if (!g.ok()) return;
    keys_ = fusion_key_points(g.path, o_.key_point_tolerance);
    if (keys_.size() < 2) keys_.push_back(goal_);
    key_ = 1;
    ++out_.replans;
  }

  // Advance the local goal past key points passed or made unreachable by an unknown cell.
  void advance_local_goal(Point pos) {
    while (key_ + 1 < keys_.size()) {
      const Point k = keys_[key_];
      double clear = kInf;
      for (const Cell& c : fs_.seen_cells) clear = std::min(clear, point_cell_distance(k, c));
      if (clear >= keep_out_ && !passes_goal(pos, keys_[key_ - 1], k, passing_)) break;
      ++key_;
    }
  }

  // Sense: the moving discs within range, with their observed velocity when predicted.
  void sense_moving(Point pos) {
    fs_.visible.clear();
    for (std::size_t j = 0; j < world_.moving().size(); ++j) {
      const MovingDisc& m = world_.moving()[j];
      const bool seen = point_distance(pos, m.centre) - m.radius <= o_.sensor_range;
      Point velocity;  // observed: the displacement since the previous control step
      if (seen && o_.predict_moving && fs_.was_seen[j])
        velocity = {(m.centre.x - fs_.last_seen[j].x) / dp_.dt,
                    (m.centre.y - fs_.last_seen[j].y) / dp_.dt};
      if (seen) fs_.visible.push_back({m.centre, m.radius, velocity});
      fs_.was_seen[j] = seen;
      fs_.last_seen[j] = m.centre;
    }
  }

  // The local goal and the key points after it (rollouts that pass one aim at the next), or the
  // final goal alone.
  DwaTarget local_target(Point pos) const {
    DwaTarget target;
    // Only key points a rollout can reach within the horizon (at most v_max T along the path).
    std::size_t reach = 1;
    for (double along = point_distance(pos, keys_[key_]);
         key_ + reach < keys_.size() && reach < kLookaheadGoals; ++reach) {
      if (along > horizon_cells_) break;
      along += point_distance(keys_[key_ + reach - 1], keys_[key_ + reach]);
    }
    target.goals = std::span<const Point>(keys_.data() + key_, reach);
    target.passing = passing_;
    target.from = keys_[key_ - 1];
    target.aim_segment = o_.aim_segment;
    target.lookahead = o_.lookahead;
    if (o_.heading_final) {
      target.goals = std::span<const Point>(&goal_, 1);
      target.from = pos;
      target.aim_segment = false;
    } else if (o_.turn_speed_limit) {
      target.speed_cap =
          turn_speed_cap(o_, keys_, key_, pose_,
                         aim_point(keys_[key_ - 1], keys_[key_], pos, o_.lookahead), edge_);
    }
    return target;
  }

  // Executes the command for one control period; the world moves with the robot.
  void move(const DwaDecision& d) {
    v_ = d.v;
    w_ = d.w;
    pose_ = unicycle_step(pose_, v_ / edge_, w_, dp_.dt);
    const Point robot = position(pose_);
    world_.advance(dp_.dt, o_.moving_yield ? &robot : nullptr, dp_.robot_radius);
    ++out_.steps;
    tr_->v.push_back(v_);
    tr_->w.push_back(w_);
    record();
  }

  // Why the run ends after this step (`pos`: where the step started), or nullptr.
  const char* end_of_run(const DwaDecision& d, Point pos) {
    const Point now = position(pose_);
    if (world_.contact(now, dp_.robot_radius) != DwaWorld::Contact::none) return "contact";
    // Stuck: no admissible velocity that moves the robot, or one the DWA does not take (the
    // classic local minimum: every forward rollout ends at an obstacle, standing scores best).
    const bool moved = d.any_moving && point_distance(now, pos) >= kStandStill;
    stuck_ = moved ? 0 : stuck_ + 1;
    if (stuck_ >= o_.stuck_steps) return "stuck";
    if (out_.steps >= max_steps_ && point_distance(now, goal_) > o_.goal_tolerance)
      return "timeout";
    if (out_.steps % kDeadlineCheckSteps == 0 && req_.deadline.expired()) {
      out_.deadline_hit = true;
      return "timeout";
    }
    return nullptr;
  }

  const FusionOptions& o_;
  const PlanRequest& req_;
  const Grid& grid_;
  DwaWorld& world_;
  const Planner* global_;
  DriveScratch& fs_;
  const double edge_;
  const Point start_, goal_;
  std::vector<Point> keys_;
  DwaParams dp_;
  long long max_steps_ = 0;
  double keep_out_ = 0.0;
  GoalPassing passing_;
  double horizon_cells_ = 0.0;

  // The DWA's rollouts poll the deadline about once per kRolloutPointsPerPoll rollout points.
  DeadlinePoller rollout_poll_;
  DriveResult out_;
  std::shared_ptr<Trajectory> tr_;
  Pose pose_;
  double v_ = 0.0, w_ = 0.0;
  std::size_t key_ = 1;  // the current local goal
  int stuck_ = 0;
};

}  // namespace

DriveResult drive(const FusionOptions& o, const PlanRequest& req, DwaWorld& world,
                  std::vector<Point> keys, const Planner* global) {
  return Drive(o, req, world, std::move(keys), global).run();
}

}  // namespace agv
