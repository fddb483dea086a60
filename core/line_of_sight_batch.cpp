#include "core/line_of_sight_batch.h"

// Compiled with -ffp-contract=off, like line_of_sight.cpp (see line_of_sight_internal.h): every
// value compared here is the reference walk's value, computed by the same expression.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>

#include "core/line_of_sight_internal.h"

namespace agv {

namespace {

using sight_internal::is_integer;
using sight_internal::line_crossing;
using sight_internal::squared_distance;
using sight_internal::Walk;

constexpr std::uint64_t kAllBits = ~std::uint64_t{0};
// Widening of the clearance candidate bands, in cells: far above the rounding of any coordinate
// on a grid we load (~1e-12), far below anything that matters. Candidates are only candidates:
// each is then judged by the reference's exact squared distance.
constexpr double kBandSlack = 1e-6;
// Single segments: columns walked one at a time before the vectorised blocks start, and the
// shortest block worth vectorising (perf/bench_los.cpp chose both).
constexpr int kLead = 8;
constexpr int kMinBlock = 16;
constexpr double kSingleVectorFrom = 24.0;  // cells along the major axis
// Batches: a segment this long (along its major axis) has more columns than the lanes take
// (line_of_sight_lanes.cpp kMaxLaneColumns); a batch of such segments skips the lanes.
constexpr double kLongForLanes = 18.0;

// Any blocked cell among x0..x1 of grid row y (x0 <= x1 in [-1, W], y in [-1, H]): one masked
// word, or a masked OR over the words of a long interval.
inline bool row_any(const Grid& grid, int y, int x0, int x1) {
  const std::uint64_t* row = grid.bit_row(y);
  const auto b0 = static_cast<unsigned>(x0 + 1);
  const auto b1 = static_cast<unsigned>(x1 + 1);
  const unsigned w0 = b0 >> 6;
  const unsigned w1 = b1 >> 6;
  const std::uint64_t first = kAllBits << (b0 & 63U);
  const std::uint64_t last = kAllBits >> (63U - (b1 & 63U));
  if (w0 == w1) return (row[w0] & first & last) != 0;
  std::uint64_t acc = row[w0] & first;
  for (unsigned w = w0 + 1; w < w1; ++w) acc |= row[w];
  return (acc | (row[w1] & last)) != 0;
}

inline bool cell_bit(const Grid& grid, int x, int y) {
  const auto b = static_cast<unsigned>(x + 1);
  return ((grid.bit_row(y)[b >> 6] >> (b & 63U)) & 1U) != 0;
}

// Cell (u, v) of the walk frame.
template <bool kTransposed>
inline bool frame_bit(const Grid& grid, int u, int v) {
  return kTransposed ? cell_bit(grid, v, u) : cell_bit(grid, u, v);
}

inline bool corner_fails(CornerRule rule, bool s1, bool s2) {
  return rule == CornerRule::no_squeeze ? (s1 && s2) : (s1 || s2);
}

// floor / ceil clamped to [lo, hi] before the cast (the reference's clearance scan bounds).
inline int floor_clamped(double v, int lo, int hi) {
  return static_cast<int>(std::clamp(std::floor(v), double(lo), double(hi)));
}
inline int ceil_clamped(double v, int lo, int hi) {
  return static_cast<int>(std::clamp(std::ceil(v), double(lo), double(hi)));
}

// The column lines of the reference walk: column i covers u in [i, i + 1], columns c0..c1.
struct Lines {
  double ua, va, ub, vb, slope;
  int c0, c1;

  Lines(const Walk& w, double slope_)
      : ua(w.ua),
        va(w.va),
        ub(w.ub),
        vb(w.vb),
        slope(slope_),
        c0(static_cast<int>(std::ceil(w.ua)) - 1),
        c1(static_cast<int>(std::floor(w.ub))) {}

