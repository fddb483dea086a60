#include "algos/postprocess/path_curves.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <optional>
#include <utility>

#include "algos/postprocess/path_simplify.h"
#include "core/cell_geometry.h"

namespace agv {

namespace {

double squared_distance_to_segment(Point p, Point a, Point b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double ex = p.x - (a.x + t * dx), ey = p.y - (a.y + t * dy);
  return ex * ex + ey * ey;
}

// Points closer than this to their predecessor are dropped: two separately computed copies of
// one point (a curve's end and the next curve's start) would otherwise leave a segment of
// 1e-15 cells whose heading is noise, counted as a turn by the metrics.
constexpr double kSamePoint = 1e-9;

// A sample exactly on a grid vertex (within the line of sight's tolerance) is left out of a
// sampled curve: the polyline then passes THROUGH the vertex, judged by the corner rule like the
// control polygon it follows (e.g. a diagonal squeeze under `allow`), instead of stopping on it,
// where as an endpoint it would touch all four cells around it.
bool on_vertex(Point p) {
  return std::abs(p.x - std::nearbyint(p.x)) <= kSightEpsilon &&
         std::abs(p.y - std::nearbyint(p.y)) <= kSightEpsilon;
}

// Paper 004 appendix A: P(t) = 1/6 [1 t t^2 t^3] M [P0 P1 P2 P3]^T.
constexpr double kBSplineBasis[4][4] = {{1 / 6.0, 4 / 6.0, 1 / 6.0, 0 / 6.0},
                                        {-3 / 6.0, 0 / 6.0, 3 / 6.0, 0 / 6.0},
                                        {3 / 6.0, -6 / 6.0, 3 / 6.0, 0 / 6.0},
                                        {-1 / 6.0, 3 / 6.0, -3 / 6.0, 1 / 6.0}};

// The coefficients of 1, t, t^2, t^3 of the segment whose controls are q[j..j+3]: the basis times
// the controls, summed in control order. A plain loop, not an Eigen product: Eigen's products
// use FMA instructions wherever the build's -march has them (its pmadd), so their last bits
// followed the build (docs/ARCHITECTURE.md "Determinism").
std::array<Point, 4> bspline_coefficients(const std::vector<Point>& q, int j) {
  std::array<Point, 4> c{};
  for (int i = 0; i < 4; ++i) {
    const Point& q0 = q[static_cast<std::size_t>(j)];
    c[i] = {kBSplineBasis[i][0] * q0.x, kBSplineBasis[i][0] * q0.y};
    for (int k = 1; k < 4; ++k) {
      const Point& qk = q[static_cast<std::size_t>(j + k)];
      c[i].x = c[i].x + kBSplineBasis[i][k] * qk.x;
      c[i].y = c[i].y + kBSplineBasis[i][k] * qk.y;
    }
  }
  return c;
}

}  // namespace

std::vector<Point> sample_quadratic_bezier(Point p0, Point p1, Point p2, int points) {
  points = std::max(points, 2);
  std::vector<Point> out;
  out.reserve(static_cast<std::size_t>(points));
  for (int k = 0; k < points; ++k) {
    const double t = static_cast<double>(k) / (points - 1);
    const double a = (1 - t) * (1 - t), b = 2 * t * (1 - t), c = t * t;  // paper 002 eq. 14
    out.push_back({a * p0.x + b * p1.x + c * p2.x, a * p0.y + b * p1.y + c * p2.y});
  }
  out.front() = p0;  // exact ends, so the pieces join the straight segments without a gap
  out.back() = p2;
  return out;
}

std::vector<Point> sample_bspline(std::span<const Point> controls, double step,
                                  std::vector<int>* segment_of) {
  std::vector<Point> out;
  if (segment_of) segment_of->clear();
  if (controls.empty()) return out;
  if (controls.size() == 1) {
    out.push_back(controls[0]);
    if (segment_of) segment_of->push_back(0);
    return out;
  }
  // Clamped: each end three times, so P(0) of the first segment is the first control point
  // ((P0 + 4 P0 + P0) / 6) and P(1) of the last is the last one.
  std::vector<Point> q;
  q.reserve(controls.size() + 4);
  q.push_back(controls.front());
  q.push_back(controls.front());
  q.insert(q.end(), controls.begin(), controls.end());
  q.push_back(controls.back());
  q.push_back(controls.back());
  step = std::max(step, 1e-6);
  const int segments = static_cast<int>(q.size()) - 3;
  for (int j = 0; j < segments; ++j) {
    double hull = 0.0;  // control polygon length: bounds the segment's arc length
    for (int r = 1; r < 4; ++r) hull += point_distance(q[j + r - 1], q[j + r]);
    const std::array<Point, 4> c = bspline_coefficients(q, j);
    const int samples = std::max(1, static_cast<int>(std::ceil(hull / step)));
    for (int k = 0; k < samples; ++k) {
      const double t = static_cast<double>(k) / samples;
      const Point p{c[0].x + t * (c[1].x + t * (c[2].x + t * c[3].x)),
                    c[0].y + t * (c[1].y + t * (c[2].y + t * c[3].y))};
      if (!out.empty() && (point_distance(out.back(), p) <= kSamePoint || on_vertex(p))) continue;
      out.push_back(p);
      if (segment_of) segment_of->push_back(j);
    }
  }
  out.front() = controls.front();  // exact ends: the validator compares them with start and goal
  if (out.size() > 1 && point_distance(out.back(), controls.back()) <= kSamePoint) {
    out.back() = controls.back();
  } else {
    out.push_back(controls.back());
    if (segment_of) segment_of->push_back(segments - 1);
  }
  return out;
}

namespace {

// P0 and P2 of the corner at keys[i] for distance d (paper 002: on the incoming and outgoing
// segments, d from the corner).
std::pair<Point, Point> bezier_ends(std::span<const Point> keys, std::size_t i, double d) {
  const Point prev = keys[i - 1], k = keys[i], next = keys[i + 1];
  const double l_in = point_distance(prev, k), l_out = point_distance(k, next);
  return {{k.x - d * (k.x - prev.x) / l_in, k.y - d * (k.y - prev.y) / l_in},
          {k.x + d * (next.x - k.x) / l_out, k.y + d * (next.y - k.y) / l_out}};
}

// The polyline of keys with a curve of distance d[i] at each corner i (0: sharp); owner[p] is the
// corner a point belongs to (-1 for a key point kept as is).
void build_bezier_path(std::span<const Point> keys, const std::vector<double>& d, int points,
                       std::vector<Point>& out, std::vector<int>& owner) {
  out.clear();
  owner.clear();
  auto add = [&](Point p, int who) {
    if (!out.empty() && point_distance(out.back(), p) <= kSamePoint) {
      if (who < 0) {  // a key point wins over a curve end it coincides with
        out.back() = p;
        owner.back() = who;
      }
      return;
    }
    out.push_back(p);
    owner.push_back(who);
  };
  add(keys.front(), -1);
  for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
    if (d[i] > 0.0) {
      const auto [p0, p2] = bezier_ends(keys, i, d[i]);
      for (const Point& q : sample_quadratic_bezier(p0, keys[i], p2, points))
        add(q, static_cast<int>(i));
    } else {
      add(keys[i], -1);
    }
  }
  add(keys.back(), -1);
}

}  // namespace

