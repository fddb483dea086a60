#include "core/corner_rule.h"

namespace agv {

std::string_view to_string(CornerRule rule) {
  switch (rule) {
    case CornerRule::allow:
      return "allow";
    case CornerRule::no_squeeze:
      return "no_squeeze";
    case CornerRule::no_corner_cut:
      return "no_corner_cut";
  }
  return "allow";
}

std::optional<CornerRule> corner_rule_from_string(std::string_view name) {
  if (name == "allow") return CornerRule::allow;
  if (name == "no_squeeze") return CornerRule::no_squeeze;
  if (name == "no_corner_cut") return CornerRule::no_corner_cut;
  return std::nullopt;
}

}  // namespace agv
