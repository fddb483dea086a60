// The batched cells test: kLanes segments side by side, one per SIMD lane (GCC / Clang vector
// extensions: 8 x 64-bit lanes, one AVX-512 register under -march=native, split into narrower
// registers or scalar code on other targets, always the same results). Every step advances each
// lane's walk by one column of the reference walk (core/line_of_sight.cpp) with the reference's
// values computed lane by lane by the same IEEE operations, so the verdicts agree bit for bit;
// the per-segment branches of a scalar walk (which axis, which direction, where it stops) become
// selects, and the cells' bits arrive by gathers. Compiled with -ffp-contract=off.

#include <algorithm>
#include <cstdint>
#include <type_traits>

#include "core/line_of_sight_internal.h"

namespace agv::sight_internal {

namespace {

using LaneD = double __attribute__((vector_size(8 * kLanes)));
using LaneI = std::int64_t __attribute__((vector_size(8 * kLanes)));
using LaneU = std::uint64_t __attribute__((vector_size(8 * kLanes)));

// Lanes longer than this (columns along the major axis) are left to the single check, so that
// one long segment does not hold seven short ones.
constexpr std::int64_t kMaxLaneColumns = 16;

inline LaneD splat(double v) { return LaneD{} + v; }
inline LaneI splat_i(std::int64_t v) { return LaneI{} + v; }

// std::nearbyint for |x| < 2^51 (every coordinate here): adding and removing 1.5 * 2^52 rounds
// to the nearest integer, ties to even, in the default rounding mode. (A zero may come out
// with the other sign than nearbyint's; no comparison below can tell.)
inline LaneD round_lanes(LaneD x) {
  const LaneD m = splat(0x1.8p52);
  return (x + m) - m;
}
inline LaneD abs_lanes(LaneD x) { return x < splat(0.0) ? -x : x; }
inline LaneD snap_lanes(LaneD v) {
  const LaneD r = round_lanes(v);
  return abs_lanes(v - r) <= splat(kSightEpsilon) ? r : v;
}
inline LaneI to_int(LaneD x) { return __builtin_convertvector(x, LaneI); }
inline LaneD to_double(LaneI x) { return __builtin_convertvector(x, LaneD); }
// floor and ceil from the nearest integer q (comparisons give -1 for true).
inline LaneI floor_lanes(LaneD x) {
  const LaneD q = round_lanes(x);
  return to_int(q) + (q > x);
}
inline LaneI ceil_lanes(LaneD x) {
  const LaneD q = round_lanes(x);
  return to_int(q) - (q < x);
}
inline LaneD min_lanes(LaneD a, LaneD b) { return a < b ? a : b; }
inline LaneD max_lanes(LaneD a, LaneD b) { return a < b ? b : a; }
inline LaneI clamp_lanes(LaneI v, std::int64_t lo, std::int64_t hi) {
  v = v < splat_i(lo) ? splat_i(lo) : v;
  return v > splat_i(hi) ? splat_i(hi) : v;
}

}  // namespace

void walk_lanes(const Grid& grid, const Point* a, const Point* b, int count, CornerRule rule,
                LaneVerdicts& out) {
  // Canonical walks (canonical_walk, lane by lane); invalid lanes walk the point (0.5, 0.5).
  LaneD ax, ay, bx, by;
  LaneI valid;
  for (int k = 0; k < kLanes; ++k) {
    const bool real = k < count;
    ax[k] = real ? a[k].x : 0.5;
    ay[k] = real ? a[k].y : 0.5;
    bx[k] = real ? b[k].x : 0.5;
    by[k] = real ? b[k].y : 0.5;
    valid[k] = real ? -1 : 0;
  }
  ax = snap_lanes(ax);
  ay = snap_lanes(ay);
  bx = snap_lanes(bx);
  by = snap_lanes(by);
  const LaneD zero = splat(0.0), width = splat(grid.width()), height = splat(grid.height());
  // Written so that NaN fails too.
  const LaneI inside = valid & (ax >= zero) & (ax <= width) & (ay >= zero) & (ay <= height) &
                       (bx >= zero) & (bx <= width) & (by >= zero) & (by <= height);
  const LaneI transposed = ~(abs_lanes(by - ay) <= abs_lanes(bx - ax));
  const LaneD u1 = transposed ? ay : ax, v1 = transposed ? ax : ay;
  const LaneD u2 = transposed ? by : bx, v2 = transposed ? bx : by;
  const LaneI swap = u2 < u1;
  const LaneD half = splat(0.5);
  LaneD ua = inside ? (swap ? u2 : u1) : half;
  LaneD va = inside ? (swap ? v2 : v1) : half;
  LaneD ub = inside ? (swap ? u1 : u2) : half;
  LaneD vb = inside ? (swap ? v1 : v2) : half;
  LaneI tr = transposed & inside;
  LaneI c0 = ceil_lanes(ua) - 1;
  LaneI c1 = floor_lanes(ub);
  const LaneI single = inside & ((c1 - c0) >= splat_i(kMaxLaneColumns));
  ua = single ? half : ua;
  va = single ? half : va;
  ub = single ? half : ub;
  vb = single ? half : vb;
  tr = single ? splat_i(0) : tr;
  c0 = single ? splat_i(0) : c0;
  c1 = single ? splat_i(0) : c1;
  // A point: 0 / 1 (the reference takes slope 0 for it).
  const LaneD slope = (vb - va) / (ua == ub ? splat(1.0) : ub - ua);
  // Steps: the most columns of a lane walked here (none when every lane is invalid or single).
  std::int64_t columns = 0;
  for (int k = 0; k < kLanes; ++k)
    if (inside[k] != 0 && single[k] == 0) columns = std::max(columns, c1[k] - c0[k] + 1);

  const std::uint64_t* bits = grid.bit_row(-1);
  const auto words = static_cast<std::int64_t>(grid.words_per_row());
  // Cell (u, v) of each lane's walk frame, as 0 or 1.
  const auto cell = [&](LaneI u, LaneI v) {
    const LaneI x = tr ? v : u;
    const LaneI y = tr ? u : v;
    const LaneI bit = x + 1;
    const LaneI index = (y + 1) * words + (bit >> 6);
    LaneU word;
    for (int k = 0; k < kLanes; ++k) word[k] = bits[index[k]];
    return (word >> (LaneU)(bit & 63)) & 1U;
  };
  const LaneI rising = slope > zero;
  const LaneI moving = slope != zero;
  const auto walk = [&](auto corner_rule) {
    constexpr CornerRule kRule = decltype(corner_rule)::value;
    LaneD vl = va;
    LaneI lv = splat_i(0);
    LaneU hit = LaneU{};
    for (std::int64_t step = 0; step < columns; ++step) {
      const LaneI column = c0 + step;
      const LaneI active = column <= c1;
      const LaneI i = active ? column : c1;
      // The reference's right line of column i: line_crossing and the vertex flag.
      const LaneD ur = to_double(column + 1);
      const LaneI interior = ur < ub;
      const LaneD vr = interior ? snap_lanes(va + (ur - ua) * slope) : vb;
      const LaneD qr = round_lanes(vr);
      const LaneI rv = interior & moving & (ur > ua) & (qr == vr);
      // Rows ceil(min) - 1 .. floor(max), vertex side cells left out.
      LaneI j_lo = ceil_lanes(min_lanes(vl, vr)) - 1;
      LaneI j_hi = floor_lanes(max_lanes(vl, vr));
      j_lo -= lv & rising;
      j_hi += lv & ~rising;
      j_hi += rv & rising;
      j_lo -= rv & ~rising;
      const LaneI span = j_hi - j_lo;
      LaneU cells = cell(i, j_lo) | cell(i, j_lo + clamp_lanes(span, 0, 1));
      // A third cell only at the ends (an endpoint on a row line): gathered when some lane has one.
      std::int64_t third = 0;
      for (int k = 0; k < kLanes; ++k) third |= span[k] >= 2;
      if (third != 0) cells |= cell(i, j_lo + clamp_lanes(span, 0, 2));
      hit |= cells & (LaneU)(span >= splat_i(0)) & (LaneU)active;
      if constexpr (kRule != CornerRule::allow) {
        // The corner rule at a right vertex k = vr: sides (i, k | k - 1), (i + 1, k - 1 | k).
        const LaneI kv = to_int(qr);
        const LaneU s1 = cell(i, rising ? kv : kv - 1);
        const LaneU s2 = cell(rv ? i + 1 : i, rising ? kv - 1 : kv);
        const LaneU bad = kRule == CornerRule::no_squeeze ? (s1 & s2) : (s1 | s2);
        hit |= bad & (LaneU)rv & (LaneU)active;
      }
      vl = vr;
      lv = rv;
      // Stop once every lane is blocked or done.
      const LaneI running = (hit == 0U) & (column < c1);
      std::int64_t any = 0;
      for (int k = 0; k < kLanes; ++k) any |= running[k];
      if (any == 0) break;
    }
    return hit;
  };
  using Allow = std::integral_constant<CornerRule, CornerRule::allow>;
  using NoSqueeze = std::integral_constant<CornerRule, CornerRule::no_squeeze>;
  using NoCornerCut = std::integral_constant<CornerRule, CornerRule::no_corner_cut>;
  const LaneU hit = rule == CornerRule::allow        ? walk(Allow{})
                    : rule == CornerRule::no_squeeze ? walk(NoSqueeze{})
                                                     : walk(NoCornerCut{});
  for (int k = 0; k < kLanes; ++k) {
    out.single[k] = single[k] != 0;
    out.cells_free[k] = inside[k] != 0 && single[k] == 0 && hit[k] == 0;
    out.walk[k] = {tr[k] != 0, ua[k], va[k], ub[k], vb[k]};
    out.slope[k] = slope[k];
  }
}

}  // namespace agv::sight_internal
