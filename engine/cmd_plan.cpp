// `agvbench plan`: planners on one map, with the path drawn in ASCII and the metrics printed.
// A generated map is the very map a sweep cell would produce for (seed, map index), so any run
// record can be replayed and looked at.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "algos/registry.h"
#include "engine/cli_numbers.h"
#include "engine/cli_params.h"
#include "engine/commands.h"
#include "engine/json_text.h"
#include "engine/output_paths.h"
#include "engine/report.h"
#include "engine/run_executor.h"
#include "engine/sweep_plan.h"
#include "generators/movingai.h"
#include "generators/registry.h"

namespace agv {

namespace {

GridSize parse_size(const std::string& text) {
  const auto x = text.find_first_of("xX");
  if (x == std::string::npos) {
    const auto side = static_cast<int>(parse_cli_integer(text, "--size", kMapSideRange));
    return {side, side};
  }
  return {
      static_cast<int>(parse_cli_integer(text.substr(0, x), "--size (width)", kMapSideRange)),
      static_cast<int>(parse_cli_integer(text.substr(x + 1), "--size (height)", kMapSideRange))};
}

void check_endpoint(const Grid& grid, Cell c, const std::string& what) {
  if (!grid.in_bounds(c))
    throw InputError(what + ": (" + std::to_string(c.x) + "," + std::to_string(c.y) +
                     ") is outside the " + std::to_string(grid.width()) + "x" +
                     std::to_string(grid.height()) + " grid");
  if (grid.blocked(c))
    throw InputError(what + ": (" + std::to_string(c.x) + "," + std::to_string(c.y) +
                     ") is an obstacle cell");
}

std::string draw(const Grid& grid, Cell start, Cell goal,
                 const std::vector<std::pair<char, const std::vector<Point>*>>& paths) {
  std::vector<std::string> rows(static_cast<std::size_t>(grid.height()),
                                std::string(static_cast<std::size_t>(grid.width()), '.'));
  for (int y = 0; y < grid.height(); ++y)
    for (int x = 0; x < grid.width(); ++x)
      if (grid.blocked(x, y)) rows[y][x] = '#';
  for (const auto& [mark, path] : paths) {
    for (std::size_t i = 0; i + 1 < path->size(); ++i) {
      const Point a = (*path)[i], b = (*path)[i + 1];
      const double len = std::hypot(b.x - a.x, b.y - a.y);
      const int steps = std::max(1, static_cast<int>(std::ceil(len * 8)));
      for (int s = 0; s <= steps; ++s) {
        const double t = static_cast<double>(s) / steps;
        const int x = static_cast<int>(std::floor(a.x + (b.x - a.x) * t));
        const int y = static_cast<int>(std::floor(a.y + (b.y - a.y) * t));
        if (grid.in_bounds(x, y) && !grid.blocked(x, y)) rows[y][x] = mark;
      }
    }
  }
  rows[start.y][start.x] = 'S';
  rows[goal.y][goal.x] = 'G';
  std::string out;
  for (const auto& r : rows) out += r + "\n";
  return out;
}

nlohmann::json grid_rows(const Grid& grid) {
  nlohmann::json rows = nlohmann::json::array();
  for (int y = 0; y < grid.height(); ++y) {
    std::string r(static_cast<std::size_t>(grid.width()), '.');
    for (int x = 0; x < grid.width(); ++x)
      if (grid.blocked(x, y)) r[x] = '@';
    rows.push_back(r);
  }
  return rows;
}

nlohmann::json points_json(const std::vector<Point>& points) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : points) out.push_back({p.x, p.y});
  return out;
}

// A simulated robot run (fusion planners): the executed trajectory, the moving obstacles'
// tracks and the unknown cells, under the keys reports/plot_paths.py draws.
void add_trajectory(nlohmann::json& run, const Trajectory& tr) {
  run["trajectory"] = points_json(tr.position);
  run["trajectory_t"] = tr.t;
  run["trajectory_heading"] = tr.heading;
  run["trajectory_v"] = tr.v;
  run["trajectory_w"] = tr.w;
  run["robot_radius"] = tr.robot_radius;
  run["end_reason"] = tr.end_reason;
  nlohmann::json obstacles = nlohmann::json::array();
  for (const auto& ob : tr.obstacles)
    obstacles.push_back({{"track", points_json(ob.centre)}, {"radius", ob.radius}});
  run["obstacles"] = obstacles;
  nlohmann::json unknown = nlohmann::json::array();
  for (const auto& c : tr.unknown_cells) unknown.push_back({c.x, c.y});
  run["unknown_cells"] = unknown;
  run["global_path"] = points_json(tr.global_path);
  run["key_points"] = points_json(tr.key_points);
}

