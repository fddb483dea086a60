#pragma once
// One explicit table of planners, one line per planner (docs/ARCHITECTURE.md "Style" item 6). A
// config names a planner by its stable public name and sets any of its declared parameters.
// What a planner declares about itself is algos/planner_info.h, which the planners include: the
// registry includes them, never the other way round.

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "algos/planner.h"
#include "algos/planner_info.h"
#include "core/collision_model.h"
#include "core/params.h"

namespace agv {

const std::vector<PlannerInfo>& planner_registry();
// For test binaries only, before any sweep starts: makes a planner findable by name without
// putting it in the real registry (the isolation tests' deliberately faulty planners).
void add_planner_for_testing(PlannerInfo info);

// Before any sweep starts: makes a plugin's planner (info.plugin set) findable by name after the
// built-in ones. Throws InputError naming the plugin when the name is taken, by a built-in planner
// or another plugin's. Its collision-model parameters follow the default model as built-in ones do.
void add_plugin_planner(PlannerInfo info);
// Every planner `list` shows: the built-in table, then the plugins' planners in load order.
std::vector<const PlannerInfo*> all_planners();

// nullptr when unknown.
const PlannerInfo* find_planner(std::string_view name);

// The parameters that follow the collision model (docs/METRICS.md "Collision model"): a corner
// rule (`corner_rule`, a fusion planner's `global_corner_rule`) takes the model's rule, and a
// clearance (`shortcut_margin`, `global_margin`, the smoothing's `curve_clearance` and the
// sampling planners' `clearance`, in margin cells; MA*'s and HMA*'s obstacle radius `r_obs` =
// clearance + 0.5) takes the larger of its declared default and the model's clearance, whenever the
// user leaves them unset.
enum class ModelRole { corner_rule, margin, radius };
std::optional<ModelRole> model_role(std::string_view param);

// A parameter the user set looser than the model: the planner is then a labelled variant whose
// paths are still judged under the model (a path that breaks it is invalid_path).
struct ModelDeviation {
  std::string param;
  nlohmann::json value;  // as set
  nlohmann::json model;  // what the model asks for
};

// Looks the planner up and validates its parameters, the collision-model ones defaulting to
// `model`; throws InputError naming `where`.
struct ConfiguredPlanner {
  const PlannerInfo* info = nullptr;
  Params params;
  std::unique_ptr<Planner> planner;
  std::vector<ModelDeviation> looser_than_model;
};
ConfiguredPlanner configure_planner(const std::string& name, const nlohmann::json& params,
                                    const std::string& where, const CollisionModel& model = {});

// The registry as JSON (`agvbench list --json`).
nlohmann::json registry_json();

}  // namespace agv
