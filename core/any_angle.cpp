#include "core/any_angle.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <utility>

namespace agv {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kStartNode = 0;
constexpr int kGoalNode = 1;
constexpr int kFirstBendNode = 2;
// Bend points are grouped in tiles of kTile x kTile vertices, so an expansion can skip whole
// tiles on the wrong side of a taut bend or too far for the goal's cost so far.
constexpr int kTile = 8;
constexpr double kUpperMargin = 1e-9;
constexpr std::size_t kUpperBoundNodes = 512;

// The padded occupancy: blocked(x, y) is valid for x in [-1, width], y in [-1, height].
struct Cells {
  const std::uint8_t* occupancy;
  int stride;
  bool blocked(int x, int y) const { return occupancy[(y + 1) * stride + (x + 1)] != 0; }
};

int sign(int v) { return (v > 0) - (v < 0); }

// Two diagonally opposite cells around vertex (i, j) blocked, the other two free.
bool pinch_at(const Cells& cells, int i, int j) {
  const bool nw = cells.blocked(i - 1, j - 1);
  const bool ne = cells.blocked(i, j - 1);
  const bool sw = cells.blocked(i - 1, j);
  const bool se = cells.blocked(i, j);
  return (nw && se && !ne && !sw) || (ne && sw && !nw && !se);
}

// The cell holding the first open piece of a segment leaving doubled coordinate p in direction
// s (-1, 0 or +1) along that axis; s == 0 only for odd p (a line through cell centres).
int first_cell(int p, int s) { return (p >> 1) - ((p & 1) == 0 && s < 0 ? 1 : 0); }

// A segment lying on a grid line (doubled coordinate even on the fixed axis): each piece between
// two vertices runs along the edge of two cells, at least one of which must be free; each vertex
// strictly inside is a pinch crossing when its four cells form a pinch. `from`, `to`: doubled
// coordinates along the line; `line`: its doubled coordinate on the fixed axis.
bool visible_on_grid_line(const Cells& cells, int from, int to, int line, bool horizontal,
                          bool allow) {
  const int lo = std::min(from, to);
  const int hi = std::max(from, to);
  const int r = line >> 1;
  for (int i = lo >> 1; 2 * i < hi; ++i) {
    const bool free_before = horizontal ? !cells.blocked(i, r - 1) : !cells.blocked(r - 1, i);
    const bool free_after = horizontal ? !cells.blocked(i, r) : !cells.blocked(r, i);
    if (!free_before && !free_after) return false;
    if (!allow && 2 * i > lo && (horizontal ? pinch_at(cells, i, r) : pinch_at(cells, r, i)))
      return false;
  }
  return true;
}

// The exact walk of closure_visible(): the segment's open pieces between successive grid-line
// crossings each lie inside one cell, which must be free; the crossing points then lie in the
// closure of free cells. The next crossing is the smaller of two parameters nx / |dx| and
// ny / |dy|, compared by cross-multiplication (all values below 2^22 for maps up to 2^10 cells
// a side, far below 2^63 for any map the readers accept).
bool visible(const Cells& cells, HalfPoint a, HalfPoint b, bool allow) {
  const int dx = b.x - a.x;
  const int dy = b.y - a.y;
  if (dx == 0 && dy == 0) return true;
  if (dy == 0 && (a.y & 1) == 0) return visible_on_grid_line(cells, a.x, b.x, a.y, true, allow);
  if (dx == 0 && (a.x & 1) == 0) return visible_on_grid_line(cells, a.y, b.y, a.x, false, allow);
  const int sx = sign(dx);
  const int sy = sign(dy);
  const std::int64_t adx = std::abs(dx);
  const std::int64_t ady = std::abs(dy);
  int cx = first_cell(a.x, sx);
  int cy = first_cell(a.y, sy);
  for (;;) {
    if (cells.blocked(cx, cy)) return false;
    // Doubled distance from a to the next column (row) line in the direction of travel.
    const std::int64_t nx = sx > 0 ? 2 * (cx + 1) - a.x : sx < 0 ? a.x - 2 * cx : 1;
    const std::int64_t ny = sy > 0 ? 2 * (cy + 1) - a.y : sy < 0 ? a.y - 2 * cy : 1;
    if (nx >= adx && ny >= ady) return true;  // b lies in (or on the boundary of) this cell
    const std::int64_t tx = nx * ady;
    const std::int64_t ty = ny * adx;
    if (tx < ty) {
      cx += sx;
    } else if (tx > ty) {
      cy += sy;
    } else {
      // Through a vertex, diagonally: both side cells blocked is a pinch crossing.
      if (!allow && cells.blocked(cx + sx, cy) && cells.blocked(cx, cy + sy)) return false;
      cx += sx;
      cy += sy;
    }
  }
}

double half_distance(HalfPoint a, HalfPoint b) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  return std::sqrt(dx * dx + dy * dy);
}

