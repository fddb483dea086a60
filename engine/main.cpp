// agvbench: sweeps, single plans, MovingAI scenarios and the planner registry.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "core/input_error.h"
#include "engine/cli_numbers.h"
#include "engine/commands.h"
#include "engine/environment.h"
#include "engine/isolated_worker.h"
#include "engine/plugins.h"

namespace {

// Every numeric option goes through engine/cli_numbers.h: the whole argument one number in the
// range (the config's where it has the same setting), canonicalised before CLI11 converts it
// (transform, not check: CLI11 hands a check a copy of the text).
CLI::Validator integer_in(agv::IntRange range) {
  return CLI::Validator(
      [range](std::string& text) { return agv::cli_integer_error(text, range); },
      "INT in [" + std::to_string(range.lo) + ", " + std::to_string(range.hi) + "]");
}
CLI::Validator number_in(agv::NumberRange range) {
  return CLI::Validator([range](std::string& text) { return agv::cli_number_error(text, range); },
                        "NUMBER");
}

// --isolate-timeout: above the longest per-run limit a config can set, twice over (the default
// is 2 x time_limit_s + 1 s).
constexpr agv::NumberRange kIsolateTimeoutRange{agv::kTimeLimitRange.lo,
                                                2 * agv::kTimeLimitRange.hi + 1};
constexpr agv::IntRange kIsolateMemoryRange{64, 1LL << 40};
// scen --tolerance: relative and absolute; 1 already accepts any length up to twice the optimum.
constexpr agv::NumberRange kToleranceRange{0.0, 1.0};
// compare --fail-on-regression: percent of planning time.
constexpr agv::NumberRange kRegressionPctRange{0.0, 1e6};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"agvbench: a parallel benchmark engine for AGV grid path planners"};
  app.require_subcommand(1);
  app.set_version_flag("--version", agv::version_text());

  agv::RunCommand run;
  auto* run_cmd = app.add_subcommand("run", "run a sweep and write its JSON report");
  run_cmd->add_option("config", run.config, "sweep config (default: configs/default.json)");
  run_cmd->add_option("--threads", run.threads, "worker threads (0 = all)")
      ->transform(integer_in(agv::kThreadsRange));
  run_cmd->add_option("--out", run.out, "report path (overrides the config)");
  run_cmd->add_option("--runs-out", run.runs_out, "JSON Lines file of per-run records");
  run_cmd->add_option("--resume", run.resume,
                      "journal of an interrupted run: skip its runs, append to it");
  run_cmd->add_option("--shard", run.shard, "i/N: run only the i-th of N slices (split by map)");
  run_cmd->add_flag("--isolate", run.isolate, "run planners in worker processes (fault isolation)");
  run_cmd
      ->add_option("--isolate-timeout", run.isolate_timeout_s,
                   "hard wall-clock limit per run in seconds (default 2x time_limit_s + 1)")
      ->transform(number_in(kIsolateTimeoutRange));
  run_cmd
      ->add_option("--isolate-memory", run.isolate_memory_mb, "address-space cap per worker, MiB")
      ->transform(integer_in(kIsolateMemoryRange));
  run_cmd->add_flag("--quiet", run.quiet, "no progress meter and no summary table");
  run_cmd->add_option("--db", run.db, "SQLite database: append the sweep as one experiment");

  std::string merge_config, merge_out;
  std::vector<std::string> merge_journals;
  auto* merge_cmd = app.add_subcommand("merge", "build one report from shard or partial journals");
  merge_cmd->add_option("journals", merge_journals, "JSON Lines journals")->required();
  merge_cmd->add_option("--config", merge_config, "the sweep config the journals belong to")
      ->required();
  merge_cmd->add_option("--out", merge_out, "report path (default: the config's)");

  long long worker_memory = 0;
  auto* worker_cmd = app.add_subcommand("worker", "");  // internal: an --isolate worker process
  worker_cmd->add_option("--memory-mb", worker_memory)
      ->transform(integer_in({0, kIsolateMemoryRange.hi}));
  worker_cmd->group("");

  std::string validate_path;
  auto* validate_cmd = app.add_subcommand("validate", "check a sweep config without running it");
  validate_cmd->add_option("config", validate_path, "sweep config")->required();

  bool list_json = false;
  auto* list_cmd =
      app.add_subcommand("list", "list planners and map generators, their parameters and defaults");
  list_cmd->add_flag("--json", list_json,
                     "print the registries as one JSON object {planners, generators}");
  agv::ListOptions list;
  list_cmd->add_option("names", list.names, "only these planners or generators");
  list_cmd->add_flag("--brief", list.brief, "one line per planner and generator");

  agv::ExportCommand export_args;
  auto* export_cmd =
      app.add_subcommand("export", "append a sweep's journals to an SQLite database");
  export_cmd->add_option("journals", export_args.journals, "JSON Lines journals")->required();
  export_cmd->add_option("--config", export_args.config, "the sweep config of the journals")
      ->required();
  export_cmd->add_option("--sqlite", export_args.sqlite, "database (created or appended to)")
      ->required();

  agv::CompareCommand compare;
  auto* compare_cmd = app.add_subcommand(
      "compare", "compare two reports: non-timing differences and planning-time ratios");
  compare_cmd->add_option("before", compare.before, "report BEFORE")->required();
  compare_cmd->add_option("after", compare.after, "report AFTER")->required();
  compare_cmd->add_option("--runs-before", compare.runs_before,
                          "BEFORE's journals (per-run times: paired tests)");
  compare_cmd->add_option("--runs-after", compare.runs_after, "AFTER's journals");
  double regression_pct = 0.0;
  auto* regression_opt =
      compare_cmd
          ->add_option("--fail-on-regression", regression_pct,
                       "exit 1 when planning time grows by more than PCT percent (default: never)")
          ->transform(number_in(kRegressionPctRange));
  compare_cmd->add_flag("--json", compare.json, "print the comparison as JSON");

  agv::PlanCommand plan;
  auto* plan_cmd = app.add_subcommand("plan", "run planners on one map and show the paths");
  plan_cmd->add_option("--planner", plan.planners, "planner name (repeatable)");
  plan_cmd->add_option("--param", plan.params, "KEY=VALUE parameter (repeatable)");
  plan_cmd->add_option("--map", plan.map_file, "MovingAI .map file (else a generated grid)");
  plan_cmd->add_option("--generator", plan.generator, "generator for a generated grid");
  plan_cmd->add_option("--gen-param", plan.gen_params,
                       "KEY=VALUE shape parameter of the generator (repeatable)");
  plan_cmd->add_option("--size", plan.size, "N or WxH");
  plan_cmd->add_option("--density", plan.density, "obstacle density")
      ->transform(number_in(agv::kDensityRange));
  plan_cmd->add_option("--endpoints", plan.endpoints,
                       "corners, random, or fixed (the cells of --start and --goal)");
  plan_cmd->add_option("--seed", plan.seed, "sweep seed")->transform(integer_in(agv::kSeedRange));
  plan_cmd->add_option("--map-index", plan.map_index, "map index within its sweep cell")
      ->transform(integer_in(agv::kMapIndexRange));
  plan_cmd->add_option("--start", plan.start, "start cell x,y (overrides the endpoints)");
  plan_cmd->add_option("--goal", plan.goal, "goal cell x,y (overrides the endpoints)");
  plan_cmd->add_option("--corner-rule", plan.corner_rule,
                       "collision model: allow, no_squeeze or no_corner_cut (default)");
  plan_cmd
      ->add_option("--clearance", plan.clearance,
                   "collision model: cells from obstacle centres beyond half a cell (default 0)")
      ->transform(number_in(agv::kFiniteRange));
  plan_cmd->add_flag("--json", plan.json, "print the result as JSON instead of text");
  plan_cmd->add_option("--json-out", plan.json_out, "also write the result JSON to this file");
  plan_cmd->add_flag("!--no-ascii", plan.ascii, "do not draw the map");

  agv::ScenCommand scen;
  auto* scen_cmd = app.add_subcommand("scen", "run every query of a MovingAI scenario file");
  scen_cmd->add_option("map", scen.map_file, "MovingAI .map file")->required();
  scen_cmd->add_option("scen", scen.scen_file, "MovingAI .scen file")->required();
  scen_cmd->add_option("--planner", scen.planner, "planner name (default astar)");
  scen_cmd->add_option("--param", scen.params, "KEY=VALUE parameter (repeatable)");
  scen_cmd
      ->add_option("--tolerance", scen.tolerance,
                   "relative (and absolute) tolerance on optimal lengths, in [0, 1]")
      ->transform(number_in(kToleranceRange));
  scen_cmd->add_flag("--json", scen.json, "print the summary as JSON");

  // Planner plugins (engine/plugins.h), loaded before the command runs.
  std::vector<std::string> plugins;
  for (auto* cmd : {run_cmd, merge_cmd, validate_cmd, list_cmd, plan_cmd, scen_cmd})
    cmd->add_option("--plugin", plugins, "planner plugin (shared library) to load (repeatable)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }

  try {
    for (const auto& path : plugins) agv::load_plugin(path, "--plugin");
    if (*run_cmd) return agv::command_run(run);
    if (*merge_cmd) return agv::command_merge(merge_config, merge_journals, merge_out);
    if (*worker_cmd) return agv::worker_main(worker_memory);
    if (*validate_cmd) return agv::command_validate(validate_path);
    if (*list_cmd) {
      list.json = list_json;
      return agv::command_list(list);
    }
    if (*export_cmd) return agv::command_export(export_args);
    if (*compare_cmd) {
      if (*regression_opt) compare.fail_on_regression_pct = regression_pct;
      return agv::command_compare(compare);
    }
    if (*plan_cmd) return agv::command_plan(plan);
    if (*scen_cmd) return agv::command_scen(scen);
  } catch (const agv::InputError& e) {
    std::fprintf(stderr, "agvbench: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "agvbench: failed: %s\n", e.what());
    return 1;
  }
  return 1;
}
