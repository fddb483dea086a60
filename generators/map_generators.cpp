#include "generators/map_generators.h"

// The four generators and what `density` means for each. Common to all: the density base M is
// the number of cells that may hold obstacles (all W*H cells, minus the two reserved endpoint
// cells in `corners` mode) and the target obstacle count is T = round(density * M). Every random
// draw goes through Rng::below (no std:: distributions), so a spec and a seed give the same map
// on every machine and standard library.
//
// uniform  Exactly T obstacle cells, a uniform random T-subset of the M candidates (Floyd's
//          sampling: T draws, and the canvas itself is the membership set, so no index array).
// blocks   Workshop production areas (paper 002 section 5.1: "large in area and simple in
//          shape"). Repeat: draw a width and a height in [block_min, block_max], a top-left
//          corner uniform in [-(w-1), W-1] x [-(h-1), H-1] (rectangles may hang over the edge and
//          are clipped, so every cell is equally likely to be covered: no bias towards the
//          middle); paint its cells row by row, skipping reserved cells, stopping the moment the
//          count reaches T. So the count is exactly T and the last rectangle may be partial.
//          Rectangles overlap freely. A safety cap on the number of rectangles (never reached
//          below density ~0.999) finishes with uniform cells.
// maze     A perfect maze by randomized depth-first search on a lattice of `corridor`-wide
//          corridors separated by `corridor`-wide walls; the grid edge is the outer wall. The
//          lattice has nx = (W + corridor) / (2 corridor) columns of maze cells; the remainder
//          widens a few corridors by a cell (spread evenly), so the first and last corridors
//          touch the grid edges and the corner cells are always corridor cells. The perfect
//          maze's wall fraction w0 is about 0.47 for corridor 1 (a bit less where corridors were
//          widened). Density is the target obstacle fraction over the whole range:
//            T < walls: "braiding": closed wall segments between two maze cells are removed in
//                       random order (each adds a loop) while the obstacle count exceeds T; if
//                       all are gone and it still exceeds T, the wall pillars (the blocks where
//                       walls cross) are removed the same way. Density 0 is an empty grid.
//                       The count ends at most one segment (corridor^2 cells, a little more for
//                       a widened corridor) below T.
//            T > walls: clutter: T - walls extra obstacle cells, uniform over free non-reserved
//                       cells. With corridor 1 a perfect maze has one path between two cells,
//                       so clutter almost always disconnects it: above w0, expect
//                       require_solvable to fail.
// rooms    Rooms of room_size x room_size cells separated by one-cell walls (the grid edge is the
//          outer wall); nx = max(1, (W + 1) / (room_size + 1)) room columns (rows alike), the
//          remainder spread evenly as one extra cell for some rooms (a room_size wider than
//          the grid gives one room). Every
//          wall segment between two neighbouring rooms has one door of door_width cells (clamped
//          to the segment) at a uniform random offset. Density is the target obstacle fraction:
//            T < walls: whole wall segments (door and all, i.e. two rooms merge) are removed in
//                       random order while the count exceeds T, then wall junction cells, as for
//                       the maze. Density 0 is an empty grid.
//            T > walls: clutter inside the rooms: T - walls obstacle cells, uniform over free
//                       cells that are not reserved, not door cells and not 4-neighbours of a
//                       door cell (so a door is never sealed by clutter right behind it). If
//                       fewer candidates exist, all of them are filled (the fraction saturates).
//
// Endpoints: `corners` = (0, H-1) -> (W-1, 0), reserved free before the map is drawn.
// `random` = two distinct free cells drawn uniformly, redrawn (up to kEndpointTries pairs) until
// their centres are at least min_distance apart; a map where that fails counts as a rejection.
// require_solvable: a map whose endpoints do not connect under solvable_rule is rejected and a
// new one drawn from the same Rng; after max_attempts maps, std::runtime_error.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/connectivity.h"

