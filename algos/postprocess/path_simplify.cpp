#include "algos/postprocess/path_simplify.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace agv {

namespace {

// 2v as an integer when v is a multiple of 0.5 of moderate size (the half-cell lattice).
bool doubled(double v, std::int64_t& out) {
  const double d = 2.0 * v;
  if (!(std::abs(d) < 1e15) || d != std::floor(d)) return false;
  out = static_cast<std::int64_t>(d);
  return true;
}

bool lattice(Point p, std::int64_t& x, std::int64_t& y) {
  return doubled(p.x, x) && doubled(p.y, y);
}

std::vector<int> all_indices(std::size_t n) {
  std::vector<int> keep(n);
  std::iota(keep.begin(), keep.end(), 0);
  return keep;
}

}  // namespace

bool goes_straight(Point a, Point b, Point c) {
  std::int64_t ax, ay, bx, by, cx, cy;
  if (lattice(a, ax, ay) && lattice(b, bx, by) && lattice(c, cx, cy)) {
    const std::int64_t ux = bx - ax, uy = by - ay, vx = cx - bx, vy = cy - by;
    if ((ux == 0 && uy == 0) || (vx == 0 && vy == 0)) return true;
    // Doubled grid coordinates are below 2^15 on any grid we load, so the products fit.
    return ux * vy - uy * vx == 0 && ux * vx + uy * vy > 0;
  }
  const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - b.x, vy = c.y - b.y;
  const double lu = std::hypot(ux, uy), lv = std::hypot(vx, vy);
  if (lu == 0.0 || lv == 0.0) return true;
  return std::abs(ux * vy - uy * vx) <= 1e-12 * lu * lv && ux * vx + uy * vy > 0.0;
}

std::vector<int> collinear_keep(std::span<const Point> path) {
  std::vector<int> keep;
  const int n = static_cast<int>(path.size());
  if (n == 0) return keep;
  keep.push_back(0);
  for (int i = 1; i + 1 < n; ++i) {
    if (path[i] == path[keep.back()]) continue;  // duplicate
    if (goes_straight(path[keep.back()], path[i], path[i + 1])) continue;
    keep.push_back(i);
  }
  if (n > 1) {
    // A trailing duplicate of the last kept point is dropped in favour of the last point.
    if (keep.size() > 1 && path[keep.back()] == path[n - 1]) keep.pop_back();
    keep.push_back(n - 1);
  }
  return keep;
}

void remove_collinear(std::vector<Point>& path) {
  path = select_points(path, collinear_keep(path));
}

std::vector<int> turning_point_keep(const Grid& grid, std::span<const Point> path,
                                    const SightRule& sight, DeadlinePoller* poll) {
  std::vector<int> keep = all_indices(path.size());
  bool changed = true;
  while (changed && keep.size() > 2) {
    changed = false;
    std::vector<int> next;
    next.reserve(keep.size());
    next.push_back(keep.front());
    for (std::size_t k = 1; k + 1 < keep.size(); ++k) {
      if (poll_expired(poll)) return keep;
      if (segment_free(grid, path[next.back()], path[keep[k + 1]], sight)) {
        changed = true;  // keep[k] is a removable turning point (eq. 5.1b: no obstacle between)
        continue;
      }
      next.push_back(keep[k]);
    }
    next.push_back(keep.back());
    keep.swap(next);
  }
  return keep;
}

void remove_turning_points(const Grid& grid, std::vector<Point>& path, const SightRule& sight,
                           DeadlinePoller* poll) {
  path = select_points(path, turning_point_keep(grid, path, sight, poll));
}

std::vector<int> greedy_keep(const Grid& grid, std::span<const Point> path, const SightRule& sight,
                             bool from_goal, DeadlinePoller* poll) {
  const int n = static_cast<int>(path.size());
  if (n <= 2) return all_indices(path.size());
  // Walking from the goal is the same walk on the reversed index order.
  auto at = [&](int i) { return from_goal ? path[n - 1 - i] : path[i]; };
  std::vector<int> keep{0};
  int anchor = 0;
  while (anchor < n - 1) {
    int next = anchor + 1;  // consecutive points are kept when nothing farther is in sight
    for (int j = n - 1; j > anchor + 1; --j) {
      if (poll_expired(poll)) return all_indices(path.size());
      if (segment_free(grid, at(anchor), at(j), sight)) {
        next = j;
        break;
      }
    }
    keep.push_back(next);
    anchor = next;
  }
  if (from_goal) {
    for (int& k : keep) k = n - 1 - k;
    std::reverse(keep.begin(), keep.end());
  }
  return keep;
}

