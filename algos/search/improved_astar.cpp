#include "algos/search/improved_astar.h"

// Internal part (section 4.1), a policy of the one search core (algos/search/search_core.h):
// - neighbour rule `no_squeeze` (Algorithm 1, Node_traversal()): a diagonal is refused only when
//   both adjacent cardinal cells are obstacles;
// - heuristic octile with D_diag = diagonal_cost = 1.4 (eq. 7 read the sane way; the printed
//   weights are `heuristic: octile_as_printed`), g with diagonal moves of 1.4 (eq. 6);
// - turning weight (eq. 8-10): f = g + C * h, C = turn_weight (1.2) when parent -> node -> child
//   turns (cross product K != 0, i.e. the move into the child differs from the move into the
//   node), else 1; no turn is charged at the start, which has no parent.
// External part (section 4.2), on the search path, each step free under SightRule::cells(rule):
// 1. a midpoint between every two consecutive nodes (Algorithm 2 lines 1-12, eq. 11);
// 2. forward key-point search (Algorithm 2's intent): the next key point is the last point still
//    in sight before the first one that is not;
// 3. obstacle-avoidance adjustment (eq. 12-13): key points pushed L/2 from adjacent obstacles,
//    points inserted where a segment passes closer than L to an obstacle centre; none that
//    turns the path back (kReversalAngle), nor (`avoid_cap: search_path`) one that makes it
//    longer than the search path;
// 4. quadratic Bezier corners (eq. 14, `smoothing: bezier`), shrunk where they would hit.
// Work counters: grid_search_counters() (docs/METRICS.md "Work counters").

#include <limits>
#include <memory>
#include <vector>

#include "algos/postprocess/path_curves.h"
#include "algos/postprocess/postprocess_params.h"
#include "algos/search/grid_search_params.h"
#include "algos/search/search_core.h"

namespace agv {

namespace {

template <class H>
struct TurnWeightedPolicy : PolicyDefaults {
  TurnWeightedPolicy(H heuristic_fn, Cell goal, double weight)
      : h_fn(heuristic_fn), goal_cell(goal), turn_weight(weight) {}
  double heuristic(int x, int y, int /*index*/) const {
    return h_fn(std::abs(goal_cell.x - x), std::abs(goal_cell.y - y));
  }
  // Eq. 8-10: K != 0 exactly when the two moves differ (a reversal would re-enter the closed
  // parent, so it never reaches here).
  double key(double g, double h, int dir_in, int dir_out) const {
    const bool turns = dir_in != kNoDirection && dir_in != dir_out;
    return g + (turns ? turn_weight : 1.0) * h;
  }
  H h_fn;
  Cell goal_cell;
  double turn_weight;
};

struct ImprovedAStarOptions {
  GridSearchOptions search;
  double turn_weight = 1.2;
  double avoid_offset = 0.5;
  double avoid_near = 1.0;
  bool avoid_capped = true;  // avoid_cap: search_path (true) or none
  PostprocessOptions post;   // the smoothing (step 4)
};

ParamDecls<ImprovedAStarOptions> internal_decls() {
  ParamDecls<ImprovedAStarOptions> d;
  d.include(&ImprovedAStarOptions::search,
            grid_search_decls(CornerRule::no_squeeze, Heuristic::octile, 1.4))
      .number("turn_weight", &ImprovedAStarOptions::turn_weight, 1.2, 1.0, 10.0,
              "C of eq. 9-10: the heuristic's weight when parent -> node -> child turns (1 = no "
              "turning cost)");
  return d;
}

ParamDecls<ImprovedAStarOptions> improved_internal_decls() {
  ParamDecls<ImprovedAStarOptions> d = internal_decls();
  d.include(&ImprovedAStarOptions::post, smoothing_decls(SmoothingMode::none));
  return d;
}

ParamDecls<ImprovedAStarOptions> improved_decls() {
  ParamDecls<ImprovedAStarOptions> d = internal_decls();
  d.number("avoid_offset", &ImprovedAStarOptions::avoid_offset, 0.5, 0.0, 2.0,
           "eq. 13: how far key points are pushed from nearby obstacles, cells (L/2)")
      .number("avoid_near", &ImprovedAStarOptions::avoid_near, 1.0, 0.0, 3.0,
              "section 4.2 step 3: a segment passing closer than this to an obstacle centre gets "
              "a point inserted at that obstacle's pushed vertex, cells (L)")
      .choice("avoid_cap", &ImprovedAStarOptions::avoid_capped, true,
              ChoiceTable<bool>{{"search_path", true}, {"none", false}},
              "step 3: search_path = a move or insertion that would make the key polyline "
              "longer than the search path is refused (Table 5: the external part shortens the "
              "internal path); none = the adjustment as printed, unbounded (duplicates and "
              "reversals above 150 degrees are refused either way)")
      .include(&ImprovedAStarOptions::post, smoothing_decls(SmoothingMode::bezier));
  return d;
}

class ImprovedAStarPlanner final : public Planner {
 public:
  ImprovedAStarPlanner(const ImprovedAStarOptions& options, bool external)
      : o_(options), external_(external) {}

