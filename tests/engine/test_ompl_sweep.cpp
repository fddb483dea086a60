// OMPL's planners (algos/ompl/) as ordinary sweep planners: on uniform and blocks maps, under a
// collision model with clearance, ompl_rrtconnect, ompl_rrtstar and ompl_prmstar (small budgets)
// return paths the engine's validator confirms, and the report is identical in every non-timing
// field on one and on two threads (each run seeded from its own Rng, whatever OMPL's process-wide
// seed sequence does). A variant set looser than the model (clearance 0) is judged under the
// model like any planner: some of its paths are invalid_path.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "algos/registry.h"
#include "engine/outputs/report.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/sweep_config.h"
#include "engine/sweep/sweep_runner.h"

namespace agv {
namespace {

using nlohmann::json;

constexpr int kMaps = 8;

SweepConfig ompl_config() {
  return parse_config(json{{"name", "ompl-test"},
                           {"seed", 11},
                           {"generators", {"uniform", "blocks"}},
                           {"sizes", {24}},
                           {"densities", {0.1, 0.25}},
                           {"maps_per_cell", kMaps},
                           {"collision", {{"corner_rule", "no_corner_cut"}, {"clearance", 0.2}}},
                           {"map", {{"endpoints", "corners"}, {"require_solvable", true}}},
                           {"planners",
                            {{{"name", "astar"}},
                             {{"name", "ompl_rrtconnect"}, {"params", {{"max_iterations", 5000}}}},
                             {{"name", "ompl_rrtstar"}, {"params", {{"max_iterations", 1500}}}},
                             {{"name", "ompl_prmstar"}, {"params", {{"samples", 300}}}},
                             {{"name", "ompl_rrtconnect"},
                              {"label", "ompl_rrtconnect_loose"},
                              {"params", {{"max_iterations", 5000}, {"clearance", 0.0}}}}}},
                           {"baseline", "astar"},
                           {"time_limit_s", 60}});
}

json report(const SweepConfig& config, int threads) {
  SweepOptions options;
  options.threads = threads;
  return deterministic_part(build_report(config, run_sweep(config, options)));
}

TEST(OmplSweep, PathsValidateAndReportIsIdenticalOnOneAndTwoThreads) {
  const SweepConfig config = ompl_config();
  const json one = report(config, 1);
  const json two = report(config, 2);
  EXPECT_EQ(one.dump(1), two.dump(1));

  int loose_invalid = 0;
  for (const auto& cell : one["cells"]) {
    for (const auto& p : cell["planners"]) {
      const std::string name = p["planner"].get<std::string>();
      SCOPED_TRACE(cell["cell"].dump() + " " + name);
      EXPECT_EQ(p["runs"], kMaps);
      std::int64_t counted = p["successes"].get<std::int64_t>();
      for (const auto& [outcome, n] : p["failures"].items()) {
        counted += n.get<std::int64_t>();
        EXPECT_NE(outcome, "crash");
        EXPECT_NE(outcome, "missed_path");
        if (outcome == "invalid_path") {
          // Only the variant looser than the model breaks it; the others follow the model.
          EXPECT_EQ(name, "ompl_rrtconnect_loose");
          loose_invalid += n.get<int>();
        }
      }
      EXPECT_EQ(counted, kMaps) << "every run ends in a counted outcome";
      // Small budgets still solve most of these 24x24 maps.
      if (name != "ompl_rrtconnect_loose") {
        EXPECT_GE(p["successes"].get<int>(), kMaps / 2);
      }
    }
  }
  // Clearance 0 against a model asking 0.2: paths that graze obstacles are caught.
  EXPECT_GT(loose_invalid, 0);
}

TEST(OmplSweep, ListsEveryOmplPlannerWithItsParameters) {
  const json planners = registry_json();
  for (const char* name : {"ompl_rrt", "ompl_rrtconnect", "ompl_rrtstar", "ompl_informed_rrtstar",
                           "ompl_bitstar", "ompl_prm", "ompl_prmstar", "ompl_lazyprmstar"}) {
    SCOPED_TRACE(name);
    const auto it = std::find_if(planners.begin(), planners.end(),
                                 [&](const json& p) { return p["name"] == name; });
    ASSERT_NE(it, planners.end());
    EXPECT_EQ((*it)["kind"], "sampling");
    EXPECT_EQ((*it)["proves_no_path"], false);
    bool budget = false, clearance = false;
    for (const auto& param : (*it)["params"]) {
      budget |= param["name"] == "max_iterations" || param["name"] == "samples";
      clearance |= param["name"] == "clearance";
    }
    EXPECT_TRUE(budget);
    EXPECT_TRUE(clearance);
  }
}

}  // namespace
}  // namespace agv