namespace agv {
namespace {

constexpr int kMinSide = 2;
constexpr int kMaxSide = 8192;
constexpr int kEndpointTries = 1000;

template <class... Parts>
std::string cat(const Parts&... parts) {
  std::ostringstream out;
  (out << ... << parts);
  return out.str();
}

// The map under construction: a padded occupancy array in the Grid's layout (so the
// connectivity check runs on it directly) plus an obstacle count. Reused across attempts.
class Canvas {
 public:
  void reset(int width, int height, bool interior_blocked) {
    width_ = width;
    height_ = height;
    stride_ = width + 2;
    cells_.assign(static_cast<std::size_t>(stride_) * (height + 2), 1);
    if (!interior_blocked) {
      for (int y = 0; y < height; ++y) {
        std::fill_n(cells_.begin() + index(0, y), width, std::uint8_t{0});
      }
    }
    obstacles_ = interior_blocked ? static_cast<std::int64_t>(width) * height : 0;
  }
  int width() const { return width_; }
  int height() const { return height_; }
  int stride() const { return stride_; }
  int padded_size() const { return static_cast<int>(cells_.size()); }
  int index(int x, int y) const { return (y + 1) * stride_ + (x + 1); }
  bool blocked(int x, int y) const { return cells_[index(x, y)] != 0; }
  bool blocked_at(int i) const { return cells_[i] != 0; }
  void set_at(int i, bool blocked) {
    std::uint8_t& c = cells_[i];
    if ((c != 0) == blocked) return;
    c = blocked ? 1 : 0;
    obstacles_ += blocked ? 1 : -1;
  }
  void set(int x, int y, bool blocked) { set_at(index(x, y), blocked); }
  std::int64_t obstacles() const { return obstacles_; }
  const std::uint8_t* data() const { return cells_.data(); }

