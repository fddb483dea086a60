#pragma once
// What this build offers, as one JSON object: the planners, generators and map sources with
// their parameters. `agvbench list --json` prints it and the Python module's planners() and
// generators() return it, so both front-ends describe the same registries the same way.

#include <nlohmann/json.hpp>

namespace agv {

// {"planners": [...], "generators": [...], "map_sources": [...]}, each in registry order.
nlohmann::json catalogue_json();

}  // namespace agv
