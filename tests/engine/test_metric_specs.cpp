// Every metric the engine or a planner reports declares its direction
// (engine/judge/metric_specs.h), and the report's paired comparisons follow the declarations: wins
// in the declared direction, only metrics both planners define, the timing over every run.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "algos/registry.h"
#include "engine/judge/metric_specs.h"
#include "engine/judge/run_executor.h"
#include "engine/outputs/report.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/sweep_config.h"
#include "engine/sweep/sweep_runner.h"
#include "generators/map_generators.h"
#include "tests/test_size.h"

namespace agv {
namespace {

using nlohmann::json;

TEST(MetricSpecs, NamesAreUniqueAndEveryRunMetricIsDeclared) {
  std::set<std::string_view> names;
  for (const MetricSpec& s : kMetricSpecs) EXPECT_TRUE(names.insert(s.name).second) << s.name;
  for (std::string_view name : kRunMetricNames)
    EXPECT_NE(find_metric_spec(name), nullptr) << name << " has no direction";
  EXPECT_EQ(find_metric_spec("min_clearance")->better, Better::larger);
  EXPECT_EQ(find_metric_spec("turns")->ratio, RatioKind::shifted);
  EXPECT_EQ(find_metric_spec("plan_time_ns"), &kPlanTimeSpec);
  EXPECT_EQ(find_metric_spec("no_such_metric"), nullptr);
}

TEST(MetricSpecs, EveryExtraARegisteredPlannerReportsIsDeclared) {
  std::set<std::string> undeclared;
  for (const PlannerInfo& info : planner_registry()) {
    const ConfiguredPlanner c = configure_planner(info.name, json::object(), "test");
    for (int i = 0; i < test::sized(4, 2); ++i) {
      MapSpec spec;
      spec.generator = i % 2 ? "blocks" : "uniform";
      spec.width = 20;
      spec.height = 20;
      spec.density = 0.2;
      spec.endpoints = EndpointMode::corners;
      spec.require_solvable = true;
      Rng map_rng(14, static_cast<std::uint64_t>(i));
      const MapInstance m = make_map(spec, map_rng);
      MapReference ref(m.grid, m.start, m.goal);
      Rng rng(15, static_cast<std::uint64_t>(i));
      Scratch scratch;
      const RunOutput out =
          execute_run(*c.planner, ref, rng, scratch, Deadline::never(), MotionTimeParams{});
      for (const auto& [name, value] : out.result.extra)
        if (find_metric_spec(name) == nullptr) undeclared.insert(info.name + ": " + name);
    }
  }
  for (const std::string& u : undeclared) ADD_FAILURE() << u << " has no direction";
}

// Wins of `planner` over the baseline (label 0) on `metric`, recounted from the run slots: the
// planner better in the declared direction, beyond the 1e-9 relative tie.
int recount_wins(const SweepResults& r, std::size_t planner, std::string_view metric) {
  std::size_t index = 0;
  while (kRunMetricNames[index] != metric) ++index;
  const bool larger = find_metric_spec(metric)->better == Better::larger;
  int wins = 0;
  for (std::int64_t task = 0; task < r.plan.map_tasks(); ++task) {
    const RunSlot& a = r.run(task, planner);
    const RunSlot& b = r.run(task, 0);
    if (a.outcome != Outcome::success || b.outcome != Outcome::success) continue;
    const double c = a.metrics[index];
    const double base = b.metrics[index];
    if (std::abs(c - base) <= 1e-9 * std::max(std::abs(c), std::abs(base))) continue;
    wins += (larger ? c > base : c < base) ? 1 : 0;
  }
  return wins;
}

TEST(MetricSpecs, ReportComparesInTheDeclaredDirection) {
  // astar (the baseline), a sampling planner and another grid search.
  const json j = {{"name", "specs"},
                  {"seed", 3},
                  {"generators", {"uniform"}},
                  {"sizes", {16}},
                  {"densities", {0.2}},
                  {"maps_per_cell", 6},
                  {"planners", {"astar", "prm", "alt_astar"}},
                  {"baseline", "astar"}};
  const SweepConfig config = parse_config(j);
  SweepOptions options;
  options.threads = 1;
  const SweepResults results = run_sweep(config, options);
  const json report = build_report(config, results);
  EXPECT_EQ(report["schema_version"], 2);
  const json& cell = report["cells"][0];
  ASSERT_EQ(cell["paired"].size(), 2U);
  for (std::size_t p = 1; p <= 2; ++p) {
    const json& paired = cell["paired"][p - 1];
    const json& metrics = paired["metrics"];
    ASSERT_TRUE(metrics.contains("min_clearance")) << paired["planner"];
    EXPECT_EQ(metrics["min_clearance"]["better"], "larger");
    EXPECT_EQ(metrics["path_length"]["better"], "smaller");
    for (const char* name : {"min_clearance", "path_length", "turns", "waypoints"})
      EXPECT_EQ(metrics[name]["wins"], recount_wins(results, p, name))
          << paired["planner"] << " " << name;
    EXPECT_EQ(metrics["turns"]["ratio"], "shifted");
    EXPECT_EQ(metrics["turns"]["ratios_excluded"], 0);
    // Not compared: metre twins and the reference ratios.
    EXPECT_FALSE(metrics.contains("path_length_m"));
    EXPECT_FALSE(metrics.contains("optimality_ratio"));
    // A metric only one side reports is absent: astar has no PRM edge checks.
    EXPECT_FALSE(metrics.contains("edge_checks"));
    EXPECT_FALSE(metrics.contains("roadmap_edges"));
    for (const auto& [name, comparison] : metrics.items()) {
      ASSERT_NE(find_metric_spec(name), nullptr) << name;
      EXPECT_TRUE(find_metric_spec(name)->paired) << name;
      EXPECT_TRUE(comparison.contains("wilcoxon_exact")) << name;
      EXPECT_TRUE(comparison.contains("difference_ci95")) << name;
    }
    EXPECT_EQ(paired["timing"]["plan_time_ns"]["pairs"], 6) << "timing over every run";
  }
}

}  // namespace
}  // namespace agv
