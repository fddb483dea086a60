#include "algos/search/astar.h"

#include <memory>

#include "algos/search/grid_search_params.h"
#include "algos/postprocess/postprocess_params.h"
#include "algos/search/search_core.h"

namespace agv {

namespace {

class AStarPlanner final : public Planner {
 public:
  explicit AStarPlanner(const Params& params)
      : setup_(grid_search_setup_of(params)), heuristic_(heuristic_of(params)) {
    read_shortcut_params(params, post_);
    read_smoothing_params(params, post_);
  }

  PlanResult plan(const PlanRequest& request) const override {
    PlanResult result = with_heuristic(heuristic_, setup_.diagonal_cost, [&](auto h) {
      return plan_grid_search(request, setup_, AStarPolicy<decltype(h)>(h, request.goal));
    });
    apply_postprocessing(request.grid, post_, result);
    return result;
  }

 private:
  GridSearchSetup setup_;
  Heuristic heuristic_;
  PostprocessOptions post_;
};

}  // namespace

PlannerInfo astar_planner() {
  PlannerInfo info;
  info.name = "astar";
  info.summary = "classic A*: 8-connected, f = g + h, closed set";
  info.source = "PLANNERS.md A* (classic); the traditional A* baseline of papers 000-004";
  info.expanded_nodes_meaning =
      "cells taken off the open list and closed (goal included; stale duplicates not counted)";
  info.params = {corner_rule_param(CornerRule::allow), heuristic_param(Heuristic::euclidean),
                 diagonal_cost_param()};
  // Off by default: the classic baseline; on, "A* + the same post-processing" isolates what a
  // family member's search itself contributes.
  for (auto& spec : shortcut_params(ShortcutMode::none)) info.params.push_back(std::move(spec));
  for (auto& spec : smoothing_params(SmoothingMode::none)) info.params.push_back(std::move(spec));
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<AStarPlanner>(params);
  };
  return info;
}

}  // namespace agv