std::vector<Point> bezier_corners(const Grid& grid, std::span<const Point> keys,
                                  const SightRule& sight, const BezierOptions& options,
                                  DeadlinePoller* poll) {
  std::vector<Point> input(keys.begin(), keys.end());
  if (keys.size() < 3) return input;
  // 1. Per corner, the largest distance (L, halved up to shrink_steps times) whose curve, joined
  //    by its straight lead-in from where the path has got to, is free; else a sharp corner.
  std::vector<double> d(keys.size(), 0.0);
  Point reached = keys.front();
  std::vector<Point> piece;
  for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
    const Point prev = keys[i - 1], k = keys[i], next = keys[i + 1];
    const double l_in = point_distance(prev, k), l_out = point_distance(k, next);
    if (l_in > 0.0 && l_out > 0.0 && !goes_straight(prev, k, next)) {
      double di = std::min({options.corner_distance, l_in / 2, l_out / 2});
      for (int s = 0; s <= options.shrink_steps; ++s, di *= 0.5) {
        if (poll_expired(poll)) return input;
        const auto [p0, p2] = bezier_ends(keys, i, di);
        piece.assign(1, reached);
        const auto curve = sample_quadratic_bezier(p0, k, p2, options.points_per_curve);
        piece.insert(piece.end(), curve.begin(), curve.end());
        if (polyline_free(grid, piece, sight)) {
          d[i] = di;
          break;
        }
      }
    }
    reached = d[i] > 0.0 ? bezier_ends(keys, i, d[i]).second : k;
  }
  // 2. The whole path, checked; a segment that fails (a sharp corner's lead-in from a curve end,
  //    or the last segment) makes the corners it joins sharp, until it passes. Segments between
  //    two key points are free by precondition, so this ends.
  std::vector<Point> out;
  std::vector<int> owner;
  for (;;) {
    build_bezier_path(keys, d, options.points_per_curve, out, owner);
    std::size_t bad = out.size();
    for (std::size_t p = 0; p + 1 < out.size(); ++p) {
      if (poll_expired(poll)) return input;
      if (!segment_free(grid, out[p], out[p + 1], sight)) {
        bad = p;
        break;
      }
    }
    if (bad == out.size()) return out;
    bool changed = false;
    for (int who : {owner[bad], owner[bad + 1]}) {
      if (who >= 0 && d[static_cast<std::size_t>(who)] > 0.0) {
        d[static_cast<std::size_t>(who)] = 0.0;
        changed = true;
      }
    }
    if (!changed) return input;
  }
}

