#pragma once
// The time-stepped world a fusion run drives through (docs/PLANNERS.md "DWA local planner and the
// fusion planners"): the grid's static obstacles, unknown static cells (obstacles the global
// planner did not see) and moving obstacles (discs at constant speed, reflecting off the walls
// and off static and unknown cells). The world does not react to the robot, and the planner
// only ever sees it through DwaView (algos/local/dwa.h). Whether the robot collided is decided by
// the engine from the recorded trajectory (engine/judge/trajectory_judge.h); contact() here only
// lets the simulation stop at the first touch instead of driving on through an obstacle.
//
// Generation is deterministic from the Rng handed in. The fusion planners seed it from the map
// (its cells, start and goal) and the world_seed parameter, not from the planner's label, so
// every fusion planner run on a map meets the same world and paired comparisons are fair.

#include <span>
#include <vector>

#include "algos/local/dwa.h"
#include "algos/planner.h"
#include "core/grid.h"
#include "core/rng.h"

namespace agv {

struct MovingDisc {
  Point centre;    // cells
  Point velocity;  // cells per second
  double radius = 0.0;
};

struct WorldSpec {
  int moving_obstacles = 0;
  double moving_speed = 0.5;   // m/s
  double moving_radius = 0.4;  // cells
  // true: each disc starts on a random point of the middle part (35%-65% of the length) of the
  // reference path, heading in a uniformly random direction; false: anywhere free.
  bool moving_on_path = true;
  int unknown_obstacles = 0;
  double robot_radius = 0.3;  // cells: nothing is placed where the robot starts in contact
  // Discs reflect off the robot as off a wall (not in the papers): collisions are then the
  // robot's doing; without it a disc also runs into a robot that has stopped, which in a
  // one-cell corridor no local planner can prevent.
  bool moving_yield = false;
};

class DwaWorld {
 public:
  // Explicit world (tests). The grid must outlive the world.
  DwaWorld(const Grid& grid, std::vector<Cell> unknown, std::vector<MovingDisc> moving);

  // Random world. Unknown cells: a random cell of the reference path (not within 2 cells,
  // Chebyshev, of start or goal), or with probability 1/2 one of its 8 neighbours; kept only
  // when free, new, and start and goal stay connected under no_corner_cut (a disc robot's
  // moves), else redrawn (up to 50 tries, then fewer cells). Moving discs: redrawn (up to 200
  // tries, then fewer discs) until clear of every static and unknown cell, at least
  // robot_radius + radius + 1 cell from the start and radius + 0.5 from the goal centre.
  // `poll` (optional) is polled once per try (an unknown cell's costs a flood fill of the map);
  // once it has expired the world is left unfinished, for the caller to discard.
  static DwaWorld generate(const Grid& grid, Cell start, Cell goal,
                           std::span<const Point> reference_path, const WorldSpec& spec, Rng& rng,
                           DeadlinePoller* poll = nullptr);

  const Grid& grid() const { return *grid_; }
  std::span<const Cell> unknown_cells() const { return unknown_; }
  std::span<const MovingDisc> moving() const { return moving_; }

  // Moves every disc by velocity * dt; a disc whose new position would overlap a wall, a static
  // or an unknown cell reflects: first the x component, else the y component, else both (it
  // goes back the way it came); if even that overlaps, it stays this step, reversed. With
  // `robot` (the robot disc's centre after its step, and its radius), discs reflect off the
  // robot too: they never run into it (WorldSpec::moving_yield).
  void advance(double dt, const Point* robot = nullptr, double robot_radius = 0.0);

  // Exact distance from p to the nearest static (grid) or unknown obstacle square.
  double static_clearance(Point p) const;
  double unknown_clearance(Point p) const;  // +inf without unknown cells
  double obstacle_clearance(Point p) const {
    return std::min(static_clearance(p), unknown_clearance(p));
  }

  enum class Contact { none, static_cell, unknown_cell, moving };
  // Whether a robot disc at p overlaps anything now (1e-9 cells of tolerance in its favour).
  Contact contact(Point p, double radius) const;

 private:
  const Grid* grid_;
  std::vector<Cell> unknown_;
  std::vector<MovingDisc> moving_;
};

}  // namespace agv
