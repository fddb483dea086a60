#include "algos/registry.h"

#include <algorithm>
#include <deque>

#include "algos/local/fusion.h"
#include "algos/ompl/ompl_planners.h"
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
#include "core/input_error.h"

namespace agv {

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

// The declared defaults of the collision-model parameters become what a run gets when neither
// the user nor a sweep's "collision" sets them: the default model's rule, and the larger of the
// declared clearance and the default model's (configure_planner applies a sweep's own model).
void follow_default_model(std::vector<PlannerInfo>& registry) {
  const CollisionModel model;
  for (auto& info : registry)
    for (auto& spec : info.params) {
      const std::optional<ModelRole> role = model_role(spec.name);
      if (!role) continue;
      if (*role == ModelRole::corner_rule) {
        spec.default_value = std::string(to_string(model.corner_rule));
        spec.doc += "; unset: the sweep's collision model's rule";
      } else {
        spec.default_value =
            std::max(spec.default_value.get<double>(),
                     *role == ModelRole::margin ? model.clearance : model.clearance + 0.5);
        spec.doc += "; unset: at least the sweep's collision-model clearance";
      }
    }
}

// A fusion planner's reference and global planners (algos/local/fusion.h PlannerLookup).
std::unique_ptr<Planner> make_planner(const std::string& name, const nlohmann::json& params,
                                      const std::string& where) {
  return configure_planner(name, params, where).planner;
}

// The local planners, last: a fusion planner's `global_planner` chooses among the grid planners
// registered before it (planner_registry() cannot be asked while it is being built).
std::vector<PlannerInfo> build_registry() {
  std::vector<PlannerInfo> registry = standalone_planners();
  for (PlannerInfo& info : ompl_planners()) registry.push_back(std::move(info));
  const FusionRegistry fusion{planner_names(registry, PlannerKind::grid_search),
                              {&find_planner, &make_planner}};
  registry.push_back(dwa_planner(fusion));
  registry.push_back(fusion_astar_dwa_planner(fusion));
  registry.push_back(fusion_alt_dwa_planner(fusion));
  registry.push_back(fusion_kin_dwa_planner(fusion));
  follow_default_model(registry);
  return registry;
}

}  // namespace

