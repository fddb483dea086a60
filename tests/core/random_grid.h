#pragma once
// A grid whose cells are blocked independently with probability p: the core tests' random maps.

#include "core/grid.h"
#include "core/rng.h"

namespace agv::test {

inline Grid random_grid(int w, int h, double p, Rng& rng) {
  Grid g(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) g.set_blocked(x, y, rng.chance(p));
  }
  return g;
}

}  // namespace agv::test
