#include "core/line_of_sight.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/line_of_sight_internal.h"

namespace agv {

SightRule SightRule::cells(CornerRule rule) { return {Kind::cells, rule, 0.0}; }
SightRule SightRule::margin(double d, CornerRule rule) { return {Kind::clearance, rule, d + 0.5}; }
SightRule SightRule::circles(double r_obs, CornerRule rule) {
  return {Kind::clearance, rule, r_obs};
}

namespace {

using sight_internal::is_integer;
using sight_internal::squared_distance;

// floor / ceil clamped to [lo, hi] before the cast, so no out-of-range conversion.
int floor_clamped(double v, int lo, int hi) {
  return static_cast<int>(std::clamp(std::floor(v), double(lo), double(hi)));
}
int ceil_clamped(double v, int lo, int hi) {
  return static_cast<int>(std::clamp(std::ceil(v), double(lo), double(hi)));
}

// The walk runs along the major axis u (|dv| <= |du|, so at most 3 rows per column); a steep
// segment is walked in the transposed frame (cell (u, v) = grid cell (v, u)). Both corner rules
// and the clearance test are symmetric under transposition.
template <bool kTransposed>
class Frame {
 public:
  explicit Frame(const Grid& grid) : grid_(grid) {}
  bool blocked(int u, int v) const {
    return kTransposed ? grid_.blocked(v, u) : grid_.blocked(u, v);
  }
  Cell cell(int u, int v) const { return kTransposed ? Cell{v, u} : Cell{u, v}; }
  int u_size() const { return kTransposed ? grid_.height() : grid_.width(); }
  int v_size() const { return kTransposed ? grid_.width() : grid_.height(); }

