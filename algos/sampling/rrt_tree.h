#pragma once
// The tree of RRT and RRT-Connect (docs/PLANNERS.md "Baselines"): one implementation shared by
// algos/sampling/rrt.cpp and algos/sampling/birrt.cpp. It stores continuous points with parent
// links and answers "nearest tree node to q" through a spatial index, and extends itself towards a
// target by one step with the shared line-of-sight test.
//
// Nearest-neighbour index, option `nn_index` (perf/README.md "Baselines" has the measurements):
//   buckets  a uniform grid of square buckets with intrusive per-bucket lists; a query scans
//            rings of buckets outwards from q's bucket and stops once the best distance found is
//            no larger than the distance to the next ring. Exact; ties go to the lower node
//            index. The bucket side adapts to the tree: it starts with about 16 buckets over
//            the map and halves whenever the tree outgrows two nodes per bucket (all nodes are
//            relinked, amortised O(1) per node), so a typical query scans a few buckets
//            whatever the map and tree sizes. Reset per plan by a stamp, no clearing. The
//            buckets the tree occupies are bounded by a box (in bucket coordinates): a query
//            starts at the first ring that meets it, scans only the part of each ring inside
//            it and stops at the last ring that meets it. A sample far from a young tree (most
//            of RRT's samples on an open map) no longer scans the empty rings between them.
//   kdtree   nanoflann's KDTreeSingleIndexDynamicAdaptor (a logarithmic set of static k-d
//            trees, rebuilt as points are added). Exact; ties as nanoflann resolves them.
// Both return a nearest node; they can differ only on exact distance ties.

#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "core/grid.h"
#include "core/line_of_sight.h"

namespace agv {

enum class NearestIndex { buckets, kdtree };
std::string_view to_string(NearestIndex index);
std::optional<NearestIndex> nearest_index_from_string(std::string_view name);

// Result of one extension step (Kuffner & LaValle 2000's EXTEND).
enum class ExtendStatus {
  trapped,   // the step's segment is not free; nothing added
  advanced,  // a node one step towards the target was added
  reached,   // the target itself is in the tree now (added, or already the nearest node's point,
             // in which case nothing is added)
};

struct Extension {
  ExtendStatus status = ExtendStatus::trapped;
  int node = -1;  // the added node, or the node holding the target when reached without adding
};

class RrtTree {
 public:
  RrtTree();
  ~RrtTree();
  RrtTree(const RrtTree&) = delete;
  RrtTree& operator=(const RrtTree&) = delete;

  // Empties the tree and makes `root` node 0. bucket_side (buckets only): 0 = adaptive; a
  // positive value fixes the side in cells (for measurements, perf/bench_baselines.cpp).
  void reset(const Grid& grid, Point root, NearestIndex index, double bucket_side = 0.0);

  int size() const { return static_cast<int>(points_.size()); }
  Point point(int node) const { return points_[static_cast<std::size_t>(node)]; }
  int parent(int node) const { return parents_[static_cast<std::size_t>(node)]; }

  int add(Point p, int parent);
  int nearest(Point q) const;

  // EXTEND(T, target): from the nearest node, move `step` cells towards target (or to target
  // when it is closer than step); add the new point when the segment is free under `sight`.
  Extension extend(const Grid& grid, Point target, double step, const SightRule& sight);

  // Appends the points root -> node (root first) to out.
  void append_path_from_root(int node, std::vector<Point>& out) const;

 private:
  struct KdIndex;
  static constexpr double kInitialBuckets = 16.0;
  static constexpr double kMaxPerBucket = 2.0;
  static constexpr double kMinBucketSide = 0.25;  // cells
  void rebucket(double side);
  void link(int node);
  int bucket_of(Point p) const;
  int nearest_in_buckets(Point q) const;

  std::vector<Point> points_;
  std::vector<int> parents_;
  NearestIndex index_ = NearestIndex::buckets;
  // buckets: head node per bucket (valid when the bucket's stamp is the current one), next node
  // in the same bucket per node.
  std::vector<int> bucket_head_;
  std::vector<std::uint32_t> bucket_stamp_;
  std::vector<int> next_in_bucket_;
  std::uint32_t stamp_ = 0;
  double bucket_side_ = 1.0;
  bool fixed_side_ = false;
  int width_ = 0;
  int height_ = 0;
  int buckets_x_ = 0;
  int buckets_y_ = 0;
  // The box of the buckets that hold a node (valid once a node is linked).
  int box_x0_ = 0, box_x1_ = -1, box_y0_ = 0, box_y1_ = -1;
  // kdtree
  std::unique_ptr<KdIndex> kd_;
};

}  // namespace agv
