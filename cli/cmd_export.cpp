// `agvbench export`: a sweep's journals as one experiment of an SQLite database.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/locate_config.h"
#include "core/input_error.h"
#include "engine/outputs/journal.h"
#include "engine/outputs/report.h"
#include "engine/outputs/results_db.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/files_read.h"
#include "engine/plan/output_paths.h"
#include "engine/plan/sweep_size.h"
#include "engine/system/environment.h"

namespace agv {

namespace {

// A sweep's journals as one experiment of an SQLite database (engine/outputs/results_db.h).
struct ExportCommand {
  std::vector<std::string> journals;
  std::string config;
  std::string sqlite;
};

int command_export(const ExportCommand& cmd) {
  const std::string located = locate_config(cmd.config);
  const SweepConfig config = load_config(located);
  check_sweep_size(config, true);  // export restores every run's slot
  std::vector<InputPath> inputs = files_read(config, located);
  for (const auto& j : cmd.journals) inputs.push_back({"journal", j});
  check_paths(inputs, {{"--sqlite", cmd.sqlite, OutputKind::database}});
  check_results_db(cmd.sqlite, "--sqlite");
  ignore_file_size_signal();
  SweepResults results = empty_results(config);
  RunMessages messages;
  for (const auto& j : cmd.journals) restore_journal(j, results, &messages);
  update_completeness(results);
  if (coverage_of(results).runs_present == 0)
    throw InputError("the journals hold no run of this config; nothing exported");
  const nlohmann::json report = build_report(config, results);
  // Journals record no machine: the environment is the exporting one's (source "export").
  const std::int64_t id = append_experiment(
      cmd.sqlite, {&config, &results, &report, &messages, "export", environment_json(0)});
  const Coverage coverage = coverage_of(results);
  std::printf("exported %zu journal%s as experiment %lld of %s: %lld of %lld runs%s\n",
              cmd.journals.size(), cmd.journals.size() == 1 ? "" : "s", static_cast<long long>(id),
              cmd.sqlite.c_str(), static_cast<long long>(coverage.runs_present),
              static_cast<long long>(coverage.runs_expected),
              results.complete ? "" : " (INCOMPLETE: complete = 0 in the database)");
  return 0;
}

}  // namespace

Command add_export_command(CLI::App& app) {
  auto cmd = std::make_shared<ExportCommand>();
  auto* sub = app.add_subcommand("export", "append a sweep's journals to an SQLite database");
  sub->add_option("journals", cmd->journals, "JSON Lines journals")->required();
  sub->add_option("--config", cmd->config, "the sweep config of the journals")->required();
  sub->add_option("--sqlite", cmd->sqlite, "database (created or appended to)")->required();
  return {sub, [cmd] { return command_export(*cmd); }};
}
}  // namespace agv
