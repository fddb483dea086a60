#include "engine/judge/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/distance_transform.h"
#include "core/numbers.h"
#include "engine/judge/statistics.h"

namespace agv {

namespace {

// Difference of two headings wrapped to (-pi, pi].
double wrapped_turn(double from, double to) {
  double d = to - from;  // in (-2 pi, 2 pi)
  if (d > kPi) d -= 2.0 * kPi;
  if (d <= -kPi) d += 2.0 * kPi;
  return d;
}

struct Vertex {
  double turn;  // signed, wrapped to (-pi, pi]
  double at;    // arc length from the start, cells
};

struct TurnSummary {
  std::int64_t count = 0;
  double max = 0.0;
};

// A turning vertex with its share of the curvature density (docs/METRICS.md "turns").
struct Bend {
  double turn;     // |turn|
  double at;       // arc position
  double lo, hi;   // its spread
  double density;  // turn / (hi - lo), rad per cell
  int sign;
};

void bends_of(std::span<const Vertex> vertices, double length, std::vector<Bend>& bends) {
  bends.clear();
  for (const Vertex& v : vertices)
    if (std::abs(v.turn) > kStraightTolerance)
      bends.push_back({std::abs(v.turn), v.at, 0.0, 0.0, 0.0, v.turn > 0.0 ? 1 : -1});
  for (std::size_t i = 0; i < bends.size(); ++i) {
    Bend& b = bends[i];
    // Half way to the neighbouring turning vertex, so a collinear joint changes nothing.
    const double before = i > 0 ? (b.at - bends[i - 1].at) / 2.0 : b.at;
    const double after = i + 1 < bends.size() ? (bends[i + 1].at - b.at) / 2.0 : length - b.at;
    b.lo = b.at - std::min(kTurnSpread, before);
    b.hi = b.at + std::min(kTurnSpread, after);
    b.density = b.turn / std::max(b.hi - b.lo, 1e-12);
  }
}

// One lobe, bends[first .. last], cut into ceil(extent / kTurnMaxExtent) pieces of equal arc.
void close_lobe(std::span<const Bend> bends, std::size_t first, std::size_t last, TurnSummary& t) {
  const double from = bends[first].at;
  const double extent = bends[last].at - from;
  const int pieces = std::max(1, static_cast<int>(std::ceil(extent / kTurnMaxExtent - 1e-12)));
  std::vector<double> sums(static_cast<std::size_t>(pieces), 0.0);
  for (std::size_t i = first; i <= last; ++i) {
    const int k = extent > 0.0 ? static_cast<int>((bends[i].at - from) / extent * pieces) : 0;
    sums[static_cast<std::size_t>(std::min(k, pieces - 1))] += bends[i].turn;
  }
  for (const double sum : sums) {
    if (sum > kTurnThreshold) ++t.count;
    t.max = std::max(t.max, sum);
  }
}

// docs/METRICS.md "turns": runs of one sign whose spreads touch, cut at density valleys below
// kTurnValleyRatio of the peak on either side, each lobe capped at kTurnMaxExtent of arc.
TurnSummary merged_turns(std::span<const Vertex> vertices, double length,
                         std::vector<Bend>& bends) {
  TurnSummary t;
  bends_of(vertices, length, bends);
  if (bends.empty()) return t;
  std::size_t first = 0;
  double peak = bends[0].density;  // the open lobe's highest density since its last valley
  double valley = std::numeric_limits<double>::infinity();  // the lowest density after the peak
  std::size_t valley_at = 0;
  for (std::size_t i = 1; i < bends.size(); ++i) {
    const Bend& b = bends[i];
    if (b.sign != bends[i - 1].sign || b.lo > bends[i - 1].hi) {
      close_lobe(bends, first, i - 1, t);
      first = i;
      peak = b.density;
      valley = std::numeric_limits<double>::infinity();
      continue;
    }
    if (b.density > peak && valley > kTurnValleyRatio * peak) {
      peak = b.density;  // a shallow dip: still the same lobe
      valley = std::numeric_limits<double>::infinity();
    } else if (b.density < valley) {
      valley = b.density;
      valley_at = i;
    }
    if (valley_at > first && i > valley_at && valley <= kTurnValleyRatio * peak &&
        valley <= kTurnValleyRatio * b.density) {
      close_lobe(bends, first, valley_at - 1, t);  // the valley bend starts the next lobe
      first = valley_at;
      peak = 0.0;
      for (std::size_t k = valley_at; k <= i; ++k) peak = std::max(peak, bends[k].density);
      valley = std::numeric_limits<double>::infinity();
    }
  }
  close_lobe(bends, first, bends.size() - 1, t);
  return t;
}

// docs/METRICS.md "smoothness_max": each vertex's |turn| spread evenly over the arc within
// kTurnSpread of it (at most to the middle of either adjacent segment), a curvature density;
// the largest integral of that density over a kSmoothnessWindow of arc, per cell. A window
// with an end at a box edge is a largest one. The spread makes a curve sampled every h score
// its curvature, not one sample's turn more (a point mass per vertex would count floor(W / h)
// or that plus one of them, 10 % apart at h = 0.1).
struct TurnBox {
  double lo;
  double hi;
  double turn;  // |turn|, spread over [lo, hi]
};

double window_integral(std::span<const TurnBox> boxes, double from) {
  const double to = from + kSmoothnessWindow;
  double sum = 0.0;
  for (const TurnBox& b : boxes) {
    if (b.lo >= to) break;
    const double overlap = std::min(b.hi, to) - std::max(b.lo, from);
    if (!(overlap > 0.0)) continue;
    // A box wholly inside the window (most of them) adds its turn: overlap == hi - lo exactly
    // then, so the ratio below is 1.0 and the division (the loop's cost) can be skipped.
    const double spread = b.hi - b.lo;
    sum += overlap >= spread ? b.turn : b.turn * std::min(1.0, overlap / spread);
  }
  return sum;
}

// The windows scored: one starting at each box's start, one ending at each box's end, each with
// the range of boxes window_integral() sums (from the first that ends after the window starts to
// the first that starts at or after its end) and the plain sum of those boxes' turns, which no
// window's integral exceeds (each box adds at most its turn).
struct Window {
  double from;
  std::size_t first, last;
  double bound;
};

void scored_windows(std::span<const TurnBox> boxes, std::span<const double> prefix,
                    std::vector<Window>& windows) {
  windows.clear();
  const auto pass = [&](auto&& from_of) {
    std::size_t first = 0;
    std::size_t last = 0;
    for (const TurnBox& b : boxes) {  // `from` never decreases within a pass
      const double from = from_of(b);
      while (first < boxes.size() && boxes[first].hi <= from) ++first;
      last = std::max(last, first);
      while (last < boxes.size() && boxes[last].lo < from + kSmoothnessWindow) ++last;
      windows.push_back({from, first, last, prefix[last] - prefix[first]});
    }
  };
  pass([](const TurnBox& b) { return b.lo; });
  pass([](const TurnBox& b) { return b.hi - kSmoothnessWindow; });
}

double max_window_turn(std::span<const TurnBox> boxes, std::vector<double>& prefix,
                       std::vector<Window>& windows) {
  if (boxes.empty()) return 0.0;
  prefix.assign(boxes.size() + 1, 0.0);
  for (std::size_t i = 0; i < boxes.size(); ++i) prefix[i + 1] = prefix[i] + boxes[i].turn;
  scored_windows(boxes, prefix, windows);
  const auto integral = [&](const Window& w) {
    return window_integral(boxes.subspan(w.first), w.from);
  };
  // Integrals cost a scan of their boxes each; a window whose bound stays under the best so far
  // by more than the rounding of both sums (terms are positive, so a few ulps of the total per
  // box) cannot be the largest, and the largest is the same double whatever order finds it.
  const auto top =
      std::max_element(windows.begin(), windows.end(),
                       [](const Window& l, const Window& r) { return l.bound < r.bound; });
  double best = integral(*top);
  const double margin = 4.0 * static_cast<double>(boxes.size() + 1) *
                        std::numeric_limits<double>::epsilon() * (prefix.back() + 1.0);
  for (const Window& w : windows)
    if (w.bound + margin >= best) best = std::max(best, integral(w));
  return best / kSmoothnessWindow;
}

// A path's working arrays, kept per thread from run to run: sampled curves have thousands of
// points, and fresh arrays for each run cost their growth copies and, once the allocator has
// given the pages back, a page fault per page (perf showed both above the metrics' own work).
struct MetricBuffers {
  std::vector<Vertex> vertices;
  std::vector<TurnBox> boxes;
  std::vector<Bend> bends;
  std::vector<double> prefix;
  std::vector<Window> windows;
};

MetricBuffers& thread_buffers() {
  thread_local MetricBuffers buffers;
  return buffers;
}

}  // namespace

PathMetrics compute_path_metrics(const Grid& grid, std::span<const Point> path,
                                 const MotionTimeParams& motion, std::int64_t waypoints) {
  PathMetrics m;
  m.waypoints = waypoints >= 0 ? waypoints : static_cast<std::int64_t>(path.size());
  if (path.empty()) return m;

  CompensatedSum length;
  CompensatedSum turn_sum;
  MetricBuffers& buffers = thread_buffers();
  std::vector<Vertex>& vertices = buffers.vertices;
  std::vector<TurnBox>& boxes = buffers.boxes;
  vertices.clear();
  boxes.clear();
  bool have_previous = false;
  double previous_heading = 0.0;
  double previous_length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double dx = path[i].x - path[i - 1].x;
    const double dy = path[i].y - path[i - 1].y;
    const double l = std::hypot(dx, dy);
    if (l == 0.0) continue;  // duplicate waypoint: no heading
    const double heading = std::atan2(dy, dx);
    if (have_previous) {
      const double turn = wrapped_turn(previous_heading, heading);
      turn_sum.add(std::abs(turn));
      const double at = length.value();
      vertices.push_back({turn, at});
      if (std::abs(turn) > 0.0)
        boxes.push_back({at - std::min(kTurnSpread, previous_length / 2.0),
                         at + std::min(kTurnSpread, l / 2.0), std::abs(turn)});
    }
    length.add(l);
    have_previous = true;
    previous_heading = heading;
    previous_length = l;
  }
  m.path_length = length.value();
  m.path_length_m = m.path_length * grid.cell_edge();
  m.turn_angle_rad = turn_sum.value();
  const TurnSummary turns = merged_turns(vertices, m.path_length, buffers.bends);
  m.turns = turns.count;
  m.max_turn_rad = turns.max;
  if (m.path_length > 0.0) m.smoothness_mean = m.turn_angle_rad / m.path_length;
  m.smoothness_max = max_window_turn(boxes, buffers.prefix, buffers.windows);

