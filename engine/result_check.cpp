#include "engine/result_check.h"

#include <algorithm>
#include <set>
#include <string_view>

#include "engine/run_metrics.h"
#include "engine/trajectory_judge.h"

namespace agv {

namespace {

bool engine_measures(std::string_view name) {
  const auto in = [name](const auto& names) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  return in(kRunMetricNames) || in(kWorkCounterNames) || in(kJudgedMetricNames);
}

}  // namespace

std::string result_names_problem(const PlanResult& result) {
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

}  // namespace agv
