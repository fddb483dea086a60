#pragma once
// The parameters every grid search declares the same way (PLANNERS.md "Common ground"):
// corner_rule, heuristic, diagonal_cost. A variant picks its own defaults and reads them back
// with the helpers below, so names, ranges and docs never drift between A* variants.

#include "algos/search/heuristics.h"
#include "core/params.h"
#include "algos/search/search_core.h"
#include "core/corner_rule.h"

namespace agv {

ParamSpec corner_rule_param(CornerRule default_rule);
ParamSpec heuristic_param(Heuristic default_heuristic);
// Range [1, 2]; kSqrt2 by default, paper 002 uses 1.4.
ParamSpec diagonal_cost_param(double default_cost = kSqrt2);

// Read back from a set resolved against the specs above.
CornerRule corner_rule_of(const Params& params);
Heuristic heuristic_of(const Params& params);
GridSearchSetup grid_search_setup_of(const Params& params);  // corner_rule + diagonal_cost

}  // namespace agv
