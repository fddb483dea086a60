#include "core/grid.h"

#include <stdexcept>

#include "core/cell_blocks.h"
#include "core/distance_transform.h"
#include "core/summed_area.h"

namespace agv {

struct Grid::Companions {
  std::once_flag dt_once;
  std::unique_ptr<DistanceTransform> dt;
  std::once_flag sat_once;
  std::unique_ptr<SummedAreaTable> sat;
  std::once_flag blocks_once;
  std::unique_ptr<CellBlocks> blocks;
};

Grid::Grid() : companions_(std::make_unique<Companions>()) {
  occupancy_.assign(4, 1);
  bits_.assign(2, 0b11);
}

Grid::Grid(int width, int height, double cell_edge)
    : width_(width),
      height_(height),
      stride_(width + 2),
      words_per_row_((width + 2 + 63) / 64),
      cell_edge_(cell_edge),
      companions_(std::make_unique<Companions>()) {
  if (width < 1 || height < 1) throw std::invalid_argument("grid size must be at least 1x1");
  if (!(cell_edge > 0.0)) throw std::invalid_argument("cell edge must be positive");
  occupancy_.assign(static_cast<std::size_t>(padded_size()), 0);
  bits_.assign(static_cast<std::size_t>(words_per_row_) * (height + 2), 0);
  auto set_raw = [this](int x, int y) {
    occupancy_[index(x, y)] = 1;
    const int bit = x + 1;
    bits_[static_cast<std::size_t>(y + 1) * words_per_row_ + bit / 64] |= std::uint64_t{1}
                                                                          << (bit % 64);
  };
  for (int x = -1; x <= width; ++x) {
    set_raw(x, -1);
    set_raw(x, height);
  }
  for (int y = 0; y < height; ++y) {
    set_raw(-1, y);
    set_raw(width, y);
  }
}

Grid::Grid(const Grid& other)
    : width_(other.width_),
      height_(other.height_),
      stride_(other.stride_),
      words_per_row_(other.words_per_row_),
      cell_edge_(other.cell_edge_),
      obstacles_(other.obstacles_),
      occupancy_(other.occupancy_),
      bits_(other.bits_),
      companions_(std::make_unique<Companions>()) {}

Grid& Grid::operator=(const Grid& other) {
  if (this != &other) {
    Grid copy(other);
    *this = std::move(copy);
  }
  return *this;
}

Grid::Grid(Grid&&) noexcept = default;
Grid& Grid::operator=(Grid&&) noexcept = default;
Grid::~Grid() = default;

void Grid::set_blocked(int x, int y, bool blocked) {
  if (!in_bounds(x, y)) throw std::out_of_range("set_blocked outside the grid");
  std::uint8_t& cell = occupancy_[index(x, y)];
  if ((cell != 0) == blocked) return;
  cell = blocked ? 1 : 0;
  obstacles_ += blocked ? 1 : -1;
  const int bit = x + 1;
  std::uint64_t& word = bits_[static_cast<std::size_t>(y + 1) * words_per_row_ + bit / 64];
  const std::uint64_t mask = std::uint64_t{1} << (bit % 64);
  word = blocked ? (word | mask) : (word & ~mask);
  companions_ = std::make_unique<Companions>();
}

const DistanceTransform& Grid::distance_transform() const {
  std::call_once(companions_->dt_once,
                 [this] { companions_->dt = std::make_unique<DistanceTransform>(*this); });
  return *companions_->dt;
}

const SummedAreaTable& Grid::summed_area() const {
  std::call_once(companions_->sat_once,
                 [this] { companions_->sat = std::make_unique<SummedAreaTable>(*this); });
  return *companions_->sat;
}

const CellBlocks& Grid::cell_blocks() const {
  std::call_once(companions_->blocks_once,
                 [this] { companions_->blocks = std::make_unique<CellBlocks>(*this); });
  return *companions_->blocks;
}

bool Grid::same_cells(const Grid& other) const {
  return width_ == other.width_ && height_ == other.height_ && cell_edge_ == other.cell_edge_ &&
         occupancy_ == other.occupancy_;
}

}  // namespace agv
