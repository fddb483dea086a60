#pragma once
// "KEY=VALUE" command-line parameters turned into a JSON object for one planner (--param) or
// the map generator (--gen-param): a value is read as JSON when it parses (numbers,
// true/false), else as a string ("no_corner_cut").

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "algos/registry.h"
#include "generators/registry.h"

namespace agv {

// Only keys the planner declares are taken; a key no requested planner declares is an error
// (raised by check_cli_params).
nlohmann::json cli_params_for(const PlannerInfo& info, const std::vector<std::string>& params);
void check_cli_params(const std::vector<const PlannerInfo*>& planners,
                      const std::vector<std::string>& params);

// Every key must be a parameter of the generator (InputError naming --gen-param and the key).
nlohmann::json cli_generator_params(const GeneratorInfo& info,
                                    const std::vector<std::string>& params);

// "x,y" -> Cell; throws InputError naming `what`.
Cell parse_cell(const std::string& text, const std::string& what);

}  // namespace agv
