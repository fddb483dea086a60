#include "engine/judge/run_executor.h"

#include <cmath>
#include <exception>
#include <limits>
#include <new>
#include <optional>
#include <stdexcept>

#include "algos/search/dijkstra.h"
#include "core/any_angle.h"
#include "engine/judge/result_check.h"
#include "engine/judge/trajectory_judge.h"
#include "engine/judge/validator.h"
#include "engine/system/phase_clock.h"

namespace agv {

std::optional<double> MapReference::optimal_length(CornerRule rule, Scratch& scratch) {
  const auto r = static_cast<std::size_t>(rule);
  if (!known_[r]) {
    const PhaseScope timed(EnginePhase::reference);
    optimal_[r] = shortest_length(grid_, start_, goal_, rule, scratch);
    known_[r] = true;
  }
  return optimal_[r];
}

std::optional<double> MapReference::any_angle_length(Scratch& scratch) {
  if (!any_angle_known_) {
    const PhaseScope timed(EnginePhase::reference);
    any_angle_ = agv::any_angle_length(grid_, start_, goal_, model_.corner_rule,
                                       scratch.get<AnyAngleScratch>());
    any_angle_known_ = true;
  }
  return any_angle_;
}

namespace {

// The planner's call, timed on this thread's CPU clock; false when it threw (the outcome set).
bool call_planner(const Planner& planner, const PlanRequest& request, RunOutput& out) {
  const std::int64_t t0 = thread_cpu_ns();
  try {
    out.result = plan_checked(planner, request);
    out.plan_time_ns = thread_cpu_ns() - t0;
    add_phase_time(EnginePhase::planner, out.plan_time_ns);
    return true;
  } catch (const std::bad_alloc&) {
    out.outcome = Outcome::oom;
    out.message = "planner ran out of memory";
  } catch (const std::exception& e) {
    out.outcome = Outcome::crash;
    out.message = std::string("planner threw: ") + e.what();
  } catch (...) {
    out.outcome = Outcome::crash;
    out.message = "planner threw a non-standard exception";
  }
  out.plan_time_ns = thread_cpu_ns() - t0;
  add_phase_time(EnginePhase::planner, out.plan_time_ns);
  return false;
}

// The outcome of a run the planner gave up on; a claimed "no path" counts as such only when the
// map truly has none.
Outcome failure_outcome(const PlanResult& r, MapReference& map, Scratch& scratch) {
  switch (r.failure) {
    case Failure::limit:
      return Outcome::limit;
    case Failure::invalid_input:
      return Outcome::invalid_input;
    case Failure::invalid_path:
      return Outcome::invalid_path;
    case Failure::no_path:
    case Failure::none:
      break;
  }
  return map.optimal_length(r.rule, scratch) ? Outcome::missed_path : Outcome::no_path;
}

// length / reference, 1 for a zero reference, NaN (left) without one.
void set_ratio(double& metric, double length, std::optional<double> reference) {
  if (reference && *reference > 0.0) {
    metric = length / *reference;
  } else if (reference && *reference == 0.0) {
    metric = 1.0;
  }
}

// A successful run's metrics, every one computed here from the path (docs/METRICS.md).
void measure(const PlanResult& r, MapReference& map, Scratch& scratch,
             const MotionTimeParams& motion, const std::optional<TrajectoryVerdict>& verdict,
             RunOutput& out) {
  PathMetrics m = compute_path_metrics(map.grid(), r.path, motion, r.waypoints_before_sampling);
  if (verdict) apply_trajectory_verdict(*verdict, map.grid().cell_edge(), m);
  const auto values = metric_values(m);
  for (std::size_t i = 0; i < values.size(); ++i) {
    // The names are one list; a mismatch is a bug caught here, not a mislabelled report.
    if (values[i].first != kRunMetricNames[i]) throw std::logic_error("metric order mismatch");
    out.metrics[i] = values[i].second;
  }
  // The reference is the 8-connected optimum under the model's rule, which also keeps the model's
  // clearance (core/collision_model.h): exactly 1 for an optimal grid search under the model.
  set_ratio(out.metrics[kOptimalityMetric], m.path_length,
            map.optimal_length(map.model().corner_rule, scratch));
  // The lower bound no valid path beats (docs/METRICS.md "Any-angle reference"): >= 1 for every
  // planner, the distance to the best any robot on this grid could do.
  set_ratio(out.metrics[kAnyAngleMetric], m.path_length, map.any_angle_length(scratch));
  // A MovingAI scenario's optimum (docs/METRICS.md "scen_ratio"): 1 for an optimal grid search.
  set_ratio(out.metrics[kScenMetric], m.path_length, map.scenario_optimum());
}

}  // namespace

RunOutput execute_run(const Planner& planner, MapReference& map, Rng& rng, Scratch& scratch,
                      Deadline deadline, const MotionTimeParams& motion) {
  RunOutput out;
  out.metrics.fill(std::numeric_limits<double>::quiet_NaN());
  const PlanRequest request{map.grid(), map.start(), map.goal(), rng, scratch, deadline};
  if (!call_planner(planner, request, out)) return out;
  const PhaseScope timed(EnginePhase::judge);
  std::string why = result_contract_problem(out.result);
  if (why.empty()) why = phase_time_problem(out.result, out.plan_time_ns);
  if (!why.empty()) {
    // Nothing of it is recorded: its extras could pass for what the engine measures.
    out.outcome = Outcome::crash;
    out.message = "planner broke the result contract: " + why;
    out.result = PlanResult{};
    return out;
  }
  const PlanResult& r = out.result;
  // Before the planner's own extras, for every outcome the planner returned from: the work was
  // done whether or not the path is good.
  std::vector<std::pair<std::string, double>> counted;
  for (const auto& [name, value] : work_counter_values(r.work))
    counted.emplace_back(name, static_cast<double>(value));
  out.result.extra.insert(out.result.extra.begin(), counted.begin(), counted.end());

  // A simulated robot run (fusion planners) is judged from its executed trajectory by
  // engine/judge/trajectory_judge.h, never by the grid validator and its corner rule.
  std::optional<TrajectoryVerdict> verdict;
  if (r.trajectory) {
    verdict = judge_trajectory(map.grid(), map.start(), map.goal(), *r.trajectory);
    for (const auto& m : verdict->metrics) out.result.extra.push_back(m);
    if (verdict->outcome != Outcome::success) {
      out.outcome = verdict->outcome;
      out.message = std::move(verdict->message);
      return out;
    }
  }
  if (!r.ok()) {
    out.message = r.message;
    out.outcome = failure_outcome(r, map, scratch);
    return out;
  }
  if (!verdict) {
    // Under the sweep's model, whatever rule the planner searched with (docs/METRICS.md
    // "Collision model"): a looser variant's path that breaks it is invalid, never scored.
    const ValidationResult v =
        validate_path(map.grid(), map.start(), map.goal(), r.path, map.model().sight());
    if (!v.ok) {
      out.outcome = Outcome::invalid_path;
      out.message = v.reason;
      return out;
    }
  }
  out.outcome = Outcome::success;
  measure(r, map, scratch, motion, verdict, out);
  return out;
}

std::optional<double> MapReference::scenario_optimum() const {
  if (!scenario_optimum_) return std::nullopt;
  if (model_.corner_rule != CornerRule::no_corner_cut || model_.clearance != 0.0)
    return std::nullopt;
  return scenario_optimum_;
}

}  // namespace agv
