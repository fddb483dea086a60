#pragma once
// Parameters the sampling baselines (PRM, RRT, RRT-Connect) declare the same way, declared once
// here so names, ranges and docs never drift between them (docs/ARCHITECTURE.md "Style" item 5).

#include "algos/sampling/rrt_tree.h"
#include "core/corner_rule.h"
#include "core/line_of_sight.h"
#include "core/params.h"

namespace agv {

// `corner_rule` for continuous segments: how a segment passing exactly through a grid vertex
// between two diagonally adjacent cells is judged by the shared line-of-sight test
// (core/line_of_sight.h); the result is validated under the same rule. Fills a
// SightRule::cells test.
ParamDecls<SightRule> segment_sight_decls(CornerRule default_rule);

struct RrtSettings {
  double step = 0.0;       // cells
  double goal_bias = 0.0;  // probability of sampling the goal (the other tree's root)
  long long max_iterations = 0;
  NearestIndex index = NearestIndex::buckets;
  SightRule sight = SightRule::cells();
};
// RRT and RRT-Connect: step, goal_bias, max_iterations, nn_index, corner_rule.
ParamDecls<RrtSettings> rrt_decls();

// Deadline poll period of the sampling planners, in iterations (samples, edge checks); a power
// of two (docs/ARCHITECTURE.md "Style" item 7).
inline constexpr long long kSamplingDeadlineInterval = 256;

}  // namespace agv
