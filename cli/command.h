#pragma once
// The subcommands of `agvbench`, one file each (cli/cmd_*.cpp). Each adds its subcommand and
// options to the app and says how it runs once the command line is parsed; main only
// dispatches. A command's run returns the process exit code: 0 ok, 1 runtime failure, 2 bad
// input; an InputError escaping it is turned into exit 2 by main.

#include <CLI/CLI.hpp>
#include <functional>

namespace agv {

struct Command {
  CLI::App* sub = nullptr;
  std::function<int()> run;
  bool takes_plugins =
      true;  // --plugin: planner plugins loaded before it runs (engine/plan/plugins.h)
};

Command add_run_command(CLI::App& app);       // cli/cmd_run.cpp
Command add_merge_command(CLI::App& app);     // cli/cmd_merge.cpp
Command add_worker_command(CLI::App& app);    // cli/cmd_worker.cpp
Command add_validate_command(CLI::App& app);  // cli/cmd_validate.cpp
Command add_list_command(CLI::App& app);      // cli/cmd_list.cpp
Command add_export_command(CLI::App& app);    // cli/cmd_export.cpp
Command add_compare_command(CLI::App& app);   // cli/cmd_compare.cpp
Command add_digest_command(CLI::App& app);    // cli/cmd_digest.cpp
Command add_plan_command(CLI::App& app);      // cli/cmd_plan.cpp
Command add_scen_command(CLI::App& app);      // cli/cmd_scen.cpp

}  // namespace agv
