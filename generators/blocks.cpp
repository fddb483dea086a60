#include "generators/blocks.h"

// Repeat: draw a width and a height in [block_min, block_max], a top-left corner uniform in
// [-(w-1), W-1] x [-(h-1), H-1] (rectangles may hang over the edge and are clipped, so every cell
// is equally likely to be covered: no bias towards the middle); paint its cells row by row,
// skipping reserved cells, stopping the moment the count reaches T. So the count is exactly T
// and the last rectangle may be partial. Rectangles overlap freely. A safety cap on the number
// of rectangles (never reached below density ~0.999) finishes with uniform cells.

#include "core/input_error.h"

namespace agv {

const ParamDecls<BlocksOptions>& blocks_params() {
  static const ParamDecls<BlocksOptions> decls = [] {
    ParamDecls<BlocksOptions> d;
    d.integer("block_min", &BlocksOptions::block_min, 2, 1, kMaxMapSide,
              "smallest side of a rectangular obstacle, cells");
    d.integer("block_max", &BlocksOptions::block_max, 5, 1, kMaxMapSide,
              "largest side of a rectangular obstacle, cells (at least block_min)");
    return d;
  }();
  return decls;
}

void check_blocks(const BlocksOptions& o, int, int, const std::string& where) {
  if (o.block_max < o.block_min)
    throw InputError(where + ".block_max: " + std::to_string(o.block_max) +
                     " is smaller than block_min (" + std::to_string(o.block_min) + ")");
}

void generate_blocks(const BlocksOptions& o, MapContext& ctx) {
  Canvas& c = ctx.canvas;
  c.reset(ctx.width, ctx.height, false);
  const int width = ctx.width;
  const int height = ctx.height;
  const std::int64_t m = static_cast<std::int64_t>(width) * height - std::ssize(ctx.reserved);
  // Enough rectangles to cover every cell many times over (coupon collector: ln(8192^2) < 19);
  // reaching it means density ~1, where the remainder is filled uniformly.
  const std::int64_t max_rectangles =
      40 * m / (static_cast<std::int64_t>(o.block_min) * o.block_min) + 1000;
  for (std::int64_t n = 0; c.obstacles() < ctx.target && n < max_rectangles; ++n) {
    const int w = ctx.rng.between(o.block_min, o.block_max);
    const int h = ctx.rng.between(o.block_min, o.block_max);
    const int x0 = ctx.rng.between(-(w - 1), width - 1);
    const int y0 = ctx.rng.between(-(h - 1), height - 1);
    const int x_end = std::min(x0 + w, width);
    const int y_end = std::min(y0 + h, height);
    for (int y = std::max(y0, 0); y < y_end && c.obstacles() < ctx.target; ++y) {
      for (int x = std::max(x0, 0); x < x_end && c.obstacles() < ctx.target; ++x) {
        const int i = c.index(x, y);
        if (!ctx.is_reserved(i)) c.set_at(i, true);
      }
    }
  }
  add_clutter(ctx, [](int) { return false; });
}

}  // namespace agv
