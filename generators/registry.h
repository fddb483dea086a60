#pragma once
// The map generators, registered like the planners (algos/registry.h): one entry per generator
// with its name, summary and shape parameters (declared once in the generator's file, bound to
// its options struct). Config validation, `agvbench list`, `agvbench plan --gen-param` and
// make_map all read this table; nothing else names a generator.

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/params.h"
#include "generators/canvas.h"

namespace agv {

struct GeneratorInfo {
  std::string name;
  std::string summary;
  std::vector<ParamSpec> params;
  // What the ranges cannot say, for one grid size (a maze corridor wider than the grid): throws
  // InputError naming `where`.<parameter>. Takes parameters resolved against `params`.
  std::function<void(const Params&, int width, int height, const std::string& where)> check;
  // Paints one map onto ctx.canvas (reset to ctx.width x ctx.height).
  std::function<void(const Params&, MapContext&)> generate;
};

// The registered generators, in `list` order.
const std::vector<GeneratorInfo>& generator_registry();
// Adds a generator only a test binary knows (the config hash must not depend on the table).
void add_generator_for_testing(GeneratorInfo info);
// nullptr when unknown.
const GeneratorInfo* find_generator(std::string_view name);
// The registered generator `name` (InputError "`where`: unknown generator ... (known: ...)").
const GeneratorInfo& generator_or_throw(const std::string& name, const std::string& where);

// The shape parameters `given` for generator `info`, validated and defaulted, checked for a
// width x height grid: InputError naming `where`.<parameter>.
Params resolve_generator_params(const GeneratorInfo& info, const nlohmann::json& given,
                                const std::string& where, int width, int height);

// The generators as JSON (`agvbench list --json`): name, summary, params.
nlohmann::json generator_registry_json();

}  // namespace agv
