#pragma once
// Two reports of one config (or of configs that differ only in planner parameters) compared:
// every non-timing difference by planner, cell and metric, and planning time per planner and
// cell as a geometric-mean ratio with a test (`agvbench compare`, README "Comparing two
// reports"). Google Benchmark's compare.py is the model: a ratio and a U test per benchmark, a
// geometric mean over all of them, an exit code a CI can gate on.

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "engine/judge/statistics.h"

namespace agv {

// Planning times of one sweep's runs, by (cell key, planner label), then map index.
using RunTimes = std::map<std::pair<std::string, std::string>, std::map<int, std::int64_t>>;

// Reads the plan times of a journal's records into `times`, and the sweep of each of its segments
// that names one into `sweep_ids` (engine/outputs/sweep_identity.h). Throws InputError naming
// file:line for a line that is not a record of this tool and journal version, or a record of a
// config other than the report's (its hash `config_hash`). A torn last line is ignored, as by
// resume.
void read_run_times(const std::string& journal, const std::string& config_hash, RunTimes& times,
                    std::set<std::string>& sweep_ids);

// The config hash a report's config belongs to (the journals' `config_hash`).
std::string report_config_hash(const nlohmann::json& report);

struct ValueDifference {
  std::string planner;    // label; "(sweep)" for sweep-wide fields, "(maps)" for a cell's maps
  std::string cell;       // cell key; empty for sweep-wide fields
  std::string metric;     // metric name, or the field ("success_rate", "failures.limit", ...);
                          // "paired:NAME" for the comparison of NAME against the baseline
  std::string field;      // summary field ("mean", "ci95[0]", ...); empty for a plain value
  nlohmann::json before;  // null where absent
  nlohmann::json after;
};

enum class TimingTest { wilcoxon, mann_whitney, none };

struct TimingComparison {
  std::string planner;
  std::string cell;
  std::size_t runs_before = 0;
  std::size_t runs_after = 0;
  std::size_t pairs = 0;  // runs of the same map in both (the Wilcoxon test's sample)
  // after / before: the geometric mean of the per-map ratios (paired), of the two geometric
  // means (unpaired), or of the two medians (no per-run times).
  double ratio = kNaN;
  Interval ci95;  // paired only: t interval of the mean log ratio, exponentiated
  TimingTest test = TimingTest::none;
  double p = kNaN;
  bool regression = false;
};

struct ReportComparison {
  std::vector<std::string> parameter_changes;  // "astar: heuristic \"octile\" -> \"euclidean\""
  std::vector<ValueDifference> differences;
  std::vector<TimingComparison> timing;  // by planner (config order), then cell
  // Per planner (config order): the geometric mean of its cells' finite ratios (no test: a
  // summary line for sweeps of many cells).
  std::vector<std::pair<std::string, double>> planner_ratios;
  double overall_ratio = kNaN;  // geometric mean of every finite ratio
  std::size_t overall_groups = 0;
  bool overall_regression = false;
  std::optional<double> fail_on_regression_pct;
  int exit_code() const;
};

// A regression is a ratio above 1 + pct/100 that the test finds significant (p < kAlpha; with
// no test, the ratio alone), or an overall ratio above it.
inline constexpr double kRegressionAlpha = 0.05;

// Throws InputError (exit 2) when either document is not an agvbench report of this schema, or
// the configs differ in more than planner parameters (the message lists what differs). The
// run times are optional (both or neither).
ReportComparison compare_reports(const nlohmann::json& before, const nlohmann::json& after,
                                 const RunTimes* before_runs, const RunTimes* after_runs,
                                 std::optional<double> fail_on_regression_pct);

std::string comparison_text(const ReportComparison& c);
nlohmann::json comparison_json(const ReportComparison& c);

}  // namespace agv