  // v where the segment crosses u = X (X in [c0, c1 + 1]), and whether it passes through a
  // vertex there as an interior point: exactly the reference walk's vl / vr and flags.
  double at(int x, bool& vertex) const {
    vertex = false;
    if (x == c0) return va;
    const double ur = x;
    if (!(ur < ub)) return vb;
    const double v = line_crossing(ua, va, slope, ur);
    vertex = slope != 0.0 && ur > ua && is_integer(v);
    return v;
  }
};

// One column of the reference walk: its cells (side cells of vertex passes left out) and the
// corner rule at its right vertex. Transposed, a column is a grid row: one masked word.
template <bool kTransposed>
bool column_hit(const Grid& grid, const Lines& lines, int i, double vl, bool left_vertex, double vr,
                bool right_vertex, CornerRule rule) {
  int j_lo = static_cast<int>(std::ceil(std::min(vl, vr))) - 1;
  int j_hi = static_cast<int>(std::floor(std::max(vl, vr)));
  const bool rising = lines.slope > 0.0;
  if (left_vertex) (rising ? ++j_lo : --j_hi);
  if (right_vertex) (rising ? --j_hi : ++j_lo);
  if (j_lo <= j_hi) {
    if constexpr (kTransposed) {
      if (row_any(grid, i, j_lo, j_hi)) return true;
    } else {
      for (int j = j_lo; j <= j_hi; ++j)
        if (cell_bit(grid, i, j)) return true;
    }
  }
  if (right_vertex && rule != CornerRule::allow) {
    const int k = static_cast<int>(vr);
    return corner_fails(rule, frame_bit<kTransposed>(grid, i, rising ? k : k - 1),
                        frame_bit<kTransposed>(grid, i + 1, rising ? k - 1 : k));
  }
  return false;
}

// Columns from..to of the reference walk, one at a time as it does them (carrying the line
// values), testing bits instead of bytes.
template <bool kTransposed>
bool scalar_walk(const Grid& grid, const Lines& lines, int from, int to, CornerRule rule) {
  bool left_vertex = false;
  double vl = lines.at(from, left_vertex);
  for (int i = from; i <= to; ++i) {
    bool right_vertex = false;
    const double vr = lines.at(i + 1, right_vertex);
    if (column_hit<kTransposed>(grid, lines, i, vl, left_vertex, vr, right_vertex, rule))
      return true;
    vl = vr;
    left_vertex = right_vertex;
  }
  return false;
}

// The middle columns m0..m1 (both lines strictly inside (ua, ub)), a block at a time and without
// a branch per cell. In the mirrored frame h = s * v (s the slope's sign, so h rises; mirrored
// index j is frame index j for s > 0 and -j - 1 = ~j for s < 0) the reference's column i covers
// the cells floor(h(i)) .. ceil(h(i + 1)) - 1, h(X) being its snapped crossing of line X: the
// strict bounds leave out the side cells of vertex passes, and there are at most 2 cells since
// |slope| <= 1. Every line where h is an integer is a vertex pass whose side-cell pair the corner
// rule judges. Each block first evaluates its lines (a loop the compiler vectorises: the same
// IEEE operations lane by lane as the reference's scalar ones), then ORs the bits of every
// covered cell (vectorised too, with gathers where the target has them). Blocks grow from
// kMinBlock to kMaxBlock lines so that a blocked segment still stops early.
template <bool kTransposed>
class MiddleColumns {
 public:
  MiddleColumns(const Grid& grid, const Lines& lines)
      : bits_(grid.bit_row(-1)),
        words_(static_cast<std::size_t>(grid.words_per_row())),
        lines_(lines),
        s_(lines.slope > 0.0 ? 1.0 : -1.0),
        flip_(lines.slope > 0.0 ? 0 : -1) {}

