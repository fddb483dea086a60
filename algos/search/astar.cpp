#include "algos/search/astar.h"

#include <memory>

#include "algos/postprocess/postprocess_params.h"
#include "algos/search/grid_search_params.h"
#include "algos/search/search_core.h"

namespace agv {

namespace {

struct AStarOptions {
  GridSearchOptions search;
  PostprocessOptions post;
};

ParamDecls<AStarOptions> astar_decls() {
  ParamDecls<AStarOptions> d;
  // Post-processing off by default: the classic baseline; on, "A* + the same post-processing"
  // isolates what a family member's search itself contributes.
  d.include(&AStarOptions::search, grid_search_decls(CornerRule::allow, Heuristic::euclidean))
      .include(&AStarOptions::post, shortcut_decls(ShortcutMode::none))
      .include(&AStarOptions::post, smoothing_decls(SmoothingMode::none));
  return d;
}

class AStarPlanner final : public Planner {
 public:
  explicit AStarPlanner(const AStarOptions& options) : o_(options) {}

  PlanResult plan(const PlanRequest& request) const override {
    PlanResult result =
        with_heuristic(o_.search.heuristic, o_.search.setup.diagonal_cost, [&](auto h) {
          return plan_grid_search(request, o_.search.setup,
                                  AStarPolicy<decltype(h)>(h, request.goal));
        });
    apply_postprocessing(request.grid, o_.post, result, request.deadline);
    return result;
  }

 private:
  AStarOptions o_;
};

}  // namespace

PlannerInfo astar_planner() {
  PlannerInfo info;
  info.name = "astar";
  info.summary = "classic A*: 8-connected, f = g + h, closed set";
  info.source = "docs/PLANNERS.md A* (classic); the traditional A* baseline of papers 000-004";
  info.counters = grid_search_counters();
  info.params = astar_decls().specs();
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<AStarPlanner>(astar_decls().read(params));
  };
  return info;
}

}  // namespace agv
