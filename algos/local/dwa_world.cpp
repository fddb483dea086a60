#include "algos/local/dwa_world.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/cell_geometry.h"
#include "core/connectivity.h"
#include "core/corner_rule.h"
#include "core/distance_transform.h"
#include "core/numbers.h"

namespace agv {

namespace {

constexpr double kContactTolerance = 1e-9;  // cells, in the robot's favour
constexpr double kYieldGap = 1e-6;          // cells a yielding disc keeps from the robot

// The cells a polyline passes through, in order, without repeats in a row (sampled every
// 1/8 cell: the reference path is a chain of cell-centre moves, so no cell is skipped).
std::vector<Cell> cells_along(std::span<const Point> path) {
  std::vector<Cell> out;
  auto add = [&](Point p) {
    const Cell c{static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y))};
    if (out.empty() || !(out.back() == c)) out.push_back(c);
  };
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const Point a = path[i], b = path[i + 1];
    const int n = std::max(1, static_cast<int>(std::ceil(std::hypot(b.x - a.x, b.y - a.y) * 8)));
    for (int k = 0; k < n; ++k) {
      const double t = static_cast<double>(k) / n;
      add({a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t});
    }
  }
  if (!path.empty()) add(path.back());
  return out;
}

// The point at arc-length fraction f of a polyline.
Point point_at(std::span<const Point> path, double f) {
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    total += std::hypot(path[i + 1].x - path[i].x, path[i + 1].y - path[i].y);
  double target = f * total;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double len = std::hypot(path[i + 1].x - path[i].x, path[i + 1].y - path[i].y);
    if (target <= len && len > 0.0) {
      const double t = target / len;
      return {path[i].x + (path[i + 1].x - path[i].x) * t,
              path[i].y + (path[i + 1].y - path[i].y) * t};
    }
    target -= len;
  }
  return path.empty() ? Point{} : path.back();
}

}  // namespace

DwaWorld::DwaWorld(const Grid& grid, std::vector<Cell> unknown, std::vector<MovingDisc> moving)
    : grid_(&grid), unknown_(std::move(unknown)), moving_(std::move(moving)) {}

DwaWorld DwaWorld::generate(const Grid& grid, Cell start, Cell goal,
                            std::span<const Point> reference_path, const WorldSpec& spec, Rng& rng,
                            DeadlinePoller* poll) {
  std::vector<Cell> unknown;
  const std::vector<Cell> along = cells_along(reference_path);
  std::vector<Cell> candidates;
  for (const Cell& c : along) {
    const int ds = std::max(std::abs(c.x - start.x), std::abs(c.y - start.y));
    const int dg = std::max(std::abs(c.x - goal.x), std::abs(c.y - goal.y));
    if (ds >= 2 && dg >= 2) candidates.push_back(c);
  }
  if (spec.unknown_obstacles > 0 && !candidates.empty()) {
    Grid with_unknown = grid;
    ConnectivityScratch connectivity;
    for (int k = 0; k < spec.unknown_obstacles; ++k) {
      for (int attempt = 0; attempt < 50; ++attempt) {
        if (poll_expired(poll)) return DwaWorld(grid, std::move(unknown), {});
        Cell c = candidates[rng.below(static_cast<std::uint32_t>(candidates.size()))];
        if (rng.chance(0.5)) {
          const std::uint32_t d = rng.below(8);  // core/corner_rule.h directions
          c = {c.x + kDx[d], c.y + kDy[d]};
        }
        if (!grid.in_bounds(c) || with_unknown.blocked(c)) continue;
        if (std::max(std::abs(c.x - start.x), std::abs(c.y - start.y)) < 2 ||
            std::max(std::abs(c.x - goal.x), std::abs(c.y - goal.y)) < 2)
          continue;
        with_unknown.set_blocked(c, true);
        if (connected(with_unknown, start, goal, CornerRule::no_corner_cut, connectivity)) {
          unknown.push_back(c);
          break;
        }
        with_unknown.set_blocked(c, false);
      }
    }
  }

  DwaWorld world(grid, std::move(unknown), {});
  const double speed = spec.moving_speed / grid.cell_edge();
  const Point s = centre(start), g = centre(goal);
  for (int k = 0; k < spec.moving_obstacles; ++k) {
    for (int attempt = 0; attempt < 200; ++attempt) {
      if (poll_expired(poll)) return world;
      Point c;
      if (spec.moving_on_path && reference_path.size() >= 2) {
        c = point_at(reference_path, rng.uniform(0.35, 0.65));
      } else {
        c = {rng.uniform(0.0, grid.width()), rng.uniform(0.0, grid.height())};
      }
      const double heading = rng.uniform(0.0, 2.0 * kPi);
      if (world.obstacle_clearance(c) < spec.moving_radius) continue;
      if (std::hypot(c.x - s.x, c.y - s.y) < spec.robot_radius + spec.moving_radius + 1.0) continue;
      if (std::hypot(c.x - g.x, c.y - g.y) < spec.moving_radius + 0.5) continue;
      world.moving_.push_back(
          {c, {speed * std::cos(heading), speed * std::sin(heading)}, spec.moving_radius});
      break;
    }
  }
  return world;
}

double DwaWorld::static_clearance(Point p) const {
  return grid_->distance_transform().clearance(p);
}

double DwaWorld::unknown_clearance(Point p) const {
  double d = kInf;
  for (const Cell& c : unknown_) d = std::min(d, point_cell_distance(p, c));
  return d;
}

void DwaWorld::advance(double dt, const Point* robot, double robot_radius) {
  for (MovingDisc& m : moving_) {
    auto free_at = [&](Point q) {
      if (robot != nullptr &&
          std::hypot(q.x - robot->x, q.y - robot->y) < m.radius + robot_radius + kYieldGap)
        return false;
      return obstacle_clearance(q) >= m.radius;
    };
    const Point u = m.velocity;
    const Point candidates[3] = {{-u.x, u.y}, {u.x, -u.y}, {-u.x, -u.y}};
    Point next{m.centre.x + u.x * dt, m.centre.y + u.y * dt};
    if (!free_at(next)) {
      bool moved = false;
      for (const Point& r : candidates) {
        const Point q{m.centre.x + r.x * dt, m.centre.y + r.y * dt};
        if (free_at(q)) {
          m.velocity = r;
          next = q;
          moved = true;
          break;
        }
      }
      if (!moved) {
        m.velocity = {-u.x, -u.y};
        next = m.centre;
      }
    }
    m.centre = next;
  }
}

DwaWorld::Contact DwaWorld::contact(Point p, double radius) const {
  const double limit = radius - kContactTolerance;
  if (static_clearance(p) < limit) return Contact::static_cell;
  if (unknown_clearance(p) < limit) return Contact::unknown_cell;
  for (const MovingDisc& m : moving_)
    if (std::hypot(p.x - m.centre.x, p.y - m.centre.y) - m.radius < limit) return Contact::moving;
  return Contact::none;
}

}  // namespace agv
