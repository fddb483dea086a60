#include "engine/judge/outcome.h"

#include <array>

namespace agv {

namespace {
constexpr std::array<std::string_view, kOutcomeCount> kOutcomeNames = {"success",
                                                                       "no_path",
                                                                       "missed_path",
                                                                       "limit",
                                                                       "invalid_path",
                                                                       "invalid_input",
                                                                       "crash",
                                                                       "timeout",
                                                                       "oom",
                                                                       "collision_static",
                                                                       "collision_unknown",
                                                                       "collision_dynamic",
                                                                       "sim_timeout",
                                                                       "stuck"};
}

std::string_view to_string(Outcome outcome) { return kOutcomeNames[static_cast<int>(outcome)]; }

std::optional<Outcome> outcome_from_string(std::string_view name) {
  for (int i = 0; i < kOutcomeCount; ++i)
    if (kOutcomeNames[i] == name) return static_cast<Outcome>(i);
  return std::nullopt;
}

}  // namespace agv
