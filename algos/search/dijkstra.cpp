#include "algos/search/dijkstra.h"

#include <memory>

#include "algos/postprocess/postprocess_params.h"
#include "algos/search/grid_search_params.h"
#include "algos/search/heuristics.h"
#include "algos/search/search_core.h"

namespace agv {

namespace {

struct DijkstraOptions {
  GridSearchOptions search;
  PostprocessOptions post;
};

ParamDecls<DijkstraOptions> dijkstra_decls() {
  ParamDecls<DijkstraOptions> d;
  d.include(&DijkstraOptions::search, grid_search_decls(CornerRule::allow, std::nullopt))
      .include(&DijkstraOptions::post, shortcut_decls(ShortcutMode::none))
      .include(&DijkstraOptions::post, smoothing_decls(SmoothingMode::none));
  return d;
}

class DijkstraPlanner final : public Planner {
 public:
  explicit DijkstraPlanner(const DijkstraOptions& options) : o_(options) {}

  PlanResult plan(const PlanRequest& request) const override {
    PlanResult result = plan_grid_search(request, o_.search.setup,
                                         AStarPolicy<ZeroHeuristic>(ZeroHeuristic{}, request.goal));
    apply_postprocessing(request.grid, o_.post, result, request.deadline);
    return result;
  }

 private:
  DijkstraOptions o_;
};

}  // namespace

PlannerInfo dijkstra_planner() {
  PlannerInfo info;
  info.name = "dijkstra";
  info.summary = "Dijkstra: A* with the zero heuristic, 8-connected, optimal";
  info.source = "docs/PLANNERS.md Dijkstra; paper 002 baseline";
  info.counters = grid_search_counters();
  info.params = dijkstra_decls().specs();
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<DijkstraPlanner>(dijkstra_decls().read(params));
  };
  return info;
}

std::optional<double> shortest_length(const Grid& grid, Cell start, Cell goal, CornerRule rule,
                                      Scratch& scratch) {
  if (!grid.in_bounds(start) || !grid.in_bounds(goal) || grid.blocked(start) || grid.blocked(goal))
    return std::nullopt;
  GridSearchSetup setup;
  setup.rule = rule;
  setup.diagonal_cost = kSqrt2;
  const GridSearchOutcome out =
      grid_search(grid, start, goal, setup, Deadline::never(),
                  AStarPolicy<OctileHeuristic>(OctileHeuristic{kSqrt2}, goal),
                  scratch.get<GridSearchBuffers>());
  if (out.failure != Failure::none) return std::nullopt;
  return out.goal_g;
}

}  // namespace agv
