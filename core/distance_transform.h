#pragma once
// Exact Euclidean distance transform of a grid's obstacle cells (the border counts as obstacle:
// it is the workshop wall). Built once per map and shared read-only: clearance metrics, the
// DWA's static-obstacle distance and margin-mode line of sight all read it.
//
// The transform (Meijster et al. 2000, with squared distances and integer arithmetic throughout,
// so it is exact) runs over the padded grid: a column pass, then a lower-envelope row pass that
// also records which obstacle won (the feature transform). It copies the occupancy it needs and
// keeps no pointer to the Grid (grids move).

#include <cstdint>
#include <limits>
#include <vector>

#include "core/grid.h"

namespace agv {

class DistanceTransform {
 public:
  explicit DistanceTransform(const Grid& grid);

  int width() const { return width_; }
  int height() const { return height_; }

  // Squared distance, in cells, between the centre of (x, y) and the centre of the nearest
  // obstacle cell; 0 on an obstacle. Valid for x in [-1, width], y in [-1, height].
  std::int64_t squared_centre_distance(int x, int y) const { return squared_[index(x, y)]; }
  double centre_distance(int x, int y) const;
  // Padded index (Grid::index layout) of one nearest obstacle cell (the feature transform).
  int nearest_obstacle(int x, int y) const { return nearest_[index(x, y)]; }

  // Exact Euclidean distance, in cells, from a continuous point to the nearest obstacle cell
  // taken as a closed unit square; 0 inside or on an obstacle, and 0 outside [0, W] x [0, H]
  // (that is inside the border wall).
  double clearance(Point p) const;
  // Exact minimum of clearance() over the segment a-b (0 if it touches an obstacle square).
  // With `below`: that minimum when it is less than `below`, else some value >= below (so
  // min(below, segment_clearance(a, b, below)) is the exact min(below, clearance)); the
  // search then skips every obstacle that cannot come closer than `below`, which makes a
  // polyline's least clearance far cheaper than its segments' clearances one by one.
  double segment_clearance(Point a, Point b,
                           double below = std::numeric_limits<double>::infinity()) const;

 private:
  struct Candidate {
    std::int64_t squared;  // squared_ of the cell
    int index;             // padded index
  };
  int index(int x, int y) const { return (y + 1) * stride_ + (x + 1); }
  double search(Point a, Point b, Candidate* cells, int count, double below) const;
  bool box_search(Point a, Point b, double below, double& best) const;

  int width_ = 0;
  int height_ = 0;
  int stride_ = 0;
  std::vector<std::int64_t> squared_;  // padded layout, as the grid
  std::vector<int> nearest_;           // padded layout
  std::vector<std::uint8_t> blocked_;  // padded occupancy copy, for the exact clearance search
};

}  // namespace agv
