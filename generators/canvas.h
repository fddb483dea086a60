#pragma once
// What the map generators share: the map under construction (a padded occupancy array in the
// Grid's layout, so the connectivity check runs on it directly), the context of one draw (the
// reserved endpoint cells and the target obstacle count) and the random helpers built on
// Rng::below (no std:: distributions, so a spec and a seed give the same map on every machine).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/grid.h"
#include "core/rng.h"

namespace agv {

class Canvas {
 public:
  void reset(int width, int height, bool interior_blocked);
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

// One draw: the grid size, the reserved endpoint cells (padded indices, or none in random
// mode), the target count T = round(density * M) and reusable buffers. Each generator resets
// the canvas to width x height and paints it.
struct MapContext {
  int width = 0;
  int height = 0;
  Rng& rng;
  Canvas& canvas;
  std::vector<int> reserved;  // padded indices, ascending
  std::int64_t target = 0;
  std::vector<int>& pool;  // scratch index list
  bool is_reserved(int i) const {
    return std::find(reserved.begin(), reserved.end(), i) != reserved.end();
  }
};

// Fisher-Yates over Rng::below.
void shuffle(std::vector<int>& v, Rng& rng);

// Blocks `count` cells drawn uniformly without replacement from `candidates` (padded indices)
// by a partial Fisher-Yates shuffle; all of them if there are fewer.
void block_some(std::vector<int>& candidates, std::int64_t count, MapContext& ctx);

// Clutter up to the target: uniform over free cells that are not reserved and not excluded.
template <class Excluded>
void add_clutter(MapContext& ctx, Excluded&& excluded) {
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

// An axis-aligned cell rectangle [x0, x1) x [y0, y1).
struct Rect {
  int x0, y0, x1, y1;
};

void fill(Canvas& c, const Rect& r, bool blocked);

// Opens the given wall pieces in random order while the obstacle count exceeds the target.
void remove_while_above(std::vector<Rect>& pieces, MapContext& ctx);

// Splits [0, size) into `n` spans of about `span` cells separated by gaps of `gap` cells, the
// first span starting at 0 and the last ending at size. The remainder r is spread Bresenham-style
// (span i gets floor((i+1) r / n) - floor(i r / n) extra cells), so no span is much wider than
// the others. Span i is [starts[i], starts[i + 1] - gap).
std::vector<int> span_starts(int size, int n, int span, int gap);

}  // namespace agv