 private:
  int width_ = 0;
  int height_ = 0;
  int stride_ = 2;
  std::int64_t obstacles_ = 0;
  std::vector<std::uint8_t> cells_;
};

// What every generator needs besides the spec: the reserved endpoint cells (padded indices, or
// none in random mode), the target count and reusable buffers.
struct Context {
  const MapSpec& spec;
  Rng& rng;
  Canvas& canvas;
  std::vector<int> reserved;  // padded indices, ascending
  std::int64_t target = 0;    // T = round(density * M)
  std::vector<int>& pool;     // scratch index list
  bool is_reserved(int i) const {
    return std::find(reserved.begin(), reserved.end(), i) != reserved.end();
  }
};

void shuffle(std::vector<int>& v, Rng& rng) {
  for (std::size_t i = v.size(); i > 1; --i) {
    const std::size_t j = rng.below(static_cast<std::uint32_t>(i));
    std::swap(v[i - 1], v[j]);
  }
}

// Blocks `count` cells drawn uniformly without replacement from `candidates` (padded indices)
// by a partial Fisher-Yates shuffle; all of them if there are fewer.
void block_some(std::vector<int>& candidates, std::int64_t count, Context& ctx) {
  const std::size_t n = candidates.size();
  const std::size_t k = static_cast<std::size_t>(std::min<std::int64_t>(count, std::ssize(candidates)));
  for (std::size_t i = 0; i < k; ++i) {
    const std::size_t j = i + ctx.rng.below(static_cast<std::uint32_t>(n - i));
    std::swap(candidates[i], candidates[j]);
    ctx.canvas.set_at(candidates[i], true);
  }
}

// Clutter up to the target: uniform over free cells that are not reserved and not excluded.
template <class Excluded>
void add_clutter(Context& ctx, Excluded&& excluded) {
  const std::int64_t missing = ctx.target - ctx.canvas.obstacles();
  if (missing <= 0) return;
  auto& pool = ctx.pool;
  pool.clear();
  const Canvas& c = ctx.canvas;
  for (int y = 0; y < c.height(); ++y) {
    for (int x = 0; x < c.width(); ++x) {
      const int i = c.index(x, y);
      if (!c.blocked_at(i) && !ctx.is_reserved(i) && !excluded(i)) pool.push_back(i);
    }
  }
  block_some(pool, missing, ctx);
}

// ---- uniform ------------------------------------------------------------------------------

void generate_uniform(Context& ctx) {
  Canvas& c = ctx.canvas;
  c.reset(ctx.spec.width, ctx.spec.height, false);
  const std::int64_t m = static_cast<std::int64_t>(c.width()) * c.height() - std::ssize(ctx.reserved);
  // The k-th candidate, skipping reserved cells (reserved are in ascending padded order, which
  // is also ascending row-major order).
  std::vector<std::int64_t> reserved_rank;
  for (int r : ctx.reserved) {
    reserved_rank.push_back(static_cast<std::int64_t>(r / c.stride() - 1) * c.width() +
                            (r % c.stride() - 1));
  }
  auto candidate = [&](std::int64_t k) {
    for (std::int64_t r : reserved_rank) k += (k >= r) ? 1 : 0;
    return c.index(static_cast<int>(k % c.width()), static_cast<int>(k / c.width()));
  };
  // Floyd's algorithm: for j = M-T .. M-1 draw t in [0, j]; take t unless already taken, then j.
  for (std::int64_t j = m - ctx.target; j < m; ++j) {
    int i = candidate(ctx.rng.below(static_cast<std::uint32_t>(j + 1)));
    if (c.blocked_at(i)) i = candidate(j);
    c.set_at(i, true);
  }
}

// ---- blocks -------------------------------------------------------------------------------

void generate_blocks(Context& ctx) {
  const MapSpec& s = ctx.spec;
  Canvas& c = ctx.canvas;
  c.reset(s.width, s.height, false);
  const std::int64_t m = static_cast<std::int64_t>(s.width) * s.height - std::ssize(ctx.reserved);
  // Enough rectangles to cover every cell many times over (coupon collector: ln(8192^2) < 19);
  // reaching it means density ~1, where the remainder is filled uniformly.
  const std::int64_t max_rectangles =
      40 * m / (static_cast<std::int64_t>(s.block_min) * s.block_min) + 1000;
  for (std::int64_t n = 0; c.obstacles() < ctx.target && n < max_rectangles; ++n) {
    const int w = ctx.rng.between(s.block_min, s.block_max);
    const int h = ctx.rng.between(s.block_min, s.block_max);
    const int x0 = ctx.rng.between(-(w - 1), s.width - 1);
    const int y0 = ctx.rng.between(-(h - 1), s.height - 1);
    const int x_end = std::min(x0 + w, s.width);
    const int y_end = std::min(y0 + h, s.height);
    for (int y = std::max(y0, 0); y < y_end && c.obstacles() < ctx.target; ++y) {
      for (int x = std::max(x0, 0); x < x_end && c.obstacles() < ctx.target; ++x) {
        const int i = c.index(x, y);
        if (!ctx.is_reserved(i)) c.set_at(i, true);
      }
    }
  }
  add_clutter(ctx, [](int) { return false; });
}

// ---- shared by maze and rooms -------------------------------------------------------------

// An axis-aligned cell rectangle [x0, x1) x [y0, y1).
struct Rect {
  int x0, y0, x1, y1;
};

void fill(Canvas& c, const Rect& r, bool blocked) {
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) c.set(x, y, blocked);
  }
}