std::vector<Point> bspline_smooth(const Grid& grid, std::span<const Point> dense,
                                  std::vector<int> kept, const SightRule& sight,
                                  const BsplineOptions& options, DeadlinePoller* poll) {
  std::vector<Point> polygon = select_points(dense, kept);
  if (kept.size() < 3) {
    // Two control points: the curve is their segment.
    return polygon;
  }
  std::vector<int> multiplicity(kept.size(), 1);
  std::vector<Point> controls;
  std::vector<int> control_of;  // expanded control -> index into kept
  std::vector<int> segment_of;
  for (int refit = 0; refit <= options.max_refits; ++refit) {
    controls.clear();
    control_of.clear();
    for (std::size_t k = 0; k < kept.size(); ++k) {
      for (int r = 0; r < multiplicity[k]; ++r) {
        controls.push_back(dense[kept[k]]);
        control_of.push_back(static_cast<int>(k));
      }
    }
    std::vector<Point> samples = sample_bspline(controls, options.sample_step, &segment_of);
    std::size_t bad = samples.size();
    for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
      if (poll_expired(poll)) return polygon;
      if (!segment_free(grid, samples[i], samples[i + 1], sight)) {
        bad = i;
        break;
      }
    }
    if (bad == samples.size()) return samples;
    // Segment j uses the clamped controls q[j .. j+3] = controls[j-2 .. j+1] (ends repeated).
    const int j = segment_of[bad];
    const int last = static_cast<int>(controls.size()) - 1;
    const int k_lo = control_of[std::clamp(j - 2, 0, last)];
    const int k_hi = control_of[std::clamp(j + 1, 0, last)];
    const Point hit = samples[bad];
    // Re-insert a removed dense point between the span's control points, keeping the control
    // polygon free (the invariant that makes tripling converge): the one nearest the hit among
    // those both neighbours see; if none is seen, the whole gap nearest the hit (the polygon then
    // follows the free dense path there).
    double best = std::numeric_limits<double>::infinity();
    int best_dense = -1, best_slot = -1;
    double best_gap = std::numeric_limits<double>::infinity();
    int gap_slot = -1;
    for (int k = k_lo; k < k_hi; ++k) {
      const Point a = dense[kept[k]], b = dense[kept[k + 1]];
      for (int d = kept[k] + 1; d < kept[k + 1]; ++d) {
        if (poll_expired(poll)) return polygon;
        const double e = squared_distance_to_segment(hit, dense[d], dense[d]);
        if (e < best_gap) {
          best_gap = e;
          gap_slot = k;
        }
        if (e < best && segment_free(grid, a, dense[d], sight) &&
            segment_free(grid, dense[d], b, sight)) {
          best = e;
          best_dense = d;
          best_slot = k + 1;
        }
      }
    }
    if (best_dense >= 0) {
      kept.insert(kept.begin() + best_slot, best_dense);
      multiplicity.insert(multiplicity.begin() + best_slot, 1);
      continue;
    }
    if (gap_slot >= 0) {
      std::vector<int> gap;
      for (int d = kept[gap_slot] + 1; d < kept[gap_slot + 1]; ++d) gap.push_back(d);
      kept.insert(kept.begin() + gap_slot + 1, gap.begin(), gap.end());
      multiplicity.insert(multiplicity.begin() + gap_slot + 1, gap.size(), 1);
      continue;
    }
    // Nothing left to re-insert there: triple the interior control point nearest the hit.
    int tighten = -1;
    for (int k = std::max(k_lo, 1); k <= std::min(k_hi, static_cast<int>(kept.size()) - 2); ++k) {
      if (multiplicity[k] >= 3) continue;
      const double e = squared_distance_to_segment(hit, dense[kept[k]], dense[kept[k]]);
      if (e < best) {
        best = e;
        tighten = k;
      }
    }
    if (tighten < 0) break;
    multiplicity[tighten] = 3;
  }
  return polygon;
}