  bool hit(int m0, int m1, CornerRule rule) const {
    int block = kMinBlock;
    for (int b = m0; b <= m1; b += block, block = std::min(2 * block, kMaxBlock)) {
      const int n = std::min(block, m1 - b + 1);  // columns b .. b + n - 1, lines b .. b + n
      evaluate(b, n);
      std::uint64_t acc = 0;
      for (int k = 0; k < n; ++k) {
        const int lo = floor_[k];
        const int hi = ceil_[k + 1] - 1;
        const int extra = std::clamp(hi - lo, 0, 1);
        acc |= (bit(b + k, lo) | bit(b + k, lo + extra)) & static_cast<std::uint64_t>(lo <= hi);
      }
      if (rule != CornerRule::allow) {
        // Line X = b + k (k >= 1: the right lines of this block, up to m1 + 1) at integer
        // level t is a vertex pass with sides (X, t - 1) and (X - 1, t) in the mirrored frame.
        const bool both = rule == CornerRule::no_squeeze;
        for (int k = 1; k <= n; ++k) {
          const int t = floor_[k];
          const std::uint64_t s1 = bit(b + k, t - 1);
          const std::uint64_t s2 = bit(b + k - 1, t);
          acc |= (both ? (s1 & s2) : (s1 | s2)) & static_cast<std::uint64_t>(t == ceil_[k]);
        }
      }
      if (acc != 0) return true;
    }
    return false;
  }

 private:
  static constexpr int kMaxBlock = 64;

  void evaluate(int b, int n) const {
    const double ua = lines_.ua, va = lines_.va, slope = lines_.slope, s = s_;
    for (int k = 0; k <= n; ++k) {
      const double ur = static_cast<double>(b + k);
      // sight_internal::line_crossing, spelled out so that the loop vectorises.
      const double raw = va + (ur - ua) * slope;
      const double r = std::nearbyint(raw);
      const double h = s * (std::abs(raw - r) <= kSightEpsilon ? r : raw);
      // floor and ceil from the nearest integer q (exact; std::floor does not vectorise here).
      const double q = std::nearbyint(h);
      floor_[k] = static_cast<int>(q) - static_cast<int>(q > h);
      ceil_[k] = static_cast<int>(q) + static_cast<int>(q < h);
    }
  }

  // Cell (u, mirrored v) of the walk frame, as 0 or 1.
  std::uint64_t bit(int u, int j) const {
    const int v = j ^ flip_;
    const int x = kTransposed ? v : u;
    const int y = kTransposed ? u : v;
    const auto b = static_cast<unsigned>(x + 1);
    return (bits_[static_cast<std::size_t>(y + 1) * words_ + (b >> 6)] >> (b & 63U)) & 1U;
  }