// Opens the given wall pieces in random order while the obstacle count exceeds the target.
void remove_while_above(std::vector<Rect>& pieces, Context& ctx) {
  std::vector<int>& order = ctx.pool;
  order.resize(pieces.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  shuffle(order, ctx.rng);
  for (int i : order) {
    if (ctx.canvas.obstacles() <= ctx.target) break;
    fill(ctx.canvas, pieces[i], false);
  }
}

// Splits [0, size) into `n` spans of about `span` cells separated by gaps of `gap` cells, the
// first span starting at 0 and the last ending at size. The remainder r is spread Bresenham-style
// (span i gets floor((i+1) r / n) - floor(i r / n) extra cells), so no span is much wider than
// the others. Span i is [starts[i], starts[i + 1] - gap).
std::vector<int> span_starts(int size, int n, int span, int gap) {
  const std::int64_t r = size - (std::int64_t{n} * span + std::int64_t{n - 1} * gap);
  std::vector<int> starts(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) starts[i] = static_cast<int>(i * std::int64_t{span + gap} + i * r / n);
  return starts;
}

// ---- maze ---------------------------------------------------------------------------------

void generate_maze(Context& ctx) {
  const MapSpec& s = ctx.spec;
  Canvas& c = ctx.canvas;
  c.reset(s.width, s.height, true);
  const int k = s.corridor;
  const int nx = (s.width + k) / (2 * k);
  const int ny = (s.height + k) / (2 * k);
  const std::vector<int> xs = span_starts(s.width, nx, k, k);
  const std::vector<int> ys = span_starts(s.height, ny, k, k);
  auto room = [&](int i, int j) { return Rect{xs[i], ys[j], xs[i + 1] - k, ys[j + 1] - k}; };
  // The wall between maze cell (i, j) and its east (d = 0) or south (d = 1) neighbour.
  auto wall = [&](int i, int j, int d) {
    const Rect r = room(i, j);
    return d == 0 ? Rect{r.x1, r.y0, r.x1 + k, r.y1} : Rect{r.x0, r.y1, r.x1, r.y1 + k};
  };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) fill(c, room(i, j), false);
  }

  // Randomized depth-first search (iterative): from the cell on top of the stack, step to a
  // uniformly chosen unvisited neighbour, opening the wall between; pop when there is none.
  const int n = nx * ny;
  std::vector<std::uint8_t> visited(static_cast<std::size_t>(n), 0);
  std::vector<std::uint8_t> open_east(static_cast<std::size_t>(n), 0);
  std::vector<std::uint8_t> open_south(static_cast<std::size_t>(n), 0);
  std::vector<int> stack;
  stack.reserve(static_cast<std::size_t>(n));
  const int first = static_cast<int>(ctx.rng.below(static_cast<std::uint32_t>(n)));
  visited[first] = 1;
  stack.push_back(first);
  while (!stack.empty()) {
    const int cur = stack.back();
    const int i = cur % nx;
    const int j = cur / nx;
    std::array<int, 4> next{};  // neighbour id * 4 + direction (0 E, 1 S, 2 W, 3 N)
    int count = 0;
    if (i + 1 < nx && !visited[cur + 1]) next[count++] = (cur + 1) * 4 + 0;
    if (j + 1 < ny && !visited[cur + nx]) next[count++] = (cur + nx) * 4 + 1;
    if (i > 0 && !visited[cur - 1]) next[count++] = (cur - 1) * 4 + 2;
    if (j > 0 && !visited[cur - nx]) next[count++] = (cur - nx) * 4 + 3;
    if (count == 0) {
      stack.pop_back();
      continue;
    }
    const int pick = next[ctx.rng.below(static_cast<std::uint32_t>(count))];
    const int to = pick / 4;
    const int dir = pick % 4;
    // Walls are stored at the west / north cell of the pair.
    const int lo = (dir == 0 || dir == 1) ? cur : to;
    if (dir == 0 || dir == 2) {
      open_east[lo] = 1;
      fill(c, wall(lo % nx, lo / nx, 0), false);
    } else {
      open_south[lo] = 1;
      fill(c, wall(lo % nx, lo / nx, 1), false);
    }
    visited[to] = 1;
    stack.push_back(to);
  }

  if (c.obstacles() > ctx.target) {
    std::vector<Rect> closed;
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const int id = j * nx + i;
        if (i + 1 < nx && !open_east[id]) closed.push_back(wall(i, j, 0));
        if (j + 1 < ny && !open_south[id]) closed.push_back(wall(i, j, 1));
      }
    }
    remove_while_above(closed, ctx);
    std::vector<Rect> pillars;
    for (int j = 0; j + 1 < ny; ++j) {
      for (int i = 0; i + 1 < nx; ++i) {
        const Rect r = room(i, j);
        pillars.push_back({r.x1, r.y1, r.x1 + k, r.y1 + k});
      }
    }
    remove_while_above(pillars, ctx);
  }
  add_clutter(ctx, [](int) { return false; });
}

// ---- rooms --------------------------------------------------------------------------------

