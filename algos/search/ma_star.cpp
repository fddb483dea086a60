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
// Steps 2-3 are the pipeline's `turning_points` shortcut (algos/postprocess/postprocess_params.h)
// under SightRule::circles(r_obs), then the optional `smoothing`.
// Work counters: grid_search_counters() (docs/METRICS.md "Work counters").

#include <cmath>
#include <memory>

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
  explicit MaStarPlanner(const MaStarOptions& options) : o_(options) {
    o_.post.shortcut = ShortcutMode::turning_points;  // step 2 (eq. 5.1a), step 3 (eq. 5.1b)
  }

  PlanResult plan(const PlanRequest& request) const override {
    PlanResult result = plan_grid_search(
        request, o_.search.setup,
        MaStarPolicy(request.start, request.goal, o_.g_mode == MaStarG::euclid_from_start));
    apply_postprocessing(request.grid, o_.post, SightRule::circles(o_.r_obs, o_.search.setup.rule),
                         result, request.deadline);
    return result;
  }

 private:
  MaStarOptions o_;
};

ParamDecls<MaStarOptions> ma_star_decls() {
  ParamDecls<MaStarOptions> d = ma_star_search_decls();
  d.include(&MaStarOptions::post, smoothing_decls(SmoothingMode::none));
  return d;
}

}  // namespace

ParamDecls<MaStarOptions> ma_star_search_decls() {
  ParamDecls<MaStarOptions> d;
  d.include(&MaStarOptions::search, grid_search_decls(CornerRule::allow, std::nullopt))
      .choice("g_mode", &MaStarOptions::g_mode, MaStarG::euclid_from_start,
              ChoiceTable<MaStarG>{{"euclid_from_start", MaStarG::euclid_from_start},
                                   {"path", MaStarG::path}},
              "B(n): euclid_from_start = straight-line distance from the start (eq. 4.1b as "
              "printed, default); path = accumulated path cost (plain A*)")
      .number("r_obs", &MaStarOptions::r_obs, 0.70710678118654752, 0.0, 5.0,
              "radius of the inflated obstacle circles around cell centres for turning-point "
              "removal (eq. 5.1b), cells; default half a cell diagonal");
  return d;
}

std::unique_ptr<Planner> make_ma_star(const MaStarOptions& options) {
  return std::make_unique<MaStarPlanner>(options);
}

PlannerInfo ma_star_planner() {
  PlannerInfo info;
  info.name = "ma_star";
  info.summary =
      "MA*: f = B + C with B as printed (Euclidean from the start), collinear and "
      "turning-point removal around inflated obstacles";
  info.source = "paper 000 section 4.1, steps 2-3 (eq. 4.1a-b, 5.1a-b); docs/PLANNERS.md MA*";
  info.counters = grid_search_counters();
  info.params = ma_star_decls().specs();
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return make_ma_star(ma_star_decls().read(params));
  };
  return info;
}

}  // namespace agv
