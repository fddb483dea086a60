// Fusion (DWA) runs as ordinary sweep tasks: a small config with the moving-obstacle count as a
// swept planner parameter gives the same report on one and on two threads, every run ends in a
// counted outcome, the fusion metrics are aggregated, and the paired section compares the
// fusion planners with the baseline fusion on the same maps and the same worlds.
#include <gtest/gtest.h>

#include <string>

#include "engine/outputs/report.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/sweep_config.h"
#include "engine/sweep/sweep_runner.h"

namespace agv {
namespace {

using nlohmann::json;

SweepConfig small_fusion_config() {
  return parse_config(json{{"name", "fusion-test"},
                           {"seed", 5},
                           {"generators", {"uniform"}},
                           {"sizes", {16}},
                           {"densities", {0.1, 0.25}},
                           {"maps_per_cell", 6},
                           {"map", {{"endpoints", "corners"}, {"require_solvable", true}}},
                           {"planners",
                            {{{"name", "fusion_astar_dwa"},
                              {"label", "fusion_dyn0"},
                              {"params", {{"dynamic_obstacles", 0}}}},
                             {{"name", "fusion_astar_dwa"},
                              {"label", "fusion_dyn2"},
                              {"params", {{"dynamic_obstacles", 2}}}},
                             {{"name", "fusion_kin_dwa"}},
                             {{"name", "dwa"}}}},
                           {"baseline", "fusion_dyn0"},
                           {"time_limit_s", 60}});
}

std::string report_text(const SweepConfig& config, int threads) {
  SweepOptions options;
  options.threads = threads;
  const SweepResults r = run_sweep(config, options);
  return deterministic_part(build_report(config, r)).dump(1);
}

TEST(FusionSweep, ReportIsIdenticalOnOneAndTwoThreads) {
  const SweepConfig config = small_fusion_config();
  const std::string one = report_text(config, 1);
  const std::string two = report_text(config, 2);
  EXPECT_EQ(one, two);

  const json report = json::parse(one);
  for (const auto& cell : report["cells"]) {
    for (const auto& p : cell["planners"]) {
      EXPECT_EQ(p["runs"], 6) << cell["cell"] << " " << p["planner"];
      std::int64_t counted = p["successes"].get<std::int64_t>();
      for (const auto& [outcome, n] : p["failures"].items()) {
        counted += n.get<std::int64_t>();
        EXPECT_NE(outcome, "crash");
        EXPECT_NE(outcome, "invalid_path");
      }
      EXPECT_EQ(counted, 6) << "every run ends in a counted outcome";
      if (p["successes"].get<int>() > 0) {
        for (const char* metric : {"travelled_length", "sim_time_s", "min_clearance_static",
                                   "control_steps", "heading_change_sum", "mean_abs_w"})
          EXPECT_TRUE(p["metrics"].contains(metric)) << p["planner"] << " " << metric;
      }
    }
    EXPECT_EQ(cell["paired"].size(), 3U);
  }
}

}  // namespace
}  // namespace agv
