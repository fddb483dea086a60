#pragma once
// The fusion control loop (docs/PLANNERS.md "DWA local planner and the fusion planners"): a robot
// drives from the start through the key points of a global path, one DWA step per control
// period, in a DwaWorld. Used by the fusion planners (algos/local/fusion.h) and, with a hand-made
// world, by tests.
//
// Local goals. The key points are the successive local goals. The robot passes one
// (algos/local/dwa.h passes_goal) within waypoint_tolerance of it, or within pass_radius of it and
// beyond it along its segment; a key point that a seen unknown cell makes unreachable is
// skipped.
//
// Our additions to the papers' fusion, each a parameter (algos/local/fusion.cpp documents them):
// - heading_aim = segment: the heading term aims `lookahead` ahead on the segment leading to
//   the local goal (pure-pursuit style) rather than at the key point itself;
// - turn speed limit: the robot may turn by phi only within turn_distance cells at w_max, so
//   it slows for the turn in progress and, braking at acc_v, for the coming key points;
// - a sensor range for unknown cells and moving obstacles;
// - replanning when a newly seen unknown cell lies on the remaining global path.
// Measured on 100 random 20x20 maps per density 0.1 / 0.2 / 0.3 (no moving or unknown
// obstacles, fusion_astar_dwa), the literal reading (heading at the key point, no turn speed
// limit, waypoint tolerance 0.5, no overshoot passing) reached the goal on 82 / 51 / 29 % of
// them: the robot cuts corridor corners or overshoots 90-degree corners and ends facing a wall,
// the DWA's classic local minimum; with these additions 99 / 99 / 98 % (tests/algos/test_dwa.cpp).
//
// Ends: reached (within goal_tolerance of the goal centre), timeout (sim_time_limit), stuck
// (stuck_steps consecutive control steps without moving), contact (the robot disc touches an
// obstacle: the simulation stops there; the engine's judge decides what was hit).

#include <memory>
#include <string>
#include <vector>

#include "algos/local/dwa.h"
#include "algos/local/dwa_world.h"
#include "algos/planner.h"

namespace agv {

struct FusionOptions {
  DwaParams dwa;                    // cell_edge is taken from the grid
  double waypoint_tolerance = 0.3;  // cells
  double pass_radius = 0.6;         // cells
  double goal_tolerance = 0.5;      // cells
  bool heading_final = false;       // heading term aims at the final goal only
  bool aim_segment = true;
  double lookahead = 0.75;  // cells
  bool turn_speed_limit = true;
  double turn_distance = 1.0;   // cells
  double sensor_range = 8.0;    // cells
  bool moving_yield = false;    // moving discs reflect off the robot (WorldSpec::moving_yield)
  bool predict_moving = false;  // the DWA extrapolates discs at their observed velocity
  bool replan = true;
  double key_point_tolerance = 0.1;  // cells, for replanned paths
  double sim_time_limit = 120.0;     // s
  int stuck_steps = 100;
};

struct DriveResult {
  std::shared_ptr<Trajectory> trajectory;  // end_reason set
  long long steps = 0;                     // control steps
  int replans = 0;
  std::int64_t expansions = 0;  // the global planner's search_expansions, over the replans
  bool deadline_hit = false;    // stopped by the run's wall-clock deadline
};

// Drives from request.start's centre through `keys` (keys[0] = the start) to request.goal.
// `global` (may be null) replans on the grid with the seen unknown cells blocked.
DriveResult drive(const FusionOptions& options, const PlanRequest& request, DwaWorld& world,
                  std::vector<Point> keys, const Planner* global);

// Key points of a global path: Ramer-Douglas-Peucker with `tolerance` cells (first and last
// point always kept); on cell-centre paths any tolerance below 0.3 is exact collinear removal.
std::vector<Point> fusion_key_points(std::span<const Point> path, double tolerance);

}  // namespace agv
