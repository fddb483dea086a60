#pragma once
// One run: one planner on one map. The planner proposes; the engine judges. Its path is
// validated independently and every metric is computed here from the path, so all planners are
// measured by one ruler (docs/METRICS.md). Used by the sweep runner and by `agvbench plan`.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "algos/planner.h"
#include "core/collision_model.h"
#include "engine/metrics.h"

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
  // engine/trajectory_judge.h; reaching the goal is `success`.
  collision_static,   // the robot disc hit a grid obstacle
  collision_unknown,  // ... an unknown static cell (one the global planner did not see)
  collision_dynamic,  // ... a moving obstacle
  sim_timeout,        // simulated time limit reached before the goal
  stuck,              // no admissible moving velocity for the planner's stuck_steps
};
inline constexpr int kOutcomeCount = 14;
std::string_view to_string(Outcome outcome);
std::optional<Outcome> outcome_from_string(std::string_view name);

// The per-run scalar metrics, in report order; NaN where a metric does not apply.
// The path metrics of engine/metrics.h first (metric_values order), then the engine's own.
// The work counters a planner defines (algos/planner.h WorkCounters) are not among them: they
// travel under their own names with the planner's extra metrics (RunOutput::result.extra), so
// only planners that define one report it (docs/METRICS.md "Work counters").
inline constexpr std::array<std::string_view, kPathMetricCount + 3> kRunMetricNames = {
    "path_length",   "path_length_m",    "waypoints",       "turns",         "turn_angle_rad",
    "max_turn_rad",  "smoothness_mean",  "smoothness_max",  "min_clearance", "min_clearance_m",
    "motion_time_s", "optimality_ratio", "any_angle_ratio", "scen_ratio"};
inline constexpr std::size_t kOptimalityMetric = kPathMetricCount;
inline constexpr std::size_t kAnyAngleMetric = kPathMetricCount + 1;
inline constexpr std::size_t kScenMetric = kPathMetricCount + 2;
using RunMetrics = std::array<double, kRunMetricNames.size()>;

// What the engine knows about a map, shared by every planner run on it.
class MapReference {
 public:
  MapReference(const Grid& grid, Cell start, Cell goal, const CollisionModel& model = {})
      : grid_(grid), start_(start), goal_(goal), model_(model) {}
  const Grid& grid() const { return grid_; }
  // What every path on this map is judged under.
  const CollisionModel& model() const { return model_; }
  Cell start() const { return start_; }
  Cell goal() const { return goal_; }
  // Optimal 8-connected length under `rule` (Dijkstra), computed once per rule; nullopt when
  // start and goal do not connect under it.
  std::optional<double> optimal_length(CornerRule rule, Scratch& scratch);
  // The any-angle optimum under the model's rule (core/any_angle.h), computed once: a lower
  // bound of every path valid under the model (its clearance only removes paths).
  std::optional<double> any_angle_length(Scratch& scratch);
  // The sweep does without the any-angle reference: any_angle_length is nullopt, never computed.
  void skip_any_angle() {
    any_angle_known_ = true;
    any_angle_.reset();
  }
  // A MovingAI scenario's optimal length for this query (a map source's .scen query).
  void set_scenario_optimum(double length) { scenario_optimum_ = length; }
  // The scenario's optimum where the model is the scenario's convention (MovingAI: no corner
  // cutting, clearance 0, octile lengths), so the two lengths measure the same thing.
  std::optional<double> scenario_optimum() const;

 private:
  const Grid& grid_;
  Cell start_;
  Cell goal_;
  CollisionModel model_;
  std::array<bool, 3> known_{};
  std::array<std::optional<double>, 3> optimal_{};
  bool any_angle_known_ = false;
  std::optional<double> any_angle_;
  std::optional<double> scenario_optimum_;
};

struct RunOutput {
  Outcome outcome = Outcome::crash;
  std::string message;
  PlanResult result;
  RunMetrics metrics{};
  std::int64_t plan_time_ns = 0;
};

RunOutput execute_run(const Planner& planner, MapReference& map, Rng& rng, Scratch& scratch,
                      Deadline deadline, const MotionTimeParams& motion);

}  // namespace agv
