// Grid basics: the padded border, bit rows against occupancy, copies, counts, and the summed-area
// table against brute force.

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <utility>

#include "core/cell_blocks.h"
#include "core/distance_transform.h"
#include "core/grid.h"
#include "core/rng.h"
#include "core/summed_area.h"
#include "tests/core/random_grid.h"

namespace agv {
namespace {

using test::random_grid;

bool bit_at(const Grid& g, int x, int y) {
  const int bit = x + 1;
  return ((g.bit_row(y)[bit / 64] >> (bit % 64)) & 1U) != 0;
}

TEST(Grid, BorderIsBlockedInteriorFree) {
  const Grid g(5, 4, 0.5);
  EXPECT_EQ(g.width(), 5);
  EXPECT_EQ(g.height(), 4);
  EXPECT_EQ(g.stride(), 7);
  EXPECT_EQ(g.padded_size(), 7 * 6);
  EXPECT_DOUBLE_EQ(g.cell_edge(), 0.5);
  for (int x = -1; x <= 5; ++x) {
    EXPECT_TRUE(g.blocked(x, -1));
    EXPECT_TRUE(g.blocked(x, 4));
  }
  for (int y = -1; y <= 4; ++y) {
    EXPECT_TRUE(g.blocked(-1, y));
    EXPECT_TRUE(g.blocked(5, y));
  }
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 5; ++x) EXPECT_FALSE(g.blocked(x, y));
  }
  EXPECT_EQ(g.obstacle_count(), 0);
  EXPECT_EQ(g.free_count(), 20);
}

TEST(Grid, IndexAndCellOfAreInverse) {
  const Grid g(7, 3);
  for (int y = -1; y <= 3; ++y) {
    for (int x = -1; x <= 7; ++x) EXPECT_EQ(g.cell_of(g.index(x, y)), (Cell{x, y}));
  }
}

TEST(Grid, BadSizesThrow) {
  EXPECT_THROW(Grid(0, 5), std::invalid_argument);
  EXPECT_THROW(Grid(5, 0), std::invalid_argument);
  EXPECT_THROW(Grid(5, 5, 0.0), std::invalid_argument);
}

TEST(Grid, BitRowsAgreeWithOccupancyOnRandomGrids) {
  Rng rng(7, 1);
  for (int trial = 0; trial < 40; ++trial) {
    const int w = rng.between(1, 200);
    const int h = rng.between(1, 20);
    const Grid g = random_grid(w, h, rng.uniform01(), rng);
    for (int y = -1; y <= h; ++y) {
      for (int x = -1; x <= w; ++x) {
        ASSERT_EQ(bit_at(g, x, y), g.blocked(x, y)) << w << "x" << h << " at " << x << "," << y;
        ASSERT_EQ(g.blocked_at(g.index(x, y)), g.blocked(x, y));
        ASSERT_EQ(g.occupancy()[g.index(x, y)] != 0, g.blocked(x, y));
      }
      // Bits past the padded row are zero.
      for (int bit = w + 2; bit < g.words_per_row() * 64; ++bit) {
        ASSERT_EQ((g.bit_row(y)[bit / 64] >> (bit % 64)) & 1U, 0U);
      }
    }
  }
}

TEST(Grid, SetBlockedCounts) {
  Grid g(10, 10);
  g.set_blocked(3, 4, true);
  g.set_blocked(3, 4, true);  // idempotent
  EXPECT_EQ(g.obstacle_count(), 1);
  g.set_blocked(Cell{0, 0}, true);
  g.set_blocked(9, 9, true);
  EXPECT_EQ(g.obstacle_count(), 3);
  EXPECT_EQ(g.free_count(), 97);
  g.set_blocked(3, 4, false);
  g.set_blocked(3, 4, false);
  EXPECT_EQ(g.obstacle_count(), 2);
  EXPECT_FALSE(g.blocked(3, 4));
  EXPECT_THROW(g.set_blocked(-1, 0, true), std::out_of_range);
  EXPECT_THROW(g.set_blocked(10, 0, true), std::out_of_range);

  Rng rng(3, 3);
  const Grid r = random_grid(37, 23, 0.3, rng);
  std::int64_t count = 0;
  for (int y = 0; y < 23; ++y) {
    for (int x = 0; x < 37; ++x) count += r.blocked(x, y) ? 1 : 0;
  }
  EXPECT_EQ(r.obstacle_count(), count);
}