void generate_rooms(Context& ctx) {
  const MapSpec& s = ctx.spec;
  Canvas& c = ctx.canvas;
  c.reset(s.width, s.height, false);
  const int side = s.room_size;
  const int nx = std::max(1, (s.width + 1) / (side + 1));
  const int ny = std::max(1, (s.height + 1) / (side + 1));
  const std::vector<int> xs = span_starts(s.width, nx, side, 1);
  const std::vector<int> ys = span_starts(s.height, ny, side, 1);

  // Wall segments (between two rooms, door cut out) and junction cells.
  std::vector<Rect> segments;
  std::vector<std::uint8_t> door(static_cast<std::size_t>(c.padded_size()), 0);
  auto add_segment = [&](Rect r, bool vertical) {
    fill(c, r, true);
    const int length = vertical ? r.y1 - r.y0 : r.x1 - r.x0;
    const int width = std::min(s.door_width, length);
    const int offset = ctx.rng.between(0, length - width);
    for (int t = offset; t < offset + width; ++t) {
      const int x = vertical ? r.x0 : r.x0 + t;
      const int y = vertical ? r.y0 + t : r.y0;
      c.set(x, y, false);
      door[c.index(x, y)] = 1;
    }
    segments.push_back(r);
  };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int x1 = xs[i + 1] - 1;  // end of room (i, j), exclusive: the wall column
      const int y1 = ys[j + 1] - 1;
      if (i + 1 < nx) add_segment({x1, ys[j], x1 + 1, y1}, true);
      if (j + 1 < ny) add_segment({xs[i], y1, x1, y1 + 1}, false);
    }
  }
  std::vector<Rect> junctions;
  for (int j = 0; j + 1 < ny; ++j) {
    for (int i = 0; i + 1 < nx; ++i) {
      const Rect r{xs[i + 1] - 1, ys[j + 1] - 1, xs[i + 1], ys[j + 1]};
      fill(c, r, true);
      junctions.push_back(r);
    }
  }

  if (c.obstacles() > ctx.target) {
    remove_while_above(segments, ctx);
    remove_while_above(junctions, ctx);
    return;
  }
  const int stride = c.stride();
  add_clutter(ctx, [&](int i) {
    return door[i] || door[i - 1] || door[i + 1] || door[i - stride] || door[i + stride];
  });
}

// ---- endpoints and the driver -------------------------------------------------------------

void validate(const MapSpec& s) {
  const auto& names = generator_names();
  if (std::find(names.begin(), names.end(), s.generator) == names.end()) {
    throw std::invalid_argument(
        cat("generator: '", s.generator, "' is not one of uniform, blocks, maze, rooms"));
  }
  if (s.width < kMinSide || s.width > kMaxSide) {
    throw std::invalid_argument(cat("width: ", s.width, " is outside [2, 8192]"));
  }
  if (s.height < kMinSide || s.height > kMaxSide) {
    throw std::invalid_argument(cat("height: ", s.height, " is outside [2, 8192]"));
  }
  if (!(s.density >= 0.0 && s.density < 1.0)) {
    throw std::invalid_argument(cat("density: ", s.density, " is outside [0, 1)"));
  }
  if (!(s.cell_edge > 0.0 && std::isfinite(s.cell_edge))) {
    throw std::invalid_argument(cat("cell_edge: ", s.cell_edge, " must be positive and finite"));
  }
  const double diagonal = std::hypot(s.width - 1.0, s.height - 1.0);
  if (!(s.min_distance >= 0.0 && s.min_distance <= diagonal)) {
    throw std::invalid_argument(cat("min_distance: ", s.min_distance, " is outside [0, ",
                                    diagonal, "] (the ", s.width, "x", s.height,
                                    " grid's corner-to-corner distance)"));
  }
  if (s.max_attempts < 1) {
    throw std::invalid_argument(cat("max_attempts: ", s.max_attempts, " must be at least 1"));
  }
  if (s.block_min < 1) {
    throw std::invalid_argument(cat("block_min: ", s.block_min, " must be at least 1"));
  }
  if (s.block_max < s.block_min) {
    throw std::invalid_argument(
        cat("block_max: ", s.block_max, " is smaller than block_min (", s.block_min, ")"));
  }
  if (s.block_max > kMaxSide) {
    throw std::invalid_argument(cat("block_max: ", s.block_max, " exceeds 8192"));
  }
  const int short_side = std::min(s.width, s.height);
  if (s.corridor < 1 || s.corridor > short_side) {
    throw std::invalid_argument(
        cat("corridor: ", s.corridor, " is outside [1, ", short_side, "] (the shorter side)"));
  }
  if (s.room_size < 1 || s.room_size > kMaxSide) {
    throw std::invalid_argument(cat("room_size: ", s.room_size, " is outside [1, 8192]"));
  }
  if (s.door_width < 1 || s.door_width > kMaxSide) {
    throw std::invalid_argument(cat("door_width: ", s.door_width, " is outside [1, 8192]"));
  }
}

