#include "core/cell_geometry.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace agv {

namespace {

// Liang-Barsky: does segment p + t d meet [lo, hi] on one axis, narrowing [t0, t1]?
bool clip(double p, double d, double lo, double hi, double& t0, double& t1) {
  if (d == 0.0) return p >= lo && p <= hi;
  double ta = (lo - p) / d;
  double tb = (hi - p) / d;
  if (ta > tb) std::swap(ta, tb);
  t0 = std::max(t0, ta);
  t1 = std::min(t1, tb);
  return t0 <= t1;
}

}  // namespace

double point_distance(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

double point_segment_distance(Point p, Point a, Point b) {
  const double ux = b.x - a.x;
  const double uy = b.y - a.y;
  const double len2 = ux * ux + uy * uy;
  double t = 0.0;
  if (len2 > 0.0) t = std::clamp(((p.x - a.x) * ux + (p.y - a.y) * uy) / len2, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * ux), p.y - (a.y + t * uy));
}

double point_cell_distance(Point p, Cell c) {
  const double dx = std::max({c.x - p.x, 0.0, p.x - (c.x + 1.0)});
  const double dy = std::max({c.y - p.y, 0.0, p.y - (c.y + 1.0)});
  return std::hypot(dx, dy);
}

double segment_cell_distance(Point a, Point b, Cell c) {
  double t0 = 0.0;
  double t1 = 1.0;
  if (clip(a.x, b.x - a.x, c.x, c.x + 1.0, t0, t1) && clip(a.y, b.y - a.y, c.y, c.y + 1.0, t0, t1))
    return 0.0;
  // Apart, the closest pair has an endpoint of the segment or a corner of the square.
  double d = std::min(point_cell_distance(a, c), point_cell_distance(b, c));
  if (!(a == b)) {
    for (const Point corner : {Point{1.0 * c.x, 1.0 * c.y}, Point{c.x + 1.0, 1.0 * c.y},
                               Point{1.0 * c.x, c.y + 1.0}, Point{c.x + 1.0, c.y + 1.0}})
      d = std::min(d, point_segment_distance(corner, a, b));
  }
  return d;
}

}  // namespace agv