// The taut condition at a bend u around the blocked quadrant of direction (bx, by) from u: with
// `back` = parent - u and `out` = successor - u, the quadrant must lie inside the closed wedge
// of angle < 180 degrees between them, else the bend could be cut short. A straight pass
// (back and out opposite) is refused too: the parent sees the successor directly, with the same
// length and through the same taut test.
bool taut_around(int bx, int by, HalfPoint back, HalfPoint out) {
  const std::int64_t c = std::int64_t{back.x} * out.y - std::int64_t{back.y} * out.x;
  if (c == 0) return false;
  const std::int64_t s = c > 0 ? 1 : -1;
  // Quadrant edges (bx, 0) and (0, by), each within cone(back, out).
  const std::int64_t back_k1 = -std::int64_t{back.y} * bx;
  const std::int64_t k1_out = std::int64_t{bx} * out.y;
  const std::int64_t back_k2 = std::int64_t{back.x} * by;
  const std::int64_t k2_out = -std::int64_t{by} * out.x;
  return s * back_k1 >= 0 && s * k1_out >= 0 && s * back_k2 >= 0 && s * k2_out >= 0;
}

bool scratch_heap_worse(const AnyAngleScratch::Entry& a, const AnyAngleScratch::Entry& b) {
  if (a.f != b.f) return a.f > b.f;
  if (a.g != b.g) return a.g < b.g;
  return a.node > b.node;
}

// Marks every cell reachable from `from` by 8-connected moves under `rule` in
// scratch.component.stamp; returns the generation that marks them.
std::uint32_t flood_fill(const Grid& grid, int from, CornerRule rule, AnyAngleScratch& scratch) {
  return agv::flood_fill(grid.occupancy(), grid.stride(), grid.padded_size(), from, -1, rule,
                         scratch.component);
}

// Length of the shortest 8-connected path from `from` to `to` under `rule` (straight 1,
// diagonal sqrt 2), which must be connected: a path of the closure of free space under the same
// pinch rule, so an upper bound of the reference that prunes the search before it has reached
// the goal. Doubled, like the search's lengths.
double grid_upper_bound(const Grid& grid, int from, int to, CornerRule rule, AnyAngleScratch& s) {
  const std::uint8_t* occupancy = grid.occupancy();
  const int stride = grid.stride();
  std::array<int, 8> offset{};
  std::array<double, 8> cost{};
  for (int d = 0; d < 8; ++d) {
    offset[d] = kDy[d] * stride + kDx[d];
    cost[d] = is_diagonal(d) ? 2.0 * std::numbers::sqrt2 : 2.0;
  }
  const MoveTable& table = move_table(rule);
  s.grid_g.assign(static_cast<std::size_t>(grid.padded_size()), kInfinity);
  auto& open = s.grid_open;
  open.clear();
  const auto later = [](const std::pair<double, int>& a, const std::pair<double, int>& b) {
    return a.first > b.first || (a.first == b.first && a.second > b.second);
  };
  s.grid_g[from] = 0.0;
  open.push_back({0.0, from});
  while (!open.empty()) {
    std::pop_heap(open.begin(), open.end(), later);
    const auto [g, i] = open.back();
    open.pop_back();
    if (g > s.grid_g[i]) continue;
    if (i == to) return g;
    unsigned free_mask = 0;
    for (int d = 0; d < 8; ++d) free_mask |= (occupancy[i + offset[d]] == 0 ? 1U : 0U) << d;
    unsigned moves = table[free_mask];
    while (moves != 0) {
      const int d = std::countr_zero(moves);
      moves &= moves - 1;
      const int j = i + offset[d];
      const double ng = g + cost[d];
      if (ng >= s.grid_g[j]) continue;
      s.grid_g[j] = ng;
      open.push_back({ng, j});
      std::push_heap(open.begin(), open.end(), later);
    }
  }
  return kInfinity;
}

