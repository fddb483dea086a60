#include "core/connectivity.h"

#include <algorithm>
#include <array>
#include <bit>

namespace agv {

std::uint32_t flood_fill(const std::uint8_t* occupancy, int stride, int padded_size, int from,
                         int stop, CornerRule rule, ConnectivityScratch& scratch) {
  std::array<int, 8> offset{};
  for (int d = 0; d < 8; ++d) offset[d] = kDy[d] * stride + kDx[d];
  const MoveTable& table = move_table(rule);

  auto& stamp = scratch.stamp;
  if (stamp.size() < static_cast<std::size_t>(padded_size)) {
    stamp.assign(static_cast<std::size_t>(padded_size), 0);
    scratch.generation = 0;
  }
  if (++scratch.generation == 0) {  // wrapped: old stamps could alias the new generation
    std::fill(stamp.begin(), stamp.end(), 0);
    scratch.generation = 1;
  }
  const std::uint32_t gen = scratch.generation;
  auto& queue = scratch.queue;
  queue.clear();
  queue.push_back(from);
  stamp[from] = gen;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int i = queue[head];
    unsigned free_mask = 0;
    for (int d = 0; d < 8; ++d) free_mask |= (occupancy[i + offset[d]] == 0 ? 1U : 0U) << d;
    unsigned moves = table[free_mask];
    while (moves != 0) {
      const int d = std::countr_zero(moves);
      moves &= moves - 1;
      const int j = i + offset[d];
      if (stamp[j] == gen) continue;
      stamp[j] = gen;
      if (j == stop) return gen;
      queue.push_back(j);
    }
  }
  return gen;
}

bool connected(const std::uint8_t* occupancy, int stride, int padded_size, int from, int to,
               CornerRule rule, ConnectivityScratch& scratch) {
  if (occupancy[from] != 0 || occupancy[to] != 0) return false;
  if (from == to) return true;
  const std::uint32_t gen = flood_fill(occupancy, stride, padded_size, from, to, rule, scratch);
  return scratch.stamp[to] == gen;
}

bool connected(const Grid& grid, Cell a, Cell b, CornerRule rule, ConnectivityScratch& scratch) {
  if (!grid.in_bounds(a) || !grid.in_bounds(b)) return false;
  return connected(grid.occupancy(), grid.stride(), grid.padded_size(), grid.index(a),
                   grid.index(b), rule, scratch);
}

bool connected(const Grid& grid, Cell a, Cell b, CornerRule rule) {
  ConnectivityScratch scratch;
  return connected(grid, a, b, rule, scratch);
}

}  // namespace agv
