#pragma once
// One run: one planner on one map. The planner proposes; the engine judges. Its path is
// validated independently and every metric is computed here from the path, so all planners are
// measured by one ruler (docs/METRICS.md). Used by the sweep runner and by `agvbench plan`.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "algos/planner.h"
#include "core/collision_model.h"
#include "engine/judge/metrics.h"
#include "engine/judge/outcome.h"
#include "engine/judge/run_metrics.h"

namespace agv {

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
  // The references computed so far, none computed here (the journal's map record keeps them).
  std::optional<double> known_optimal_length(CornerRule rule) const {
    const auto r = static_cast<std::size_t>(rule);
    return known_[r] ? optimal_[r] : std::nullopt;
  }
  std::optional<double> known_any_angle_length() const { return any_angle_; }

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