// Nodes: start, goal, then every bend point next to a cell of the start's component.
void collect_nodes(const Grid& grid, Cell start, Cell goal, bool allow, std::uint32_t gen,
                   AnyAngleScratch& s) {
  s.node.clear();
  s.block_x.clear();
  s.block_y.clear();
  s.pinch.clear();
  auto add = [&](HalfPoint p, int bx, int by, bool pinch) {
    s.node.push_back(p);
    s.block_x.push_back(static_cast<std::int8_t>(bx));
    s.block_y.push_back(static_cast<std::int8_t>(by));
    s.pinch.push_back(pinch ? 1 : 0);
  };
  add({2 * start.x + 1, 2 * start.y + 1}, 0, 0, false);
  add({2 * goal.x + 1, 2 * goal.y + 1}, 0, 0, false);
  const std::uint8_t* occ = grid.occupancy();
  const int stride = grid.stride();
  const auto& reached = s.component.stamp;
  // Vertices (i, j), i in [0, width], j in [0, height], tile by tile.
  s.tiles_x = grid.width() / kTile + 1;
  s.tiles_y = grid.height() / kTile + 1;
  s.tile_begin.assign(static_cast<std::size_t>(s.tiles_x) * s.tiles_y + 1, 0);
  for (int ty = 0; ty < s.tiles_y; ++ty) {
    for (int tx = 0; tx < s.tiles_x; ++tx) {
      s.tile_begin[static_cast<std::size_t>(ty) * s.tiles_x + tx] = static_cast<int>(s.node.size());
      const int j_end = std::min(grid.height(), (ty + 1) * kTile);
      const int i_end = std::min(grid.width(), (tx + 1) * kTile);
      for (int j = std::max(1, ty * kTile); j < j_end; ++j) {
        // Padded indices of cells (i - 1, j - 1) and (i - 1, j) for i = 0.
        const int up = grid.index(0, j - 1) - 1;
        const int down = up + stride;
        for (int i = std::max(1, tx * kTile); i < i_end; ++i) {
          const int nw = up + i;
          const int ne = nw + 1;
          const int sw = down + i;
          const int se = sw + 1;
          const int bits =
              (occ[nw] != 0) | (occ[ne] != 0) << 1 | (occ[sw] != 0) << 2 | (occ[se] != 0) << 3;
          if (std::popcount(static_cast<unsigned>(bits)) == 1) {
            // The free cells around a single blocked one are edge-connected: test one of them.
            const int probe = bits == 1 ? se : nw;
            if (reached[probe] != gen) continue;
            const int bx = (bits == 2 || bits == 8) ? 1 : -1;
            const int by = (bits == 4 || bits == 8) ? 1 : -1;
            add({2 * i, 2 * j}, bx, by, false);
          } else if (allow && (bits == 0b1001 || bits == 0b0110)) {
            const int probe = bits == 0b1001 ? ne : nw;
            if (reached[probe] != gen) continue;
            add({2 * i, 2 * j}, bits == 0b1001 ? 1 : -1, 1, true);
          }
        }
      }
    }
  }
  s.tile_begin.back() = static_cast<int>(s.node.size());
}

// Lower bound of the distance from p to the points of tile (tx, ty)'s vertex box (doubled).
double distance_to_tile(HalfPoint p, int tx, int ty) {
  const int lo_x = 2 * tx * kTile;
  const int lo_y = 2 * ty * kTile;
  const int hi_x = lo_x + 2 * (kTile - 1);
  const int hi_y = lo_y + 2 * (kTile - 1);
  const double dx = p.x < lo_x ? lo_x - p.x : p.x > hi_x ? p.x - hi_x : 0;
  const double dy = p.y < lo_y ? lo_y - p.y : p.y > hi_y ? p.y - hi_y : 0;
  return std::sqrt(dx * dx + dy * dy);
}

// Largest a * out.x + b * out.y over the outs from p to tile (tx, ty)'s vertex box (doubled).
std::int64_t max_over_tile(std::int64_t a, std::int64_t b, HalfPoint p, int tx, int ty) {
  const int lo_x = 2 * tx * kTile - p.x;
  const int lo_y = 2 * ty * kTile - p.y;
  const int hi_x = lo_x + 2 * (kTile - 1);
  const int hi_y = lo_y + 2 * (kTile - 1);
  return a * (a > 0 ? hi_x : lo_x) + b * (b > 0 ? hi_y : lo_y);
}

