#pragma once
// nanoflann's dataset adaptor over a planner's own point array (no copy), shared by PRM's
// roadmap and the RRT trees' nearest-neighbour index.

#include <cstddef>
#include <vector>

#include "core/grid.h"

namespace agv {

struct PointCloud {
  const std::vector<Point>* points;
  std::size_t kdtree_get_point_count() const { return points->size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const {
    return dim == 0 ? (*points)[i].x : (*points)[i].y;
  }
  // No precomputed bounding box: nanoflann computes it.
  template <class Box>
  bool kdtree_get_bbox(Box& /*box*/) const {
    return false;
  }
};

}  // namespace agv
