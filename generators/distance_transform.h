#pragma once
// Exact Euclidean distance transform of a grid's obstacle cells (the border counts as obstacle:
// it is the workshop wall). Built once per map and shared read-only: clearance metrics, the
// DWA's static-obstacle distance and margin-mode line of sight all read it.

#include <cstdint>
#include <vector>

#include "generators/grid.h"

namespace agv {

class DistanceTransform {
 public:
  explicit DistanceTransform(const Grid& grid);

  // Squared distance, in cells, between the centre of (x, y) and the centre of the nearest
  // obstacle cell; 0 on an obstacle. Valid for x in [-1, width], y in [-1, height].
  std::int64_t squared_centre_distance(int x, int y) const;
  double centre_distance(int x, int y) const;
  // Padded index of one nearest obstacle cell (the feature transform).
  int nearest_obstacle(int x, int y) const;

  // Exact Euclidean distance, in cells, from a continuous point to the nearest obstacle cell
  // taken as a closed unit square; 0 inside or on an obstacle.
  double clearance(Point p) const;
  // Exact minimum of clearance() over the segment a-b.
  double segment_clearance(Point a, Point b) const;

 private:
  int width_ = 0;
  int height_ = 0;
  int stride_ = 0;
  std::vector<std::int64_t> squared_;  // padded layout, as the grid
  std::vector<int> nearest_;           // padded layout
};

}  // namespace agv
