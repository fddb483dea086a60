#include "core/summed_area.h"

#include <algorithm>

#include "core/grid.h"

namespace agv {

SummedAreaTable::SummedAreaTable(const Grid& grid)
    : width_(grid.width()),
      height_(grid.height()),
      sums_(static_cast<std::size_t>(grid.width() + 1) * (grid.height() + 1), 0) {
  const int w1 = width_ + 1;
  for (int y = 0; y < height_; ++y) {
    std::int64_t row = 0;
    for (int x = 0; x < width_; ++x) {
      row += grid.blocked(x, y) ? 1 : 0;
      sums_[static_cast<std::size_t>(y + 1) * w1 + x + 1] =
          sums_[static_cast<std::size_t>(y) * w1 + x + 1] + row;
    }
  }
}

std::int64_t SummedAreaTable::obstacles(int x0, int y0, int x1, int y1) const {
  if (x0 > x1) std::swap(x0, x1);
  if (y0 > y1) std::swap(y0, y1);
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, width_ - 1);
  y1 = std::min(y1, height_ - 1);
  if (x0 > x1 || y0 > y1) return 0;
  const std::size_t w1 = static_cast<std::size_t>(width_) + 1;
  auto at = [&](int x, int y) { return sums_[static_cast<std::size_t>(y) * w1 + x]; };
  return at(x1 + 1, y1 + 1) - at(x0, y1 + 1) - at(x1 + 1, y0) + at(x0, y0);
}

std::int64_t SummedAreaTable::cells(int x0, int y0, int x1, int y1) const {
  if (x0 > x1) std::swap(x0, x1);
  if (y0 > y1) std::swap(y0, y1);
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, width_ - 1);
  y1 = std::min(y1, height_ - 1);
  if (x0 > x1 || y0 > y1) return 0;
  return static_cast<std::int64_t>(x1 - x0 + 1) * (y1 - y0 + 1);
}

}  // namespace agv