const std::vector<PlannerInfo>& planner_registry() {
  static const std::vector<PlannerInfo> registry = build_registry();
  return registry;
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

namespace {
// The plugins' planners (engine/plan/plugins.h), added before any sweep starts; a deque keeps the
// returned pointers stable.
std::deque<PlannerInfo>& plugin_planners() {
  static std::deque<PlannerInfo> planners;
  return planners;
}
}  // namespace

void add_plugin_planner(PlannerInfo info) {
  const std::string who = "plugin \"" + info.plugin + "\": planner \"" + info.name + "\"";
  for (const auto& other : planner_registry())
    if (other.name == info.name) throw InputError(who + " clashes with the built-in planner");
  for (const auto& other : plugin_planners())
    if (other.name == info.name)
      throw InputError(who + " clashes with plugin \"" + other.plugin + "\"'s planner");
  for (const auto& other : test_planners())
    if (other.name == info.name) throw InputError(who + " clashes with a test planner");
  std::vector<PlannerInfo> one;
  one.push_back(std::move(info));
  follow_default_model(one);
  plugin_planners().push_back(std::move(one.front()));
}

std::vector<const PlannerInfo*> all_planners() {
  std::vector<const PlannerInfo*> out;
  for (const auto& info : planner_registry()) out.push_back(&info);
  for (const auto& info : plugin_planners()) out.push_back(&info);
  return out;
}

const PlannerInfo* find_planner(std::string_view name) {
  for (const auto& info : planner_registry())
    if (info.name == name) return &info;
  for (const auto& info : plugin_planners())
    if (info.name == name) return &info;
  for (const auto& info : test_planners())
    if (info.name == name) return &info;
  return nullptr;
}

std::optional<ModelRole> model_role(std::string_view param) {
  if (param == "corner_rule" || param == "global_corner_rule") return ModelRole::corner_rule;
  if (param == "shortcut_margin" || param == "global_margin" || param == "clearance" ||
      param == "curve_clearance")
    return ModelRole::margin;
  if (param == "r_obs") return ModelRole::radius;
  return std::nullopt;
}

namespace {

// What the model asks of one parameter: its rule, or the clearance in the parameter's unit
// (margin cells, or an obstacle radius of clearance + 0.5).
nlohmann::json model_value(ModelRole role, const CollisionModel& model) {
  switch (role) {
    case ModelRole::corner_rule:
      return std::string(to_string(model.corner_rule));
    case ModelRole::margin:
      return model.clearance;
    case ModelRole::radius:
      return model.clearance + 0.5;
  }
  return nullptr;
}

// The user's parameters with every unset model parameter filled in from the model, and the set
// ones that are looser than it.
nlohmann::json with_model_defaults(const PlannerInfo& info, const nlohmann::json& given,
                                   const CollisionModel& model,
                                   std::vector<ModelDeviation>& looser_than_model) {
  if (!given.is_object()) return given;  // Params::resolve names the type error
  nlohmann::json out = given;
  for (const auto& spec : info.params) {
    const std::optional<ModelRole> role = model_role(spec.name);
    if (!role) continue;
    const nlohmann::json wanted = model_value(*role, model);
    const auto it = given.find(spec.name);
    if (*role == ModelRole::corner_rule) {
      if (it == given.end()) {
        out[spec.name] = wanted;
        continue;
      }
      const auto rule =
          it->is_string() ? corner_rule_from_string(it->get<std::string>()) : std::nullopt;
      // A value that is no rule (`planner_default`, a typo) is left to Params::resolve.
      if (rule && looser(*rule, model.corner_rule))
        looser_than_model.push_back({spec.name, *it, wanted});
      continue;
    }
    const double floor = wanted.get<double>();
    if (it == given.end()) {
      const double declared = spec.default_value.get<double>();
      out[spec.name] = std::max(declared, floor);
    } else if (it->is_number() && it->get<double>() < floor && it->get<double>() >= 0.0) {
      looser_than_model.push_back({spec.name, *it, wanted});
    }
  }
  return out;
}

// The planner's make function called: a plugin's that throws (a std::exception or anything
// else) or returns no planner is bad input naming the plugin and the planner, never a crash.
std::unique_ptr<Planner> make_planner(const PlannerInfo& info, const Params& params,
                                      const std::string& where) {
  const std::string who = where + ": " +
                          (info.plugin.empty() ? "" : "plugin \"" + info.plugin + "\"'s ") +
                          "planner \"" + info.name + "\"";
  std::unique_ptr<Planner> planner;
  try {
    planner = info.make(params);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    if (info.plugin.empty()) throw;  // a built-in's own error keeps its type
    throw InputError(who + ": its make function failed: " + e.what());
  } catch (...) {
    throw InputError(who + ": its make function threw something that is not a std::exception");
  }
  if (planner == nullptr) throw InputError(who + ": its make function returned no planner (null)");
  return planner;
}

}  // namespace

ConfiguredPlanner configure_planner(const std::string& name, const nlohmann::json& params,
                                    const std::string& where, const CollisionModel& model) {
  const PlannerInfo* info = find_planner(name);
  if (info == nullptr) {
    std::string known;
    for (const auto* p : all_planners()) known += (known.empty() ? "" : ", ") + p->name;
    throw InputError(where + ": unknown planner \"" + name + "\" (known: " + known +
                     "; a plugin's planner is known once its library is loaded, with --plugin or "
                     "the config's \"plugins\")");
  }
  ConfiguredPlanner c;
  c.info = info;
  const nlohmann::json given = with_model_defaults(*info, params, model, c.looser_than_model);
  c.params = Params::resolve(info->params, given, where + ".params");
  c.planner = make_planner(*info, c.params, where);
  return c;
}

nlohmann::json registry_json() {
  nlohmann::json out = nlohmann::json::array();
  for (const auto* planner : all_planners()) {
    const PlannerInfo& info = *planner;
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
    if (!info.plugin.empty()) out.back()["plugin"] = info.plugin;
  }
  return out;
}

}  // namespace agv
