// Greedy best-first search on the grid, as an agvbench planner plugin (README.md). It expands the
// open cell nearest the goal by the heuristic alone, ignoring the cost so far: fast and complete
// on a finite grid, but not optimal. Moves follow the corner rule of the run (the `corner_rule`
// parameter, which the engine sets from the sweep's collision model when left unset), and the
// deadline is polled every `check_every` expansions as the built-in planners do.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <queue>
#include <vector>

#include "agvbench/algos/plugin.h"
#include "agvbench/algos/registry.h"
#include "agvbench/core/corner_rule.h"
#include "agvbench/core/line_of_sight.h"
#include "agvbench/core/params.h"

namespace gbfs {

enum class Heuristic { octile, euclidean, manhattan };

struct Options {
  agv::CornerRule rule = agv::CornerRule::no_corner_cut;
  Heuristic heuristic = Heuristic::octile;
  long long check_every = 256;
};

agv::ParamDecls<Options> decls() {
  agv::ParamDecls<Options> d;
  d.choice("corner_rule", &Options::rule, agv::CornerRule::no_corner_cut,
           agv::ChoiceTable<agv::CornerRule>{{"allow", agv::CornerRule::allow},
                                             {"no_squeeze", agv::CornerRule::no_squeeze},
                                             {"no_corner_cut", agv::CornerRule::no_corner_cut}},
           "which diagonal moves past obstacles are allowed (docs/PLANNERS.md)")
      .choice("heuristic", &Options::heuristic, Heuristic::octile,
              agv::ChoiceTable<Heuristic>{{"octile", Heuristic::octile},
                                          {"euclidean", Heuristic::euclidean},
                                          {"manhattan", Heuristic::manhattan}},
              "distance to the goal that orders the open list")
      .integer("check_every", &Options::check_every, 256, 1, 1 << 20,
               "expansions between two polls of the run's deadline");
  return d;
}

double distance(Heuristic h, int dx, int dy) {
  const double ax = std::abs(dx), ay = std::abs(dy);
  switch (h) {
    case Heuristic::octile:
      return std::max(ax, ay) + (std::sqrt(2.0) - 1.0) * std::min(ax, ay);
    case Heuristic::euclidean:
      return std::hypot(ax, ay);
    case Heuristic::manhattan:
      return ax + ay;
  }
  return 0.0;
}

// Per-thread buffers (agv::Scratch): reset per query by a search number, not by clearing.
struct Buffers {
  std::vector<std::uint32_t> seen;  // search number that reached the cell
  std::vector<int> parent;          // padded index of the cell it was reached from
  std::uint32_t search = 0;
};

struct Open {
  double h;
  std::int64_t order;  // insertion order: equal h pops first-in first, deterministically
  int index;
  bool operator>(const Open& o) const { return h != o.h ? h > o.h : order > o.order; }
};

class GreedyBestFirst final : public agv::Planner {
 public:
  explicit GreedyBestFirst(const Options& o) : o_(o) {}

  agv::PlanResult plan(const agv::PlanRequest& request) const override {
    const agv::Grid& grid = request.grid;
    Buffers& b = request.scratch.get<Buffers>();
    if (b.seen.size() != static_cast<std::size_t>(grid.padded_size()) || ++b.search == 0) {
      b.seen.assign(grid.padded_size(), 0);
      b.parent.assign(grid.padded_size(), -1);
      b.search = 1;
    }
    int offset[8];
    for (int d = 0; d < 8; ++d) offset[d] = agv::kDy[d] * grid.stride() + agv::kDx[d];
    const agv::MoveTable& moves = agv::move_table(o_.rule);
    const int start = grid.index(request.start), goal = grid.index(request.goal);
    std::priority_queue<Open, std::vector<Open>, std::greater<>> open;
    std::int64_t order = 0, expansions = 0;
    auto reach = [&](int index, int from) {
      b.seen[index] = b.search;
      b.parent[index] = from;
      const agv::Cell c = grid.cell_of(index);
      open.push(
          {distance(o_.heuristic, c.x - request.goal.x, c.y - request.goal.y), order++, index});
    };
    reach(start, -1);
    agv::PlanResult result;
    result.rule = o_.rule;
    while (!open.empty()) {
      const int index = open.top().index;
      open.pop();
      if (index == goal) {
        for (int i = goal; i != -1; i = b.parent[i]) {
          const agv::Cell c = grid.cell_of(i);
          result.path.push_back({c.x + 0.5, c.y + 0.5});
        }
        std::reverse(result.path.begin(), result.path.end());
        result.failure = agv::Failure::none;
        break;
      }
      if (++expansions % o_.check_every == 0 && request.deadline.expired()) {
        result = agv::PlanResult::failed(agv::Failure::limit, "deadline passed");
        break;
      }
      // The 8 neighbour cells' occupancy (the padded border reads as blocked), counted as the
      // engine's collision checks like a built-in grid search's.
      unsigned free_mask = 0;
      for (int d = 0; d < 8; ++d)
        free_mask |= static_cast<unsigned>(!grid.blocked_at(index + offset[d])) << d;
      agv::count_collision_checks(8);
      const std::uint8_t allowed = moves[free_mask];
      for (int d = 0; d < 8; ++d)
        if ((allowed >> d & 1U) && b.seen[index + offset[d]] != b.search)
          reach(index + offset[d], index);
    }
    if (!result.ok() && result.failure == agv::Failure::no_path)
      result.message = "every cell reachable from the start was expanded";
    result.work.search_expansions = expansions;
    return result;
  }

 private:
  Options o_;
};

void add_planners(void* out) {
  agv::PlannerInfo info;
  info.name = "gbfs";
  info.kind = agv::PlannerKind::grid_search;
  info.summary = "greedy best-first search (plugin example): heuristic order only, not optimal";
  info.source = "examples/plugin_planner (Doran and Michie 1966)";
  info.counters = {{"search_expansions", "cells taken off the open list (the goal excluded)"},
                   {"collision_checks", "8 neighbour-cell tests per expanded cell"}};
  info.proves_no_path = true;  // it closes every reachable cell before it answers no_path
  info.params = decls().specs();
  info.make = [](const agv::Params& params) -> std::unique_ptr<agv::Planner> {
    return std::make_unique<GreedyBestFirst>(decls().read(params));
  };
  static_cast<std::vector<agv::PlannerInfo>*>(out)->push_back(std::move(info));
}

}  // namespace gbfs

// The one entry point: the build record (macros expanded here, in the plugin), its name and
// version, and the function that hands over its planners.
extern "C" AGVBENCH_PLUGIN_EXPORT const AgvPlugin* agvbench_plugin_v1(void) {
  static const AgvPlugin plugin = {AGVBENCH_PLUGIN_BUILD, "gbfs_plugin", "1.0.0",
                                   gbfs::add_planners};
  return &plugin;
}
