#pragma once
// parse_config's error message for a config, or "no error": the config tests compare messages.

#include <nlohmann/json.hpp>
#include <string>

#include "core/input_error.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/sweep_config.h"

namespace agv {

inline std::string config_error(const nlohmann::json& j) {
  try {
    parse_config(j);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace agv
