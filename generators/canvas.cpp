#include "generators/canvas.h"

#include <utility>

namespace agv {

void Canvas::reset(int width, int height, bool interior_blocked) {
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

void shuffle(std::vector<int>& v, Rng& rng) {
  for (std::size_t i = v.size(); i > 1; --i) {
    const std::size_t j = rng.below(static_cast<std::uint32_t>(i));
    std::swap(v[i - 1], v[j]);
  }
}

void block_some(std::vector<int>& candidates, std::int64_t count, MapContext& ctx) {
  const std::size_t n = candidates.size();
  const std::size_t k =
      static_cast<std::size_t>(std::min<std::int64_t>(count, std::ssize(candidates)));
  for (std::size_t i = 0; i < k; ++i) {
    const std::size_t j = i + ctx.rng.below(static_cast<std::uint32_t>(n - i));
    std::swap(candidates[i], candidates[j]);
    ctx.canvas.set_at(candidates[i], true);
  }
}

void fill(Canvas& c, const Rect& r, bool blocked) {
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) c.set(x, y, blocked);
  }
}

void remove_while_above(std::vector<Rect>& pieces, MapContext& ctx) {
  std::vector<int>& order = ctx.pool;
  order.resize(pieces.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  shuffle(order, ctx.rng);
  for (int i : order) {
    if (ctx.canvas.obstacles() <= ctx.target) break;
    fill(ctx.canvas, pieces[i], false);
  }
}

std::vector<int> span_starts(int size, int n, int span, int gap) {
  const std::int64_t r = size - (std::int64_t{n} * span + std::int64_t{n - 1} * gap);
  std::vector<int> starts(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i)
    starts[i] = static_cast<int>(i * std::int64_t{span + gap} + i * r / n);
  return starts;
}

}  // namespace agv