namespace {

// |heading change| at b of a -> b -> c, in [0, pi]; 0 where a segment has no length.
double turn_at(Point a, Point b, Point c) {
  const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - b.x, vy = c.y - b.y;
  if ((ux == 0.0 && uy == 0.0) || (vx == 0.0 && vy == 0.0)) return 0.0;
  return std::abs(std::atan2(ux * vy - uy * vx, ux * vx + uy * vy));
}

// Eq. 12-13's move of key point k: offset away from the obstacles among its cell's 8
// neighbours; nullopt when there are none or they cancel out.
std::optional<Point> pushed_key(const Grid& grid, Point k, double offset) {
  const int cx = static_cast<int>(std::floor(k.x));
  const int cy = static_cast<int>(std::floor(k.y));
  double ax = 0.0, ay = 0.0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if ((dx == 0 && dy == 0) || !grid.blocked(cx + dx, cy + dy)) continue;
      const Point o = centre({cx + dx, cy + dy});
      const double len = point_distance(k, o);
      if (len > 0.0) {
        ax += (o.x - k.x) / len;  // eq. 12: direction from the key point to the obstacle
        ay += (o.y - k.y) / len;
      }
    }
  }
  const double len = std::hypot(ax, ay);
  if (len < 1e-9) return std::nullopt;  // none, or obstacles on opposite sides: no way out
  return Point{k.x - offset * ax / len, k.y - offset * ay / len};  // eq. 13
}

// Section 4.2 step 3's k_insert for obstacle cell `cell` near segment a-b: the cell's vertex
// nearest the segment, moved `offset` further from the cell centre.
Point inserted_vertex(Cell cell, Point a, Point b, double offset) {
  const Point c = centre(cell);
  Point vertex{};
  double best = std::numeric_limits<double>::infinity();
  for (int corner = 0; corner < 4; ++corner) {
    const Point v{c.x + ((corner & 1) ? 0.5 : -0.5), c.y + ((corner & 2) ? 0.5 : -0.5)};
    const double e = squared_distance_to_segment(v, a, b);
    if (e < best) {
      best = e;
      vertex = v;
    }
  }
  const double len = point_distance(c, vertex);
  return {vertex.x + offset * (vertex.x - c.x) / len, vertex.y + offset * (vertex.y - c.y) / len};
}

