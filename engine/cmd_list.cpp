// `agvbench list`: the planner and generator registries, as text or as one JSON object.
#include <iostream>
#include <string>
#include <vector>

#include "algos/registry.h"
#include "engine/commands.h"
#include "generators/map_files.h"
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

}  // namespace

int command_list(bool as_json) {
  if (as_json) {
    nlohmann::json sources = nlohmann::json::array();
    for (const auto& info : map_source_registry()) {
      nlohmann::json params = nlohmann::json::object();
      for (const auto& [name, doc] : info.params) params[name] = doc;
      sources.push_back({{"name", info.name}, {"summary", info.summary}, {"params", params}});
    }
    const nlohmann::json doc = {{"planners", registry_json()},
                                {"generators", generator_registry_json()},
                                {"map_sources", sources}};
    std::cout << doc.dump(2) << "\n";
    return 0;
  }
  std::cout << "planners:\n\n";
  for (const auto& info : planner_registry()) {
    std::cout << info.name << "  -  " << info.summary << "\n    source: " << info.source;
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
  std::cout << "map sources (the user's map files, one cell each; a \"generators\" entry "
               "{\"name\": ..., \"params\": {\"files\": [...]}}):\n\n";
  for (const auto& info : map_source_registry()) {
    std::cout << info.name << "  -  " << info.summary << "\n";
    for (const auto& [name, doc] : info.params) std::cout << "    " << name << ": " << doc << "\n";
    std::cout << "\n";
  }
  return 0;
}

}  // namespace agv
