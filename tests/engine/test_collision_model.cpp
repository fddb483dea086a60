// One collision model per sweep (docs/METRICS.md "Collision model"): the config's model is the
// default of every planner's rule and clearance and what every path is judged under; a planner
// set looser is a labelled variant whose model-breaking paths are invalid_path.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "algos/registry.h"
#include "core/collision_model.h"
#include "core/input_error.h"
#include "engine/judge/validator.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/sweep_config.h"
#include "engine/sweep/map_task.h"
#include "tests/engine/config_error.h"
#include "tests/engine/for_each_run.h"
#include "tests/test_size.h"

namespace agv {
namespace {

using nlohmann::json;

json small_sweep(json collision, json planners) {
  json j = {{"name", "model"},
            {"seed", 14},
            {"generators", {"uniform", "blocks", "rooms"}},
            {"sizes", {16, 24}},
            {"densities", {0.15, 0.3}},
            {"maps_per_cell", 8},
            {"map", json::object()},
            {"planners", std::move(planners)}};
  if (!collision.is_null()) j["collision"] = std::move(collision);
  return j;
}

TEST(CollisionModel, DefaultIsTheMovingAiConvention) {
  const SweepConfig c = parse_config(small_sweep(nullptr, {"astar"}));
  EXPECT_EQ(c.collision.corner_rule, CornerRule::no_corner_cut);
  EXPECT_EQ(c.collision.clearance, 0.0);
  EXPECT_EQ(c.planners[0].resolved["corner_rule"], "no_corner_cut");
  EXPECT_EQ(config_as_run(c)["collision"],
            json({{"corner_rule", "no_corner_cut"}, {"clearance", 0.0}}));
  EXPECT_EQ(c.map.solvable_rule, CornerRule::no_corner_cut);
}

TEST(CollisionModel, ErrorsNameTheField) {
  EXPECT_NE(config_error(small_sweep({{"corner_rule", "diagonal"}}, {"astar"}))
                .find("collision.corner_rule"),
            std::string::npos);
  EXPECT_NE(config_error(small_sweep({{"radius", 1}}, {"astar"})).find("collision.radius: unknown"),
            std::string::npos);
  EXPECT_NE(config_error(small_sweep({{"clearance", -0.1}}, {"astar"})).find("collision.clearance"),
            std::string::npos);
  const std::string wide = config_error(small_sweep({{"clearance", 0.6}}, {"astar"}));
  EXPECT_NE(wide.find("collision.clearance: 0.6 is outside [0, 0.5]"), std::string::npos) << wide;
  const std::string squeeze =
      config_error(small_sweep({{"corner_rule", "allow"}, {"clearance", 0.3}}, {"astar"}));
  EXPECT_NE(squeeze.find("outside [0, 0.207107]"), std::string::npos) << squeeze;
}

TEST(CollisionModel, IsTheDefaultOfEveryPlannersRuleAndClearance) {
  const CollisionModel model{CornerRule::no_squeeze, 0.2};
  for (const PlannerInfo& info : planner_registry()) {
    const ConfiguredPlanner c = configure_planner(info.name, json::object(), "t", model);
    EXPECT_TRUE(c.looser_than_model.empty()) << info.name;
    for (const ParamSpec& spec : info.params) {
      const auto role = model_role(spec.name);
      if (!role) continue;
      const json& v = c.params.values().at(spec.name);
      SCOPED_TRACE(info.name + "." + spec.name);
      switch (*role) {
        case ModelRole::corner_rule:
          EXPECT_EQ(v, "no_squeeze");
          break;
        case ModelRole::margin:
          EXPECT_EQ(v.get<double>(), std::max(0.2, spec.default_value.get<double>()));
          break;
        case ModelRole::radius:
          EXPECT_EQ(v.get<double>(), std::max(0.7, spec.default_value.get<double>()));
          break;
      }
    }
  }
  // Every planner that tests segments off the grid's moves has a clearance to follow.
  for (const char* name :
       {"prm", "rrt", "birrt", "ma_star", "hma_star", "kin_astar", "alt_astar"}) {
    bool has = false;
    for (const ParamSpec& spec : find_planner(name)->params) {
      const auto role = model_role(spec.name);
      has = has || (role && *role != ModelRole::corner_rule);
    }
    EXPECT_TRUE(has) << name;
  }
}

TEST(CollisionModel, LooserPlannerIsALabelledVariant) {
  const json allow = {{"name", "astar"}, {"params", {{"corner_rule", "allow"}}}};
  const std::string unlabelled = config_error(small_sweep(nullptr, {"dijkstra", allow}));
  EXPECT_NE(unlabelled.find("planners[1].params.corner_rule: \"allow\" is looser"),
            std::string::npos)
      << unlabelled;
  json labelled = allow;
  labelled["label"] = "astar_allow";
  const SweepConfig c = parse_config(small_sweep(nullptr, {"astar", labelled}));
  const json run = config_as_run(c);
  EXPECT_EQ(run["planners"][1]["looser_than_model"], json({{"corner_rule", "allow"}}));
  EXPECT_FALSE(run["planners"][0].contains("looser_than_model"));
  EXPECT_EQ(config_as_run(parse_config(run)).dump(), run.dump());
  // A stated deviation that the parameters do not give is refused.
  json forged = run;
  forged["planners"][0]["looser_than_model"] = {{"corner_rule", "allow"}};
  EXPECT_NE(config_error(forged).find("planners[0].looser_than_model"), std::string::npos);
  // A clearance below the model's is looser too.
  const json thin = {{"name", "prm"}, {"params", {{"clearance", 0.1}}}};
  EXPECT_NE(
      config_error(small_sweep({{"clearance", 0.3}}, {"astar", thin})).find("params.clearance"),
      std::string::npos);
}

TEST(CollisionModel, EveryPathIsJudgedUnderTheModel) {
  for (const double clearance : {0.0, 0.3, 0.5}) {
    SCOPED_TRACE(clearance);
    const json planners = {
        "astar",
        "dijkstra",
        "bidir_astar",
        "ma_star",
        "hma_star",
        "alt_astar",
        "kin_astar",
        "prm",
        "rrt",
        "birrt",
        {{"name", "astar"}, {"label", "astar_allow"}, {"params", {{"corner_rule", "allow"}}}}};
    json sweep = small_sweep({{"clearance", clearance}}, planners);
    sweep["maps_per_cell"] = test::sized(8, 3);
    const SweepConfig config = parse_config(sweep);
    const CollisionModel& model = config.collision;
    int successes = 0, variant_invalid = 0, variant_runs = 0;
    for_each_run(config, [&](const MapTaskRun& run) {
      const std::string& label = config.planners[run.planner].label;
      const RunOutput& out = run.output;
      if (label == "astar_allow") {
        ++variant_runs;
        variant_invalid += out.outcome == Outcome::invalid_path;
      }
      if (out.outcome != Outcome::success) {
        // Planners that run with their defaults never break the model.
        if (label != "astar_allow") {
          EXPECT_NE(out.outcome, Outcome::invalid_path) << label << ": " << out.message;
        }
        return;
      }
      ++successes;
      const SweepCell& cell = run.context.plan.cell_of(run.task);
      Rng rng = map_rng(config.seed, cell, run.context.plan.map_index_of(run.task));
      const MapInstance inst = make_map(cell.spec, rng);
      EXPECT_TRUE(
          validate_path(inst.grid, inst.start, inst.goal, out.result.path, model.sight()).ok)
          << label;
      if (label == "astar" || label == "dijkstra" || label == "bidir_astar") {
        EXPECT_NEAR(out.metrics[kOptimalityMetric], 1.0, 1e-12) << label;
      }
    });
    EXPECT_GT(successes, 100);
    // On these maps corner squeezing helps often: the variant's paths are refused, not scored.
    EXPECT_GT(variant_invalid, variant_runs / 4);
  }
}

}  // namespace
}  // namespace agv
