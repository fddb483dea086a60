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
//   `shortcut_margin` (0 = SightRule::cells): the pipeline's `direct_midpoint` shortcut.
// Work counters: grid_search_counters() (docs/METRICS.md "Work counters").

#include <algorithm>
#include <cmath>
#include <memory>

#include "algos/postprocess/postprocess_params.h"
#include "algos/search/grid_search_params.h"
#include "algos/search/search_core.h"
#include "core/summed_area.h"

namespace agv {

namespace {

// Eq. 3 with the floor: 1 / Q = cells / max(obstacles, 1), capped.
double rate_weight(const SummedAreaTable& sat, Cell a, Cell b, double max_weight) {
  const auto cells = static_cast<double>(sat.cells(a.x, a.y, b.x, b.y));
  const auto obstacles =
      static_cast<double>(std::max<std::int64_t>(1, sat.obstacles(a.x, a.y, b.x, b.y)));
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

enum class WeightMode { inverse_rate, admissible };
enum class RateScope { node, query };

struct AltAStarOptions {
  GridSearchOptions search;
  WeightMode weight_mode = WeightMode::inverse_rate;
  RateScope rate_scope = RateScope::node;
  double max_weight = 5.0;
  PostprocessOptions post;  // section 2.4: direct_midpoint under shortcut_margin, then smoothing
};

ParamDecls<AltAStarOptions> alt_astar_decls() {
  ParamDecls<AltAStarOptions> d;
  d.include(&AltAStarOptions::search, grid_search_decls(CornerRule::no_corner_cut, std::nullopt))
      .choice("weight_mode", &AltAStarOptions::weight_mode, WeightMode::inverse_rate,
              ChoiceTable<WeightMode>{{"inverse_rate", WeightMode::inverse_rate},
                                      {"admissible", WeightMode::admissible}},
              "heuristic weight: inverse_rate = 1 / Q (eq. 5, capped by max_weight); "
              "admissible = 1 (the paper's alpha = min(1, 1/Q), i.e. plain A*)")
      .choice("rate_scope", &AltAStarOptions::rate_scope, RateScope::node,
              ChoiceTable<RateScope>{{"node", RateScope::node}, {"query", RateScope::query}},
              "rectangle of the obstacle rate Q: node = between the scored node and the goal "
              "(weight adapts by region); query = between start and goal")
      .number("max_weight", &AltAStarOptions::max_weight, 5.0, 1.0, 1000.0,
              "cap on the inverse_rate weight 1 / Q (Q floored at one cell's share)")
      .include(&AltAStarOptions::post, shortcut_margin_decls(0.0))
      .include(&AltAStarOptions::post, smoothing_decls(SmoothingMode::none));
  return d;
}

class AltAStarPlanner final : public Planner {
 public:
  explicit AltAStarPlanner(const AltAStarOptions& options) : o_(options) {
    o_.post.shortcut = ShortcutMode::direct_midpoint;  // section 2.4
  }

  PlanResult plan(const PlanRequest& request) const override {
    const bool inverse_rate = o_.weight_mode == WeightMode::inverse_rate;
    const bool node_scope = o_.rate_scope == RateScope::node;
    AltAStarPolicy policy;
    policy.goal_cell = request.goal;
    policy.max_weight = o_.max_weight;
    if (inverse_rate && request.grid.in_bounds(request.start) &&
        request.grid.in_bounds(request.goal)) {
      policy.sat = &request.grid.summed_area();
      policy.per_node = node_scope;
      if (!node_scope)
        policy.weight = rate_weight(*policy.sat, request.start, request.goal, o_.max_weight);
    }
    PlanResult result = plan_grid_search(request, o_.search.setup, policy);
    apply_postprocessing(request.grid, o_.post, result, request.deadline);
    return result;
  }

 private:
  AltAStarOptions o_;
};

}  // namespace

PlannerInfo alt_astar_planner() {
  PlannerInfo info;
  info.name = "alt_astar";
  info.summary =
      "paper 003 alternative A*: heuristic weighted by the inverse obstacle rate, "
      "no_corner_cut, direct and midpoint shortcuts";
  info.source = "paper 003 section 2 (eq. 3-6, sections 2.3-2.4); docs/PLANNERS.md Alternative A*";
  info.counters = grid_search_counters();
  info.params = alt_astar_decls().specs();
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<AltAStarPlanner>(alt_astar_decls().read(params));
  };
  return info;
}

}  // namespace agv
