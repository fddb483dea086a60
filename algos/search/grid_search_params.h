#pragma once
// The parameters every grid search declares the same way (docs/PLANNERS.md "Common ground"):
// corner_rule, heuristic, diagonal_cost. A variant includes grid_search_decls() with its own
// defaults, so names, ranges and docs never drift between A* variants.

#include <optional>

#include "algos/search/heuristics.h"
#include "algos/search/search_core.h"
#include "core/corner_rule.h"
#include "core/params.h"

namespace agv {

struct GridSearchOptions {
  GridSearchSetup setup;                       // corner_rule, diagonal_cost
  Heuristic heuristic = Heuristic::euclidean;  // when declared
};

// `corner_rule`, then `heuristic` when `default_heuristic` is given (Dijkstra and the variants
// with a paper's own heuristic declare none), then `diagonal_cost` (range [1, 2]; kSqrt2 by
// default, paper 002 uses 1.4).
ParamDecls<GridSearchOptions> grid_search_decls(CornerRule default_rule,
                                                std::optional<Heuristic> default_heuristic,
                                                double default_diagonal_cost = kSqrt2);

// The corner rule alone, for planners outside the search family that move on the same grid.
ParamDecls<CornerRule> corner_rule_decls(CornerRule default_rule);

}  // namespace agv
