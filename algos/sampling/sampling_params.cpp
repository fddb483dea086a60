#include "algos/sampling/sampling_params.h"

#include <stdexcept>
#include <string>

namespace agv {

ParamSpec segment_corner_rule_param(CornerRule default_rule) {
  return ParamSpec::choice(
      "corner_rule", std::string(to_string(default_rule)), {"allow", "no_squeeze", "no_corner_cut"},
      "how an edge passing exactly through a grid vertex between two diagonal cells is judged by "
      "the line-of-sight test: allow = always; no_squeeze = unless both side cells are blocked; "
      "no_corner_cut = only when both are free (the edge touches no obstacle cell)");
}

SightRule segment_sight_of(const Params& params) {
  const auto rule = corner_rule_from_string(params.choice("corner_rule"));
  if (!rule) throw std::logic_error("corner_rule not validated");
  return SightRule::cells(*rule);
}

std::vector<ParamSpec> rrt_params() {
  return {
      ParamSpec::number("step", 2.0, 0.05, 1e6,
                        "extension step in cells: a new node lies at most this far from its "
                        "parent (paper 000 gives no value)"),
      ParamSpec::number("goal_bias", 0.05, 0.0, 1.0,
                        "probability that a sample is the goal (RRT-Connect: the other tree's "
                        "root) instead of a uniform point of the map"),
      ParamSpec::integer("max_iterations", 50000, 1, 100000000,
                         "samples drawn before giving up with failure `limit`"),
      ParamSpec::choice("nn_index", "buckets", {"buckets", "kdtree"},
                        "nearest-node index: buckets = uniform bucket grid, kdtree = nanoflann "
                        "dynamic k-d tree (same answers up to exact ties; see perf/README.md)"),
      segment_corner_rule_param(CornerRule::no_corner_cut),
  };
}

RrtSettings rrt_settings_of(const Params& params) {
  RrtSettings s;
  s.step = params.number("step");
  s.goal_bias = params.number("goal_bias");
  s.max_iterations = params.integer("max_iterations");
  const auto index = nearest_index_from_string(params.choice("nn_index"));
  if (!index) throw std::logic_error("nn_index not validated");
  s.index = *index;
  s.sight = segment_sight_of(params);
  return s;
}

}  // namespace agv
