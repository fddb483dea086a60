// `agvbench merge`: one report from the journals of a sharded (or interrupted) sweep.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/locate_config.h"
#include "engine/outputs/journal.h"
#include "engine/outputs/report.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/files_read.h"
#include "engine/plan/output_paths.h"
#include "engine/plan/sweep_size.h"
#include "engine/system/file_writes.h"

namespace agv {

namespace {

int command_merge(const std::string& config_path, const std::vector<std::string>& journals,
                  const std::string& out) {
  const std::string located = locate_config(config_path);
  const SweepConfig config = load_config(located);
  check_sweep_size(config, true);  // merge restores every run's slot
  const std::string path = out.empty() ? config.report_path : out;
  std::vector<InputPath> inputs = files_read(config, located);
  for (const auto& j : journals) inputs.push_back({"journal", j});
  check_paths(inputs, {{out.empty() ? "report" : "--out", path}});
  ignore_file_size_signal();
  SweepResults results = empty_results(config);
  // The journals read in turn, each cell released once its runs are all read, and the report
  // written one cell at a time.
  restore_journals(journals, results, &config);
  update_completeness(results);
  write_file_atomic(report_text(config, results), path);
  const Coverage coverage = coverage_of(results);
  std::printf("merged %zu journals: %lld of %lld runs present%s; report: %s\n", journals.size(),
              static_cast<long long>(coverage.runs_present),
              static_cast<long long>(coverage.runs_expected),
              results.complete ? "" : " (INCOMPLETE coverage: the report says so)", path.c_str());
  return results.complete ? 0 : 1;
}

}  // namespace

Command add_merge_command(CLI::App& app) {
  struct Args {
    std::string config, out;
    std::vector<std::string> journals;
  };
  auto args = std::make_shared<Args>();
  auto* sub = app.add_subcommand("merge", "build one report from shard or partial journals");
  sub->add_option("journals", args->journals, "JSON Lines journals")->required();
  sub->add_option("--config", args->config, "the sweep config the journals belong to")->required();
  sub->add_option("--out", args->out, "report path (default: the config's)");
  return {sub, [args] { return command_merge(args->config, args->journals, args->out); }};
}

}  // namespace agv