  PlanResult plan(const PlanRequest& request) const override {
    PlanResult result =
        with_heuristic(o_.search.heuristic, o_.search.setup.diagonal_cost, [&](auto h) {
          return plan_grid_search(request, o_.search.setup,
                                  TurnWeightedPolicy<decltype(h)>(h, request.goal, o_.turn_weight));
        });
    if (!result.ok()) return result;
    WorkingPath path(std::move(result.path));
    if (external_) {
      PhaseTimer timer(result, "postprocess");
      const SightRule sight = SightRule::cells(o_.search.setup.rule);
      const double search_length = polyline_length_cells(path.points);
      DeadlinePoller poll = postprocess_poller(request.deadline);
      apply_shortcut(request.grid, ShortcutMode::forward, sight, path, &poll);  // steps 1-2
      // Step 3 (eq. 12-13), paper 002's own: it moves and inserts points, a detour around the
      // obstacles that may lengthen the shortcut polyline but never beyond the search path it
      // refines (docs/PLANNERS.md "Improved A*").
      std::vector<Point> keys = path.points;
      if (!poll.has_expired())
        avoid_obstacles(request.grid, keys, sight, o_.avoid_offset, o_.avoid_near,
                        o_.avoid_capped ? search_length : std::numeric_limits<double>::infinity(),
                        &poll);
      if (poll.has_expired()) {
        fail_postprocessing(result, "obstacle-avoidance adjustment");
        return result;
      }
      path.replace(std::move(keys));
    }
    finish_path(request.grid, o_.post, path, result, request.deadline);  // step 4: Bezier corners
    return result;
  }

 private:
  ImprovedAStarOptions o_;
  bool external_;
};

}  // namespace

PlannerInfo improved_astar_internal_planner() {
  PlannerInfo info;
  info.name = "improved_astar_internal";
  info.summary =
      "paper 002 internal improved A*: no_squeeze, octile (D_diag 1.4), turning "
      "weight 1.2";
  info.source = "paper 002 section 4.1 (Algorithm 1, eq. 6-10), Table 4; docs/PLANNERS.md";
  info.counters = grid_search_counters();
  info.params = improved_internal_decls().specs();
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<ImprovedAStarPlanner>(improved_internal_decls().read(params), false);
  };
  return info;
}

PlannerInfo improved_astar_planner() {
  PlannerInfo info;
  info.name = "improved_astar";
  info.summary =
      "paper 002 improved A*: the internal search, then midpoints, forward key "
      "points, obstacle-avoidance adjustment and quadratic Bezier corners";
  info.source = "paper 002 sections 4.1-4.2 (Algorithms 1-2, eq. 6-14), Table 5; docs/PLANNERS.md";
  info.counters = grid_search_counters();
  info.params = improved_decls().specs();
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<ImprovedAStarPlanner>(improved_decls().read(params), true);
  };
  return info;
}

}  // namespace agv
