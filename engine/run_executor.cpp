#include "engine/run_executor.h"

#include <cmath>
#include <exception>
#include <limits>
#include <new>
#include <optional>
#include <stdexcept>

#include "algos/search/dijkstra.h"
#include "core/any_angle.h"
#include "engine/trajectory_judge.h"
#include "engine/validator.h"

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

std::optional<double> MapReference::optimal_length(CornerRule rule, Scratch& scratch) {
  const auto r = static_cast<std::size_t>(rule);
  if (!known_[r]) {
    optimal_[r] = shortest_length(grid_, start_, goal_, rule, scratch);
    known_[r] = true;
  }
  return optimal_[r];
}

std::optional<double> MapReference::any_angle_length(Scratch& scratch) {
  if (!any_angle_known_) {
    any_angle_ = agv::any_angle_length(grid_, start_, goal_, model_.corner_rule,
                                       scratch.get<AnyAngleScratch>());
    any_angle_known_ = true;
  }
  return any_angle_;
}

RunOutput execute_run(const Planner& planner, MapReference& map, Rng& rng, Scratch& scratch,
                      Deadline deadline, const MotionTimeParams& motion) {
  RunOutput out;
  out.metrics.fill(std::numeric_limits<double>::quiet_NaN());
  const PlanRequest request{map.grid(), map.start(), map.goal(), rng, scratch, deadline};
  const std::int64_t t0 = thread_cpu_ns();
  try {
    out.result = plan_checked(planner, request);
  } catch (const std::bad_alloc&) {
    out.plan_time_ns = thread_cpu_ns() - t0;
    out.outcome = Outcome::oom;
    out.message = "planner ran out of memory";
    return out;
  } catch (const std::exception& e) {
    out.plan_time_ns = thread_cpu_ns() - t0;
    out.outcome = Outcome::crash;
    out.message = std::string("planner threw: ") + e.what();
    return out;
  } catch (...) {
    out.plan_time_ns = thread_cpu_ns() - t0;
    out.outcome = Outcome::crash;
    out.message = "planner threw a non-standard exception";
    return out;
  }
  out.plan_time_ns = thread_cpu_ns() - t0;
  const PlanResult& r = out.result;
  // Before the planner's own extras, for every outcome the planner returned from: the work was
  // done whether or not the path is good.
  std::vector<std::pair<std::string, double>> counted;
  for (const auto& [name, value] : work_counter_values(r.work))
    counted.emplace_back(name, static_cast<double>(value));
  out.result.extra.insert(out.result.extra.begin(), counted.begin(), counted.end());

  // A simulated robot run (fusion planners) is judged from its executed trajectory by
  // engine/trajectory_judge.h, never by the grid validator and its corner rule.
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
    switch (r.failure) {
      case Failure::limit:
        out.outcome = Outcome::limit;
        break;
      case Failure::invalid_input:
        out.outcome = Outcome::invalid_input;
        break;
      case Failure::invalid_path:
        out.outcome = Outcome::invalid_path;
        break;
      case Failure::no_path:
      case Failure::none:
        // A claimed "no path" counts as such only when the map truly has none.
        out.outcome = map.optimal_length(r.rule, scratch) ? Outcome::missed_path : Outcome::no_path;
        break;
    }
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
  PathMetrics m = compute_path_metrics(map.grid(), r.path, motion, 0, r.waypoints_before_sampling);
  if (verdict) apply_trajectory_verdict(*verdict, map.grid().cell_edge(), m);
  const auto values = metric_values(m);
  for (std::size_t i = 0; i < values.size(); ++i) {
    // The names are one list; a mismatch is a bug caught here, not a mislabelled report.
    if (values[i].first != kRunMetricNames[i]) throw std::logic_error("metric order mismatch");
    out.metrics[i] = values[i].second;
  }
  // The reference is the 8-connected optimum under the model's rule, which also keeps the model's
  // clearance (core/collision_model.h): exactly 1 for an optimal grid search under the model.
  if (auto opt = map.optimal_length(map.model().corner_rule, scratch); opt && *opt > 0.0) {
    out.metrics[kOptimalityMetric] = m.path_length / *opt;
  } else if (opt && *opt == 0.0) {
    out.metrics[kOptimalityMetric] = 1.0;
  }
  // The lower bound no valid path beats (docs/METRICS.md "Any-angle reference"): >= 1 for every
  // planner, the distance to the best any robot on this grid could do.
  if (auto bound = map.any_angle_length(scratch); bound && *bound > 0.0) {
    out.metrics[kAnyAngleMetric] = m.path_length / *bound;
  } else if (bound && *bound == 0.0) {
    out.metrics[kAnyAngleMetric] = 1.0;
  }
  // A MovingAI scenario's optimum (docs/METRICS.md "scen_ratio"): 1 for an optimal grid search.
  if (auto scen = map.scenario_optimum(); scen && *scen > 0.0) {
    out.metrics[kScenMetric] = m.path_length / *scen;
  } else if (scen && *scen == 0.0) {
    out.metrics[kScenMetric] = 1.0;
  }
  return out;
}

std::optional<double> MapReference::scenario_optimum() const {
  if (!scenario_optimum_) return std::nullopt;
  if (model_.corner_rule != CornerRule::no_corner_cut || model_.clearance != 0.0)
    return std::nullopt;
  return scenario_optimum_;
}

}  // namespace agv
