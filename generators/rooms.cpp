#include "generators/rooms.h"

// Rooms of room_size x room_size cells separated by one-cell walls (the grid edge is the outer
// wall); nx = max(1, (W + 1) / (room_size + 1)) room columns (rows alike), the remainder spread
// evenly as one extra cell for some rooms (a room_size wider than the grid gives one room).
// Every wall segment between two neighbouring rooms has one door of door_width cells (clamped to
// the segment) at a uniform random offset. Density is the target obstacle fraction:
//   T < walls: whole wall segments (door and all, i.e. two rooms merge) are removed in random
//              order while the count exceeds T, then wall junction cells, as for the maze.
//              Density 0 is an empty grid.
//   T > walls: clutter inside the rooms: T - walls obstacle cells, uniform over free cells that
//              are not reserved, not door cells and not 4-neighbours of a door cell (so a door is
//              never sealed by clutter right behind it). If fewer candidates exist, all of them
//              are filled (the fraction saturates).

namespace agv {

const ParamDecls<RoomsOptions>& rooms_params() {
  // room_size starts at 2: a one-cell "room" is a lattice of wall pillars, not rooms.
  static const ParamDecls<RoomsOptions> decls = [] {
    ParamDecls<RoomsOptions> d;
    d.integer("room_size", &RoomsOptions::room_size, 8, 2, kMaxMapSide,
              "room side, cells (wider than the grid: one room)");
    d.integer("door_width", &RoomsOptions::door_width, 2, 1, kMaxMapSide,
              "door width, cells (clamped to the wall segment)");
    return d;
  }();
  return decls;
}

void generate_rooms(const RoomsOptions& o, MapContext& ctx) {
  Canvas& c = ctx.canvas;
  c.reset(ctx.width, ctx.height, false);
  const int side = o.room_size;
  const int nx = std::max(1, (ctx.width + 1) / (side + 1));
  const int ny = std::max(1, (ctx.height + 1) / (side + 1));
  const std::vector<int> xs = span_starts(ctx.width, nx, side, 1);
  const std::vector<int> ys = span_starts(ctx.height, ny, side, 1);

  // Wall segments (between two rooms, door cut out) and junction cells.
  std::vector<Rect> segments;
  std::vector<std::uint8_t> door(static_cast<std::size_t>(c.padded_size()), 0);
  auto add_segment = [&](Rect r, bool vertical) {
    fill(c, r, true);
    const int length = vertical ? r.y1 - r.y0 : r.x1 - r.x0;
    const int width = std::min(o.door_width, length);
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

}  // namespace agv
