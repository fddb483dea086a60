#include "algos/search/search_core.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace agv {

void OpenList::grow() {
  const std::size_t capacity = std::max<std::size_t>(1024, capacity_ * 2);
  std::vector<OpenKey> storage(capacity + 2);
  // Slot 1 on a 32-byte boundary: siblings 2i+1 and 2i+2 are read together by one sift step.
  std::size_t shift = 0;
  while ((reinterpret_cast<std::uintptr_t>(storage.data() + shift + 1) & 31U) != 0) ++shift;
  OpenKey* heap = storage.data() + shift;
  if (size_ > 0) std::memcpy(static_cast<void*>(heap), heap_, size_ * sizeof(OpenKey));
  storage_ = std::move(storage);
  heap_ = heap;
  capacity_ = capacity;
}

void GridSearchBuffers::begin(int padded_size) {
  const auto n = static_cast<std::size_t>(padded_size);
  if (stamps_.size() < n) {
    stamps_.resize(n, 0);
    nodes_.resize(n);
  }
  // Stamps only grow between wraps, so cells stamped by earlier searches (of any grid size) read
  // as unseen. Before the byte would wrap, forget every stamp once.
  if (open_stamp_ >= 0xFC) {
    std::fill(stamps_.begin(), stamps_.end(), std::uint8_t{0});
    open_stamp_ = 0;
  }
  open_stamp_ = static_cast<std::uint8_t>(open_stamp_ + 2);
}

void trace_cells(const GridSearchBuffers& buffers, const Grid& grid, Cell goal,
                 std::vector<Cell>& cells) {
  cells.clear();
  const SearchNode* nodes = buffers.nodes();
  int i = grid.index(goal);
  for (;;) {
    cells.push_back(grid.cell_of(i));
    const int d = nodes[i].parent_dir;
    if (d == kNoDirection) break;
    i -= kDy[d] * grid.stride() + kDx[d];
  }
  std::reverse(cells.begin(), cells.end());
}

std::vector<Point> cell_centres(const std::vector<Cell>& cells) {
  std::vector<Point> points;
  points.reserve(cells.size());
  for (const Cell& c : cells) points.push_back(centre(c));
  return points;
}

std::optional<PlanResult> check_grid_query(const PlanRequest& request, CornerRule rule) {
  const Grid& grid = request.grid;
  auto fail = [&](std::string why) {
    PlanResult r = PlanResult::failed(Failure::invalid_input, std::move(why));
    r.rule = rule;
    return std::optional<PlanResult>(std::move(r));
  };
  if (!grid.in_bounds(request.start) || grid.blocked(request.start))
    return fail("start cell is outside the grid or blocked");
  if (!grid.in_bounds(request.goal) || grid.blocked(request.goal))
    return fail("goal cell is outside the grid or blocked");
  return std::nullopt;
}

}  // namespace agv
