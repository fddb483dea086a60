#pragma once
// The occupancy of every padded cell's 3x3 block as one bit mask: what a clearance test within
// one cell of a point needs, in one load instead of nine (algos/local/dwa.cpp's rollouts test
// some 4,000 points per control step). A read-only companion of the grid (Grid::cell_blocks()).

#include <cstdint>
#include <vector>

namespace agv {

class Grid;

enum CellBlockBit : std::uint32_t {
  kBlockLeft = 1u << 0,
  kBlockRight = 1u << 1,
  kBlockUp = 1u << 2,  // row y - 1
  kBlockDown = 1u << 3,
  kBlockUpLeft = 1u << 4,
  kBlockUpRight = 1u << 5,
  kBlockDownLeft = 1u << 6,
  kBlockDownRight = 1u << 7,
  kBlockCentre = 1u << 8,
};

class CellBlocks {
 public:
  explicit CellBlocks(const Grid& grid);
  // Indexed as Grid::occupancy() (Grid::index); neighbours beyond the padded array count as
  // blocked (only border-ring cells have such, and those are blocked themselves).
  const std::uint32_t* masks() const { return masks_.data(); }

 private:
  std::vector<std::uint32_t> masks_;
};

}  // namespace agv
