#include "engine/plan/catalogue.h"

#include "algos/registry.h"
#include "generators/map_files.h"
#include "generators/registry.h"

namespace agv {

nlohmann::json catalogue_json() {
  nlohmann::json sources = nlohmann::json::array();
  for (const auto& info : map_source_registry()) {
    nlohmann::json params = nlohmann::json::object();
    for (const auto& [name, doc] : info.params) params[name] = doc;
    sources.push_back({{"name", info.name}, {"summary", info.summary}, {"params", params}});
  }
  return {{"planners", registry_json()},
          {"generators", generator_registry_json()},
          {"map_sources", sources}};
}

}  // namespace agv
