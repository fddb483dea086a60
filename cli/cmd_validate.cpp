// `agvbench validate`: a sweep config checked without running it.
#include <cstdio>
#include <memory>
#include <string>

#include "cli/command.h"
#include "cli/run_count.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/files_read.h"
#include "engine/plan/output_paths.h"
#include "engine/plan/sweep_plan.h"
#include "engine/plan/sweep_size.h"

namespace agv {

namespace {

int command_validate(const std::string& config_path) {
  const SweepConfig config = load_config(config_path);
  // The paths a plain `run CONFIG` would write (--out, --runs-out and --resume are run's).
  check_paths(
      files_read(config, config_path),
      {{"report", config.report_path}, {"runs", config.runs_path, OutputKind::new_journal}});
  const SweepPlan plan = plan_sweep(config);
  const SweepSize size = sweep_size(config);
  std::printf("%s: ok: %s, about %s held in memory (%s with --db, merge or export)\n",
              config_path.c_str(), run_count_text(config, plan).c_str(),
              bytes_text(size.bytes).c_str(), bytes_text(size.bytes_kept).c_str());
  return 0;
}

}  // namespace

Command add_validate_command(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  auto* sub = app.add_subcommand("validate", "check a sweep config without running it");
  sub->add_option("config", *path, "sweep config")->required();
  return {sub, [path] { return command_validate(*path); }};
}

}  // namespace agv
