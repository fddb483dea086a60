#include "engine/judge/result_check.h"

#include <algorithm>
#include <set>
#include <string_view>

#include "engine/judge/run_metrics.h"
#include "engine/judge/trajectory_judge.h"

namespace agv {

namespace {

bool engine_measures(std::string_view name) {
  const auto in = [name](const auto& names) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  return in(kRunMetricNames) || in(kWorkCounterNames) || in(kJudgedMetricNames);
}

// The enum fields, read as integers: an out-of-range value is not UB to read through the
// underlying type, only to use as the enum.
std::string enums_problem(const PlanResult& result) {
  const auto failure = static_cast<int>(result.failure);
  if (failure < static_cast<int>(Failure::none) ||
      failure > static_cast<int>(Failure::invalid_input))
    return "outcome (failure) " + std::to_string(failure) + " is not one of its values";
  const auto rule = static_cast<int>(result.rule);
  if (rule < static_cast<int>(CornerRule::allow) ||
      rule > static_cast<int>(CornerRule::no_corner_cut))
    return "corner rule " + std::to_string(rule) +
           " is not one of allow, no_squeeze, no_corner_cut";
  return "";
}

}  // namespace

std::string result_contract_problem(const PlanResult& result) {
  if (std::string why = enums_problem(result); !why.empty()) return why;
  std::set<std::string_view> seen;
  for (const auto& [name, value] : result.extra) {
    if (name.empty()) return "an extra metric without a name";
    if (engine_measures(name))
      return "extra metric \"" + name + "\" is a name the engine measures itself";
    if (!seen.insert(name).second) return "extra metric \"" + name + "\" given twice";
  }
  seen.clear();
  for (const PhaseTime& phase : result.phases) {
    if (phase.name.empty()) return "a phase without a name";
    if (!seen.insert(phase.name).second) return "phase \"" + phase.name + "\" given twice";
  }
  return "";
}

std::string phase_time_problem(const PlanResult& result, std::int64_t plan_time_ns) {
  for (const PhaseTime& phase : result.phases) {
    if (phase.ns < 0)
      return "phase \"" + phase.name + "\" time " + std::to_string(phase.ns) + " ns is negative";
    if (phase.ns > plan_time_ns)
      return "phase \"" + phase.name + "\" time " + std::to_string(phase.ns) +
             " ns is longer than the whole call (" + std::to_string(plan_time_ns) + " ns)";
  }
  return "";
}

}  // namespace agv
