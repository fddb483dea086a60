#pragma once
// Arithmetic shared by the reference walk (line_of_sight.cpp) and the word-parallel checks
// (line_of_sight_batch.cpp). Both must reach the same verdict bit for bit, so every floating
// point value either of them compares is computed here, by one expression, and, like all of the
// engine, both are compiled with -ffp-contract=off (CMakeLists.txt): no FMA contraction may round
// one differently from the other.

#include <algorithm>
#include <cmath>

#include "core/line_of_sight.h"

namespace agv::sight_internal {

// A coordinate within kSightEpsilon of an integer is that integer.
inline double snap(double v) {
  const double r = std::nearbyint(v);
  return std::abs(v - r) <= kSightEpsilon ? r : v;
}

inline bool is_integer(double v) { return v == std::floor(v); }

// Squared distance from p to the segment a-b (a == b allowed), in the walk frame (u, v): the
// caller passes the coordinates in the order the reference walk does.
inline double squared_distance(double pu, double pv, double ua, double va, double ub, double vb) {
  const double du = ub - ua;
  const double dv = vb - va;
  const double len2 = du * du + dv * dv;
  double t = len2 > 0.0 ? ((pu - ua) * du + (pv - va) * dv) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double eu = pu - (ua + t * du);
  const double ev = pv - (va + t * dv);
  return eu * eu + ev * ev;
}

// The clearance test's threshold: a centre is too close when squared_distance < this.
inline double clearance_limit(double radius) { return radius * radius - kSightEpsilon; }

// v where the segment crosses the column line u = ur (ua < ur < ub), snapped as the walk does.
inline double line_crossing(double ua, double va, double slope, double ur) {
  return snap(va + (ur - ua) * slope);
}

// A query as both walks see it: endpoints snapped and inside the grid, the major axis u (the
// walk is transposed when |dy| > |dx|, so |dv| <= |du|), endpoints ordered by u.
struct Walk {
  bool transposed = false;
  double ua = 0.0, va = 0.0, ub = 0.0, vb = 0.0;
};

// False when an endpoint is not finite or lies outside [0, W] x [0, H].
inline bool canonical_walk(const Grid& grid, Point a, Point b, Walk& w) {
  a = {snap(a.x), snap(a.y)};
  b = {snap(b.x), snap(b.y)};
  const double width = grid.width();
  const double height = grid.height();
  // Written so that NaN fails too.
  const auto inside = [width, height](Point p) {
    return p.x >= 0.0 && p.x <= width && p.y >= 0.0 && p.y <= height;
  };
  if (!inside(a) || !inside(b)) return false;
  w.transposed = !(std::abs(b.y - a.y) <= std::abs(b.x - a.x));
  if (w.transposed) {
    std::swap(a.x, a.y);
    std::swap(b.x, b.y);
  }
  if (b.x < a.x) std::swap(a, b);
  w.ua = a.x;
  w.va = a.y;
  w.ub = b.x;
  w.vb = b.y;
  return true;
}

// The reference walk on a canonical query (line_of_sight.cpp): check_segment after the
// canonicalisation.
SightHit reference_walk(const Grid& grid, const Walk& w, const SightRule& rule);

}  // namespace agv::sight_internal
