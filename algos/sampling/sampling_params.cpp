#include "algos/sampling/sampling_params.h"

namespace agv {

namespace {
// `clearance` sets the kind and the radius of the rule together (SightRule::margin), whatever
// order the parameters are read in: the corner rule is a field of its own.
struct ClearanceField {
  SightRule& sight;
  void operator=(double margin) {
    sight =
        margin > 0.0 ? SightRule::margin(margin, sight.corners) : SightRule::cells(sight.corners);
  }
};
}  // namespace

ParamDecls<SightRule> segment_sight_decls(CornerRule default_rule) {
  ParamDecls<SightRule> d;
  d.choice("corner_rule", &SightRule::corners, default_rule,
           ChoiceTable<CornerRule>{{"allow", CornerRule::allow},
                                   {"no_squeeze", CornerRule::no_squeeze},
                                   {"no_corner_cut", CornerRule::no_corner_cut}},
           "how an edge passing exactly through a grid vertex between two diagonal cells is "
           "judged by the line-of-sight test: allow = always; no_squeeze = unless both side "
           "cells are blocked; no_corner_cut = only when both are free (the edge touches no "
           "obstacle cell)")
      .number(
          "clearance", [](SightRule& s) { return ClearanceField{s}; }, 0.0, 0.0, 10.0,
          "cells every edge keeps from obstacles: each obstacle cell centre at least "
          "clearance + 0.5 away (0 = the edge touches no obstacle cell)");
  return d;
}

ParamDecls<RrtSettings> rrt_decls() {
  ParamDecls<RrtSettings> d;
  d.number("step", &RrtSettings::step, 2.0, 0.05, 1e6,
           "extension step in cells: a new node lies at most this far from its parent (paper 000 "
           "gives no value)")
      .number("goal_bias", &RrtSettings::goal_bias, 0.05, 0.0, 1.0,
              "probability that a sample is the goal (RRT-Connect: the other tree's root) "
              "instead of a uniform point of the map")
      .integer("max_iterations", &RrtSettings::max_iterations, 50000, 1, 100000000,
               "samples drawn before giving up with failure `limit`")
      .choice("nn_index", &RrtSettings::index, NearestIndex::buckets,
              ChoiceTable<NearestIndex>{{"buckets", NearestIndex::buckets},
                                        {"kdtree", NearestIndex::kdtree}},
              "nearest-node index: buckets = uniform bucket grid, kdtree = nanoflann dynamic k-d "
              "tree (same answers up to exact ties; see perf/README.md)")
      .include(&RrtSettings::sight, segment_sight_decls(CornerRule::no_corner_cut));
  return d;
}

}  // namespace agv
