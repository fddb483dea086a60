#pragma once
// The per-run scalar metrics, in report order; NaN where a metric does not apply.
// The path metrics of engine/judge/metrics.h first (metric_values order), then the engine's own.
// The work counters a planner defines (algos/planner.h WorkCounters) are not among them: they
// travel under their own names with the planner's extra metrics (RunOutput::result.extra), so
// only planners that define one report it (docs/METRICS.md "Work counters").

#include <array>
#include <string_view>

#include "engine/judge/metrics.h"

namespace agv {

inline constexpr std::array<std::string_view, kPathMetricCount + 3> kRunMetricNames = {
    "path_length",   "path_length_m",    "waypoints",       "turns",         "turn_angle_rad",
    "max_turn_rad",  "smoothness_mean",  "smoothness_max",  "min_clearance", "min_clearance_m",
    "motion_time_s", "optimality_ratio", "any_angle_ratio", "scen_ratio"};
inline constexpr std::size_t kOptimalityMetric = kPathMetricCount;
inline constexpr std::size_t kAnyAngleMetric = kPathMetricCount + 1;
inline constexpr std::size_t kScenMetric = kPathMetricCount + 2;
using RunMetrics = std::array<double, kRunMetricNames.size()>;

}  // namespace agv
