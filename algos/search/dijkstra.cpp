#include "algos/search/dijkstra.h"

#include <memory>

#include "algos/search/grid_search_params.h"
#include "algos/postprocess/postprocess_params.h"
#include "algos/search/heuristics.h"
#include "algos/search/search_core.h"

namespace agv {

namespace {

class DijkstraPlanner final : public Planner {
 public:
  explicit DijkstraPlanner(const Params& params) : setup_(grid_search_setup_of(params)) {
    read_shortcut_params(params, post_);
    read_smoothing_params(params, post_);
  }

  PlanResult plan(const PlanRequest& request) const override {
    PlanResult result = plan_grid_search(request, setup_,
                                         AStarPolicy<ZeroHeuristic>(ZeroHeuristic{}, request.goal));
    apply_postprocessing(request.grid, post_, result);
    return result;
  }

 private:
  GridSearchSetup setup_;
  PostprocessOptions post_;
};

}  // namespace

PlannerInfo dijkstra_planner() {
  PlannerInfo info;
  info.name = "dijkstra";
  info.summary = "Dijkstra: A* with the zero heuristic, 8-connected, optimal";
  info.source = "PLANNERS.md Dijkstra; paper 002 baseline";
  info.expanded_nodes_meaning =
      "cells taken off the open list and closed (goal included; stale duplicates not counted)";
  info.params = {corner_rule_param(CornerRule::allow), diagonal_cost_param()};
  for (auto& spec : shortcut_params(ShortcutMode::none)) info.params.push_back(std::move(spec));
  for (auto& spec : smoothing_params(SmoothingMode::none)) info.params.push_back(std::move(spec));
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<DijkstraPlanner>(params);
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
