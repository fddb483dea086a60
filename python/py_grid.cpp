#include "python/py_grid.h"

#include <string>

#include "core/input_error.h"

namespace py = pybind11;

namespace agv::py_bind {

Grid grid_from_array(const py::handle& array, const std::string& field, double cell_edge) {
  if (!py::isinstance<py::array>(array))
    throw InputError(field +
                     ": expected a numpy bool array (rows x columns, True = obstacle), got " +
                     std::string(py::str(py::type::of(array).attr("__name__"))));
  const auto a = py::reinterpret_borrow<py::array>(array);
  if (a.dtype().kind() != 'b')
    throw InputError(field + ": expected dtype bool (True = obstacle), got " +
                     std::string(py::str(a.dtype())));
  if (a.ndim() != 2)
    throw InputError(field + ": expected a 2-D array (rows x columns), got " +
                     std::to_string(a.ndim()) + " dimensions");
  const auto rows = a.shape(0), cols = a.shape(1);
  for (const auto side : {rows, cols})
    if (side < 2 || side > kMaxMapSide)
      throw InputError(field + ": " + std::to_string(rows) + " x " + std::to_string(cols) +
                       " cells; each side must be 2.." + std::to_string(kMaxMapSide));
  // Any strides (a slice, a transposed view): read through the unchecked accessor.
  const auto cells = py::array_t<bool>::ensure(a);
  const auto view = cells.unchecked<2>();
  Grid grid(static_cast<int>(cols), static_cast<int>(rows), cell_edge);
  for (py::ssize_t y = 0; y < rows; ++y)
    for (py::ssize_t x = 0; x < cols; ++x)
      if (view(y, x)) grid.set_blocked(static_cast<int>(x), static_cast<int>(y), true);
  return grid;
}

py::array_t<bool> array_from_grid(const Grid& grid) {
  py::array_t<bool> out({grid.height(), grid.width()});
  auto view = out.mutable_unchecked<2>();
  for (int y = 0; y < grid.height(); ++y)
    for (int x = 0; x < grid.width(); ++x) view(y, x) = grid.blocked(x, y);
  return out;
}

Cell cell_from_object(const py::handle& point, const std::string& field) {
  const auto fail = [&] {
    return InputError(field + ": expected a cell (x, y) of two integers (column, row), got " +
                      std::string(py::repr(point)));
  };
  if (!py::isinstance<py::sequence>(point) || py::isinstance<py::str>(point)) throw fail();
  const auto seq = py::reinterpret_borrow<py::sequence>(point);
  if (seq.size() != 2) throw fail();
  Cell c;
  int* parts[2] = {&c.x, &c.y};
  for (int k = 0; k < 2; ++k) {
    // Python ints and numpy integers; a float (even 3.0) is not a cell.
    const py::handle v = seq[k];
    if (py::isinstance<py::bool_>(v) || !py::hasattr(v, "__index__")) throw fail();
    const auto value = py::int_(py::reinterpret_borrow<py::object>(v)).cast<long long>();
    if (value < -(1LL << 30) || value > (1LL << 30)) throw fail();
    *parts[k] = static_cast<int>(value);
  }
  return c;
}

}  // namespace agv::py_bind
