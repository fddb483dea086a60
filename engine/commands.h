#pragma once
// The subcommands of `agvbench`. Each returns the process exit code: 0 ok, 1 runtime failure,
// 2 bad input. InputError escaping a command is turned into exit 2 by main.

#include <optional>
#include <string>
#include <vector>

#include "engine/sweep_config.h"

namespace agv {

struct RunCommand {
  std::string config = "configs/default.json";
  int threads = -1;  // -1: the config's value
  std::string out;   // overrides the config's report path
  std::string runs_out;
  std::string resume;  // journal to resume from (appended to)
  std::string shard;   // "i/N"
  bool isolate = false;
  double isolate_timeout_s = 0.0;  // 0: twice the config's time limit + 1 s
  long long isolate_memory_mb = 4096;
  bool quiet = false;
  std::string db;  // SQLite database the sweep is appended to as one experiment (results_db.h)
};
// Exit code 130 when interrupted by SIGINT/SIGTERM (the report is written, marked incomplete).
int command_run(const RunCommand& cmd);

// Builds one report from the journals of a sharded (or interrupted) sweep.
int command_merge(const std::string& config_path, const std::vector<std::string>& journals,
                  const std::string& out);

// The config file, found from any working directory: as given, else in the source checkout.
std::string locate_config(const std::string& path);

int command_validate(const std::string& config_path);

// A sweep's journals as one experiment of an SQLite database (engine/results_db.h).
struct ExportCommand {
  std::vector<std::string> journals;
  std::string config;
  std::string sqlite;
};
int command_export(const ExportCommand& cmd);

// Two reports compared (engine/report_compare.h): exit 0 no difference, 1 a non-timing
// difference or a timing regression, 2 bad input (configs that differ beyond planner params).
struct CompareCommand {
  std::string before;
  std::string after;
  std::vector<std::string> runs_before;  // the sweeps' journals: per-run times, paired tests
  std::vector<std::string> runs_after;
  std::optional<double> fail_on_regression_pct;  // none: timing never fails
  bool json = false;
};
int command_compare(const CompareCommand& cmd);

// `list NAME... [--brief]`: only the named planners or generators (unknown: InputError).
struct ListOptions {
  bool json = false;
  bool brief = false;
  std::vector<std::string> names;
};
int command_list(const ListOptions& options);

// Planners and generators; as_json: one object {"planners": [...], "generators": [...]}.
int command_list(bool as_json);

struct PlanCommand {
  std::vector<std::string> planners = {"astar"};
  std::vector<std::string> params;  // "key=value", applied to every planner that declares key
  std::string map_file;             // a MovingAI .map; else a generated grid
  std::string generator = "uniform";
  std::vector<std::string> gen_params;  // "key=value", the generator's shape parameters
  std::string size = "32";
  double density = 0.2;
  std::string endpoints = "corners";
  bool require_solvable = true;
  long long seed = 1;
  int map_index = 0;
  std::string start;  // "x,y"; required with a map file
  std::string goal;
  bool json = false;
  bool ascii = true;
  std::string json_out;  // write the result document to this file
  // The collision model every path is judged under, and every planner's default rule and
  // clearance (as a sweep's "collision").
  std::string corner_rule = "no_corner_cut";
  double clearance = 0.0;
};
int command_plan(const PlanCommand& cmd);

struct ScenCommand {
  std::string map_file;
  std::string scen_file;
  std::string planner = "astar";
  std::vector<std::string> params;
  bool json = false;
  double tolerance = 1e-5;  // relative; files in the wild carry 6 significant digits
};
int command_scen(const ScenCommand& cmd);

}  // namespace agv