 private:
  const Grid& grid_;
};

// Every obstacle centre (i + 0.5, j + 0.5) within `radius` of the segment has its closest point
// p with |p.u - centre.u| <= radius, so only columns within radius of [ua, ub] and, in each,
// rows within radius of the segment's v-range over [centre.u - radius, centre.u + radius] can
// matter. Cells beyond the border ring are never closer than the ring cell between them and the
// (in-grid) segment, so the scan is clamped to the padded range.
template <bool kTransposed>
SightHit clearance_scan(const Frame<kTransposed>& f, double ua, double va, double ub, double vb,
                        double slope, double radius) {
  // A segment that enters no obstacle interior is >= 0.5 from every obstacle centre (a line
  // missing an open unit square is at least the inscribed radius from its centre).
  if (!(radius > 0.5)) return {};
  const double limit = sight_internal::clearance_limit(radius);
  const int i_lo = ceil_clamped(ua - radius - 0.5, -1, f.u_size());
  const int i_hi = floor_clamped(ub + radius - 0.5, -1, f.u_size());
  for (int i = i_lo; i <= i_hi; ++i) {
    const double cu = i + 0.5;
    const double u0 = std::max(ua, cu - radius);
    const double u1 = std::min(ub, cu + radius);
    if (u0 > u1) continue;
    const double v0 = va + (u0 - ua) * slope;
    const double v1 = va + (u1 - ua) * slope;
    const int j_lo = ceil_clamped(std::min(v0, v1) - radius - 0.5, -1, f.v_size());
    const int j_hi = floor_clamped(std::max(v0, v1) + radius - 0.5, -1, f.v_size());
    for (int j = j_lo; j <= j_hi; ++j) {
      if (f.blocked(i, j) && squared_distance(cu, j + 0.5, ua, va, ub, vb) < limit)
        return {SightHit::Kind::clearance, f.cell(i, j)};
    }
  }
  return {};
}

template <bool kTransposed>
SightHit walk(const Grid& grid, double ua, double va, double ub, double vb, const SightRule& rule) {
  const Frame<kTransposed> f(grid);
  if (ub < ua) {
    std::swap(ua, ub);
    std::swap(va, vb);
  }
  double slope = 0.0;
  if (ua == ub) {
    // A single point (|dv| <= |du| = 0): it touches every cell whose closed square holds it.
    for (int i = static_cast<int>(std::ceil(ua)) - 1; i <= static_cast<int>(std::floor(ua)); ++i)
      for (int j = static_cast<int>(std::ceil(va)) - 1; j <= static_cast<int>(std::floor(va)); ++j)
        if (f.blocked(i, j)) return {SightHit::Kind::cell, f.cell(i, j)};
  } else {
    slope = (vb - va) / (ub - ua);
    // Column i covers u in [i, i + 1]; the closed segment touches columns ceil(ua) - 1 ..
    // floor(ub) (an endpoint on a column line touches the column beyond it, with zero width).
    const int c0 = static_cast<int>(std::ceil(ua)) - 1;
    const int c1 = static_cast<int>(std::floor(ub));
    double vl = va;            // v where the segment enters column i
    bool left_vertex = false;  // it enters through a vertex, as an interior point
    for (int i = c0; i <= c1; ++i) {
      const double ur = i + 1.0;
      double vr = vb;
      bool right_vertex = false;
      if (ur < ub) {
        // Direct evaluation (not incremental), then snapped: exact for the usual binary
        // fractions, so a pass through a vertex is seen as one.
        vr = sight_internal::line_crossing(ua, va, slope, ur);
        right_vertex = slope != 0.0 && ur > ua && is_integer(vr);
      }
      // Rows whose closed square meets the segment's v-range in this column.
      int j_lo = static_cast<int>(std::ceil(std::min(vl, vr))) - 1;
      int j_hi = static_cast<int>(std::floor(std::max(vl, vr)));
      // Leave out the side cells of vertex passes; they are judged by the corner rule below.
      // Rising (slope > 0) through vertex (X, k): from (X-1, k-1) to (X, k), sides (X, k-1)
      // and (X-1, k); falling: from (X-1, k) to (X, k-1), sides (X-1, k-1) and (X, k).
      if (left_vertex) {
        if (slope > 0.0)
          ++j_lo;
        else
          --j_hi;
      }
      if (right_vertex) {
        if (slope > 0.0)
          --j_hi;
        else
          ++j_lo;
      }
      for (int j = j_lo; j <= j_hi; ++j)
        if (f.blocked(i, j)) return {SightHit::Kind::cell, f.cell(i, j)};
      if (right_vertex && rule.corners != CornerRule::allow) {
        const int k = static_cast<int>(vr);
        const int s1v = slope > 0.0 ? k : k - 1;  // side cell in column i
        const int s2v = slope > 0.0 ? k - 1 : k;  // side cell in column i + 1
        const bool s1 = f.blocked(i, s1v);
        const bool s2 = f.blocked(i + 1, s2v);
        const bool bad = rule.corners == CornerRule::no_squeeze ? (s1 && s2) : (s1 || s2);
        if (bad) return {SightHit::Kind::corner, s1 ? f.cell(i, s1v) : f.cell(i + 1, s2v)};
      }
      vl = vr;
      left_vertex = right_vertex;
    }
  }
  if (rule.kind == SightRule::Kind::clearance)
    return clearance_scan(f, ua, va, ub, vb, slope, rule.radius);
  return {};
}

}  // namespace

SightHit sight_internal::reference_walk(const Grid& grid, const Walk& w, const SightRule& rule) {
  if (w.transposed) return walk<true>(grid, w.ua, w.va, w.ub, w.vb, rule);
  return walk<false>(grid, w.ua, w.va, w.ub, w.vb, rule);
}

SightHit check_segment(const Grid& grid, Point a, Point b, const SightRule& rule) {
  count_collision_checks(1);
  sight_internal::Walk w;
  if (!sight_internal::canonical_walk(grid, a, b, w)) return {SightHit::Kind::outside, {}};
  return sight_internal::reference_walk(grid, w, rule);
}

bool polyline_free(const Grid& grid, std::span<const Point> points, const SightRule& rule) {
  if (points.size() == 1) return segment_free(grid, points[0], points[0], rule);
  for (std::size_t i = 1; i < points.size(); ++i)
    if (!segment_free(grid, points[i - 1], points[i], rule)) return false;
  return true;
}

}  // namespace agv