// Two distinct free cells with centres at least min_distance apart, or false.
bool draw_random_endpoints(Context& ctx, Cell& start, Cell& goal) {
  const Canvas& c = ctx.canvas;
  auto& free = ctx.pool;
  free.clear();
  for (int y = 0; y < c.height(); ++y) {
    for (int x = 0; x < c.width(); ++x) {
      if (!c.blocked(x, y)) free.push_back(y * c.width() + x);
    }
  }
  if (free.size() < 2) return false;
  const double min_sq = ctx.spec.min_distance * ctx.spec.min_distance;
  const auto n = static_cast<std::uint32_t>(free.size());
  for (int t = 0; t < kEndpointTries; ++t) {
    const int a = free[ctx.rng.below(n)];
    const int b = free[ctx.rng.below(n)];
    if (a == b) continue;
    const std::int64_t dx = a % c.width() - b % c.width();
    const std::int64_t dy = a / c.width() - b / c.width();
    if (static_cast<double>(dx * dx + dy * dy) >= min_sq) {
      start = {a % c.width(), a / c.width()};
      goal = {b % c.width(), b / c.width()};
      return true;
    }
  }
  return false;
}

void generate(Context& ctx) {
  const std::string& g = ctx.spec.generator;
  if (g == "uniform") {
    generate_uniform(ctx);
  } else if (g == "blocks") {
    generate_blocks(ctx);
  } else if (g == "maze") {
    generate_maze(ctx);
  } else {
    generate_rooms(ctx);
  }
}

}  // namespace

const std::vector<std::string>& generator_names() {
  static const std::vector<std::string> names = {"uniform", "blocks", "maze", "rooms"};
  return names;
}

MapInstance make_map(const MapSpec& spec, Rng& rng) {
  validate(spec);
  Canvas canvas;
  canvas.reset(spec.width, spec.height, false);
  std::vector<int> pool;
  Context ctx{spec, rng, canvas, {}, 0, pool};
  const Cell corner_start{0, spec.height - 1};
  const Cell corner_goal{spec.width - 1, 0};
  const bool corners = spec.endpoints == EndpointMode::corners;
  if (corners) {
    ctx.reserved = {canvas.index(corner_goal.x, corner_goal.y),
                    canvas.index(corner_start.x, corner_start.y)};  // ascending
  }
  const std::int64_t m =
      static_cast<std::int64_t>(spec.width) * spec.height - std::ssize(ctx.reserved);
  ctx.target = std::llround(spec.density * static_cast<double>(m));

  ConnectivityScratch scratch;
  bool endpoints_failed = false;
  for (int attempt = 0; attempt < spec.max_attempts; ++attempt) {
    generate(ctx);
    Cell start = corner_start;
    Cell goal = corner_goal;
    if (!corners && !draw_random_endpoints(ctx, start, goal)) {
      endpoints_failed = true;
      continue;
    }
    endpoints_failed = false;
    if (spec.require_solvable &&
        !connected(canvas.data(), canvas.stride(), canvas.padded_size(),
                   canvas.index(start.x, start.y), canvas.index(goal.x, goal.y),
                   spec.solvable_rule, scratch)) {
      continue;
    }
    MapInstance out{Grid(spec.width, spec.height, spec.cell_edge), start, goal, attempt};
    for (int y = 0; y < spec.height; ++y) {
      for (int x = 0; x < spec.width; ++x) {
        if (canvas.blocked(x, y)) out.grid.set_blocked(x, y, true);
      }
    }
    return out;
  }
  const std::string what = cat(spec.generator, " ", spec.width, "x", spec.height, " at density ",
                               spec.density);
  if (endpoints_failed) {
    throw std::runtime_error(cat("random endpoints: no two free cells min_distance = ",
                                 spec.min_distance, " apart found on ", spec.max_attempts,
                                 " maps (", what, ")"));
  }
  throw std::runtime_error(cat("require_solvable: start and goal not connected under ",
                               to_string(spec.solvable_rule), " in ", spec.max_attempts,
                               " maps (", what, ")"));
}

}  // namespace agv
