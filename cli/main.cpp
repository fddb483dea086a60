// agvbench: sweeps, single plans, MovingAI scenarios and the planner registry. Each subcommand
// is a file of its own (cli/command.h); this only parses, loads the plugins and dispatches.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli/command.h"
#include "core/input_error.h"
#include "core/printable.h"
#include "core/simd_path.h"
#include "engine/plan/plugins.h"
#include "engine/system/environment.h"

namespace {

// Messages quote files and file names: on one line, without their raw bytes, and not a megabyte of
// a binary file's first line (core/printable.h).
constexpr std::size_t kMessageBytes = 2000;

// The one subcommand the command line chose (CLI11 requires exactly one).
int run_chosen(const std::vector<agv::Command>& commands, const std::vector<std::string>& plugins) {
  agv::active_simd_path();  // a bad AGVBENCH_SIMD is bad input, named before anything runs
  for (const auto& path : plugins) agv::load_plugin(path, "--plugin");
  for (const auto& c : commands)
    if (*c.sub) return c.run();
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"agvbench: a parallel benchmark engine for AGV grid path planners"};
  app.require_subcommand(1);
  app.set_version_flag("--version", agv::version_text());
  const std::vector<agv::Command> commands = {
      agv::add_run_command(app),      agv::add_merge_command(app),  agv::add_worker_command(app),
      agv::add_validate_command(app), agv::add_list_command(app),   agv::add_export_command(app),
      agv::add_compare_command(app),  agv::add_digest_command(app), agv::add_plan_command(app),
      agv::add_scen_command(app)};
  // Planner plugins (engine/plan/plugins.h), loaded before the command runs.
  std::vector<std::string> plugins;
  for (const auto& c : commands)
    if (c.takes_plugins)
      c.sub->add_option("--plugin", plugins,
                        "planner plugin (shared library) to load (repeatable)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    return run_chosen(commands, plugins);
  } catch (const agv::InputError& e) {
    std::fprintf(stderr, "agvbench: error: %s\n", agv::printable(e.what(), kMessageBytes).c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "agvbench: failed: %s\n", agv::printable(e.what(), kMessageBytes).c_str());
    return 1;
  }
}
