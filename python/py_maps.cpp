#include "python/py_maps.h"

#include <pybind11_json/pybind11_json.hpp>
#include <stdexcept>
#include <string>

#include "core/input_error.h"
#include "core/json_reader.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/sweep_plan.h"
#include "engine/sweep/single_map.h"
#include "generators/movingai.h"
#include "generators/occupancy_image.h"
#include "generators/registry.h"
#include "python/py_grid.h"

namespace py = pybind11;
using nlohmann::json;

namespace agv::py_bind {

namespace {

GridSize size_from_json(const json& size) {
  if (size.is_array() && size.size() == 2)
    return {static_cast<int>(ObjectReader::check_integer(size[0], "size[0]", kMapSideRange)),
            static_cast<int>(ObjectReader::check_integer(size[1], "size[1]", kMapSideRange))};
  if (size.is_number_integer()) {
    const auto side = static_cast<int>(ObjectReader::check_integer(size, "size", kMapSideRange));
    return {side, side};
  }
  throw InputError("size: expected a side length or (width, height), got " + size.dump());
}

py::tuple cell_tuple(Cell c) { return py::make_tuple(c.x, c.y); }

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

py::dict make_map(const json& generator, const json& size, const json& density, const json& seed,
                  const json& map_index, const json& map_options, const json& params) {
  if (!generator.is_string()) throw InputError("generator: expected a generator name");
  const std::string name = generator.get<std::string>();
  const GeneratorInfo& info = generator_or_throw(name, "generator");
  const GridSize cells = size_from_json(size);
  MapSpec spec;
  parse_map_options(map_options.is_null() ? json::object() : map_options, spec);
  spec.generator = name;
  spec.width = cells.width;
  spec.height = cells.height;
  spec.density = ObjectReader::check_number(density, "density", kDensityRange);
  spec.params =
      resolve_generator_params(info, params, "params", cells.width, cells.height).values();
  const auto run_seed = ObjectReader::check_integer(seed, "seed", kSeedRange);
  const auto index =
      static_cast<int>(ObjectReader::check_integer(map_index, "map_index", kMapIndexRange));
  const std::string key = cell_key(name, cells, spec.density);
  MapInstance inst;
  try {
    inst = make_cell_map(spec, key, static_cast<std::uint64_t>(run_seed), index);
  } catch (const std::invalid_argument& e) {
    // The spec's fields are the "map" object's (map.start, map.min_distance) or a parameter's.
    const std::string what = e.what();
    throw InputError(what.rfind("params.", 0) == 0 ? what : "map." + what);
  }
  py::dict out;
  out["grid"] = array_from_grid(inst.grid);
  out["start"] = cell_tuple(inst.start);
  out["goal"] = cell_tuple(inst.goal);
  out["cell"] = key;
  out["map_index"] = index;
  out["seed"] = run_seed;
  out["cell_edge"] = spec.cell_edge;
  out["params"] = pyjson::from_json(spec.params);
  return out;
}

py::dict load_map(const std::string& path) {
  Grid grid;
  if (ends_with(path, ".map")) {
    grid = read_map(path);
  } else if (ends_with(path, ".yaml") || ends_with(path, ".yml") || ends_with(path, ".pgm") ||
             ends_with(path, ".png")) {
    grid = read_occupancy_image(path, 1.0).grid;
  } else {
    throw InputError(path + ": not a map file (.map, .yaml, .yml, .pgm or .png)");
  }
  py::dict out;
  out["grid"] = array_from_grid(grid);
  out["cell"] = path;
  out["cell_edge"] = grid.cell_edge();
  return out;
}

}  // namespace agv::py_bind
