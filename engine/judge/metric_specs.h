#pragma once
// Which way every metric improves, and how a paired comparison forms its ratio
// (docs/METRICS.md "Metric directions"). One table for the engine's run metrics
// (kRunMetricNames), the work counters, the planners' extras and the fusion judge's metrics;
// tests/engine/test_report.cpp checks that every run metric and every extra a registered planner
// reports is declared here, so none is compared in the wrong direction or silently left out.

#include <array>
#include <string_view>

#include "engine/judge/statistics.h"

namespace agv {

struct MetricSpec {
  std::string_view name;
  Better better = Better::smaller;
  RatioKind ratio = RatioKind::plain;
  // false: summarised per planner but never compared in pairs, because the comparison would
  // repeat another one (a metre twin of a cell metric, a ratio to the same per-map reference
  // as path_length) or because neither direction is better (a descriptive count).
  bool paired = true;
};

inline constexpr Better kSmaller = Better::smaller;
inline constexpr Better kLarger = Better::larger;
inline constexpr RatioKind kPlain = RatioKind::plain;
inline constexpr RatioKind kShifted = RatioKind::shifted;

// In the order paired comparisons are computed (a report lists them by name).
inline constexpr std::array kMetricSpecs = {
    // Path metrics (engine/judge/metrics.h).
    MetricSpec{"path_length", kSmaller, kPlain},
    MetricSpec{"path_length_m", kSmaller, kPlain, false},
    MetricSpec{"waypoints", kSmaller, kShifted},
    MetricSpec{"turns", kSmaller, kShifted},
    MetricSpec{"turn_angle_rad", kSmaller, kPlain},
    MetricSpec{"max_turn_rad", kSmaller, kPlain},
    MetricSpec{"smoothness_mean", kSmaller, kPlain},
    MetricSpec{"smoothness_max", kSmaller, kPlain},
    MetricSpec{"min_clearance", kLarger, kPlain},
    MetricSpec{"min_clearance_m", kLarger, kPlain, false},
    MetricSpec{"motion_time_s", kSmaller, kPlain},
    // The per-map references: their ratios between two planners equal path_length's.
    MetricSpec{"optimality_ratio", kSmaller, kPlain, false},
    MetricSpec{"any_angle_ratio", kSmaller, kPlain, false},
    // A map source's .scen optimum (docs/METRICS.md "scen_ratio"): ratios equal path_length's.
    MetricSpec{"scen_ratio", kSmaller, kPlain, false},
    // Work counters (docs/METRICS.md "Work counters"): counts, 0 on trivial maps.
    MetricSpec{"search_expansions", kSmaller, kShifted},
    MetricSpec{"samples", kSmaller, kShifted},
    MetricSpec{"ant_steps", kSmaller, kShifted},
    MetricSpec{"pso_evaluations", kSmaller, kShifted},
    MetricSpec{"collision_checks", kSmaller, kShifted},
    // Planner extras (docs/METRICS.md "Planner-specific metrics").
    MetricSpec{"generated_nodes", kSmaller, kShifted},
    MetricSpec{"edge_checks", kSmaller, kShifted},
    MetricSpec{"iterations", kSmaller, kShifted},
    MetricSpec{"key_points", kSmaller, kShifted, false},  // = waypoints for the grid pipelines
    MetricSpec{"roadmap_edges", kSmaller, kShifted, false},
    MetricSpec{"pso_windows", kSmaller, kShifted, false},
    MetricSpec{"pso_improvements", kLarger, kShifted, false},
    MetricSpec{"successful_ants", kLarger, kShifted, false},
    MetricSpec{"replans", kSmaller, kShifted, false},
    // Fusion runs (engine/judge/trajectory_judge.h).
    MetricSpec{"travelled_length", kSmaller, kPlain},
    MetricSpec{"sim_time_s", kSmaller, kPlain},
    MetricSpec{"control_steps", kSmaller, kShifted},
    MetricSpec{"min_clearance_static", kLarger, kPlain},
    MetricSpec{"min_clearance_dynamic", kLarger, kPlain},
    MetricSpec{"heading_change_sum", kSmaller, kPlain},
    MetricSpec{"mean_abs_w", kSmaller, kPlain},
};

// The timing comparison (plan_time_ns, over every run: docs/METRICS.md "Statistics conventions").
inline constexpr MetricSpec kPlanTimeSpec{"plan_time_ns", kSmaller, kPlain};

// nullptr for a name the table does not declare (such a metric is summarised, never compared).
constexpr const MetricSpec* find_metric_spec(std::string_view name) {
  for (const MetricSpec& s : kMetricSpecs)
    if (s.name == name) return &s;
  return name == kPlanTimeSpec.name ? &kPlanTimeSpec : nullptr;
}

}  // namespace agv
