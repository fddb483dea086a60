#pragma once
// The grid every planner, generator and metric works on: a flat row-major occupancy array with
// a one-cell obstacle border (neighbour loops never bounds-check), a bit-packed copy of the same
// padded rows for word-parallel line-of-sight tests, and lazily built read-only companions.
//
// Coordinates: cell (x, y), x in [0, width), y in [0, height); y = 0 is the TOP row (MovingAI
// and image convention). Continuous coordinates put cell (x, y)'s centre at (x + 0.5, y + 0.5),
// in cells; multiply by cell_edge() for metres.

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace agv {

// The one map size limit: the largest side of any map agvbench generates or reads (generated
// maps, MovingAI files, occupancy images), and the cap of every shape parameter's range (a room
// or block wider than any grid changes nothing). 8192^2 cells are 64 MiB of occupancy.
inline constexpr int kMaxMapSide = 8192;

struct Cell {
  int x = 0;
  int y = 0;
  friend bool operator==(const Cell&, const Cell&) = default;
};

struct Point {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const Point&, const Point&) = default;
};

inline Point centre(Cell c) { return {c.x + 0.5, c.y + 0.5}; }

class DistanceTransform;
class SummedAreaTable;
class CellBlocks;

class Grid {
 public:
  Grid();
  // All interior cells free, border blocked.
  Grid(int width, int height, double cell_edge = 1.0);
  Grid(const Grid& other);
  Grid& operator=(const Grid& other);
  // Defined in grid.cpp, where Companions is complete (an inline default needs its destructor).
  Grid(Grid&&) noexcept;
  Grid& operator=(Grid&&) noexcept;
  ~Grid();

  int width() const { return width_; }
  int height() const { return height_; }
  double cell_edge() const { return cell_edge_; }
  // Row length of the padded array (width + 2).
  int stride() const { return stride_; }
  // Index into the padded arrays; valid for x in [-1, width], y in [-1, height].
  int index(int x, int y) const { return (y + 1) * stride_ + (x + 1); }
  int index(Cell c) const { return index(c.x, c.y); }
  Cell cell_of(int index) const { return {index % stride_ - 1, index / stride_ - 1}; }
  // Size of the padded arrays.
  int padded_size() const { return stride_ * (height_ + 2); }

  bool in_bounds(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  bool in_bounds(Cell c) const { return in_bounds(c.x, c.y); }
  // Valid on the border too (always blocked there).
  bool blocked(int x, int y) const { return occupancy_[index(x, y)] != 0; }
  bool blocked(Cell c) const { return blocked(c.x, c.y); }
  bool blocked_at(int index) const { return occupancy_[index] != 0; }
  // Padded occupancy, 1 = obstacle; padded_size() bytes.
  const std::uint8_t* occupancy() const { return occupancy_.data(); }

  // Interior cells only. Invalidates the companions.
  void set_blocked(int x, int y, bool blocked);
  void set_blocked(Cell c, bool blocked) { set_blocked(c.x, c.y, blocked); }

  std::int64_t obstacle_count() const { return obstacles_; }
  std::int64_t free_count() const {
    return static_cast<std::int64_t>(width_) * height_ - obstacles_;
  }

  // Bit-packed padded rows: bit (x + 1) of row y (y in [-1, height]) is set when (x, y) is
  // blocked; bit i lives in word i / 64 at position i % 64. Bits past the padded row are zero.
  int words_per_row() const { return words_per_row_; }
  const std::uint64_t* bit_row(int y) const {
    return bits_.data() + static_cast<std::size_t>(y + 1) * words_per_row_;
  }

  // Built on first use, then shared read-only by every planner of this map (thread-safe).
  const DistanceTransform& distance_transform() const;
  const SummedAreaTable& summed_area() const;
  const CellBlocks& cell_blocks() const;

  // Same size, edge and obstacles.
  bool same_cells(const Grid& other) const;

 private:
  struct Companions;
  int width_ = 0;
  int height_ = 0;
  int stride_ = 2;
  int words_per_row_ = 1;
  double cell_edge_ = 1.0;
  std::int64_t obstacles_ = 0;
  std::vector<std::uint8_t> occupancy_;
  std::vector<std::uint64_t> bits_;
  mutable std::unique_ptr<Companions> companions_;
};

}  // namespace agv
