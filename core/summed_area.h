#pragma once
// Summed-area table of obstacle cells: the obstacle count of any axis-aligned rectangle in O(1)
// (paper 003 eq. 3's obstacle rate is queried once per scored node).

#include <cstdint>
#include <vector>

namespace agv {

class Grid;

class SummedAreaTable {
 public:
  explicit SummedAreaTable(const Grid& grid);
  // Obstacle cells in the inclusive rectangle spanned by two corner cells (any order),
  // clipped to the grid interior.
  std::int64_t obstacles(int x0, int y0, int x1, int y1) const;
  // Interior cells in the same clipped rectangle.
  std::int64_t cells(int x0, int y0, int x1, int y1) const;

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<std::int64_t> sums_;  // (width + 1) x (height + 1), sums_[0][*] = sums_[*][0] = 0
};

}  // namespace agv
