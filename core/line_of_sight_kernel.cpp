// The line-of-sight kernel (core/line_of_sight_batch.h says how it works), compiled once per
// instruction-set level into a namespace of its own (core/simd_target.h, core/simd_path.h): the
// same source, so the same verdicts, with the level's instructions where the compiler finds a use
// for them (SSE4.1 rounding for floor and ceil, BMI for the bit scans, wider registers).
//
// Compiled with -ffp-contract=off, like line_of_sight.cpp (see line_of_sight_internal.h): every
// value compared here is the reference walk's value, computed by the same expression. A level's
// FMA unit changes nothing: no multiply-add is fused.

#include "core/line_of_sight_kernel.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>

#include "core/line_of_sight_internal.h"
#include "core/simd_target.h"

AGV_SIMD_TARGET_BEGIN

namespace agv::sight_levels::AGV_SIMD_LEVEL {

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

// Columns x0..x1 (x0 <= x1 in [-1, W]) of a bit row: words w0..w1 of it, the first one masked by
// `first`, the last by `last` (the same word with both masks when w0 == w1).
struct WordSpan {
  unsigned w0, w1;
  std::uint64_t first, last;
};
inline WordSpan word_span(int x0, int x1) {
  const auto b0 = static_cast<unsigned>(x0 + 1);
  const auto b1 = static_cast<unsigned>(x1 + 1);
  return {b0 >> 6, b1 >> 6, kAllBits << (b0 & 63U), kAllBits >> (63U - (b1 & 63U))};
}

// Any blocked cell among x0..x1 of grid row y (x0 <= x1 in [-1, W], y in [-1, H]): one masked
// word, or a masked OR over the words of a long interval.
inline bool row_any(const Grid& grid, int y, int x0, int x1) {
  const std::uint64_t* row = grid.bit_row(y);
  const WordSpan s = word_span(x0, x1);
  if (s.w0 == s.w1) return (row[s.w0] & s.first & s.last) != 0;
  std::uint64_t acc = row[s.w0] & s.first;
  for (unsigned w = s.w0 + 1; w < s.w1; ++w) acc |= row[w];
  return (acc | (row[s.w1] & s.last)) != 0;
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

// Screen, then walk. The walk's columns go in blocks; each block is first screened:
// one masked word test per grid row over a box holding every cell the reference walk can touch
// in those columns, and every vertex side cell it can judge there (the segment's extent over the
// block, widened by kScreenSlack in both axes, far above any snapping or rounding). Only a block
// whose box holds a blocked cell is walked exactly (scalar_walk: the reference's columns and
// corner checks), with the column before it for the corner check at its left line. A column never
// walked has every cell it touches and every side cell it judges in a free box, so the verdict
// is the reference's; on free space a segment costs a few word tests per block of columns.
constexpr double kScreenSlack = 1e-6;
// Blocks grow from kFirstBlock columns by kGrowth to kMaxBlock: a blocked segment most often
// stops in its first columns, where a large box would be screened in vain (perf/bench_los.cpp
// chose all three; box_any takes boxes under 64 cells wide, a box is at most kMaxBlock + 3).
constexpr int kFirstBlock = 2;
constexpr int kGrowth = 4;
constexpr int kMaxBlock = 32;

// Any blocked cell in rows y0..y1 among columns x0..x1 (x1 - x0 < 64, so at most two words).
inline bool box_any(const Grid& grid, int x0, int x1, int y0, int y1) {
  const WordSpan s = word_span(x0, x1);
  // Two words read per row, without a branch: the second masked to nothing when it is the first.
  const std::uint64_t m0 = s.w0 == s.w1 ? s.first & s.last : s.first;
  const std::uint64_t m1 = s.w0 == s.w1 ? 0 : s.last;
  std::uint64_t acc = 0;
  for (int y = y0; y <= y1; ++y) {
    const std::uint64_t* row = grid.bit_row(y);
    acc |= (row[s.w0] & m0) | (row[s.w1] & m1);
  }
  return acc != 0;
}

// The cells lo .. hi along one axis holding the extent [lo, hi], widened, within [min, max].
inline int first_cell(double lo, int min) {
  return std::max(static_cast<int>(std::ceil(lo - kScreenSlack)) - 1, min);
}
inline int last_cell(double hi, int max) {
  return std::min(static_cast<int>(std::floor(hi + kScreenSlack)), max);
}

// Whether the box of walk columns i0..i1 holds a blocked cell. Transposed, a walk column is a
// grid row and the box spans the segment's v extent (grid x); else the box is those grid columns
// over the rows of the v extent.
// With a pad, the box grows by that many cells on every side (within the padded grid).
template <bool kTransposed>
bool block_screen(const Grid& grid, const Lines& lines, int i0, int i1, int pad = 0) {
  const double e0 = lines.va + ((i0 - kScreenSlack) - lines.ua) * lines.slope;
  const double e1 = lines.va + ((i1 + 1 + kScreenSlack) - lines.ua) * lines.slope;
  const double lo = std::max(std::min(e0, e1), std::min(lines.va, lines.vb));
  const double hi = std::min(std::max(e0, e1), std::max(lines.va, lines.vb));
  const int u_max = kTransposed ? grid.height() : grid.width();
  const int v_max = kTransposed ? grid.width() : grid.height();
  const int u0 = std::max(i0 - pad, -1);
  const int u1 = std::min(i1 + pad, u_max);
  const int v0 = std::max(first_cell(lo, -1) - pad, -1);
  const int v1 = std::min(last_cell(hi, v_max) + pad, v_max);
  return kTransposed ? box_any(grid, v0, v1, u0, u1) : box_any(grid, u0, u1, v0, v1);
}

template <bool kTransposed>
bool screened_walk(const Grid& grid, const Lines& lines, CornerRule rule) {
  int walked = lines.c0 - 1;  // the columns walked exactly: none yet, then up to this one
  int block = kFirstBlock;
  for (int i0 = lines.c0; i0 <= lines.c1;
       i0 += block, block = std::min(kGrowth * block, kMaxBlock)) {
    const int i1 = std::min(i0 + block - 1, lines.c1);
    if (!block_screen<kTransposed>(grid, lines, i0, i1)) continue;
    if (scalar_walk<kTransposed>(grid, lines, std::max({lines.c0, i0 - 1, walked + 1}), i1, rule))
      return true;
    walked = i1;
  }
  return false;
}

template <bool kTransposed>
bool cells_hit(const Grid& grid, const Lines& lines, CornerRule rule) {
  if (lines.slope == 0.0) {
    // Every line at v = va, no vertex pass: the rows around va of every column. Transposed,
    // each column is one grid row: a word test per row; else a word test per row of the span.
    const int j_lo = static_cast<int>(std::ceil(lines.va)) - 1;
    const int j_hi = static_cast<int>(std::floor(lines.va));
    if constexpr (kTransposed) {
      for (int i = lines.c0; i <= lines.c1; ++i)
        if (row_any(grid, i, j_lo, j_hi)) return true;
    } else {
      for (int j = j_lo; j <= j_hi; ++j)
        if (row_any(grid, j, lines.c0, lines.c1)) return true;
    }
    return false;
  }
  return screened_walk<kTransposed>(grid, lines, rule);
}

// Each blocked bit among x0..x1 of row y (the candidates), judged by `too_close(x)`.
template <class TooClose>
bool any_candidate(const Grid& grid, int y, int x0, int x1, TooClose&& too_close) {
  if (x0 > x1) return false;
  const std::uint64_t* row = grid.bit_row(y);
  const WordSpan s = word_span(x0, x1);
  for (unsigned w = s.w0; w <= s.w1; ++w) {
    std::uint64_t bits = row[w];
    if (w == s.w0) bits &= s.first;
    if (w == s.w1) bits &= s.last;
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

// Clearance screens: every obstacle centre closer than the radius to a point of the segment lies
// within radius + 1/2 of it in both axes, so within ceil(radius) + 1 cells of the cells box of
// the block holding that point. Boxes padded so are screened a block of kClearanceBlock columns
// at a time; all free means no candidate at all. Boxes stay under 64 cells wide up to a pad of
// kMaxClearancePad; wider clearances go to the scan directly, and so does a segment that
// spans fewer than kMinClearanceScreen + 1 columns: its padded box is mostly border.
constexpr int kClearanceBlock = 16;
constexpr int kMaxClearancePad = 20;
constexpr int kMinClearanceScreen = 4;  // perf/bench_los.cpp, circles at 2 and 8 cells

template <bool kTransposed>
bool clearance_screened_free(const Grid& grid, const Lines& lines, int pad) {
  for (int i0 = lines.c0; i0 <= lines.c1; i0 += kClearanceBlock)
    if (block_screen<kTransposed>(grid, lines, i0, std::min(i0 + kClearanceBlock - 1, lines.c1),
                                  pad))
      return false;
  return true;
}

bool clearance_free(const Grid& grid, const Walk& w, const Lines& lines, const SightRule& rule) {
  // (At radius <= 0.5 the cells test already implies the clearance, as in the reference.)
  if (rule.kind != SightRule::Kind::clearance || !(rule.radius > 0.5)) return true;
  if (rule.radius < kMaxClearancePad - 1 && lines.c1 - lines.c0 >= kMinClearanceScreen) {
    const int pad = static_cast<int>(std::ceil(rule.radius)) + 1;
    if (w.transposed ? clearance_screened_free<true>(grid, lines, pad)
                     : clearance_screened_free<false>(grid, lines, pad))
      return true;
  }
  return w.transposed ? !steep_clearance_hit(grid, w, lines.slope, rule.radius)
                      : !shallow_clearance_hit(grid, w, lines.slope, rule.radius);
}

// Whether p lies well inside a blocked cell (both coordinates further than kInsideMargin from
// the cell's edges): the reference walk touches that cell in the first or last column, so the
// segment is not free. Near an edge the reference may leave the cell to the corner rule (an
// endpoint snapped onto a vertex pass), so such a point is left to the walk. Most segments that
// are not free on a dense map stop here.
constexpr double kInsideMargin = 1e-6;
inline bool endpoint_blocked(const Grid& grid, Point p) {
  // Written so that NaN fails the range test; the cell is then one of the padded grid's.
  if (!(p.x >= 0.0 && p.x < grid.width() && p.y >= 0.0 && p.y < grid.height())) return false;
  const double fx = std::floor(p.x);
  const double fy = std::floor(p.y);
  const bool inside = p.x - fx > kInsideMargin && p.x - fx < 1.0 - kInsideMargin &&
                      p.y - fy > kInsideMargin && p.y - fy < 1.0 - kInsideMargin;
  return inside && grid.blocked(static_cast<int>(fx), static_cast<int>(fy));
}

bool free_fast(const Grid& grid, Point a, Point b, const SightRule& rule) {
  if (endpoint_blocked(grid, a) || endpoint_blocked(grid, b)) return false;
  Walk w;
  if (!sight_internal::canonical_walk(grid, a, b, w)) return false;
  // A point: the reference's cells around it.
  if (w.ub == w.ua) return !sight_internal::reference_walk(grid, w, rule);
  const double slope = (w.vb - w.va) / (w.ub - w.ua);
  const Lines lines(w, slope);
  if (w.transposed ? cells_hit<true>(grid, lines, rule.corners)
                   : cells_hit<false>(grid, lines, rule.corners))
    return false;
  return clearance_free(grid, w, lines, rule);
}

}  // namespace

bool segment(const Grid& grid, Point a, Point b, const SightRule& rule) {
  return free_fast(grid, a, b, rule);
}

void segments(const Grid& grid, std::span<const Point> a, std::span<const Point> b,
              const SightRule& rule, std::span<std::uint8_t> out) {
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = free_fast(grid, a[i], b[i], rule) ? 1 : 0;
}

void segments_from(const Grid& grid, Point from, std::span<const Point> to, const SightRule& rule,
                   std::span<std::uint8_t> out) {
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = free_fast(grid, from, to[i], rule) ? 1 : 0;
}

void points(const Grid& grid, std::span<const Point> p, const SightRule& rule,
            std::span<std::uint8_t> out) {
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = free_fast(grid, p[i], p[i], rule) ? 1 : 0;
}

extern const SightKernel kKernel{segment, segments, segments_from, points};

}  // namespace agv::sight_levels::AGV_SIMD_LEVEL

AGV_SIMD_TARGET_END