// Whether some out from p into tile (tx, ty) could pass taut_around(bx, by, back, out). Its
// sign s is fixed by the back terms, and its out conditions are linear in out (the cross product
// strictly, the two quadrant edges not), so a tile where one of them fails at its best corner
// holds no node the expansion would relax: skipping it changes nothing but the time.
bool taut_cone_meets_tile(int bx, int by, HalfPoint back, HalfPoint p, int tx, int ty) {
  const std::int64_t back_k1 = -std::int64_t{back.y} * bx;
  const std::int64_t back_k2 = std::int64_t{back.x} * by;
  if (back_k1 == 0 && back_k2 == 0) return false;
  const std::int64_t s = back_k1 > 0 || back_k2 > 0 ? 1 : -1;
  if (s * back_k1 < 0 || s * back_k2 < 0) return false;
  return max_over_tile(-s * back.y, s * back.x, p, tx, ty) > 0 &&
         max_over_tile(0, s * bx, p, tx, ty) >= 0 && max_over_tile(-s * by, 0, p, tx, ty) >= 0;
}

void relax(int u, int w, HalfPoint pu, double gu, const Cells& cells, bool allow,
           AnyAngleScratch& s) {
  const double ng = gu + half_distance(pu, s.node[w]);
  if (ng >= s.g[w] || ng + s.h[w] >= s.g[kGoalNode] || ng + s.h[w] > s.upper) return;
  if (!visible(cells, pu, s.node[w], allow)) return;
  s.g[w] = ng;
  s.parent[w] = u;
  s.heap.push_back({ng + s.h[w], ng, w});
  std::push_heap(s.heap.begin(), s.heap.end(), scratch_heap_worse);
}

void expand(int u, const Cells& cells, bool allow, AnyAngleScratch& s) {
  const HalfPoint pu = s.node[u];
  const double gu = s.g[u];
  const bool bend = u >= kFirstBendNode;
  HalfPoint back;
  if (bend) back = {s.node[s.parent[u]].x - pu.x, s.node[s.parent[u]].y - pu.y};
  const int ubx = s.block_x[u];
  const int uby = s.block_y[u];
  const bool upinch = s.pinch[u] != 0;
  auto taut = [&](HalfPoint out) {
    return !bend || taut_around(ubx, uby, back, out) ||
           (upinch && taut_around(-ubx, -uby, back, out));
  };
  if (!s.closed[kGoalNode] && taut({s.node[kGoalNode].x - pu.x, s.node[kGoalNode].y - pu.y}))
    relax(u, kGoalNode, pu, gu, cells, allow, s);
  // A taut bend leaves on the far side of each axis through u from its parent (the blocked
  // quadrant's edges lie between the two segments): only the tiles on that side.
  int tx0 = 0;
  int tx1 = s.tiles_x - 1;
  int ty0 = 0;
  int ty1 = s.tiles_y - 1;
  if (bend) {
    const int tu_x = pu.x / 2 / kTile;
    const int tu_y = pu.y / 2 / kTile;
    if (back.x > 0) tx1 = tu_x;
    if (back.x < 0) tx0 = tu_x;
    if (back.y > 0) ty1 = tu_y;
    if (back.y < 0) ty0 = tu_y;
  }
  const HalfPoint goal = s.node[kGoalNode];
  for (int ty = ty0; ty <= ty1; ++ty) {
    for (int tx = tx0; tx <= tx1; ++tx) {
      const std::size_t t = static_cast<std::size_t>(ty) * s.tiles_x + tx;
      const int begin = s.tile_begin[t];
      const int end = s.tile_begin[t + 1];
      if (begin == end) continue;
      // No node of the tile can improve on the goal's cost so far.
      const double through = gu + distance_to_tile(pu, tx, ty) + distance_to_tile(goal, tx, ty);
      if (through >= s.g[kGoalNode] || through > s.upper) continue;
      if (bend && !taut_cone_meets_tile(ubx, uby, back, pu, tx, ty) &&
          !(upinch && taut_cone_meets_tile(-ubx, -uby, back, pu, tx, ty)))
        continue;
      for (int w = begin; w < end; ++w) {
        if (s.closed[w]) continue;
        const HalfPoint out{s.node[w].x - pu.x, s.node[w].y - pu.y};
        // The segment must neither leave w into its blocked quadrant (no bend there can be
        // taut) nor arrive through it (not visible); for a pinch, either of its two.
        const int ax = out.x * s.block_x[w];
        const int ay = out.y * s.block_y[w];
        if ((ax > 0 && ay > 0) || (ax < 0 && ay < 0)) continue;
        if (!taut(out)) continue;
        relax(u, w, pu, gu, cells, allow, s);
      }
    }
  }
}

