#pragma once
// The dynamic window approach (Fox, Burgard, Thrun 1997; paper 003 section 3, paper 004
// section 3; docs/PLANNERS.md "DWA local planner and the fusion planners"). One control step:
//   1. window V_m n V_d (eq. 8-9): velocity limits intersected with what one control period
//      of maximum acceleration reaches from the current (v, w);
//   2. n_v x n_w velocity pairs sampled on a regular grid over that window (endpoints included);
//   3. each pair rolled out for the predict time T at the control period dt, all pairs at once
//      (lanes over the samples, one time step after another; algos/local/dwa_rollout.h, compiled
//      for each instruction-set level) against the static grid,
//      the unknown static cells seen so far and the moving obstacles at their current positions;
//   4. V_a (eq. 10): a pair is admissible when it can stop before the first point of its
//      rollout that comes closer than robot_radius + safety_margin to any obstacle:
//      v <= sqrt(2 dist a_v) and |w| <= sqrt(2 dist a_w) (the second per eq. 10, optional),
//      dist = the arc length to the last rollout point before that hit, less the v dt driven
//      before the next step can brake; with no admissible pair the robot brakes as hard as the
//      window allows along its current arc;
//   5. every score term normalised over the admissible samples (each term divided by its sum,
//      Fox et al.), weighted and summed; `following_004` then smooths the weighted sum over
//      neighbouring samples (the sigma of paper 004 eq. 13); the best pair is executed.
//
// Units: positions and distances in cells; velocities given in m/s and rad/s (paper 003 Table 2)
// and converted with the grid's cell edge.
//
// Clearance terms. Static clearance is the exact distance from a rollout point to the nearest
// known obstacle square, capped at 1 cell: within that cap only the 3x3 block around the point's
// cell can matter, so it is computed exactly and branch-free from the padded occupancy (no
// distance-transform search in the inner loop). Unknown cells: exact point-to-square distance.
// Moving obstacles: centre distance minus their radius and dynamic_margin. A rollout point
// "hits" when its clearance is below robot_radius + safety_margin (for a class of obstacle the
// robot is already closer to than that, just below its current clearance, so it can move away).

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "algos/local/unicycle.h"
#include "algos/planner.h"
#include "core/grid.h"

