#include "core/collision_model.h"

#include <cstdio>
#include <numbers>

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

bool looser(CornerRule rule, CornerRule than) { return strictness(rule) < strictness(than); }

std::string to_string(const CollisionModel& model) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", model.clearance);
  return std::string(to_string(model.corner_rule)) + ", clearance " + buf;
}

}  // namespace agv
