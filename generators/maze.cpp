#include "generators/maze.h"

// A perfect maze by randomized depth-first search on a lattice of `corridor`-wide corridors
// separated by `corridor`-wide walls; the grid edge is the outer wall. The lattice has
// nx = (W + corridor) / (2 corridor) columns of maze cells; the remainder widens a few corridors
// by a cell (spread evenly), so the first and last corridors touch the grid edges and the corner
// cells are always corridor cells. The perfect maze's wall fraction w0 is about 0.47 for
// corridor 1 (a bit less where corridors were widened). Density is the target obstacle fraction
// over the whole range:
//   T < walls: "braiding": closed wall segments between two maze cells are removed in random
//              order (each adds a loop) while the obstacle count exceeds T; if all are gone and
//              it still exceeds T, the wall pillars (the blocks where walls cross) are removed
//              the same way. Density 0 is an empty grid. The count ends at most one segment
//              (corridor^2 cells, a little more for a widened corridor) below T.
//   T > walls: clutter: T - walls extra obstacle cells, uniform over free non-reserved cells.
//              With corridor 1 a perfect maze has one path between two cells, so clutter almost
//              always disconnects it: above w0, expect require_solvable to fail.

#include <array>

#include "core/input_error.h"

namespace agv {

const ParamDecls<MazeOptions>& maze_params() {
  static const ParamDecls<MazeOptions> decls = [] {
    ParamDecls<MazeOptions> d;
    d.integer("corridor", &MazeOptions::corridor, 1, 1, kMaxMapSide,
              "corridor and wall width, cells (at most the grid's shorter side)");
    return d;
  }();
  return decls;
}

void check_maze(const MazeOptions& o, int width, int height, const std::string& where) {
  const int short_side = std::min(width, height);
  if (o.corridor > short_side)
    throw InputError(where + ".corridor: " + std::to_string(o.corridor) + " is outside [1, " +
                     std::to_string(short_side) + "] (the shorter side of " +
                     std::to_string(width) + "x" + std::to_string(height) + ")");
}

void generate_maze(const MazeOptions& o, MapContext& ctx) {
  Canvas& c = ctx.canvas;
  c.reset(ctx.width, ctx.height, true);
  const int k = o.corridor;
  const int nx = (ctx.width + k) / (2 * k);
  const int ny = (ctx.height + k) / (2 * k);
  const std::vector<int> xs = span_starts(ctx.width, nx, k, k);
  const std::vector<int> ys = span_starts(ctx.height, ny, k, k);
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

}  // namespace agv
