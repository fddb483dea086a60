// `agvbench list`: the planner and generator registries, as text or as one JSON object.
#include <iostream>
#include <string>
#include <vector>

#include "algos/registry.h"
#include "engine/commands.h"
#include "engine/plugins.h"
#include "generators/registry.h"

namespace agv {

namespace {

void print_params(const std::vector<ParamSpec>& params) {
  for (const auto& p : params) {
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
}

// "NAME VERSION (PATH, sha256 HASH)" of a loaded plugin.
std::string plugin_line(const std::string& name) {
  for (const auto& p : loaded_plugins())
    if (p.name == name)
      return p.name + " " + p.version + " (" + p.path + ", sha256 " + p.sha256 + ")";
  return name;
}

}  // namespace

int command_list(bool as_json) {
  if (as_json) {
    nlohmann::json doc = {{"planners", registry_json()}, {"generators", generator_registry_json()}};
    // Only when plugins are loaded (--plugin), so the plain listing keeps its shape.
    if (const auto plugins = loaded_plugins(); !plugins.empty()) {
      doc["plugins"] = nlohmann::json::array();
      for (const auto& p : plugins) {
        nlohmann::json entry = p.as_run();
        entry["compiler"] = p.compiler;
        entry["planners"] = p.planners;
        doc["plugins"].push_back(std::move(entry));
      }
    }
    std::cout << doc.dump(2) << "\n";
    return 0;
  }
  std::cout << "planners:\n\n";
  for (const auto* planner : all_planners()) {
    const PlannerInfo& info = *planner;
    std::cout << info.name << "  -  " << info.summary << "\n    source: " << info.source;
    if (!info.plugin.empty()) std::cout << "\n    plugin: " << plugin_line(info.plugin);
    for (const auto& [name, meaning] : info.counters)
      std::cout << "\n    " << name << ": " << meaning;
    std::cout << (info.stochastic ? "\n    stochastic: draws from the run's RNG" : "") << "\n";
    print_params(info.params);
    std::cout << "\n";
  }
  std::cout << "generators (a config's \"generators\" entry: a name or {\"name\": ..., "
               "\"params\": {...}}):\n\n";
  for (const auto& info : generator_registry()) {
    std::cout << info.name << "  -  " << info.summary << "\n";
    print_params(info.params);
    std::cout << "\n";
  }
  return 0;
}

}  // namespace agv
