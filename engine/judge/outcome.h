#pragma once
// How a run ended, as the engine judged it (never as the planner claims it): the report's
// outcome counts and every success-conditioned statistic read it (docs/METRICS.md "Outcomes").

#include <optional>
#include <string_view>

namespace agv {

enum class Outcome {
  success,
  no_path,        // planner found none and none exists under its corner rule (checked)
  missed_path,    // planner reported no path, but one exists under its corner rule
  limit,          // time or iteration cap
  invalid_path,   // returned path failed validation
  invalid_input,  // planner refused the query
  crash,          // planner threw, or (isolated) its process died of a signal
  timeout,        // isolated: killed at the hard wall-clock limit
  oom,            // isolated: ran out of its address-space cap
  // Simulated robot runs (fusion planners), judged from the executed trajectory by
  // engine/judge/trajectory_judge.h; reaching the goal is `success`.
  collision_static,   // the robot disc hit a grid obstacle
  collision_unknown,  // ... an unknown static cell (one the global planner did not see)
  collision_dynamic,  // ... a moving obstacle
  sim_timeout,        // simulated time limit reached before the goal
  stuck,              // no admissible moving velocity for the planner's stuck_steps
};
inline constexpr int kOutcomeCount = 14;
std::string_view to_string(Outcome outcome);
std::optional<Outcome> outcome_from_string(std::string_view name);

}  // namespace agv