CollisionModel plan_model(const PlanCommand& cmd) {
  CollisionModel model;
  const auto rule = corner_rule_from_string(cmd.corner_rule);
  if (!rule)
    throw InputError("--corner-rule: \"" + cmd.corner_rule +
                     "\" is not a corner rule (allow, no_squeeze, no_corner_cut)");
  model.corner_rule = *rule;
  model.clearance = cmd.clearance;
  check_model_clearance(model, "--clearance");
  return model;
}

}  // namespace

int command_plan(const PlanCommand& cmd) {
  std::vector<const PlannerInfo*> infos;
  for (const auto& name : cmd.planners) {
    const PlannerInfo* info = find_planner(name);
    if (info == nullptr) configure_planner(name, {}, "--planner");  // throws the listing error
    infos.push_back(info);
  }
  check_cli_params(infos, cmd.params);
  if (!cmd.json_out.empty()) {
    check_paths({{"--map", cmd.map_file}}, {{"--json-out", cmd.json_out}});
    ignore_file_size_signal();
  }

  Grid grid;
  Cell start, goal;
  nlohmann::json map_doc;
  if (!cmd.map_file.empty()) {
    grid = read_map(cmd.map_file);
    if (cmd.start.empty() || cmd.goal.empty())
      throw InputError("--start and --goal are required with --map");
    if (!cmd.gen_params.empty())
      throw InputError("--gen-param: a generator parameter, meaningless with --map");
    map_doc = {{"file", cmd.map_file}};
  } else {
    SweepCell cell;
    const GridSize size = parse_size(cmd.size);
    const GeneratorInfo& generator = generator_or_throw(cmd.generator, "--generator");
    cell.generator = cmd.generator;
    cell.size = size;
    cell.density = cmd.density;
    cell.key = cell_key(cmd.generator, size, cmd.density);
    cell.spec.generator = cmd.generator;
    cell.spec.params =
        resolve_generator_params(generator, cli_generator_params(generator, cmd.gen_params),
                                 "--gen-param", size.width, size.height)
            .values();
    cell.spec.width = size.width;
    cell.spec.height = size.height;
    cell.spec.density = cmd.density;
    cell.spec.require_solvable = cmd.require_solvable;
    if (cmd.endpoints == "corners") {
      cell.spec.endpoints = EndpointMode::corners;
    } else if (cmd.endpoints == "random") {
      cell.spec.endpoints = EndpointMode::random;
    } else if (cmd.endpoints == "fixed") {
      // A sweep's "fixed" rule: --start and --goal are the cells the generator keeps free.
      if (cmd.start.empty() || cmd.goal.empty())
        throw InputError("--endpoints fixed: --start and --goal are required");
      cell.spec.endpoints = EndpointMode::fixed;
      cell.spec.start = parse_cell(cmd.start, "--start");
      cell.spec.goal = parse_cell(cmd.goal, "--goal");
    } else {
      throw InputError("--endpoints: expected corners, random or fixed, got \"" + cmd.endpoints +
                       "\"");
    }
    Rng rng = map_rng(static_cast<std::uint64_t>(cmd.seed), cell, cmd.map_index);
    MapInstance inst;
    try {
      inst = make_map(cell.spec, rng);
    } catch (const std::invalid_argument& e) {
      // The fixed endpoints' fields are the command's --start and --goal.
      const std::string what = e.what();
      const bool endpoint = what.rfind("start: ", 0) == 0 || what.rfind("goal: ", 0) == 0;
      throw InputError(endpoint ? "--" + what : what);
    }
    grid = std::move(inst.grid);
    start = inst.start;
    goal = inst.goal;
    map_doc = {{"generator", cmd.generator},
               {"params", cell.spec.params},
               {"cell", cell.key},
               {"seed", cmd.seed},
               {"map_index", cmd.map_index}};
  }
  if (!cmd.start.empty()) start = parse_cell(cmd.start, "--start");
  if (!cmd.goal.empty()) goal = parse_cell(cmd.goal, "--goal");
  check_endpoint(grid, start, "--start");
  check_endpoint(grid, goal, "--goal");
  map_doc["width"] = grid.width();
  map_doc["height"] = grid.height();
  map_doc["start"] = {start.x, start.y};
  map_doc["goal"] = {goal.x, goal.y};
  map_doc["rows"] = grid_rows(grid);

  const CollisionModel model = plan_model(cmd);
  MapReference ref(grid, start, goal, model);
  Scratch scratch;
  std::vector<RunOutput> outputs;
  nlohmann::json runs = nlohmann::json::array();
  for (std::size_t i = 0; i < infos.size(); ++i) {
    ConfiguredPlanner c = configure_planner(infos[i]->name, cli_params_for(*infos[i], cmd.params),
                                            "--planner " + infos[i]->name, model);
    SweepCell replay;
    replay.key = map_doc.value("cell", cmd.map_file);
    Rng rng = run_rng(static_cast<std::uint64_t>(cmd.seed), replay, cmd.map_index, infos[i]->name);
    outputs.push_back(
        execute_run(*c.planner, ref, rng, scratch, Deadline::never(), MotionTimeParams{}));
    const RunOutput& o = outputs.back();
    nlohmann::json metrics = nlohmann::json::object();
    for (std::size_t m = 0; m < kRunMetricNames.size(); ++m)
      metrics[std::string(kRunMetricNames[m])] =
          std::isfinite(o.metrics[m]) ? nlohmann::json(o.metrics[m]) : nlohmann::json(nullptr);
    for (const auto& [name, value] : o.result.extra) metrics[name] = value;
    nlohmann::json path = nlohmann::json::array();
    for (const auto& p : o.result.path) path.push_back({p.x, p.y});
    nlohmann::json phases = nlohmann::json::object();
    for (const auto& ph : o.result.phases) phases[ph.name] = ph.ns;
    runs.push_back({{"planner", infos[i]->name},
                    {"params", c.params.values()},
                    {"outcome", std::string(to_string(o.outcome))},
                    {"message", o.message},
                    {"rule", std::string(to_string(o.result.rule))},
                    {"metrics", metrics},
                    {"path", path},
                    {"timing", {{"plan_time_ns", o.plan_time_ns}, {"phases", phases}}}});
    if (o.result.trajectory) add_trajectory(runs.back(), *o.result.trajectory);
  }
  const nlohmann::json doc = {{"map", map_doc},
                              {"collision",
                               {{"corner_rule", std::string(to_string(model.corner_rule))},
                                {"clearance", model.clearance}}},
                              {"runs", runs}};
  if (!cmd.json_out.empty()) write_json_atomic(doc, cmd.json_out);
  if (cmd.json) {
    std::cout << json_text(doc, 1) << "\n";
    return 0;
  }

  static constexpr char kMarks[] = "*ox+=~%&";
  std::vector<std::pair<char, const std::vector<Point>*>> drawn;
  for (std::size_t i = 0; i < outputs.size(); ++i)
    if (outputs[i].outcome == Outcome::success)
      drawn.push_back({kMarks[i % 8], &outputs[i].result.path});
  if (cmd.ascii) std::cout << draw(grid, start, goal, drawn) << "\n";
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const RunOutput& o = outputs[i];
    std::cout << "[" << kMarks[i % 8] << "] " << infos[i]->name << ": " << to_string(o.outcome);
    if (!o.message.empty()) std::cout << " (" << o.message << ")";
    std::cout << "\n";
    for (std::size_t m = 0; m < kRunMetricNames.size(); ++m)
      if (std::isfinite(o.metrics[m]))
        std::cout << "    " << kRunMetricNames[m] << " = " << o.metrics[m] << "\n";
    for (const auto& [name, value] : o.result.extra)
      std::cout << "    " << name << " = " << value << "\n";
    // The CLI prints times in µs, the JSON keeps ns (README "Time units").
    std::cout << "    timing: plan time " << static_cast<double>(o.plan_time_ns) / 1e3 << " µs";
    for (const auto& ph : o.result.phases)
      std::cout << ", " << ph.name << " " << static_cast<double>(ph.ns) / 1e3 << " µs";
    std::cout << "\n";
  }
  return 0;
}

}  // namespace agv
