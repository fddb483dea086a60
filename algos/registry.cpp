#include "algos/registry.h"

#include <deque>

#include "algos/local/fusion.h"
#include "algos/sampling/birrt.h"
#include "algos/sampling/prm.h"
#include "algos/sampling/rrt.h"
#include "algos/search/alt_astar.h"
#include "algos/search/astar.h"
#include "algos/search/bidir_astar.h"
#include "algos/search/dijkstra.h"
#include "algos/search/improved_astar.h"
#include "algos/search/kin_astar.h"
#include "algos/search/ma_star.h"
#include "algos/swarm/aco.h"
#include "algos/swarm/hma_star.h"

namespace agv {

const char* to_string(PlannerKind kind) {
  switch (kind) {
    case PlannerKind::grid_search:
      return "grid_search";
    case PlannerKind::sampling:
      return "sampling";
    case PlannerKind::swarm:
      return "swarm";
    case PlannerKind::local:
      return "local";
  }
  return "?";
}

namespace {

// The planners that stand on no other registered planner, in `list` order.
std::vector<PlannerInfo> standalone_planners() {
  return {
      astar_planner(),
      dijkstra_planner(),
      prm_planner(),
      rrt_planner(),
      birrt_planner(),
      aco_planner(),
      bidir_astar_planner(),
      ma_star_planner(),
      hma_star_planner(),
      improved_astar_internal_planner(),
      improved_astar_planner(),
      alt_astar_planner(),
      kin_astar_planner(),
  };
}

// The local planners, last: a fusion planner's `global_planner` chooses among the grid planners
// registered before it (planner_registry() cannot be asked while it is being built).
std::vector<PlannerInfo> build_registry() {
  std::vector<PlannerInfo> registry = standalone_planners();
  const std::vector<std::string> grid = planner_names(registry, PlannerKind::grid_search);
  registry.push_back(dwa_planner());
  registry.push_back(fusion_astar_dwa_planner(grid));
  registry.push_back(fusion_alt_dwa_planner(grid));
  registry.push_back(fusion_kin_dwa_planner(grid));
  return registry;
}

}  // namespace

const std::vector<PlannerInfo>& planner_registry() {
  static const std::vector<PlannerInfo> registry = build_registry();
  return registry;
}

std::vector<std::string> planner_names(std::span<const PlannerInfo> planners, PlannerKind kind) {
  std::vector<std::string> names;
  for (const auto& info : planners)
    if (info.kind == kind) names.push_back(info.name);
  return names;
}

namespace {
// Planners that only test binaries add (deliberately faulty ones for the isolation tests); the
// agvbench program never adds any. A deque keeps the returned pointers stable.
std::deque<PlannerInfo>& test_planners() {
  static std::deque<PlannerInfo> planners;
  return planners;
}
}  // namespace

void add_planner_for_testing(PlannerInfo info) { test_planners().push_back(std::move(info)); }

const PlannerInfo* find_planner(std::string_view name) {
  for (const auto& info : planner_registry())
    if (info.name == name) return &info;
  for (const auto& info : test_planners())
    if (info.name == name) return &info;
  return nullptr;
}

ConfiguredPlanner configure_planner(const std::string& name, const nlohmann::json& params,
                                    const std::string& where) {
  const PlannerInfo* info = find_planner(name);
  if (info == nullptr) {
    std::string known;
    for (const auto& p : planner_registry()) known += (known.empty() ? "" : ", ") + p.name;
    throw InputError(where + ": unknown planner \"" + name + "\" (known: " + known + ")");
  }
  ConfiguredPlanner c;
  c.info = info;
  c.params = Params::resolve(info->params, params, where + ".params");
  c.planner = info->make(c.params);
  return c;
}

nlohmann::json registry_json() {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& info : planner_registry()) {
    nlohmann::json p = nlohmann::json::array();
    for (const auto& s : info.params) p.push_back(s.to_json());
    nlohmann::json counters = nlohmann::json::object();
    for (const auto& [name, meaning] : info.counters) counters[name] = meaning;
    out.push_back({{"name", info.name},
                   {"kind", to_string(info.kind)},
                   {"summary", info.summary},
                   {"source", info.source},
                   {"counters", counters},
                   {"stochastic", info.stochastic},
                   {"proves_no_path", info.proves_no_path},
                   {"params", p}});
  }
  return out;
}

}  // namespace agv
