#include "python/py_plan.h"

#include <pybind11/numpy.h>

#include <chrono>
#include <cmath>
#include <pybind11_json/pybind11_json.hpp>
#include <string>

#include "algos/registry.h"
#include "core/input_error.h"
#include "core/json_reader.h"
#include "engine/judge/run_metrics.h"
#include "engine/plan/config_loader.h"
#include "engine/sweep/single_map.h"
#include "python/py_grid.h"

namespace py = pybind11;
using nlohmann::json;

namespace agv::py_bind {

namespace {

void check_endpoint(const Grid& grid, Cell c, const std::string& field) {
  const std::string at = "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")";
  if (!grid.in_bounds(c))
    throw InputError(field + ": " + at + " is outside the " + std::to_string(grid.width()) + " x " +
                     std::to_string(grid.height()) + " grid (x is the column, y the row)");
  if (grid.blocked(c)) throw InputError(field + ": " + at + " is an obstacle cell");
}

Deadline deadline_of(const json& time_limit_s) {
  if (time_limit_s.is_null()) return Deadline::never();
  const double s = ObjectReader::check_number(time_limit_s, "time_limit_s", kTimeLimitRange);
  return Deadline::after(std::chrono::nanoseconds(static_cast<std::int64_t>(s * 1e9)));
}

py::array_t<double> path_array(const std::vector<Point>& path) {
  py::array_t<double> out({static_cast<py::ssize_t>(path.size()), py::ssize_t{2}});
  auto view = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < path.size(); ++i) {
    view(static_cast<py::ssize_t>(i), 0) = path[i].x;
    view(static_cast<py::ssize_t>(i), 1) = path[i].y;
  }
  return out;
}

// The metrics of `agvbench plan --json`: every run metric (None where undefined) and the
// planner's extras.
py::dict metrics_dict(const RunOutput& o) {
  py::dict metrics;
  for (std::size_t m = 0; m < kRunMetricNames.size(); ++m) {
    const py::str name(std::string(kRunMetricNames[m]));
    metrics[name] = std::isfinite(o.metrics[m]) ? py::object(py::float_(o.metrics[m])) : py::none();
  }
  for (const auto& [name, value] : o.result.extra) metrics[py::str(name)] = value;
  return metrics;
}

}  // namespace

py::dict plan(const py::handle& grid_array, const py::handle& start, const py::handle& goal,
              const PlanCall& call) {
  const Grid grid = grid_from_array(grid_array, "grid", call.cell_edge);
  const Cell s = cell_from_object(start, "start");
  const Cell g = cell_from_object(goal, "goal");
  check_endpoint(grid, s, "start");
  check_endpoint(grid, g, "goal");
  const CollisionModel model =
      parse_collision(call.collision.is_null() ? json::object() : call.collision);
  const auto seed = ObjectReader::check_integer(call.seed, "seed", kSeedRange);
  const Deadline deadline = deadline_of(call.time_limit_s);
  const ConfiguredPlanner c = configure_planner(call.planner, call.params, "planner", model);
  MapReference ref(grid, s, g, model);
  Scratch scratch;
  RunOutput o;
  {
    // The run is the engine's alone: other Python threads may go on meanwhile.
    py::gil_scoped_release released;
    o = run_on_map(*c.planner, ref, static_cast<std::uint64_t>(seed), call.cell, call.map_index,
                   call.planner, scratch, deadline, MotionTimeParams{});
  }
  py::dict phases;
  for (const auto& ph : o.result.phases) phases[py::str(ph.name)] = ph.ns;
  py::dict out;
  out["outcome"] = std::string(to_string(o.outcome));
  out["message"] = o.message;
  out["rule"] = std::string(to_string(o.result.rule));
  out["path"] = path_array(o.result.path);
  out["metrics"] = metrics_dict(o);
  out["phases"] = phases;
  out["plan_time_ns"] = o.plan_time_ns;
  out["params"] = pyjson::from_json(c.params.values());
  return out;
}

}  // namespace agv::py_bind
