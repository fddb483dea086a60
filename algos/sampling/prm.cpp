#include "algos/sampling/prm.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <nanoflann.hpp>
#include <utility>
#include <vector>

#include "algos/sampling/point_cloud.h"
#include "algos/sampling/sampling_params.h"
#include "core/cell_geometry.h"
#include "core/line_of_sight.h"

namespace agv {

namespace {

// Rejection sampling draws at most this many points per requested sample, so a nearly full map
// ends with fewer samples instead of looping (expected draws per sample: 1 / free fraction).
constexpr long long kMaxDrawsPerSample = 64;

// Deadline poll period of the roadmap's plain linear passes (a few instructions per element).
constexpr std::size_t kLinearPassPollInterval = 4096;

constexpr int kStartNode = 0;
constexpr int kGoalNode = 1;

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>,
                                                   PointCloud, 2, std::uint32_t>;

// Per-thread buffers, reused from plan to plan.
struct PrmScratch {
  std::vector<Point> points;
  std::vector<std::uint32_t> knn_index;
  std::vector<double> knn_d2;
  std::vector<std::uint64_t> pairs;      // candidate edges (lo << 32 | hi), lo < hi
  std::vector<std::size_t> pair_start;   // the candidates bucketed by lo: CSR offsets
  std::vector<std::size_t> pair_cursor;  // filling cursors
  std::vector<std::uint32_t> pair_hi;    // the candidates' hi ends
  std::vector<std::uint64_t> edges;      // the free ones
  std::vector<int> offsets;              // CSR adjacency
  std::vector<int> targets;
  std::vector<double> dist;
  std::vector<int> parent;
  std::vector<std::pair<double, int>> heap;
};

struct PrmOptions {
  long long samples = 0;
  std::size_t k = 0;
  double radius = 0.0;  // cells; 0 = unlimited
  SightRule sight = SightRule::cells();
};

const ParamDecls<PrmOptions>& prm_decls() {
  static const ParamDecls<PrmOptions> decls = [] {
    ParamDecls<PrmOptions> d;
    d.integer("samples", &PrmOptions::samples, 500, 0, 10000000,
              "free-space samples (paper 000 gives no value); rejection sampling stops after 64 "
              "draws per sample, so a nearly full map may get fewer")
        .integer("k", &PrmOptions::k, 10, 1, 10000,
                 "nearest neighbours each node tries to connect to")
        .number("radius", &PrmOptions::radius, 0.0, 0.0, 1e6,
                "connection radius in cells: neighbours farther away are not tried; 0 = "
                "unlimited")
        .include(&PrmOptions::sight, segment_sight_decls(CornerRule::no_corner_cut));
    return d;
  }();
  return decls;
}

class PrmPlanner final : public Planner {
 public:
  explicit PrmPlanner(const PrmOptions& options)
      : samples_(options.samples), k_(options.k), radius_(options.radius), sight_(options.sight) {}

  PlanResult plan(const PlanRequest& request) const override {
    PlanResult result;
    result.rule = sight_.corners;
    if (request.start == request.goal) {
      result.failure = Failure::none;
      result.path = {centre(request.start)};
      result.work.samples = 0;
      return result;
    }
    PrmScratch& s = request.scratch.get<PrmScratch>();
    bool built = false;
    {
      PhaseTimer timer(result, "roadmap");
      built = build_roadmap(request, s, result);
    }
    if (!built) {
      result.failure = Failure::limit;
      result.message = "deadline passed while building the roadmap";
      return result;
    }
    Search found = Search::no_path;
    {
      PhaseTimer timer(result, "search");
      found = shortest_path(s, request.deadline);
    }
    if (found != Search::found) {
      result.failure = Failure::limit;
      result.message = found == Search::deadline
                           ? "deadline passed during the roadmap search"
                           : "the roadmap does not connect start and goal (too few samples?)";
      return result;
    }
    result.failure = Failure::none;
    for (int n = kGoalNode; n >= 0; n = s.parent[static_cast<std::size_t>(n)])
      result.path.push_back(s.points[static_cast<std::size_t>(n)]);
    std::reverse(result.path.begin(), result.path.end());
    return result;
  }

