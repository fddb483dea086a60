#include "core/cell_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

// The offsets whose std::hypot each distance is, computed one way for every caller.
struct Offset {
  double x, y;
};

Offset point_segment_offset(Point p, Point a, Point b) {
  const double ux = b.x - a.x;
  const double uy = b.y - a.y;
  const double len2 = ux * ux + uy * uy;
  double t = 0.0;
  if (len2 > 0.0) t = std::clamp(((p.x - a.x) * ux + (p.y - a.y) * uy) / len2, 0.0, 1.0);
  return {p.x - (a.x + t * ux), p.y - (a.y + t * uy)};
}

Offset point_cell_offset(Point p, Cell c) {
  return {std::max({c.x - p.x, 0.0, p.x - (c.x + 1.0)}),
          std::max({c.y - p.y, 0.0, p.y - (c.y + 1.0)})};
}

}  // namespace

double point_distance(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

double point_segment_distance(Point p, Point a, Point b) {
  const Offset o = point_segment_offset(p, a, b);
  return std::hypot(o.x, o.y);
}

double point_cell_distance(Point p, Cell c) {
  const Offset o = point_cell_offset(p, c);
  return std::hypot(o.x, o.y);
}

double segment_cell_distance(Point a, Point b, Cell c) {
  double t0 = 0.0;
  double t1 = 1.0;
  if (clip(a.x, b.x - a.x, c.x, c.x + 1.0, t0, t1) && clip(a.y, b.y - a.y, c.y, c.y + 1.0, t0, t1))
    return 0.0;
  // Apart, the closest pair has an endpoint of the segment or a corner of the square: the least
  // of up to six distances. std::hypot is the cost (the engine's clearance metric calls this
  // millions of times), so it is taken only of the offsets whose plain sum of squares is within
  // a relative 1e-9 of the least: that sum is within a few ulps of the square of hypot, so no
  // offset left out can have the least hypot, and the minimum is the same double as hypot's of
  // all six. Sums near underflow (or NaN) take every hypot.
  Offset o[6];
  int n = 0;
  o[n++] = point_cell_offset(a, c);
  o[n++] = point_cell_offset(b, c);
  if (!(a == b)) {
    for (const Point corner : {Point{1.0 * c.x, 1.0 * c.y}, Point{c.x + 1.0, 1.0 * c.y},
                               Point{1.0 * c.x, c.y + 1.0}, Point{c.x + 1.0, c.y + 1.0}})
      o[n++] = point_segment_offset(corner, a, b);
  }
  double sq[6];
  double least = std::numeric_limits<double>::infinity();
  for (int k = 0; k < n; ++k) {
    sq[k] = o[k].x * o[k].x + o[k].y * o[k].y;
    least = std::min(least, sq[k]);
  }
  auto hypot_of = [&](int k) { return std::hypot(o[k].x, o[k].y); };
  if (!(least >= 1e-280 && least <= 1e280)) {  // NaN too: every hypot, in the order of old
    double d = std::min(hypot_of(0), hypot_of(1));
    for (int k = 2; k < n; ++k) d = std::min(d, hypot_of(k));
    return d;
  }
  const double keep = least * (1.0 + 1e-9);
  double d = std::numeric_limits<double>::infinity();
  for (int k = 0; k < n; ++k)
    if (sq[k] <= keep) d = std::min(d, hypot_of(k));
  return d;
}

}  // namespace agv
