// The generator registry: every generator listed with its declared parameters, shape parameters
// validated by their one declaration, test-only generators reachable by name.

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "core/input_error.h"
#include "core/rng.h"
#include "generators/map_generators.h"
#include "generators/registry.h"

namespace agv {
namespace {

using nlohmann::json;

std::string message_of(const GeneratorInfo& info, const json& given, int w = 64, int h = 64) {
  try {
    resolve_generator_params(info, given, "generators[0].params", w, h);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(GeneratorRegistry, EveryGeneratorIsListedWithItsParams) {
  const json listed = generator_registry_json();
  ASSERT_EQ(listed.size(), generator_registry().size());
  const std::map<std::string, std::set<std::string>> expected = {
      {"uniform", {}},
      {"blocks", {"block_min", "block_max"}},
      {"maze", {"corridor"}},
      {"rooms", {"room_size", "door_width"}}};
  std::set<std::string> seen;
  for (const auto& g : listed) {
    const std::string name = g.at("name");
    ASSERT_TRUE(expected.count(name)) << name;
    EXPECT_FALSE(g.at("summary").get<std::string>().empty()) << name;
    std::set<std::string> params;
    for (const auto& p : g.at("params")) {
      params.insert(p.at("name").get<std::string>());
      EXPECT_EQ(p.at("type"), "integer") << name;
      EXPECT_FALSE(p.at("doc").get<std::string>().empty()) << name;
      EXPECT_TRUE(p.contains("default") && p.contains("min") && p.contains("max")) << p.dump();
    }
    EXPECT_EQ(params, expected.at(name)) << name;
    seen.insert(name);
    EXPECT_EQ(find_generator(name), &generator_registry()[seen.size() - 1]);
  }
  EXPECT_EQ(seen.size(), expected.size());
}

TEST(GeneratorRegistry, ShapeParamsAreValidatedByTheirDeclaration) {
  const GeneratorInfo& rooms = generator_or_throw("rooms", "x");
  EXPECT_EQ(message_of(rooms, {{"room_size", 6}}), "no error");
  EXPECT_EQ(message_of(rooms, {{"room_size", 1}}),
            "generators[0].params.room_size: 1 is outside [2, 8192]");
  EXPECT_NE(message_of(rooms, {{"room_width", 6}})
                .find("generators[0].params.room_width: unknown "
                      "parameter (known: room_size, door_width)"),
            std::string::npos)
      << message_of(rooms, {{"room_width", 6}});
  EXPECT_NE(message_of(rooms, {{"door_width", "2"}}).find("door_width: expected an integer"),
            std::string::npos);
  const GeneratorInfo& blocks = generator_or_throw("blocks", "x");
  EXPECT_EQ(message_of(blocks, {{"block_min", 4}, {"block_max", 3}}),
            "generators[0].params.block_max: 3 is smaller than block_min (4)");
  const GeneratorInfo& maze = generator_or_throw("maze", "x");
  EXPECT_EQ(message_of(maze, {{"corridor", 20}}, 64, 64), "no error");
  EXPECT_NE(message_of(maze, {{"corridor", 20}}, 64, 16)
                .find("generators[0].params.corridor: 20 is outside [1, 16]"),
            std::string::npos);
  const GeneratorInfo& uniform = generator_or_throw("uniform", "x");
  EXPECT_NE(message_of(uniform, {{"corridor", 2}}).find("corridor: unknown parameter"),
            std::string::npos);
  // Resolved values carry every declared parameter, defaults filled in.
  EXPECT_EQ(resolve_generator_params(rooms, json::object(), "p", 64, 64).values(),
            (json{{"door_width", 2}, {"room_size", 8}}));
}

TEST(GeneratorRegistry, UnknownGeneratorNamesTheKnownOnes) {
  try {
    generator_or_throw("fractal", "generators[2]");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "generators[2]: unknown generator \"fractal\" (known: uniform, blocks, maze, rooms)");
  }
}

TEST(GeneratorRegistry, TestGeneratorsAreFoundAndDrawn) {
  GeneratorInfo border;
  border.name = "test_border";
  border.summary = "every edge cell blocked but the corners";
  border.generate = [](const Params&, MapContext& ctx) {
    ctx.canvas.reset(ctx.width, ctx.height, false);
    for (int x = 1; x + 1 < ctx.width; ++x) ctx.canvas.set(x, 0, true);
  };
  add_generator_for_testing(border);
  ASSERT_NE(find_generator("test_border"), nullptr);
  for (const auto& g : generator_registry()) EXPECT_NE(g.name, "test_border");
  MapSpec spec;
  spec.generator = "test_border";
  spec.width = 8;
  spec.height = 5;
  Rng rng(1, 2);
  const MapInstance m = make_map(spec, rng);
  EXPECT_EQ(m.grid.obstacle_count(), 6);
  EXPECT_TRUE(m.grid.blocked(3, 0));
}

}  // namespace
}  // namespace agv
