// `agvbench compare BEFORE AFTER`: two reports of one config, result by result, and their
// planning times with a test (engine/outputs/report_compare.h).
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "cli/report_file.h"
#include "core/input_error.h"
#include "core/json_text.h"
#include "engine/outputs/report_compare.h"
#include "engine/outputs/sweep_identity.h"

namespace agv {

namespace {

// Two reports compared (engine/outputs/report_compare.h): exit 0 no difference, 1 a non-timing
// difference or a timing regression, 2 bad input (configs that differ beyond planner params).
struct CompareCommand {
  std::string before;
  std::string after;
  std::vector<std::string> runs_before;  // the sweeps' journals: per-run times, paired tests
  std::vector<std::string> runs_after;
  std::optional<double> fail_on_regression_pct;  // none: timing never fails
  bool json = false;
};

// compare --fail-on-regression: percent of planning time.
constexpr NumberRange kRegressionPctRange{0.0, 1e6};

// One side's journals: each of the report's config, together exactly the report's sweeps.
void read_side_times(const std::vector<std::string>& journals, const nlohmann::json& report,
                     const std::string& option, const std::string& report_name, RunTimes& times) {
  std::set<std::string> sweep_ids;
  std::string names;
  for (const auto& j : journals) {
    read_run_times(j, report_config_hash(report), times, sweep_ids);
    names += (names.empty() ? "" : " ") + ("\"" + j + "\"");
  }
  require_same_sweeps(report_sweep_ids(report, report_name), sweep_ids, option + " " + names,
                      report_name);
}

int command_compare(const CompareCommand& cmd) {
  if (cmd.runs_before.empty() != cmd.runs_after.empty())
    throw InputError(
        "--runs-before and --runs-after go together: per-run times pair up only when both "
        "sweeps' journals are given");
  const nlohmann::json before = read_report(cmd.before, "BEFORE");
  const nlohmann::json after = read_report(cmd.after, "AFTER");
  RunTimes times_before, times_after;
  const bool with_runs = !cmd.runs_before.empty();
  if (with_runs) {
    // Inside compare_reports the reports are checked first; the journals need their hashes.
    if (!before.is_object() || !before.contains("config") || !after.is_object() ||
        !after.contains("config"))
      throw InputError("BEFORE or AFTER is not an agvbench report (no \"config\")");
    read_side_times(cmd.runs_before, before, "--runs-before", "BEFORE \"" + cmd.before + "\"",
                    times_before);
    read_side_times(cmd.runs_after, after, "--runs-after", "AFTER \"" + cmd.after + "\"",
                    times_after);
  }
  // A shape the checks of require_report do not cover is still bad input naming both files.
  const ReportComparison c = [&] {
    try {
      return compare_reports(before, after, with_runs ? &times_before : nullptr,
                             with_runs ? &times_after : nullptr, cmd.fail_on_regression_pct);
    } catch (const nlohmann::json::exception& e) {
      throw InputError("BEFORE \"" + cmd.before + "\" or AFTER \"" + cmd.after +
                       "\": a report of an unexpected shape (" + e.what() + ")");
    }
  }();
  if (cmd.json) {
    nlohmann::json doc = comparison_json(c);
    doc["before"] = cmd.before;
    doc["after"] = cmd.after;
    std::cout << json_text(doc, 1) << "\n";
  } else {
    std::cout << "agvbench compare: " << cmd.before << " -> " << cmd.after << "\n"
              << comparison_text(c);
  }
  return c.exit_code();
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  auto cmd = std::make_shared<CompareCommand>();
  auto regression_pct = std::make_shared<double>(0.0);
  auto* sub = app.add_subcommand(
      "compare", "compare two reports: non-timing differences and planning-time ratios");
  sub->add_option("before", cmd->before, "report BEFORE")->required();
  sub->add_option("after", cmd->after, "report AFTER")->required();
  sub->add_option("--runs-before", cmd->runs_before,
                  "BEFORE's journals (per-run times: paired tests)");
  sub->add_option("--runs-after", cmd->runs_after, "AFTER's journals");
  auto* regression =
      sub->add_option("--fail-on-regression", *regression_pct,
                      "exit 1 when planning time grows by more than PCT percent (default: never)")
          ->transform(number_in(kRegressionPctRange));
  sub->add_flag("--json", cmd->json, "print the comparison as JSON");
  return {sub,
          [cmd, regression_pct, regression] {
            if (*regression) cmd->fail_on_regression_pct = *regression_pct;
            return command_compare(*cmd);
          },
          false};
}
}  // namespace agv
