#include "generators/registry.h"

#include <deque>
#include <type_traits>
#include <utility>

#include "core/input_error.h"
#include "generators/blocks.h"
#include "generators/maze.h"
#include "generators/rooms.h"
#include "generators/uniform.h"

namespace agv {

namespace {

template <class Options>
using CheckFn = void (*)(const Options&, int, int, const std::string&);
template <class Options>
using GenerateFn = void (*)(const Options&, MapContext&);

// One registry line: the declarations give the specs and turn a resolved set back into the
// generator's options struct.
template <class Options>
GeneratorInfo entry(std::string name, std::string summary, const ParamDecls<Options>& decls,
                    std::type_identity_t<CheckFn<Options>> check,
                    std::type_identity_t<GenerateFn<Options>> generate) {
  GeneratorInfo info;
  info.name = std::move(name);
  info.summary = std::move(summary);
  info.params = decls.specs();
  if (check != nullptr) {
    info.check = [&decls, check](const Params& p, int w, int h, const std::string& where) {
      check(decls.read(p), w, h, where);
    };
  }
  info.generate = [&decls, generate](const Params& p, MapContext& ctx) {
    generate(decls.read(p), ctx);
  };
  return info;
}

// Generators that only test binaries add; agvbench never adds any. A deque keeps the returned
// pointers stable.
std::deque<GeneratorInfo>& test_generators() {
  static std::deque<GeneratorInfo> generators;
  return generators;
}

}  // namespace

const std::vector<GeneratorInfo>& generator_registry() {
  static const std::vector<GeneratorInfo> registry = {
      entry("uniform", "exactly round(density * M) obstacle cells, a uniform random subset",
            uniform_params(), nullptr, generate_uniform),
      entry("blocks", "overlapping rectangles, the workshop production areas of paper 002",
            blocks_params(), check_blocks, generate_blocks),
      entry("maze", "a perfect maze, braided below its wall fraction, cluttered above",
            maze_params(), check_maze, generate_maze),
      entry("rooms", "square rooms with a door in every wall, merged or cluttered to density",
            rooms_params(), nullptr, generate_rooms),
  };
  return registry;
}

void add_generator_for_testing(GeneratorInfo info) { test_generators().push_back(std::move(info)); }

const GeneratorInfo* find_generator(std::string_view name) {
  for (const auto& info : generator_registry())
    if (info.name == name) return &info;
  for (const auto& info : test_generators())
    if (info.name == name) return &info;
  return nullptr;
}

const GeneratorInfo& generator_or_throw(const std::string& name, const std::string& where) {
  const GeneratorInfo* info = find_generator(name);
  if (info != nullptr) return *info;
  std::string known;
  for (const auto& g : generator_registry()) known += (known.empty() ? "" : ", ") + g.name;
  throw InputError(where + ": unknown generator \"" + name + "\" (known: " + known + ")");
}

Params resolve_generator_params(const GeneratorInfo& info, const nlohmann::json& given,
                                const std::string& where, int width, int height) {
  Params p = Params::resolve(info.params, given, where);
  if (info.check) info.check(p, width, height, where);
  return p;
}

nlohmann::json generator_registry_json() {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& info : generator_registry()) {
    nlohmann::json p = nlohmann::json::array();
    for (const auto& s : info.params) p.push_back(s.to_json());
    out.push_back({{"name", info.name}, {"summary", info.summary}, {"params", p}});
  }
  return out;
}

}  // namespace agv