void shortcut_greedy(const Grid& grid, std::vector<Point>& path, const SightRule& sight) {
  path = select_points(path, greedy_keep(grid, path, sight, false));
}

void remove_redundant_from_goal(const Grid& grid, std::vector<Point>& path,
                                const SightRule& sight) {
  path = select_points(path, greedy_keep(grid, path, sight, true));
}

std::vector<int> forward_keep(const Grid& grid, std::span<const Point> path, const SightRule& sight,
                              DeadlinePoller* poll) {
  const int n = static_cast<int>(path.size());
  if (n <= 2) return all_indices(path.size());
  const SightRule cells = SightRule::cells(sight.corners);
  // An expired deadline answers "not in sight", which ends every scan below.
  const auto in_sight = [&](Point a, Point b, const SightRule& rule) {
    return !poll_expired(poll) && segment_free(grid, a, b, rule);
  };
  std::vector<int> keep{0};
  int key = 0;
  while (key < n - 1) {
    // A point not in sight even from its predecessor (a midpoint on an obstacle's vertex, or
    // under a margin a point too close to a wall) cannot be a key point: the run of points in
    // sight starts at the first one that is, else at the first free under plain cells.
    int j = key + 1;
    while (j < n - 1 && !poll_expired(poll) && !segment_free(grid, path[key], path[j], sight)) ++j;
    if (j == n - 1 && !in_sight(path[key], path[j], sight)) {
      j = key + 1;
      while (j < n - 1 && !poll_expired(poll) && !segment_free(grid, path[key], path[j], cells))
        ++j;
    } else {
      while (j + 1 < n && in_sight(path[key], path[j + 1], sight)) ++j;
    }
    if (poll_expired(poll)) return all_indices(path.size());
    keep.push_back(j);
    key = j;
  }
  return keep;
}

void forward_key_points(const Grid& grid, std::vector<Point>& path, const SightRule& sight) {
  path = select_points(path, forward_keep(grid, path, sight));
}

void insert_midpoints(std::vector<Point>& path) {
  if (path.size() < 2) return;
  std::vector<Point> out;
  out.reserve(2 * path.size() - 1);
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    out.push_back(path[i]);
    out.push_back({(path[i].x + path[i + 1].x) / 2, (path[i].y + path[i + 1].y) / 2});
  }
  out.push_back(path.back());
  path.swap(out);
}

void shortcut_direct_midpoint(const Grid& grid, std::vector<Point>& path, const SightRule& sight,
                              DeadlinePoller* poll) {
  remove_collinear(path);
  if (path.size() <= 2) return;
  auto mid = [](Point a, Point b) { return Point{(a.x + b.x) / 2, (a.y + b.y) / 2}; };
  std::vector<Point> out{path.front()};
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    if (poll_expired(poll)) return;  // path unchanged past its collinear removal
    const Point s = out.back(), b = path[i], g = path[i + 1];
    if (segment_free(grid, s, g, sight)) continue;  // direct connection: B is redundant
    // S-C-G (Figure 5): S-C lies on S-B, checked anyway since its end moved onto the segment.
    const Point c1 = mid(s, b);
    if (segment_free(grid, s, c1, sight) && segment_free(grid, c1, g, sight)) {
      out.push_back(c1);
      continue;
    }
    const Point c2 = mid(b, g);
    if (segment_free(grid, s, c2, sight) && segment_free(grid, c2, g, sight)) {
      out.push_back(c2);
      continue;
    }
    out.push_back(b);
  }
  out.push_back(path.back());
  path.swap(out);
}

std::vector<Point> select_points(std::span<const Point> path, std::span<const int> keep) {
  std::vector<Point> out;
  out.reserve(keep.size());
  for (int k : keep) out.push_back(path[k]);
  return out;
}

}  // namespace agv