bool distinct(Point a, Point b) { return point_distance(a, b) > kSamePoint; }

}  // namespace

double polyline_length_cells(std::span<const Point> path) {
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) length += point_distance(path[i], path[i + 1]);
  return length;
}

void avoid_obstacles(const Grid& grid, std::vector<Point>& keys, const SightRule& sight,
                     double offset, double near, double max_length, DeadlinePoller* poll) {
  if (keys.size() < 3) return;
  double length = polyline_length_cells(keys);
  // An adjustment may bend the path around an obstacle (it lengthens it: that is eq. 12-13's
  // safety detour) but never turn it back on itself, nor make it longer than `max_length`
  // (docs/PLANNERS.md "Improved A*").
  auto turns_ok = [](std::initializer_list<double> turns) {
    for (double t : turns)
      if (t > kReversalAngle) return false;
    return true;
  };
  // 1. Push key points away from the obstacles around them (eq. 12-13).
  for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
    if (poll_expired(poll)) return;  // every move so far kept the polyline free
    const std::optional<Point> moved = pushed_key(grid, keys[i], offset);
    if (!moved) continue;
    const Point before = keys[i - 1], after = keys[i + 1];
    if (!distinct(*moved, before) || !distinct(*moved, after)) continue;
    const double grown = point_distance(before, *moved) + point_distance(*moved, after) -
                         point_distance(before, keys[i]) - point_distance(keys[i], after);
    if (length + grown > max_length) continue;
    if (!turns_ok({i >= 2 ? turn_at(keys[i - 2], before, *moved) : 0.0,
                   turn_at(before, *moved, after),
                   i + 2 < keys.size() ? turn_at(*moved, after, keys[i + 2]) : 0.0}))
      continue;
    if (!segment_free(grid, before, *moved, sight) || !segment_free(grid, *moved, after, sight))
      continue;
    keys[i] = *moved;
    length += grown;
  }
  // 2. Where a segment passes closer than `near` to an obstacle centre, bend it around that
  //    obstacle's nearest vertex (section 4.2 step 3: k_insert). Consecutive segments often pass
  //    the same obstacle and would insert the same vertex twice, a path that goes there, back to
  //    the key point and there again: a point already on the path is never inserted.
  const SightRule close{SightRule::Kind::clearance, sight.corners, near};
  std::vector<Point> out{keys.front()};
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    if (poll_expired(poll)) return;
    const Point a = keys[i], b = keys[i + 1];
    const SightHit hit = check_segment(grid, a, b, close);
    if (hit.kind == SightHit::Kind::clearance) {
      const Point insert = inserted_vertex(hit.cell, a, b, offset);
      const bool fresh =
          std::none_of(out.begin(), out.end(), [&](Point p) { return !distinct(p, insert); }) &&
          std::none_of(keys.begin() + static_cast<std::ptrdiff_t>(i) + 1, keys.end(),
                       [&](Point p) { return !distinct(p, insert); });
      const double grown =
          point_distance(a, insert) + point_distance(insert, b) - point_distance(a, b);
      if (fresh && length + grown <= max_length &&
          turns_ok({out.size() >= 2 ? turn_at(out[out.size() - 2], a, insert) : 0.0,
                    turn_at(a, insert, b),
                    i + 2 < keys.size() ? turn_at(insert, b, keys[i + 2]) : 0.0}) &&
          segment_free(grid, a, insert, sight) && segment_free(grid, insert, b, sight)) {
        out.push_back(insert);
        length += grown;
      }
    }
    out.push_back(b);
  }
  keys.swap(out);
}

}  // namespace agv
