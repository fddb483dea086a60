#pragma once
// agvbench._core.make_map and load_map: a sweep cell's map, or a map file read as a map-file
// sweep reads it. Each returns a dict the package (python/agvbench/maps.py) turns into a Map.

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <string>

namespace agv::py_bind {

// The map `map_index` of the cell (generator, size, density) of a sweep with this seed and "map"
// object (`map_options`, null = {}), and generator shape parameters `params`: what
// `agvbench plan --generator ...` and the sweep draw. InputError naming the argument.
pybind11::dict make_map(const nlohmann::json& generator, const nlohmann::json& size,
                        const nlohmann::json& density, const nlohmann::json& seed,
                        const nlohmann::json& map_index, const nlohmann::json& map_options,
                        const nlohmann::json& params);
// A MovingAI .map, or a ROS map_server .yaml / .pgm / .png occupancy image.
pybind11::dict load_map(const std::string& path);

}  // namespace agv::py_bind
