// `agvbench run`, `validate` and `list`.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "algos/registry.h"
#include "engine/commands.h"
#include "engine/report.h"
#include "engine/sweep_runner.h"

#ifndef AGV_SOURCE_DIR
#define AGV_SOURCE_DIR "."
#endif

namespace agv {

namespace {

// The default config is found from any working directory: first as given, then in the checkout
// the binary was built from.
std::string locate_config(const std::string& path) {
  namespace fs = std::filesystem;
  if (fs::exists(path) || fs::path(path).is_absolute()) return path;
  const fs::path in_source = fs::path(AGV_SOURCE_DIR) / path;
  if (fs::exists(in_source)) return in_source.string();
  return path;
}

}  // namespace

int command_run(const RunCommand& cmd) {
  SweepConfig config = load_config(locate_config(cmd.config));
  if (cmd.threads >= 0) config.threads = cmd.threads;
  if (!cmd.out.empty()) config.report_path = cmd.out;
  if (!cmd.runs_out.empty()) config.runs_path = cmd.runs_out;

  SweepOptions options;
  options.threads = config.threads;
  options.progress = !cmd.quiet;
  options.runs_path = config.runs_path;
  const SweepPlan plan = plan_sweep(config);
  if (!cmd.quiet) {
    std::fprintf(stderr, "agvbench: sweep \"%s\": %zu cells x %d maps x %zu planners = %lld runs\n",
                 config.name.c_str(), plan.cells.size(), plan.maps_per_cell,
                 config.planners.size(),
                 static_cast<long long>(plan.map_tasks() * static_cast<long long>(config.planners.size())));
  }
  SweepResults results = run_sweep(config, options);
  write_json_atomic(build_report(config, results), config.report_path);
  if (!cmd.quiet) {
    std::cout << summary_table(config, results);
    std::printf("\n%lld runs in %.2f s on %d threads (%.0f runs/s); report: %s\n",
                static_cast<long long>(results.runs.size()), results.wall_s, results.threads,
                results.wall_s > 0 ? static_cast<double>(results.runs.size()) / results.wall_s : 0.0,
                config.report_path.c_str());
  }
  return 0;
}

int command_validate(const std::string& config_path) {
  const SweepConfig config = load_config(config_path);
  const SweepPlan plan = plan_sweep(config);
  std::printf("%s: ok: %zu cells x %d maps x %zu planners = %lld runs\n", config_path.c_str(),
              plan.cells.size(), plan.maps_per_cell, config.planners.size(),
              static_cast<long long>(plan.map_tasks() * static_cast<long long>(config.planners.size())));
  return 0;
}

int command_list(bool as_json) {
  if (as_json) {
    std::cout << registry_json().dump(2) << "\n";
    return 0;
  }
  for (const auto& info : planner_registry()) {
    std::cout << info.name << "  -  " << info.summary << "\n    source: " << info.source
              << "\n    expanded_nodes: " << info.expanded_nodes_meaning
              << (info.stochastic ? "\n    stochastic: draws from the run's RNG" : "") << "\n";
    for (const auto& p : info.params) {
      const auto j = p.to_json();
      std::cout << "    " << p.name << " = " << p.default_value.dump();
      if (p.type == ParamType::choice) {
        std::string list;
        for (const auto& c : p.choices) list += (list.empty() ? "" : "|") + c;
        std::cout << "  (" << list << ")";
      } else if (p.type != ParamType::boolean) {
        std::cout << "  [" << j["min"].dump() << ", " << j["max"].dump() << "]";
      }
      std::cout << "\n        " << p.doc << "\n";
    }
    std::cout << "\n";
  }
  return 0;
}

}  // namespace agv
