#pragma once
// Grids between numpy and the engine: a 2-D bool array (rows x columns, True = obstacle) is
// the Python side's grid, the padded agv::Grid the engine's.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include "core/grid.h"

namespace agv::py_bind {

// InputError naming `field` unless `array` is a 2-D numpy bool array of sides the engine takes
// (2..kMaxMapSide).
Grid grid_from_array(const pybind11::handle& array, const std::string& field, double cell_edge);
// rows x columns bool array, True = obstacle.
pybind11::array_t<bool> array_from_grid(const Grid& grid);
// A cell from a Python pair (x, y) = (column, row); InputError naming `field` otherwise.
Cell cell_from_object(const pybind11::handle& point, const std::string& field);

}  // namespace agv::py_bind