namespace agv {

enum class DwaScore {
  classic,  // paper 003 eq. 12: a heading + b vel + g dist (dist: nearest obstacle of any kind)
  improved_003,   // paper 003 eq. 13: a Heading + b vel + g dist_sta + d dist_dyna
  following_004,  // paper 004 eq. 13: sigma[a PHead + b dist + g vel]
};
const char* to_string(DwaScore s);

struct DwaWeights {
  double heading = 0.0;
  double velocity = 0.0;
  double clearance = 0.0;  // dist (classic, following_004) or dist_sta (improved_003)
  double dynamic = 0.0;    // dist_dyna (improved_003 only)
};
// Defaults per score. improved_003: paper 003 section 5 (0.2, 0.4, 0.2, 0.35). classic: paper 003
// section 3.1 asks beta < alpha < gamma (velocity < heading < clearance) and gives no values:
// 0.2 / 0.1 / 0.3. following_004: paper 004 gives none; the classic ones.
DwaWeights default_weights(DwaScore s);

struct DwaParams {
  // Paper 003 Table 2.
  double v_max = 2.0;         // m/s (v_min = 0: the AGV does not reverse)
  double w_max = 0.7;         // rad/s
  double acc_v = 0.4;         // m/s^2
  double acc_w = 1.7;         // rad/s^2
  double predict_time = 3.0;  // s
  double dt = 0.1;            // s, control period and rollout step
  int v_samples = 9;
  int w_samples = 15;
  DwaScore score = DwaScore::classic;
  DwaWeights weights = default_weights(DwaScore::classic);
  bool smoothing = false;       // sigma over the sample grid (following_004)
  bool va_omega = true;         // eq. 10's |w| <= sqrt(2 dist a_w) as well as the v bound
  double robot_radius = 0.3;    // cells
  double safety_margin = 0.05;  // cells: covers the chord between rollout points
  // What the clearance terms (dist, dist_sta, dist_dyna) measure:
  //   collision (Fox et al. 1997, default): the arc length, in metres, the rollout travels
  //     before its first hit, capped at dist_cap (a rollout without a hit scores dist_cap);
  //   clearance: the minimum clearance over the rollout minus robot_radius, in cells (static
  //     capped at static_clearance_cap <= 1, unknown and moving at dynamic_clearance_cap).
  // The clearance reading couples speed and distance: a faster rollout sweeps farther and so
  // passes closer to something, and on grid maps the robot then crawls (mean speed about
  // 0.2 m/s on 20x20 maps at density 0.2 when measured, against about 0.5 m/s).
  enum class DistMode { collision, clearance };
  DistMode dist_mode = DistMode::collision;
  double dist_cap = 3.0;               // metres (collision mode)
  double static_clearance_cap = 1.0;   // cells, at most 1 (the exact 3x3 method's reach)
  double dynamic_clearance_cap = 2.0;  // cells
  // Moving obstacles are seen at their current position only; their discs are inflated by this
  // much (cells) for hits and clearance, as they will have moved by the time the robot passes.
  double dynamic_margin = 0.2;
  double cell_edge = 1.0;  // metres per cell (from the grid)
};

// What the local planner sees at one control step.
struct Disc {
  Point centre;  // cells
  double radius = 0.0;
  // cells/s: the rollouts move the disc at this velocity; zero = seen at its current position
  // only (docs/PLANNERS.md), which is the papers' DWA.
  Point velocity;
};
struct DwaView {
  const Grid& known;              // the static obstacles the global planner saw
  std::span<const Cell> unknown;  // unknown static cells discovered so far
  std::span<const Disc> moving;   // moving obstacles seen, at their current positions
};

// V_m n V_d (eq. 8-9), in m/s and rad/s. Never empty: when the current velocity lies outside
// V_m (it cannot, for a robot driven by this DWA) the window is clamped to V_m.
struct VelocityWindow {
  double v_lo = 0.0, v_hi = 0.0, w_lo = 0.0, w_hi = 0.0;
};
VelocityWindow dynamic_window(const DwaParams& p, double v, double w);

// Per-thread buffers, sized on first use; nothing is allocated per sample or per step after that.
struct DwaScratch {
  Eigen::ArrayXd v, w;                 // sampled pairs (m/s, rad/s), index iv * n_w + iw
  Eigen::ArrayXd px, py, ux, uy;       // rollout position (cells), chord direction
  Eigen::ArrayXd chord, rot_c, rot_s;  // per-step chord length and rotation
  Eigen::ArrayXd step_static, step_other, min_static, min_other;
  Eigen::ArrayXd hit_static, hit_other;  // rollout step of the first hit (K + 1: none)
  Eigen::ArrayXd goal_index;             // local goals the rollout has passed so far
  Eigen::ArrayXd heading, velocity, dist, dist_dyna, score, smoothed;
  Eigen::Array<bool, Eigen::Dynamic, 1> admissible;
  Eigen::ArrayXd turn_sinc;                              // sinc(w dt / 2) per w sample
  Eigen::ArrayXd frac_x, frac_y;                         // rollout point within its cell
  Eigen::Array<std::uint32_t, Eigen::Dynamic, 1> block;  // occupancy of its 3x3 block
};

struct DwaDecision {
  bool any_admissible = false;
  bool any_moving = false;     // some admissible pair has v > 0
  double v = 0.0, w = 0.0;     // the command (m/s, rad/s); maximum braking when none admissible
  double stop_distance = 0.0;  // dist(v, w) of the chosen pair in metres (inf: rollout clear)
  int samples = 0;             // velocity pairs evaluated
  int rollout_steps = 0;       // K = round(predict_time / dt)
  bool cut = false;            // the deadline expired during the rollouts: no command chosen
};

// One DWA control step from `pose` (cells) at velocity (v, w). `goals` (cells, at least one) is
// the current local goal followed by the next key points (fusion) or just the goal. The heading
// term of a rollout aims at the first of them the rollout has not yet passed, in order; a
// rollout that passes them all scores the best heading, pi. A point passes a goal when it is
// within `tolerance` of it, or within `radius` of it and beyond it along the segment that leads
// to it (an overshoot): the fusion's goal switching (algos/local/fusion.h) applied to the predicted
// trajectory, as paper 003 section 3.2 has the goal node "update in real time when a new goal
// node is reached". Aiming every rollout at the current key point instead makes the robot crawl
// up to each key point, because only slow rollouts end short of it still facing it.
struct GoalPassing {
  double tolerance = 0.3;  // cells
  double radius = 0.6;     // cells
};
// `prev`: where the segment to `goal` starts.
bool passes_goal(Point p, Point prev, Point goal, const GoalPassing& rule);

// The point `lookahead` cells ahead of p's projection on segment a-b, clamped to [a, b].
Point aim_point(Point a, Point b, Point p, double lookahead);

struct DwaTarget {
  std::span<const Point> goals;
  GoalPassing passing;
  // Where the segment to goals[0] starts (the previous key point, or the robot's position).
  Point from;
  // Where the heading term aims: aim_segment false, at the goal itself (Fox; paper 003
  // Heading, paper 004 PHead read literally); true, at the point `lookahead` cells ahead of the
  // rollout end's projection on the segment leading to its goal (from -> goals[0],
  // goals[0] -> goals[1], ...), clamped to that goal: pure-pursuit style, which keeps the robot
  // on the global path's line between key points instead of letting it cut across to the next
  // key point through a corridor's corner.
  bool aim_segment = false;
  double lookahead = 1.0;
  // m/s: caps the window's upper linear velocity this step (the fusion's turn speed limit,
  // algos/local/fusion_drive.h); the window never drops below what maximum braking reaches.
  double speed_cap = std::numeric_limits<double>::infinity();
};

// `poll` (optional) is polled once per rollout step of all pairs: a step of many pairs and many
// rollout steps is long. When it expires the decision is `cut` and holds no command.
DwaDecision dwa_step(const DwaParams& p, const Pose& pose, double v, double w,
                     const DwaTarget& target, const DwaView& view, DwaScratch& scratch,
                     DeadlinePoller* poll = nullptr);

// Exact distance from p to the nearest known obstacle square, capped at 1 cell (the DWA's static
// term; exposed for tests). 0 inside an obstacle or outside the grid.
double capped_static_clearance(const Grid& grid, Point p);

}  // namespace agv