std::optional<double> search(const Grid& grid, Cell start, Cell goal, CornerRule rule,
                             AnyAngleScratch& s, std::vector<Point>* vertices) {
  if (vertices != nullptr) vertices->clear();
  if (!grid.in_bounds(start) || !grid.in_bounds(goal) || grid.blocked(start) || grid.blocked(goal))
    return std::nullopt;
  if (start == goal) {
    if (vertices != nullptr) vertices->push_back(centre(start));
    return 0.0;
  }
  const bool allow = rule == CornerRule::allow;
  // Without pinch crossings, free space connects as the grid under no_squeeze (which also
  // connects like no_corner_cut); with them, as under allow.
  const CornerRule connectivity = allow ? CornerRule::allow : CornerRule::no_squeeze;
  const std::uint32_t gen = flood_fill(grid, grid.index(start), connectivity, s);
  if (s.component.stamp[grid.index(goal)] != gen) return std::nullopt;

  collect_nodes(grid, start, goal, allow, gen, s);
  // Worth its cost on maps with many bend points only (perf/README.md "Any-angle reference");
  // it prunes nodes whose f exceeds the optimum, so it never changes the result. The grid
  // optimum's rounding may differ from the search's in the last bits: a margin keeps an optimum
  // equal to it (a straight axis-parallel path) from being pruned.
  s.upper = kInfinity;
  if (s.node.size() > kUpperBoundNodes)
    s.upper = grid_upper_bound(grid, grid.index(start), grid.index(goal), connectivity, s) *
              (1 + kUpperMargin);
  const auto n = s.node.size();
  s.g.assign(n, kInfinity);
  s.h.resize(n);
  s.parent.assign(n, -1);
  s.closed.assign(n, 0);
  for (std::size_t k = 0; k < n; ++k) s.h[k] = half_distance(s.node[k], s.node[kGoalNode]);
  s.heap.clear();
  s.g[kStartNode] = 0.0;
  s.heap.push_back({s.h[kStartNode], 0.0, kStartNode});
  const Cells cells{grid.occupancy(), grid.stride()};
  while (!s.heap.empty()) {
    std::pop_heap(s.heap.begin(), s.heap.end(), scratch_heap_worse);
    const AnyAngleScratch::Entry e = s.heap.back();
    s.heap.pop_back();
    const int u = e.node;
    if (s.closed[u] || e.g > s.g[u]) continue;
    s.closed[u] = 1;
    if (u == kGoalNode) {
      if (vertices != nullptr) {
        for (int k = kGoalNode; k != -1; k = s.parent[k])
          vertices->push_back({s.node[k].x * 0.5, s.node[k].y * 0.5});
        std::reverse(vertices->begin(), vertices->end());
      }
      return s.g[kGoalNode] * 0.5;
    }
    expand(u, cells, allow, s);
  }
  // Unreachable: the visibility graph of a connected region connects its start and goal.
  return std::nullopt;
}

}  // namespace

std::optional<double> any_angle_length(const Grid& grid, Cell start, Cell goal, CornerRule rule,
                                       AnyAngleScratch& scratch) {
  return search(grid, start, goal, rule, scratch, nullptr);
}

std::optional<double> any_angle_path(const Grid& grid, Cell start, Cell goal, CornerRule rule,
                                     AnyAngleScratch& scratch, std::vector<Point>& vertices) {
  return search(grid, start, goal, rule, scratch, &vertices);
}

bool closure_visible(const Grid& grid, HalfPoint a, HalfPoint b, CornerRule rule) {
  return visible(Cells{grid.occupancy(), grid.stride()}, a, b, rule == CornerRule::allow);
}

int blocked_around_vertex(const Grid& grid, int i, int j) {
  return grid.blocked(i - 1, j - 1) + grid.blocked(i, j - 1) + grid.blocked(i - 1, j) +
         grid.blocked(i, j);
}

bool is_pinch_vertex(const Grid& grid, int i, int j) {
  return pinch_at(Cells{grid.occupancy(), grid.stride()}, i, j);
}

}  // namespace agv
