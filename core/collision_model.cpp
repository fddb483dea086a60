#include "core/collision_model.h"

#include <cstdio>
#include <numbers>

#include "core/input_error.h"

namespace agv {

SightRule CollisionModel::sight() const {
  return clearance > 0.0 ? SightRule::margin(clearance, corner_rule)
                         : SightRule::cells(corner_rule);
}

double max_model_clearance(CornerRule rule) {
  return rule == CornerRule::no_corner_cut ? 0.5 : std::numbers::sqrt2 / 2.0 - 0.5;
}

namespace {
int strictness(CornerRule rule) {
  switch (rule) {
    case CornerRule::allow:
      return 0;
    case CornerRule::no_squeeze:
      return 1;
    case CornerRule::no_corner_cut:
      return 2;
  }
  return 0;
}
}  // namespace

void check_model_clearance(const CollisionModel& model, const std::string& field) {
  const double max = max_model_clearance(model.corner_rule);
  if (model.clearance >= 0.0 && model.clearance <= max) return;
  char range[96];
  std::snprintf(range, sizeof range, "%g is outside [0, %.6g]", model.clearance, max);
  throw InputError(field + ": " + range + ", the range a model with corner_rule " +
                   std::string(to_string(model.corner_rule)) +
                   " supports (every grid move between free cell centres must keep it; an "
                   "inflated map for larger clearances is not built)");
}

bool looser(CornerRule rule, CornerRule than) { return strictness(rule) < strictness(than); }

std::string to_string(const CollisionModel& model) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", model.clearance);
  return std::string(to_string(model.corner_rule)) + ", clearance " + buf;
}

}  // namespace agv
