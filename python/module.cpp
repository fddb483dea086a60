// agvbench._core: the compiled half of the Python module (docs/PYTHON.md). Each function is a
// thin binding of an engine entry point the command line calls too; the package
// python/agvbench wraps the results in Python types. Bad input is agv::InputError in the
// engine and ValueError here, its message naming the argument.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <pybind11_json/pybind11_json.hpp>

#include "core/input_error.h"
#include "core/version.h"
#include "engine/outputs/run_record.h"
#include "engine/plan/catalogue.h"
#include "python/py_maps.h"
#include "python/py_plan.h"
#include "python/py_run.h"

namespace py = pybind11;
using nlohmann::json;

PYBIND11_MODULE(_core, m) {
  using namespace agv;
  m.doc() = "agvbench's engine (the agvbench package wraps it; docs/PYTHON.md)";
  m.attr("__version__") = AGVBENCH_VERSION;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  m.def(
      "catalogue", [] { return pyjson::from_json(catalogue_json()); },
      "planners, generators and map sources, as `agvbench list --json`");
  m.def("make_map", &py_bind::make_map, py::arg("generator"), py::arg("size"), py::arg("density"),
        py::arg("seed"), py::arg("map_index"), py::arg("map_options"), py::arg("params"));
  m.def("load_map", &py_bind::load_map, py::arg("path"));
  m.def(
      "plan",
      [](const py::handle& grid, const py::handle& start, const py::handle& goal,
         const std::string& planner, const json& params, const json& collision,
         const json& time_limit_s, const json& seed, const std::string& cell, int map_index,
         double cell_edge) {
        return py_bind::plan(
            grid, start, goal,
            {planner, params, collision, time_limit_s, seed, cell, map_index, cell_edge});
      },
      py::arg("grid"), py::arg("start"), py::arg("goal"), py::arg("planner"), py::arg("params"),
      py::arg("collision"), py::arg("time_limit_s"), py::arg("seed"), py::arg("cell"),
      py::arg("map_index"), py::arg("cell_edge"));
  m.def(
      "run",
      [](const json& config, const std::string& config_path, const json& threads,
         const std::string& out, const std::string& runs_out, const json& shard, bool keep_runs,
         const py::object& progress) {
        return py_bind::run({config, config_path, threads, out, runs_out, shard, keep_runs},
                            progress);
      },
      py::arg("config"), py::arg("config_path"), py::arg("threads"), py::arg("out"),
      py::arg("runs_out"), py::arg("shard"), py::arg("keep_runs"), py::arg("progress"));
  m.def(
      "merge",
      [](const json& config, const std::string& config_path,
         const std::vector<std::string>& journals, const std::string& out, bool keep_runs) {
        return py_bind::merge({config, config_path, nullptr, out, "", nullptr, keep_runs},
                              journals);
      },
      py::arg("config"), py::arg("config_path"), py::arg("journals"), py::arg("out"),
      py::arg("keep_runs"));
  m.def("read_journal", &py_bind::read_journal, py::arg("path"));
  m.def(
      "metric_names", [] { return pyjson::from_json(journal_metric_names()); },
      "the journal's metric order (reports/SCHEMA.md)");
  m.def("outcome_names", &py_bind::outcome_names);
}
