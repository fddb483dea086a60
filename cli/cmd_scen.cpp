// `agvbench scen MAP SCEN`: every query of a MovingAI scenario file, each length checked against
// the stated optimum, as a MovingAI user expects of a grid planner.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "algos/registry.h"
#include "cli/cli_params.h"
#include "cli/command.h"
#include "cli/option_checks.h"
#include "core/json_text.h"
#include "engine/judge/metrics.h"
#include "engine/judge/validator.h"
#include "engine/system/exit_guard.h"
#include "generators/movingai.h"

namespace agv {

namespace {

struct ScenCommand {
  std::string map_file;
  std::string scen_file;
  std::string planner = "astar";
  std::vector<std::string> params;
  bool json = false;
  double tolerance = 1e-5;  // relative; files in the wild carry 6 significant digits
};

// scen --tolerance: relative and absolute; 1 already accepts any length up to twice the optimum.
constexpr NumberRange kToleranceRange{0.0, 1.0};

ConfiguredPlanner scen_planner(const ScenCommand& cmd) {
  const PlannerInfo* info = find_planner(cmd.planner);
  if (info == nullptr) configure_planner(cmd.planner, {}, "--planner");
  check_cli_params({info}, cmd.params);
  nlohmann::json params = cli_params_for(*info, cmd.params);
  // MovingAI optima assume no corner cutting.
  for (const auto& s : info->params)
    if (s.name == "corner_rule" && !params.contains("corner_rule"))
      params["corner_rule"] = "no_corner_cut";
  return configure_planner(cmd.planner, params, "--planner " + cmd.planner);
}

void check_queries(const ScenCommand& cmd, const Grid& grid,
                   const std::vector<ScenarioQuery>& queries) {
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const auto& q = queries[i];
    const std::string where = cmd.scen_file + ": query " + std::to_string(i + 1);
    const std::string given = std::filesystem::path(cmd.map_file).filename().string();
    if (std::filesystem::path(q.map).filename().string() != given)
      throw InputError(where + ": names map '" + q.map + "', not " + given);
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
}

// What the queries' runs add up to.
struct ScenTally {
  std::int64_t mismatches = 0, failures = 0, expansions = 0, checks = 0;
  double max_abs = 0.0, max_rel = 0.0;
  std::vector<double> times_ns;
  nlohmann::json bad = nlohmann::json::array();  // the first 20 mismatches
};

// A path is scored only once the validator accepts it under MovingAI's rule (no corner cut): a
// path with a NaN or off-grid point, a jump or a cut corner is a failure, never a length.
void score(const ScenCommand& cmd, const Grid& grid, std::size_t i, const ScenarioQuery& q,
           const PlanResult& r, ScenTally& t) {
  t.expansions += r.work.search_expansions.value_or(0);
  t.checks += r.work.collision_checks.value_or(0);
  if (!r.ok()) {
    ++t.failures;
    ++t.mismatches;
    if (t.bad.size() < 20) t.bad.push_back({{"query", i + 1}, {"failure", to_string(r.failure)}});
    return;
  }
  const ValidationResult v =
      validate_path(grid, q.start, q.goal, r.path, CornerRule::no_corner_cut);
  if (!v.ok) {
    ++t.failures;
    ++t.mismatches;
    if (t.bad.size() < 20) t.bad.push_back({{"query", i + 1}, {"invalid_path", v.reason}});
    return;
  }
  const double len = polyline_length(r.path);
  const double abs_err = std::abs(len - q.optimal_length);
  const double rel_err = q.optimal_length > 0 ? abs_err / q.optimal_length : abs_err;
  t.max_abs = std::max(t.max_abs, abs_err);
  t.max_rel = std::max(t.max_rel, rel_err);
  if (rel_err > cmd.tolerance && abs_err > cmd.tolerance) {
    ++t.mismatches;
    if (t.bad.size() < 20)
      t.bad.push_back({{"query", i + 1}, {"length", len}, {"optimal", q.optimal_length}});
  }
}

ScenTally run_queries(const ScenCommand& cmd, const Grid& grid, const Planner& planner,
                      const std::vector<ScenarioQuery>& queries) {
  Scratch scratch;
  Rng rng(1, stable_hash(cmd.planner));
  ScenTally t;
  const std::string who = "planner \"" + cmd.planner + "\", in the middle of a scenario query,";
  const ForeignCodeScope foreign(who.c_str());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const auto& q = queries[i];
    const PlanRequest req{grid, q.start, q.goal, rng, scratch, Deadline::never()};
    const std::int64_t t0 = thread_cpu_ns();
    const PlanResult r = plan_checked(planner, req);
    t.times_ns.push_back(static_cast<double>(thread_cpu_ns() - t0));
    score(cmd, grid, i, q, r, t);
  }
  return t;
}

double median_of(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n == 0 ? 0.0 : n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

void print_text(const ScenCommand& cmd, std::size_t queries, const ScenTally& t, double total_ns,
                double median_ns) {
  std::printf(
      "%s on %s: %zu queries, %lld mismatches (%lld failed), max abs error %.3g, "
      "max rel error %.3g, %lld nodes expanded\n",
      cmd.planner.c_str(), cmd.scen_file.c_str(), queries, static_cast<long long>(t.mismatches),
      static_cast<long long>(t.failures), t.max_abs, t.max_rel,
      static_cast<long long>(t.expansions));
  std::printf("timing: total %.3f s, median %.1f µs per query\n", total_ns / 1e9, median_ns / 1e3);
  for (const auto& b : t.bad) std::printf("  mismatch: %s\n", json_text(b).c_str());
}

int command_scen(const ScenCommand& cmd) {
  const Grid grid = read_map(cmd.map_file);
  const std::vector<ScenarioQuery> queries = read_scen(cmd.scen_file);
  const ConfiguredPlanner planner = scen_planner(cmd);
  check_queries(cmd, grid, queries);
  const ScenTally t = run_queries(cmd, grid, *planner.planner, queries);
  double total_ns = 0.0;
  for (double x : t.times_ns) total_ns += x;
  const double median_ns = median_of(t.times_ns);
  if (!cmd.json) {
    print_text(cmd, queries.size(), t, total_ns, median_ns);
    return t.mismatches == 0 ? 0 : 1;
  }
  const nlohmann::json doc = {{"map", cmd.map_file},
                              {"scen", cmd.scen_file},
                              {"planner", cmd.planner},
                              {"params", planner.params.values()},
                              {"queries", queries.size()},
                              {"failures", t.failures},
                              {"mismatches", t.mismatches},
                              {"max_abs_error", t.max_abs},
                              {"max_rel_error", t.max_rel},
                              {"tolerance", cmd.tolerance},
                              {"search_expansions", t.expansions},
                              {"collision_checks", t.checks},
                              {"first_mismatches", t.bad},
                              {"timing",
                               {{"total_ns", static_cast<std::int64_t>(total_ns)},
                                {"median_query_ns", static_cast<std::int64_t>(median_ns)}}}};
  std::cout << json_text(doc, 1) << "\n";
  return t.mismatches == 0 ? 0 : 1;
}

}  // namespace

Command add_scen_command(CLI::App& app) {
  auto scen = std::make_shared<ScenCommand>();
  auto* sub = app.add_subcommand("scen", "run every query of a MovingAI scenario file");
  sub->add_option("map", scen->map_file, "MovingAI .map file")->required();
  sub->add_option("scen", scen->scen_file, "MovingAI .scen file")->required();
  sub->add_option("--planner", scen->planner, "planner name (default astar)");
  sub->add_option("--param", scen->params, "KEY=VALUE parameter (repeatable)");
  sub->add_option("--tolerance", scen->tolerance,
                  "relative (and absolute) tolerance on optimal lengths, in [0, 1]")
      ->transform(number_in(kToleranceRange));
  sub->add_flag("--json", scen->json, "print the summary as JSON");
  return {sub, [scen] { return command_scen(*scen); }};
}

}  // namespace agv
