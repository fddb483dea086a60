#pragma once
// The one collision model of a sweep (docs/METRICS.md "Collision model"): the corner rule and the
// clearance every planner's path is judged under, whatever rule the planner searched with. It is
// also the default of every planner's own corner rule and clearance parameters
// (algos/registry.h), so a planner run with its defaults searches under the rule it is judged by.

#include <string>

#include "core/corner_rule.h"
#include "core/line_of_sight.h"

namespace agv {

struct CollisionModel {
  // Default: the MovingAI convention, a point robot that may not touch an obstacle cell.
  CornerRule corner_rule = CornerRule::no_corner_cut;
  // Cells: every obstacle cell centre at least clearance + 0.5 from the path (SightRule::margin).
  double clearance = 0.0;

  // The test every path of the sweep is validated under: SightRule::cells(corner_rule) for
  // clearance 0, SightRule::margin(clearance, corner_rule) otherwise.
  SightRule sight() const;
  bool operator==(const CollisionModel&) const = default;
};

// The largest clearance a model with this corner rule may ask for: every move between adjacent
// free cell centres the rule allows keeps it, so the 8-connected optimum under the rule is also
// the optimum under the model. A diagonal move that passes an obstacle's corner (allowed by
// allow and no_squeeze) comes sqrt(2)/2 from that obstacle's centre: sqrt(2)/2 - 0.5; under
// no_corner_cut the nearest obstacle centre is a whole cell from every move: 0.5. A larger
// clearance would need an inflated map for the grid references (not built).
double max_model_clearance(CornerRule rule);

// Throws InputError naming `field` unless 0 <= model.clearance <= max_model_clearance(rule):
// the one check of a model's clearance, for a config's "collision" and `plan --clearance`.
void check_model_clearance(const CollisionModel& model, const std::string& field);

// Is `rule` looser than `than` (allows a move `than` refuses)? allow < no_squeeze < no_corner_cut.
bool looser(CornerRule rule, CornerRule than);

// "no_corner_cut, clearance 0" for messages.
std::string to_string(const CollisionModel& model);

}  // namespace agv
