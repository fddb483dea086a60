#include "algos/sampling/rrt_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "algos/sampling/point_cloud.h"

// nanoflann 1.4's dynamic adaptor copies empty sub-trees whose bounding box is not yet set
// (harmless: it is computed before use); GCC flags the copy at -O2.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <nanoflann.hpp>
#pragma GCC diagnostic pop

namespace agv {

namespace {

// Below this distance the target is taken as the nearest node's own point.
constexpr double kSamePoint = 1e-12;

}  // namespace

std::string_view to_string(NearestIndex index) {
  return index == NearestIndex::buckets ? "buckets" : "kdtree";
}

std::optional<NearestIndex> nearest_index_from_string(std::string_view name) {
  if (name == "buckets") return NearestIndex::buckets;
  if (name == "kdtree") return NearestIndex::kdtree;
  return std::nullopt;
}

// The nearest-neighbour index over the tree's own point array (algos/sampling/point_cloud.h).
struct RrtTree::KdIndex {
  using Tree =
      nanoflann::KDTreeSingleIndexDynamicAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>,
                                                 PointCloud, 2, std::uint32_t>;

  // The adaptor keeps log2(maximum point count) + 1 static trees and indexes past the last one
  // when more points arrive, so the maximum is its default (1e9), far above any tree here; empty
  // trees cost one size test per query.
  explicit KdIndex(const std::vector<Point>& points)
      : cloud{&points}, tree(2, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {}

  PointCloud cloud;
  Tree tree;
};

RrtTree::RrtTree() = default;
RrtTree::~RrtTree() = default;

void RrtTree::reset(const Grid& grid, Point root, NearestIndex index, double bucket_side) {
  points_.clear();
  parents_.clear();
  kd_.reset();
  index_ = index;
  width_ = grid.width();
  height_ = grid.height();
  if (index_ == NearestIndex::buckets) {
    fixed_side_ = bucket_side > 0.0;
    // Adaptive: start with about kInitialBuckets buckets over the whole map.
    const double side =
        fixed_side_ ? bucket_side
                    : std::max(kMinBucketSide,
                               std::sqrt(static_cast<double>(width_) * height_ / kInitialBuckets));
    points_.push_back(root);
    parents_.push_back(-1);
    rebucket(side);
  } else {
    points_.push_back(root);
    parents_.push_back(-1);
    // The adaptor indexes the points present at construction (the root).
    kd_ = std::make_unique<KdIndex>(points_);
  }
}

void RrtTree::rebucket(double side) {
  bucket_side_ = side;
  buckets_x_ = std::max(1, static_cast<int>(std::ceil(width_ / bucket_side_)));
  buckets_y_ = std::max(1, static_cast<int>(std::ceil(height_ / bucket_side_)));
  const auto count = static_cast<std::size_t>(buckets_x_) * static_cast<std::size_t>(buckets_y_);
  if (bucket_head_.size() < count) {
    bucket_head_.resize(count);
    bucket_stamp_.assign(count, 0);
    stamp_ = 0;
  }
  if (++stamp_ == 0) {  // wrapped: forget every old stamp
    std::fill(bucket_stamp_.begin(), bucket_stamp_.end(), 0);
    stamp_ = 1;
  }
  next_in_bucket_.clear();
  box_x0_ = buckets_x_;
  box_x1_ = -1;
  box_y0_ = buckets_y_;
  box_y1_ = -1;
  for (int node = 0; node < size(); ++node) link(node);
}

void RrtTree::link(int node) {
  const int bucket = bucket_of(points_[static_cast<std::size_t>(node)]);
  const int bx = bucket % buckets_x_;
  const int by = bucket / buckets_x_;
  box_x0_ = std::min(box_x0_, bx);
  box_x1_ = std::max(box_x1_, bx);
  box_y0_ = std::min(box_y0_, by);
  box_y1_ = std::max(box_y1_, by);
  const auto b = static_cast<std::size_t>(bucket);
  next_in_bucket_.push_back(bucket_stamp_[b] == stamp_ ? bucket_head_[b] : -1);
  bucket_head_[b] = node;
  bucket_stamp_[b] = stamp_;
}

int RrtTree::bucket_of(Point p) const {
  const int bx = std::clamp(static_cast<int>(p.x / bucket_side_), 0, buckets_x_ - 1);
  const int by = std::clamp(static_cast<int>(p.y / bucket_side_), 0, buckets_y_ - 1);
  return by * buckets_x_ + bx;
}

int RrtTree::add(Point p, int parent) {
  const int node = size();
  points_.push_back(p);
  parents_.push_back(parent);
  if (index_ == NearestIndex::buckets) {
    const double buckets = static_cast<double>(buckets_x_) * buckets_y_;
    // Keep about one node per bucket: past kMaxPerBucket, quarter the buckets' area and relink
    // every node (amortised O(1): the next split needs four times as many nodes).
    if (!fixed_side_ && size() > kMaxPerBucket * buckets && bucket_side_ > kMinBucketSide)
      rebucket(std::max(kMinBucketSide, bucket_side_ / 2.0));
    else
      link(node);
  } else {
    const auto n = static_cast<std::uint32_t>(node);
    kd_->tree.addPoints(n, n);
  }
  return node;
}

int RrtTree::nearest(Point q) const {
  if (index_ == NearestIndex::buckets) return nearest_in_buckets(q);
  std::uint32_t found = 0;
  double d2 = 0.0;
  nanoflann::KNNResultSet<double, std::uint32_t> result(1);
  result.init(&found, &d2);
  const double query[2] = {q.x, q.y};
  kd_->tree.findNeighbors(result, query, nanoflann::SearchParams());
  return static_cast<int>(found);
}

int RrtTree::nearest_in_buckets(Point q) const {
  const int bx0 = std::clamp(static_cast<int>(q.x / bucket_side_), 0, buckets_x_ - 1);
  const int by0 = std::clamp(static_cast<int>(q.y / bucket_side_), 0, buckets_y_ - 1);
  int best = -1;
  double best_d2 = std::numeric_limits<double>::infinity();
  const auto scan = [&](int bx, int by) {
    const auto b = static_cast<std::size_t>(by * buckets_x_ + bx);
    if (bucket_stamp_[b] != stamp_) return;
    for (int n = bucket_head_[b]; n >= 0; n = next_in_bucket_[static_cast<std::size_t>(n)]) {
      const Point p = points_[static_cast<std::size_t>(n)];
      const double d2 = (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y);
      if (d2 < best_d2 || (d2 == best_d2 && n < best)) {
        best_d2 = d2;
        best = n;
      }
    }
  };
  // Rings (Chebyshev distance in buckets from q's) that meet the occupied box: below the first,
  // past the last, every bucket is empty.
  const int first_ring = std::max({0, box_x0_ - bx0, bx0 - box_x1_, box_y0_ - by0, by0 - box_y1_});
  const int last_ring = std::max({bx0 - box_x0_, box_x1_ - bx0, by0 - box_y0_, box_y1_ - by0});
  for (int r = first_ring; r <= last_ring; ++r) {
    if (best >= 0) {
      // Every unscanned node lies outside the square of rings 0..r-1: at least this far from q.
      const double lo_x = (bx0 - r + 1) * bucket_side_;
      const double hi_x = (bx0 + r) * bucket_side_;
      const double lo_y = (by0 - r + 1) * bucket_side_;
      const double hi_y = (by0 + r) * bucket_side_;
      const double gap = std::min({q.x - lo_x, hi_x - q.x, q.y - lo_y, hi_y - q.y});
      if (gap >= 0.0 && best_d2 <= gap * gap) break;
    }
    // The ring's buckets inside the occupied box (which lies within the map's buckets).
    const int y_lo = std::max(by0 - r, box_y0_);
    const int y_hi = std::min(by0 + r, box_y1_);
    const int x_lo = std::max(bx0 - r, box_x0_);
    const int x_hi = std::min(bx0 + r, box_x1_);
    for (int by = y_lo; by <= y_hi; ++by) {
      if (by == by0 - r || by == by0 + r) {
        for (int bx = x_lo; bx <= x_hi; ++bx) scan(bx, by);
      } else {
        if (bx0 - r >= box_x0_) scan(bx0 - r, by);
        if (r > 0 && bx0 + r <= box_x1_) scan(bx0 + r, by);
      }
    }
  }
  return best;
}

Extension RrtTree::extend(const Grid& grid, Point target, double step, const SightRule& sight) {
  const int near = nearest(target);
  const Point from = point(near);
  const double dx = target.x - from.x;
  const double dy = target.y - from.y;
  const double d = std::hypot(dx, dy);
  if (d <= kSamePoint) return {ExtendStatus::reached, near};
  Extension e;
  Point to = target;
  e.status = ExtendStatus::reached;
  if (d > step) {
    to = {from.x + dx / d * step, from.y + dy / d * step};
    e.status = ExtendStatus::advanced;
  }
  if (!segment_free(grid, from, to, sight)) return {ExtendStatus::trapped, -1};
  e.node = add(to, near);
  return e;
}

void RrtTree::append_path_from_root(int node, std::vector<Point>& out) const {
  const std::size_t first = out.size();
  for (int n = node; n >= 0; n = parent(n)) out.push_back(point(n));
  std::reverse(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
}

}  // namespace agv
