// `agvbench scen MAP SCEN`: every query of a MovingAI scenario file, each length checked against
// the stated optimum, as a MovingAI user expects of a grid planner.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "algos/registry.h"
#include "engine/cli_params.h"
#include "engine/commands.h"
#include "engine/json_text.h"
#include "engine/metrics.h"
#include "generators/movingai.h"

namespace agv {

int command_scen(const ScenCommand& cmd) {
  const Grid grid = read_map(cmd.map_file);
  const std::vector<ScenarioQuery> queries = read_scen(cmd.scen_file);
  const PlannerInfo* info = find_planner(cmd.planner);
  if (info == nullptr) configure_planner(cmd.planner, {}, "--planner");
  check_cli_params({info}, cmd.params);
  nlohmann::json params = cli_params_for(*info, cmd.params);
  // MovingAI optima assume no corner cutting.
  for (const auto& s : info->params)
    if (s.name == "corner_rule" && !params.contains("corner_rule"))
      params["corner_rule"] = "no_corner_cut";
  const ConfiguredPlanner planner =
      configure_planner(cmd.planner, params, "--planner " + cmd.planner);

  for (std::size_t i = 0; i < queries.size(); ++i) {
    const auto& q = queries[i];
    const std::string where = cmd.scen_file + ": query " + std::to_string(i + 1);
    if (q.map_width != grid.width() || q.map_height != grid.height())
      throw InputError(where + ": map size " + std::to_string(q.map_width) + "x" +
                       std::to_string(q.map_height) + " does not match " + cmd.map_file);
    for (const auto& [c, what] : {std::pair{q.start, "start"}, std::pair{q.goal, "goal"}}) {
      if (!grid.in_bounds(c))
        throw InputError(where + ": " + what + " (" + std::to_string(c.x) + "," +
                         std::to_string(c.y) + ") is outside the grid");
      if (grid.blocked(c))
        throw InputError(where + ": " + what + " (" + std::to_string(c.x) + "," +
                         std::to_string(c.y) + ") is an obstacle cell");
    }
  }

  Scratch scratch;
  Rng rng(1, stable_hash(cmd.planner));
  std::int64_t mismatches = 0, failures = 0, expansions = 0, checks = 0;
  double max_abs = 0.0, max_rel = 0.0;
  std::vector<double> times_ns;
  nlohmann::json bad = nlohmann::json::array();
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const auto& q = queries[i];
    const PlanRequest req{grid, q.start, q.goal, rng, scratch, Deadline::never()};
    const std::int64_t t0 = thread_cpu_ns();
    const PlanResult r = plan_checked(*planner.planner, req);
    times_ns.push_back(static_cast<double>(thread_cpu_ns() - t0));
    expansions += r.work.search_expansions.value_or(0);
    checks += r.work.collision_checks.value_or(0);
    if (!r.ok()) {
      ++failures;
      ++mismatches;
      if (bad.size() < 20) bad.push_back({{"query", i + 1}, {"failure", to_string(r.failure)}});
      continue;
    }
    const double len = polyline_length(r.path);
    const double abs_err = std::abs(len - q.optimal_length);
    const double rel_err = q.optimal_length > 0 ? abs_err / q.optimal_length : abs_err;
    max_abs = std::max(max_abs, abs_err);
    max_rel = std::max(max_rel, rel_err);
    if (rel_err > cmd.tolerance && abs_err > cmd.tolerance) {
      ++mismatches;
      if (bad.size() < 20)
        bad.push_back({{"query", i + 1}, {"length", len}, {"optimal", q.optimal_length}});
    }
  }
  double total_ns = 0.0;
  for (double t : times_ns) total_ns += t;
  std::vector<double> sorted = times_ns;
  std::sort(sorted.begin(), sorted.end());
  const double median_ns = sorted.empty() ? 0.0
                           : sorted.size() % 2
                               ? sorted[sorted.size() / 2]
                               : 0.5 * (sorted[sorted.size() / 2 - 1] + sorted[sorted.size() / 2]);
  const nlohmann::json doc = {{"map", cmd.map_file},
                              {"scen", cmd.scen_file},
                              {"planner", cmd.planner},
                              {"params", planner.params.values()},
                              {"queries", queries.size()},
                              {"failures", failures},
                              {"mismatches", mismatches},
                              {"max_abs_error", max_abs},
                              {"max_rel_error", max_rel},
                              {"tolerance", cmd.tolerance},
                              {"search_expansions", expansions},
                              {"collision_checks", checks},
                              {"first_mismatches", bad},
                              {"timing",
                               {{"total_ns", static_cast<std::int64_t>(total_ns)},
                                {"median_query_ns", static_cast<std::int64_t>(median_ns)}}}};
  if (cmd.json) {
    std::cout << json_text(doc, 1) << "\n";
  } else {
    std::printf(
        "%s on %s: %zu queries, %lld mismatches (%lld failed), max abs error %.3g, "
        "max rel error %.3g, %lld nodes expanded\n",
        cmd.planner.c_str(), cmd.scen_file.c_str(), queries.size(),
        static_cast<long long>(mismatches), static_cast<long long>(failures), max_abs, max_rel,
        static_cast<long long>(expansions));
    std::printf("timing: total %.3f s, median %.1f µs per query\n", total_ns / 1e9,
                median_ns / 1e3);
    for (const auto& b : bad) std::printf("  mismatch: %s\n", json_text(b).c_str());
  }
  return mismatches == 0 ? 0 : 1;
}

}  // namespace agv
