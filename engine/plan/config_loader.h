#pragma once
// A sweep config read from JSON with every field checked at the boundary: an unknown key, a
// wrong type or an out-of-range value is an InputError naming the field (exit code 2), never a
// silently ignored setting; a config whose results would not fit in memory is refused too
// (engine/plan/sweep_size.h).

#include <nlohmann/json.hpp>
#include <string>

#include "engine/plan/sweep_config.h"

namespace agv {

// A config's "collision" object ({} or absent: the default model) and "map" object (endpoints,
// solvability, cell edge) into `map`; InputError naming the field (collision.<key>, map.<key>).
// The Python module reads its `collision=` and `map=` arguments with these.
CollisionModel parse_collision(const nlohmann::json& j);
void parse_map_options(const nlohmann::json& j, MapSpec& map);

// Throws InputError naming the field. Loads the config's "plugins" first (engine/plan/plugins.h); a
// plugin's path and a map source's file patterns are relative to `base_dir` (load_config: the
// config file's folder).
SweepConfig parse_config(const nlohmann::json& j, const std::string& base_dir = ".");
// Reads and parses; malformed JSON -> InputError with the file, line and column.
SweepConfig load_config(const std::string& path);

}  // namespace agv