  const std::uint64_t* bits_;
  std::size_t words_;
  const Lines& lines_;
  double s_;
  int flip_;
  mutable int floor_[kMaxBlock + 1];
  mutable int ceil_[kMaxBlock + 1];
};

template <bool kTransposed>
bool cells_hit(const Grid& grid, const Lines& lines, CornerRule rule) {
  if (!kTransposed && lines.slope == 0.0) {
    // Every line at v = va, no vertex pass: the rows around va, every column, a word at a time.
    const int j_lo = static_cast<int>(std::ceil(lines.va)) - 1;
    const int j_hi = static_cast<int>(std::floor(lines.va));
    for (int j = j_lo; j <= j_hi; ++j)
      if (row_any(grid, j, lines.c0, lines.c1)) return true;
    return false;
  }
  // The first kLead columns one at a time, like the reference (most blocked segments stop
  // there); then, on a long segment, the columns whose lines are both interior (i > ua and
  // i + 1 < ub) in vectorised blocks; the one or two last columns one at a time again.
  const int m1 = std::min(static_cast<int>(std::ceil(lines.ub)) - 2, lines.c1);
  const int split = std::max(static_cast<int>(std::floor(lines.ua)) + 1, lines.c0 + kLead);
  if (lines.slope == 0.0 || m1 - split + 1 < kMinBlock)
    return scalar_walk<kTransposed>(grid, lines, lines.c0, lines.c1, rule);
  return scalar_walk<kTransposed>(grid, lines, lines.c0, split - 1, rule) ||
         MiddleColumns<kTransposed>(grid, lines).hit(split, m1, rule) ||
         scalar_walk<kTransposed>(grid, lines, m1 + 1, lines.c1, rule);
}

// Each blocked bit among x0..x1 of row y (the candidates), judged by `too_close(x)`.
template <class TooClose>
bool any_candidate(const Grid& grid, int y, int x0, int x1, TooClose&& too_close) {
  if (x0 > x1) return false;
  const std::uint64_t* row = grid.bit_row(y);
  const auto b0 = static_cast<unsigned>(x0 + 1);
  const auto b1 = static_cast<unsigned>(x1 + 1);
  for (unsigned w = b0 >> 6; w <= (b1 >> 6); ++w) {
    std::uint64_t bits = row[w];
    if (w == (b0 >> 6)) bits &= kAllBits << (b0 & 63U);
    if (w == (b1 >> 6)) bits &= kAllBits >> (63U - (b1 & 63U));
    while (bits != 0) {
      const int x = static_cast<int>(w * 64U + static_cast<unsigned>(std::countr_zero(bits))) - 1;
      if (too_close(x)) return true;
      bits &= bits - 1;
    }
  }
  return false;
}

// Clearance, steep segment: the reference scans walk columns = grid rows; the same bounds per
// row, blocked candidates taken a word at a time.
bool steep_clearance_hit(const Grid& grid, const Walk& w, double slope, double radius) {
  const double limit = sight_internal::clearance_limit(radius);
  const int i_lo = ceil_clamped(w.ua - radius - 0.5, -1, grid.height());
  const int i_hi = floor_clamped(w.ub + radius - 0.5, -1, grid.height());
  for (int i = i_lo; i <= i_hi; ++i) {
    const double cu = i + 0.5;
    const double u0 = std::max(w.ua, cu - radius);
    const double u1 = std::min(w.ub, cu + radius);
    if (u0 > u1) continue;
    const double v0 = w.va + (u0 - w.ua) * slope;
    const double v1 = w.va + (u1 - w.ua) * slope;
    const int j_lo = ceil_clamped(std::min(v0, v1) - radius - 0.5, -1, grid.width());
    const int j_hi = floor_clamped(std::max(v0, v1) + radius - 0.5, -1, grid.width());
    if (any_candidate(grid, i, j_lo, j_hi, [&](int x) {
          return squared_distance(cu, x + 0.5, w.ua, w.va, w.ub, w.vb) < limit;
        }))
      return true;
  }
  return false;
}

// Clearance, shallow segment (or a point): the reference scans columns; here each grid row takes
// every centre within radius (+ slack) of the part of the segment inside the row's band
// |v - centre| <= radius (+ slack): a superset of the cells that can be too close, each judged
// by the reference's exact squared distance in its own frame.
bool shallow_clearance_hit(const Grid& grid, const Walk& w, double slope, double radius) {
  const double limit = sight_internal::clearance_limit(radius);
  const double v_min = std::min(w.va, w.vb);
  const double v_max = std::max(w.va, w.vb);
  const int j_lo = ceil_clamped(v_min - radius - 0.5 - kBandSlack, -1, grid.height());
  const int j_hi = floor_clamped(v_max + radius - 0.5 + kBandSlack, -1, grid.height());
  for (int j = j_lo; j <= j_hi; ++j) {
    const double cv = j + 0.5;
    const double band_lo = std::max(v_min, cv - radius - kBandSlack);
    const double band_hi = std::min(v_max, cv + radius + kBandSlack);
    if (band_lo > band_hi) continue;
    double u_lo = w.ua;
    double u_hi = w.ub;
    if (slope != 0.0) {
      const double u_a = w.ua + (band_lo - w.va) / slope;
      const double u_b = w.ua + (band_hi - w.va) / slope;
      u_lo = std::clamp(std::min(u_a, u_b), w.ua, w.ub);
      u_hi = std::clamp(std::max(u_a, u_b), w.ua, w.ub);
    }
    const int x_lo = ceil_clamped(u_lo - radius - 0.5 - kBandSlack, -1, grid.width());
    const int x_hi = floor_clamped(u_hi + radius - 0.5 + kBandSlack, -1, grid.width());
    if (any_candidate(grid, j, x_lo, x_hi, [&](int x) {
          return squared_distance(x + 0.5, cv, w.ua, w.va, w.ub, w.vb) < limit;
        }))
      return true;
  }
  return false;
}

bool clearance_free(const Grid& grid, const Walk& w, double slope, const SightRule& rule) {
  // (At radius <= 0.5 the cells test already implies the clearance, as in the reference.)
  if (rule.kind != SightRule::Kind::clearance || !(rule.radius > 0.5)) return true;
  return w.transposed ? !steep_clearance_hit(grid, w, slope, rule.radius)
                      : !shallow_clearance_hit(grid, w, slope, rule.radius);
}

bool free_fast(const Grid& grid, Point a, Point b, const SightRule& rule) {
  Walk w;
  if (!sight_internal::canonical_walk(grid, a, b, w)) return false;
  // Short segments: the reference walk itself is the fastest single check (perf/README.md).
  if (w.ub - w.ua < kSingleVectorFrom) return !sight_internal::reference_walk(grid, w, rule);
  const double slope = (w.vb - w.va) / (w.ub - w.ua);
  const Lines lines(w, slope);
  if (w.transposed ? cells_hit<true>(grid, lines, rule.corners)
                   : cells_hit<false>(grid, lines, rule.corners))
    return false;
  return clearance_free(grid, w, slope, rule);
}

// Up to kLanes segments a[k]-b[k]: out[k] = 1 when free. The cells test runs in SIMD lanes; the
// clearance test, where the rule has one, per lane on the lanes it left free.
void batch_free(const Grid& grid, const Point* a, const Point* b, int count, const SightRule& rule,
                std::uint8_t* out) {
  // A batch of long segments only: the lanes would send every one to the single check anyway.
  bool any_short = false;
  for (int k = 0; k < count; ++k)
    any_short |= !(std::max(std::abs(b[k].x - a[k].x), std::abs(b[k].y - a[k].y)) >= kLongForLanes);
  if (!any_short) {
    for (int k = 0; k < count; ++k) out[k] = free_fast(grid, a[k], b[k], rule) ? 1 : 0;
    return;
  }
  sight_internal::LaneVerdicts v;
  sight_internal::walk_lanes(grid, a, b, count, rule.corners, v);
  for (int k = 0; k < count; ++k) {
    if (v.single[k])
      out[k] = free_fast(grid, a[k], b[k], rule) ? 1 : 0;
    else
      out[k] = v.cells_free[k] && clearance_free(grid, v.walk[k], v.slope[k], rule) ? 1 : 0;
  }
}

}  // namespace

bool segment_free(const Grid& grid, Point a, Point b, const SightRule& rule) {
  count_collision_checks(1);
  return free_fast(grid, a, b, rule);
}

void segments_free(const Grid& grid, std::span<const Point> a, std::span<const Point> b,
                   const SightRule& rule, std::span<std::uint8_t> out) {
  count_collision_checks(static_cast<std::int64_t>(out.size()));
  for (std::size_t i = 0; i < out.size(); i += sight_internal::kLanes) {
    const int count =
        static_cast<int>(std::min<std::size_t>(sight_internal::kLanes, out.size() - i));
    batch_free(grid, a.data() + i, b.data() + i, count, rule, out.data() + i);
  }
}

void segments_free_from(const Grid& grid, Point from, std::span<const Point> to,
                        const SightRule& rule, std::span<std::uint8_t> out) {
  count_collision_checks(static_cast<std::int64_t>(out.size()));
  Point froms[sight_internal::kLanes];
  std::fill(std::begin(froms), std::end(froms), from);
  for (std::size_t i = 0; i < out.size(); i += sight_internal::kLanes) {
    const int count =
        static_cast<int>(std::min<std::size_t>(sight_internal::kLanes, out.size() - i));
    batch_free(grid, froms, to.data() + i, count, rule, out.data() + i);
  }
}

void points_free(const Grid& grid, std::span<const Point> points, const SightRule& rule,
                 std::span<std::uint8_t> out) {
  count_collision_checks(static_cast<std::int64_t>(out.size()));
  for (std::size_t i = 0; i < out.size(); i += sight_internal::kLanes) {
    const int count =
        static_cast<int>(std::min<std::size_t>(sight_internal::kLanes, out.size() - i));
    batch_free(grid, points.data() + i, points.data() + i, count, rule, out.data() + i);
  }
}

}  // namespace agv
