#include "algos/search/alt_astar.h"

// A policy of the one search core (algos/search/search_core.h) plus paper 003's smoothing:
// - obstacle rate Q (eq. 3): obstacle cells / cells of the axis-aligned rectangle spanned by two
//   cells, O(1) from the grid's summed-area table (built once per map, shared). `rate_scope`
//   node (default): the rectangle between the scored node and the goal, so the weight adapts by
//   region as the text says; query: the start-goal rectangle, one weight per search (eq. 3's
//   symbols);
// - weight (eq. 5): F = G + H * e^(-ln Q) = G + H / Q with H Euclidean (eq. 4), `weight_mode`
//   inverse_rate (default; Q floored at one cell's share so an obstacle-free rectangle gives a
//   finite weight, the weight capped by `max_weight`) or admissible (the paper's own
//   alpha = min(1, 1/Q), always 1: plain A*);
// - child nodes (section 2.3): `corner_rule: no_corner_cut`;
// - smoothing (section 2.4): collinear nodes dropped, then for each turning point the direct
//   connection, else the midpoint shortcut S-C-G (Figure 5), each kept only when free under
//   `margin` (0 = SightRule::cells).
// expanded_nodes: cells taken off the open list and closed (the goal included).

#include <algorithm>
#include <cmath>
#include <memory>

#include "algos/search/grid_search_params.h"
#include "algos/postprocess/path_simplify.h"
#include "algos/postprocess/postprocess_params.h"
#include "algos/search/search_core.h"
#include "core/summed_area.h"

namespace agv {

namespace {

// Eq. 3 with the floor: 1 / Q = cells / max(obstacles, 1), capped.
double rate_weight(const SummedAreaTable& sat, Cell a, Cell b, double max_weight) {
  const auto cells = static_cast<double>(sat.cells(a.x, a.y, b.x, b.y));
  const auto obstacles = static_cast<double>(std::max<std::int64_t>(1, sat.obstacles(a.x, a.y, b.x, b.y)));
  return std::min(cells / obstacles, max_weight);
}

struct AltAStarPolicy : PolicyDefaults {
  double heuristic(int x, int y, int /*index*/) const {
    const double h =
        std::hypot(static_cast<double>(goal_cell.x - x), static_cast<double>(goal_cell.y - y));
    if (!per_node) return weight * h;
    return rate_weight(*sat, {x, y}, goal_cell, max_weight) * h;  // eq. 5, H / Q(node)
  }
  const SummedAreaTable* sat = nullptr;
  Cell goal_cell;
  bool per_node = false;  // rate_scope node with weight_mode inverse_rate
  double weight = 1.0;    // otherwise: the one weight of the search
  double max_weight = 5.0;
};

class AltAStarPlanner final : public Planner {
 public:
  explicit AltAStarPlanner(const Params& params)
      : setup_(grid_search_setup_of(params)),
        inverse_rate_(params.choice("weight_mode") == "inverse_rate"),
        node_scope_(params.choice("rate_scope") == "node"),
        max_weight_(params.number("max_weight")),
        margin_(params.number("margin")) {
    read_smoothing_params(params, post_);
  }

  PlanResult plan(const PlanRequest& request) const override {
    AltAStarPolicy policy;
    policy.goal_cell = request.goal;
    policy.max_weight = max_weight_;
    if (inverse_rate_ && request.grid.in_bounds(request.start) &&
        request.grid.in_bounds(request.goal)) {
      policy.sat = &request.grid.summed_area();
      policy.per_node = node_scope_;
      if (!node_scope_)
        policy.weight = rate_weight(*policy.sat, request.start, request.goal, max_weight_);
    }
    PlanResult result = plan_grid_search(request, setup_, policy);
    if (!result.ok()) return result;
    WorkingPath path(std::move(result.path));
    {
      PhaseTimer timer(result, "postprocess");  // section 2.4
      std::vector<Point> p = std::move(path.points);
      shortcut_direct_midpoint(request.grid, p, sight_rule(setup_.rule, margin_));
      path.replace(std::move(p));
    }
    finish_path(request.grid, post_, path, result);
    return result;
  }

 private:
  GridSearchSetup setup_;
  bool inverse_rate_;
  bool node_scope_;
  double max_weight_;
  double margin_;
  PostprocessOptions post_;
};

}  // namespace

PlannerInfo alt_astar_planner() {
  PlannerInfo info;
  info.name = "alt_astar";
  info.summary = "paper 003 alternative A*: heuristic weighted by the inverse obstacle rate, "
                 "no_corner_cut, direct and midpoint shortcuts";
  info.source = "paper 003 section 2 (eq. 3-6, sections 2.3-2.4); PLANNERS.md Alternative A*";
  info.expanded_nodes_meaning = "cells taken off the open list and closed (goal included)";
  info.params = {
      corner_rule_param(CornerRule::no_corner_cut),
      diagonal_cost_param(),
      ParamSpec::choice("weight_mode", "inverse_rate", {"inverse_rate", "admissible"},
                        "heuristic weight: inverse_rate = 1 / Q (eq. 5, capped by max_weight); "
                        "admissible = 1 (the paper's alpha = min(1, 1/Q), i.e. plain A*)"),
      ParamSpec::choice("rate_scope", "node", {"node", "query"},
                        "rectangle of the obstacle rate Q: node = between the scored node and the "
                        "goal (weight adapts by region); query = between start and goal"),
      ParamSpec::number("max_weight", 5.0, 1.0, 1000.0,
                        "cap on the inverse_rate weight 1 / Q (Q floored at one cell's share)"),
      ParamSpec::number("margin", 0.0, 0.0, 5.0,
                        "clearance of the smoothing shortcuts in cells: obstacle centres at "
                        "least margin + 0.5 away (0 = touch no obstacle cell)"),
  };
  for (auto& spec : smoothing_params(SmoothingMode::none)) info.params.push_back(std::move(spec));
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<AltAStarPlanner>(params);
  };
  return info;
}

}  // namespace agv
