#pragma once
// The engine's judge of a simulated robot run (the fusion planners, algos/local/fusion.h). The
// planner proposes a trajectory; the engine decides, independently of the planner's own world
// code, whether the robot disc hit anything and whether it reached the goal, and computes the
// fusion metrics of docs/METRICS.md from the record alone.
//
// Checks, in order:
// 1. shape: one time, position and heading per sample, one (v, w) command per interval, every
//    moving obstacle track as long as the trajectory, finite values, times increasing from 0,
//    the first position at the start cell's centre, unknown cells inside the grid and free in it;
// 2. kinematics: each sample follows from the previous one by the unicycle arc of its command
//    (algos/local/unicycle.h) within 1e-6 cells and 1e-9 rad (a planner cannot teleport its robot);
// 3. collisions, on the straight chords between samples (the arcs deviate from them by at most
//    v dt * |w| dt / 8, under 0.002 cells at paper 003's limits): the robot disc against the
//    static cells (exact segment clearance from the distance transform), against the unknown
//    cells (exact segment-to-square distance) and against each moving disc (both moving
//    linearly over the interval: exact minimum of the relative distance). The first interval
//    with a contact (distance < radius - 1e-12) decides: collision_static, collision_unknown or
//    collision_dynamic, in that order of precedence within one interval;
// 4. otherwise the planner's end reason: reached (confirmed: the last position within
//    goal_tolerance of the goal centre), timeout -> sim_timeout, stuck; anything else, or a
//    claimed contact the judge cannot confirm, is invalid_path.
//
// Metrics (metres = cells x cell edge): travelled_length (m), sim_time_s, control_steps,
// min_clearance_static (m: exact minimum distance from the robot CENTRE to any static or unknown
// obstacle square, as paper 003 Table 3 measures the path; subtract robot_radius for the gap),
// min_clearance_dynamic (m: centre to the nearest moving disc's edge; absent without moving
// obstacles), heading_change_sum (rad: sum of |wrapped heading change| per control step, turning
// on the spot included), mean_abs_w (rad/s, mean |w| command). CPU time per control step is
// timing and comes from the planner's phases.

#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "algos/planner.h"
#include "engine/judge/metrics.h"
#include "engine/judge/outcome.h"

namespace agv {

struct TrajectoryVerdict {
  Outcome outcome = Outcome::invalid_path;
  std::string message;  // empty when reached
  std::vector<std::pair<std::string, double>> metrics;
  // The two path metrics the grid alone cannot give (docs/METRICS.md "Fusion runs"): the
  // clearance from the robot centre to every static obstacle it met, the unknown cells
  // included, in cells; and the simulated time the run took, s.
  double min_clearance = 0.0;
  double sim_time_s = 0.0;
};

TrajectoryVerdict judge_trajectory(const Grid& grid, Cell start, Cell goal, const Trajectory& tr);

// Every metric name a verdict may carry (its `metrics`): names the engine measures, which no
// planner may report as its own (engine/judge/result_check.h).
inline constexpr std::array<std::string_view, 7> kJudgedMetricNames = {
    "travelled_length",      "sim_time_s",         "control_steps", "min_clearance_static",
    "min_clearance_dynamic", "heading_change_sum", "mean_abs_w"};

// The path metrics of a fusion run's executed positions, corrected by its verdict: the grid's
// distance transform does not know the unknown cells, and eq. 5.2e's length / speed + node time
// per waypoint is not how long the simulated robot drove (it stopped, turned and braked).
void apply_trajectory_verdict(const TrajectoryVerdict& verdict, double cell_edge, PathMetrics& m);

}  // namespace agv
