#include "core/cell_blocks.h"

#include "core/grid.h"

namespace agv {

CellBlocks::CellBlocks(const Grid& grid) {
  const int stride = grid.stride(), rows = grid.height() + 2;
  const std::uint8_t* occ = grid.occupancy();
  masks_.assign(static_cast<std::size_t>(grid.padded_size()), 0);
  auto at = [&](int col, int row) {
    return col < 0 || row < 0 || col >= stride || row >= rows || occ[row * stride + col] != 0;
  };
  for (int row = 0; row < rows; ++row)
    for (int col = 0; col < stride; ++col) {
      auto bit = [&](int dc, int dr, CellBlockBit b) {
        return at(col + dc, row + dr) ? static_cast<std::uint32_t>(b) : std::uint32_t{0};
      };
      masks_[static_cast<std::size_t>(row * stride + col)] = static_cast<std::uint32_t>(
          bit(-1, 0, kBlockLeft) | bit(1, 0, kBlockRight) | bit(0, -1, kBlockUp) |
          bit(0, 1, kBlockDown) | bit(-1, -1, kBlockUpLeft) | bit(1, -1, kBlockUpRight) |
          bit(-1, 1, kBlockDownLeft) | bit(1, 1, kBlockDownRight) | bit(0, 0, kBlockCentre));
    }
}

}  // namespace agv
