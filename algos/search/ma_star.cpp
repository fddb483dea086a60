#include "algos/search/ma_star.h"

// MA* = a policy of the one search core (algos/search/search_core.h) plus two simplification steps:
// - search: 8-connected, f(n) = B(n) + C(n) (eq. 4.1a) with C(n) the Euclidean distance to the
//   goal and B(n) per `g_mode`: `euclid_from_start` (eq. 4.1b as printed, default: the straight
//   distance from the START, fixed when a cell is first reached) or `path` (the accumulated
//   cost, i.e. plain A*);
// - step 2 (eq. 5.1a): collinear nodes removed with an integer cross product;
// - step 3 (eq. 5.1b): a turning point is removed when the segment joining its neighbours keeps
//   every obstacle circle of radius r_obs (around the cell centres) clear, repeated until no
//   point can be removed.
// expanded_nodes: cells taken off the open list and closed (the goal included).

#include <cmath>
#include <memory>

#include "algos/search/grid_search_params.h"
#include "algos/postprocess/path_simplify.h"
#include "algos/postprocess/postprocess_params.h"
#include "algos/search/search_core.h"

namespace agv {

namespace {

struct MaStarPolicy : PolicyDefaults {
  MaStarPolicy(Cell start, Cell goal, bool euclid_g)
      : start_cell(start), goal_cell(goal), euclid_from_start(euclid_g) {}
  // C(n), eq. 4.1b.
  double heuristic(int x, int y, int /*index*/) const {
    return std::hypot(static_cast<double>(goal_cell.x - x), static_cast<double>(goal_cell.y - y));
  }
  // B(n), eq. 4.1b as printed (euclid_from_start), or the path cost.
  double child_g(double parent_g, double step_cost, int x, int y) const {
    if (!euclid_from_start) return parent_g + step_cost;
    return std::hypot(static_cast<double>(x - start_cell.x), static_cast<double>(y - start_cell.y));
  }
  Cell start_cell;
  Cell goal_cell;
  bool euclid_from_start;
};

class MaStarPlanner final : public Planner {
 public:
  explicit MaStarPlanner(const Params& params)
      : setup_(grid_search_setup_of(params)),
        euclid_g_(params.choice("g_mode") == "euclid_from_start"),
        r_obs_(params.number("r_obs")) {
    read_smoothing_params(params, post_);
  }

  PlanResult plan(const PlanRequest& request) const override {
    PlanResult result = plan_grid_search(request, setup_,
                                         MaStarPolicy(request.start, request.goal, euclid_g_));
    if (!result.ok()) return result;
    WorkingPath path(std::move(result.path));
    {
      PhaseTimer timer(result, "postprocess");
      path.keep(collinear_keep(path.points));  // step 2, eq. 5.1a
      path.keep(turning_point_keep(request.grid, path.points,
                                   SightRule::circles(r_obs_, setup_.rule)));  // step 3, eq. 5.1b
    }
    finish_path(request.grid, post_, path, result);
    return result;
  }

 private:
  GridSearchSetup setup_;
  bool euclid_g_;
  double r_obs_;
  PostprocessOptions post_;
};

}  // namespace

PlannerInfo ma_star_planner() {
  PlannerInfo info;
  info.name = "ma_star";
  info.summary = "MA*: f = B + C with B as printed (Euclidean from the start), collinear and "
                 "turning-point removal around inflated obstacles";
  info.source = "paper 000 section 4.1, steps 2-3 (eq. 4.1a-b, 5.1a-b); PLANNERS.md MA*";
  info.expanded_nodes_meaning =
      "cells taken off the open list and closed (goal included), as A*";
  info.params = {
      corner_rule_param(CornerRule::allow),
      diagonal_cost_param(),
      ParamSpec::choice("g_mode", "euclid_from_start", {"euclid_from_start", "path"},
                        "B(n): euclid_from_start = straight-line distance from the start (eq. "
                        "4.1b as printed, default); path = accumulated path cost (plain A*)"),
      ParamSpec::number("r_obs", 0.70710678118654752, 0.0, 5.0,
                        "radius of the inflated obstacle circles around cell centres for "
                        "turning-point removal (eq. 5.1b), cells; default half a cell diagonal"),
  };
  for (auto& spec : smoothing_params(SmoothingMode::none)) info.params.push_back(std::move(spec));
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<MaStarPlanner>(params);
  };
  return info;
}

}  // namespace agv