 private:
  // Samples, k-nearest candidate edges, line-of-sight checks, CSR adjacency. False when the
  // deadline passed.
  bool build_roadmap(const PlanRequest& request, PrmScratch& s, PlanResult& result) const {
    const Grid& grid = request.grid;
    s.points.clear();
    s.points.push_back(centre(request.start));
    s.points.push_back(centre(request.goal));
    // Uniform over the free space: uniform over the map, rejected inside obstacle cells.
    const double width = grid.width();
    const double height = grid.height();
    const long long max_draws = samples_ * kMaxDrawsPerSample;
    long long accepted = 0;
    long long draw = 0;
    for (; draw < max_draws && accepted < samples_; ++draw) {
      if (draw % kSamplingDeadlineInterval == 0 && request.deadline.expired()) {
        result.work.samples = draw;
        count_collision_checks(draw);
        return false;
      }
      const Point p{request.rng.uniform(0.0, width), request.rng.uniform(0.0, height)};
      if (grid.blocked(static_cast<int>(p.x), static_cast<int>(p.y))) continue;
      s.points.push_back(p);
      ++accepted;
    }
    // Every draw, kept or rejected, is a point drawn and one cell test.
    result.work.samples = draw;
    count_collision_checks(draw);

    const std::size_t n = s.points.size();
    const PointCloud cloud{&s.points};
    // The k-d tree's construction (O(n log n) inside nanoflann) is the one step that cannot
    // poll; the deadline is polled right after it.
    const KdTree tree(2, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    if (request.deadline.expired()) return false;
    const std::size_t want = std::min(k_ + 1, n);  // + 1: the query point finds itself
    s.knn_index.resize(want);
    s.knn_d2.resize(want);
    const double radius2 = radius_ * radius_;
    s.pairs.clear();
    for (std::size_t i = 0; i < n; ++i) {
      if (i % kSamplingDeadlineInterval == 0 && request.deadline.expired()) return false;
      const double query[2] = {s.points[i].x, s.points[i].y};
      const std::size_t found = tree.knnSearch(query, want, s.knn_index.data(), s.knn_d2.data());
      for (std::size_t m = 0; m < found; ++m) {
        const std::uint32_t j = s.knn_index[m];
        if (j == i || (radius_ > 0.0 && s.knn_d2[m] > radius2)) continue;
        const auto lo = static_cast<std::uint64_t>(std::min<std::size_t>(i, j));
        const auto hi = static_cast<std::uint64_t>(std::max<std::size_t>(i, j));
        s.pairs.push_back(lo << 32 | hi);
      }
    }
    // An edge found from both ends is checked once.
    if (!sort_unique_pairs(s, n, request.deadline)) return false;

    s.edges.clear();
    s.offsets.assign(n + 1, 0);
    for (std::size_t e = 0; e < s.pairs.size(); ++e) {
      if (e % kSamplingDeadlineInterval == 0 && request.deadline.expired()) return false;
      const std::uint64_t pair = s.pairs[e];
      const std::size_t a = pair >> 32;
      const std::size_t b = pair & 0xFFFFFFFFU;
      if (!segment_free(grid, s.points[a], s.points[b], sight_)) continue;
      s.edges.push_back(pair);
      ++s.offsets[a + 1];
      ++s.offsets[b + 1];
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (i % kLinearPassPollInterval == 0 && request.deadline.expired()) return false;
      s.offsets[i + 1] += s.offsets[i];
    }
    s.targets.resize(static_cast<std::size_t>(s.offsets[n]));
    // Fill with a running cursor per node (`parent` is unused until the search: the cursors).
    s.parent.assign(s.offsets.begin(), s.offsets.end() - 1);
    for (std::size_t e = 0; e < s.edges.size(); ++e) {
      if (e % kLinearPassPollInterval == 0 && request.deadline.expired()) return false;
      const std::uint64_t pair = s.edges[e];
      const auto a = static_cast<int>(pair >> 32);
      const auto b = static_cast<int>(pair & 0xFFFFFFFFU);
      s.targets[static_cast<std::size_t>(s.parent[static_cast<std::size_t>(a)]++)] = b;
      s.targets[static_cast<std::size_t>(s.parent[static_cast<std::size_t>(b)]++)] = a;
    }
    result.extra.emplace_back("roadmap_edges", static_cast<double>(s.edges.size()));
    result.extra.emplace_back("edge_checks", static_cast<double>(s.pairs.size()));
    return true;
  }

  // s.pairs sorted and without repeats, as std::sort and std::unique would leave them, by a
  // counting sort on the lower end and a sort of each (small: a node's neighbours and those
  // that have it among theirs) bucket, so that the deadline is polled throughout. False when it
  // passed.
  static bool sort_unique_pairs(PrmScratch& s, std::size_t n, const Deadline& deadline) {
    const std::size_t m = s.pairs.size();
    s.pair_start.assign(n + 1, 0);
    for (std::size_t e = 0; e < m; ++e) {
      if (e % kLinearPassPollInterval == 0 && deadline.expired()) return false;
      ++s.pair_start[(s.pairs[e] >> 32) + 1];
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (i % kLinearPassPollInterval == 0 && deadline.expired()) return false;
      s.pair_start[i + 1] += s.pair_start[i];
    }
    s.pair_hi.resize(m);
    s.pair_cursor.assign(s.pair_start.begin(), s.pair_start.end() - 1);
    for (std::size_t e = 0; e < m; ++e) {
      if (e % kLinearPassPollInterval == 0 && deadline.expired()) return false;
      const std::uint64_t pair = s.pairs[e];
      s.pair_hi[s.pair_cursor[pair >> 32]++] = static_cast<std::uint32_t>(pair & 0xFFFFFFFFU);
    }
    s.pairs.clear();
    for (std::size_t lo = 0; lo < n; ++lo) {
      if (lo % kSamplingDeadlineInterval == 0 && deadline.expired()) return false;
      const auto first = s.pair_hi.begin() + static_cast<std::ptrdiff_t>(s.pair_start[lo]);
      const auto last = s.pair_hi.begin() + static_cast<std::ptrdiff_t>(s.pair_start[lo + 1]);
      std::sort(first, last);
      for (auto it = first; it != last; ++it)
        if (it == first || *it != *(it - 1))
          s.pairs.push_back(static_cast<std::uint64_t>(lo) << 32 | *it);
    }
    return true;
  }

  enum class Search { found, no_path, deadline };

  // Dijkstra on the roadmap (binary heap, lazy deletion; ties to the lower node index).
  static Search shortest_path(PrmScratch& s, const Deadline& deadline) {
    const std::size_t n = s.points.size();
    s.dist.assign(n, std::numeric_limits<double>::infinity());
    s.parent.assign(n, -1);
    s.heap.clear();
    const auto later = std::greater<std::pair<double, int>>();
    s.dist[kStartNode] = 0.0;
    s.heap.emplace_back(0.0, kStartNode);
    for (std::int64_t popped = 0; !s.heap.empty(); ++popped) {
      if (popped % kSamplingDeadlineInterval == 0 && deadline.expired()) return Search::deadline;
      std::pop_heap(s.heap.begin(), s.heap.end(), later);
      const auto [d, u] = s.heap.back();
      s.heap.pop_back();
      const auto su = static_cast<std::size_t>(u);
      if (d > s.dist[su]) continue;  // stale entry
      if (u == kGoalNode) return Search::found;
      for (int e = s.offsets[su]; e < s.offsets[su + 1]; ++e) {
        const int v = s.targets[static_cast<std::size_t>(e)];
        const auto sv = static_cast<std::size_t>(v);
        const double dv = d + point_distance(s.points[su], s.points[sv]);
        if (dv < s.dist[sv]) {
          s.dist[sv] = dv;
          s.parent[sv] = u;
          s.heap.emplace_back(dv, v);
          std::push_heap(s.heap.begin(), s.heap.end(), later);
        }
      }
    }
    return Search::no_path;
  }

  long long samples_;
  std::size_t k_;
  double radius_;
  SightRule sight_;
};

}  // namespace

PlannerInfo prm_planner() {
  PlannerInfo info;
  info.kind = PlannerKind::sampling;
  info.name = "prm";
  info.summary = "PRM: uniform free samples, k-nearest roadmap, Dijkstra on the roadmap";
  info.source = "docs/PLANNERS.md Baselines; paper 000 Tables III-XIII (PRM column); Kavraki 1996";
  info.counters = {
      {"samples", "points drawn uniformly over the map, those rejected in obstacle cells included"},
      {"collision_checks", "one cell test per point drawn, one segment test per candidate edge"}};
  info.stochastic = true;
  info.proves_no_path = false;  // gives up with limit after its budget
  info.params = prm_decls().specs();
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<PrmPlanner>(prm_decls().read(params));
  };
  return info;
}

}  // namespace agv