  const DistanceTransform& dt = grid.distance_transform();
  double clearance =
      path.size() == 1 ? dt.clearance(path[0]) : std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < path.size(); ++i)
    clearance = std::min(clearance, dt.segment_clearance(path[i - 1], path[i], clearance));
  m.min_clearance = clearance;
  m.min_clearance_m = clearance * grid.cell_edge();

  // Paper 000 eq. 5.2e.
  m.motion_time_s = m.path_length_m / motion.line_speed_mps +
                    static_cast<double>(m.waypoints) * motion.node_time_s +
                    m.turn_angle_rad / motion.turn_speed_radps;
  return m;
}

std::array<std::pair<std::string_view, double>, kPathMetricCount> metric_values(
    const PathMetrics& m) {
  return {{
      {"path_length", m.path_length},
      {"path_length_m", m.path_length_m},
      {"waypoints", static_cast<double>(m.waypoints)},
      {"turns", static_cast<double>(m.turns)},
      {"turn_angle_rad", m.turn_angle_rad},
      {"max_turn_rad", m.max_turn_rad},
      {"smoothness_mean", m.smoothness_mean},
      {"smoothness_max", m.smoothness_max},
      {"min_clearance", m.min_clearance},
      {"min_clearance_m", m.min_clearance_m},
      {"motion_time_s", m.motion_time_s},
  }};
}

double polyline_length(std::span<const Point> path) {
  CompensatedSum length;
  for (std::size_t i = 1; i < path.size(); ++i)
    length.add(std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y));
  return length.value();
}

}  // namespace agv