TEST(Grid, CopyIsDeepAndMoveKeepsCells) {
  Rng rng(11, 2);
  Grid a = random_grid(30, 20, 0.25, rng);
  Grid b = a;
  EXPECT_TRUE(b.same_cells(a));
  EXPECT_EQ(b.obstacle_count(), a.obstacle_count());
  const bool was = a.blocked(5, 5);
  b.set_blocked(5, 5, !was);
  EXPECT_EQ(a.blocked(5, 5), was);
  EXPECT_FALSE(b.same_cells(a));
  b = a;
  EXPECT_TRUE(b.same_cells(a));

  const Grid c = a;
  Grid moved = std::move(a);
  EXPECT_TRUE(moved.same_cells(c));
  Grid target(2, 2);
  target = std::move(moved);
  EXPECT_TRUE(target.same_cells(c));
}

TEST(Grid, CompanionsFollowEdits) {
  Grid g(9, 9);
  EXPECT_EQ(g.distance_transform().squared_centre_distance(4, 4), 25);  // border at x = -1
  g.set_blocked(4, 3, true);
  EXPECT_EQ(g.distance_transform().squared_centre_distance(4, 4), 1);
  EXPECT_EQ(g.summed_area().obstacles(0, 0, 8, 8), 1);
  const Grid copy = g;  // companions are rebuilt, not shared
  EXPECT_EQ(copy.distance_transform().squared_centre_distance(4, 4), 1);
}

TEST(SummedArea, CountsEqualBruteForce) {
  Rng rng(5, 9);
  for (int trial = 0; trial < 20; ++trial) {
    const int w = rng.between(1, 40);
    const int h = rng.between(1, 40);
    const Grid g = random_grid(w, h, rng.uniform01(), rng);
    const SummedAreaTable& sat = g.summed_area();
    for (int q = 0; q < 200; ++q) {
      // Corners in any order, partly outside the grid.
      const int x0 = rng.between(-3, w + 2);
      const int x1 = rng.between(-3, w + 2);
      const int y0 = rng.between(-3, h + 2);
      const int y1 = rng.between(-3, h + 2);
      std::int64_t obstacles = 0;
      std::int64_t cells = 0;
      for (int y = std::min(y0, y1); y <= std::max(y0, y1); ++y) {
        for (int x = std::min(x0, x1); x <= std::max(x0, x1); ++x) {
          if (!g.in_bounds(x, y)) continue;
          ++cells;
          obstacles += g.blocked(x, y) ? 1 : 0;
        }
      }
      ASSERT_EQ(sat.obstacles(x0, y0, x1, y1), obstacles);
      ASSERT_EQ(sat.cells(x0, y0, x1, y1), cells);
    }
  }
}

// Every padded cell's mask against its 3x3 block read cell by cell, the border ring included
// (neighbours beyond the padded array count as blocked); and the companion rebuilt after an edit.
TEST(CellBlocks, MasksEqualTheBlocksCellByCell) {
  Rng rng(6, 2);
  auto check = [](const Grid& g) {
    const std::uint32_t* masks = g.cell_blocks().masks();
    auto blocked = [&](int x, int y) {
      return x < -1 || y < -1 || x > g.width() || y > g.height() || g.blocked(x, y);
    };
    for (int y = -1; y <= g.height(); ++y)
      for (int x = -1; x <= g.width(); ++x) {
        const std::uint32_t m = masks[g.index(x, y)];
        const std::pair<int, int> offsets[] = {{-1, 0}, {1, 0},  {0, -1}, {0, 1}, {-1, -1},
                                               {1, -1}, {-1, 1}, {1, 1},  {0, 0}};
        for (int b = 0; b < 9; ++b) {
          const auto [dx, dy] = offsets[b];
          ASSERT_EQ((m >> b) & 1u, blocked(x + dx, y + dy) ? 1u : 0u)
              << "cell " << x << "," << y << " bit " << b;
        }
      }
  };
  for (int trial = 0; trial < 30; ++trial) {
    Grid g = random_grid(rng.between(1, 30), rng.between(1, 30), rng.uniform01(), rng);
    check(g);
    const int x = rng.between(0, g.width() - 1), y = rng.between(0, g.height() - 1);
    g.set_blocked(x, y, !g.blocked(x, y));
    check(g);
  }
}

}  // namespace
}  // namespace agv
