#pragma once
// MA*, the Modified A* of paper 000 section 4.1 and steps 2-3 (docs/PLANNERS.md "MA*").

#include <memory>

#include "algos/planner_info.h"
#include "algos/postprocess/postprocess_params.h"
#include "algos/search/grid_search_params.h"
#include "core/params.h"

namespace agv {

PlannerInfo ma_star_planner();

// B(n) of eq. 4.1a (parameter `g_mode`).
enum class MaStarG {
  euclid_from_start,  // eq. 4.1b as printed: straight-line distance from the start
  path,               // the accumulated path cost (plain A*)
};

struct MaStarOptions {
  GridSearchOptions search;  // corner_rule, diagonal_cost
  MaStarG g_mode = MaStarG::euclid_from_start;
  double r_obs = 0.70710678118654752;
  PostprocessOptions post;  // the smoothing; the shortcut is steps 2-3
};

// corner_rule, diagonal_cost, g_mode, r_obs: the search and steps 2-3, which HMA* (paper 000
// section 5) runs as its first stage and so declares as its own.
ParamDecls<MaStarOptions> ma_star_search_decls();
std::unique_ptr<Planner> make_ma_star(const MaStarOptions& options);

}  // namespace agv
