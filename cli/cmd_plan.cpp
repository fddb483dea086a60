// `agvbench plan`: planners on one map, with the path drawn in ASCII and the metrics printed.
// A generated map is the very map a sweep cell would produce for (seed, map index), so any run
// record can be replayed and looked at.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "algos/registry.h"
#include "cli/cli_numbers.h"
#include "cli/cli_params.h"
#include "cli/command.h"
#include "cli/option_checks.h"
#include "core/json_text.h"
#include "engine/judge/run_executor.h"
#include "engine/outputs/report.h"
#include "engine/plan/files_read.h"
#include "engine/plan/output_paths.h"
#include "engine/plan/sweep_plan.h"
#include "engine/sweep/single_map.h"
#include "generators/movingai.h"
#include "generators/registry.h"

namespace agv {

namespace {

struct PlanCommand {
  std::vector<std::string> planners = {"astar"};
  std::vector<std::string> params;  // "key=value", applied to every planner that declares key
  std::string map_file;             // a MovingAI .map; else a generated grid
  std::string generator = "uniform";
  std::vector<std::string> gen_params;  // "key=value", the generator's shape parameters
  std::string size = "32";
  double density = 0.2;
  std::string endpoints = "corners";
  bool require_solvable = true;
  long long seed = 1;
  int map_index = 0;
  std::string start;  // "x,y"; required with a map file
  std::string goal;
  bool json = false;
  bool ascii = true;
  std::string json_out;  // write the result document to this file
  // The collision model every path is judged under, and every planner's default rule and
  // clearance (as a sweep's "collision").
  std::string corner_rule = "no_corner_cut";
  double clearance = 0.0;
};

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

// The map of the command: a map file, or the generated map a sweep cell would make.
struct PlanMap {
  Grid grid;
  Cell start, goal;
  std::string cell_key;  // names the runs' random streams: the cell's key, or the map file
  nlohmann::json doc;
};

PlanMap file_map(const PlanCommand& cmd) {
  PlanMap m;
  m.grid = read_map(cmd.map_file);
  if (cmd.start.empty() || cmd.goal.empty())
    throw InputError("--start and --goal are required with --map");
  if (!cmd.gen_params.empty())
    throw InputError("--gen-param: a generator parameter, meaningless with --map");
  m.cell_key = cmd.map_file;
  m.doc = {{"file", cmd.map_file}};
  return m;
}

// The generator's map spec as a sweep cell of this generator, size and density has it.
MapSpec plan_spec(const PlanCommand& cmd, GridSize size) {
  const GeneratorInfo& generator = generator_or_throw(cmd.generator, "--generator");
  MapSpec spec;
  spec.generator = cmd.generator;
  spec.params = resolve_generator_params(generator, cli_generator_params(generator, cmd.gen_params),
                                         "--gen-param", size.width, size.height)
                    .values();
  spec.width = size.width;
  spec.height = size.height;
  spec.density = cmd.density;
  spec.require_solvable = cmd.require_solvable;
  if (cmd.endpoints == "corners") {
    spec.endpoints = EndpointMode::corners;
  } else if (cmd.endpoints == "random") {
    spec.endpoints = EndpointMode::random;
  } else if (cmd.endpoints == "fixed") {
    // A sweep's "fixed" rule: --start and --goal are the cells the generator keeps free.
    if (cmd.start.empty() || cmd.goal.empty())
      throw InputError("--endpoints fixed: --start and --goal are required");
    spec.endpoints = EndpointMode::fixed;
    spec.start = parse_cell(cmd.start, "--start");
    spec.goal = parse_cell(cmd.goal, "--goal");
  } else {
    throw InputError("--endpoints: expected corners, random or fixed, got \"" + cmd.endpoints +
                     "\"");
  }
  return spec;
}

PlanMap generated_map(const PlanCommand& cmd) {
  const GridSize size = parse_size(cmd.size);
  const MapSpec spec = plan_spec(cmd, size);
  PlanMap m;
  m.cell_key = cell_key(cmd.generator, size, cmd.density);
  MapInstance inst;
  try {
    inst = make_cell_map(spec, m.cell_key, static_cast<std::uint64_t>(cmd.seed), cmd.map_index);
  } catch (const std::invalid_argument& e) {
    // The fixed endpoints' fields are the command's --start and --goal.
    const std::string what = e.what();
    const bool endpoint = what.rfind("start: ", 0) == 0 || what.rfind("goal: ", 0) == 0;
    throw InputError(endpoint ? "--" + what : what);
  }
  m.grid = std::move(inst.grid);
  m.start = inst.start;
  m.goal = inst.goal;
  m.doc = {{"generator", cmd.generator},
           {"params", spec.params},
           {"cell", m.cell_key},
           {"seed", cmd.seed},
           {"map_index", cmd.map_index}};
  return m;
}

PlanMap plan_map(const PlanCommand& cmd) {
  PlanMap m = cmd.map_file.empty() ? generated_map(cmd) : file_map(cmd);
  if (!cmd.start.empty()) m.start = parse_cell(cmd.start, "--start");
  if (!cmd.goal.empty()) m.goal = parse_cell(cmd.goal, "--goal");
  check_endpoint(m.grid, m.start, "--start");
  check_endpoint(m.grid, m.goal, "--goal");
  m.doc["width"] = m.grid.width();
  m.doc["height"] = m.grid.height();
  m.doc["start"] = {m.start.x, m.start.y};
  m.doc["goal"] = {m.goal.x, m.goal.y};
  m.doc["rows"] = grid_rows(m.grid);
  return m;
}

std::vector<const PlannerInfo*> plan_planners(const PlanCommand& cmd) {
  std::vector<const PlannerInfo*> infos;
  for (const auto& name : cmd.planners) {
    const PlannerInfo* info = find_planner(name);
    if (info == nullptr) configure_planner(name, {}, "--planner");  // throws the listing error
    infos.push_back(info);
  }
  check_cli_params(infos, cmd.params);
  return infos;
}

// One run's entry of the result document.
nlohmann::json run_json(const std::string& planner, const Params& params, const RunOutput& o) {
  nlohmann::json metrics = nlohmann::json::object();
  for (std::size_t m = 0; m < kRunMetricNames.size(); ++m)
    metrics[std::string(kRunMetricNames[m])] =
        std::isfinite(o.metrics[m]) ? nlohmann::json(o.metrics[m]) : nlohmann::json(nullptr);
  for (const auto& [name, value] : o.result.extra) metrics[name] = value;
  nlohmann::json phases = nlohmann::json::object();
  for (const auto& ph : o.result.phases) phases[ph.name] = ph.ns;
  nlohmann::json run = {{"planner", planner},
                        {"params", params.values()},
                        {"outcome", std::string(to_string(o.outcome))},
                        {"message", o.message},
                        {"rule", std::string(to_string(o.result.rule))},
                        {"metrics", metrics},
                        {"path", points_json(o.result.path)},
                        {"timing", {{"plan_time_ns", o.plan_time_ns}, {"phases", phases}}}};
  if (o.result.trajectory) add_trajectory(run, *o.result.trajectory);
  return run;
}

constexpr char kMarks[] = "*ox+=~%&";

void print_runs(const PlanCommand& cmd, const PlanMap& map,
                const std::vector<const PlannerInfo*>& infos,
                const std::vector<RunOutput>& outputs) {
  std::vector<std::pair<char, const std::vector<Point>*>> drawn;
  for (std::size_t i = 0; i < outputs.size(); ++i)
    if (outputs[i].outcome == Outcome::success)
      drawn.push_back({kMarks[i % 8], &outputs[i].result.path});
  if (cmd.ascii) std::cout << draw(map.grid, map.start, map.goal, drawn) << "\n";
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
}

int command_plan(const PlanCommand& cmd) {
  const std::vector<const PlannerInfo*> infos = plan_planners(cmd);
  if (!cmd.json_out.empty()) {
    std::vector<InputPath> inputs = {{"--map", cmd.map_file}};
    add_plugins_read(loaded_plugins(), inputs);
    check_paths(inputs, {{"--json-out", cmd.json_out}});
    ignore_file_size_signal();
  }
  const PlanMap map = plan_map(cmd);
  const CollisionModel model = plan_model(cmd);
  MapReference ref(map.grid, map.start, map.goal, model);
  Scratch scratch;
  std::vector<RunOutput> outputs;
  nlohmann::json runs = nlohmann::json::array();
  for (const PlannerInfo* info : infos) {
    ConfiguredPlanner c = configure_planner(info->name, cli_params_for(*info, cmd.params),
                                            "--planner " + info->name, model);
    outputs.push_back(run_on_map(*c.planner, ref, static_cast<std::uint64_t>(cmd.seed),
                                 map.cell_key, cmd.map_index, info->name, scratch,
                                 Deadline::never(), MotionTimeParams{}));
    runs.push_back(run_json(info->name, c.params, outputs.back()));
  }
  const nlohmann::json doc = {{"map", map.doc},
                              {"collision",
                               {{"corner_rule", std::string(to_string(model.corner_rule))},
                                {"clearance", model.clearance}}},
                              {"runs", runs}};
  if (!cmd.json_out.empty()) write_json_atomic(doc, cmd.json_out);
  if (cmd.json) {
    std::cout << json_text(doc, 1) << "\n";
    return 0;
  }
  print_runs(cmd, map, infos, outputs);
  return 0;
}

}  // namespace

Command add_plan_command(CLI::App& app) {
  auto plan = std::make_shared<PlanCommand>();
  auto* sub = app.add_subcommand("plan", "run planners on one map and show the paths");
  sub->add_option("--planner", plan->planners, "planner name (repeatable)");
  sub->add_option("--param", plan->params, "KEY=VALUE parameter (repeatable)");
  sub->add_option("--map", plan->map_file, "MovingAI .map file (else a generated grid)");
  sub->add_option("--generator", plan->generator, "generator for a generated grid");
  sub->add_option("--gen-param", plan->gen_params,
                  "KEY=VALUE shape parameter of the generator (repeatable)");
  sub->add_option("--size", plan->size, "N or WxH");
  sub->add_option("--density", plan->density, "obstacle density")
      ->transform(number_in(kDensityRange));
  sub->add_option("--endpoints", plan->endpoints,
                  "corners, random, or fixed (the cells of --start and --goal)");
  sub->add_option("--seed", plan->seed, "sweep seed")->transform(integer_in(kSeedRange));
  sub->add_option("--map-index", plan->map_index, "map index within its sweep cell")
      ->transform(integer_in(kMapIndexRange));
  sub->add_option("--start", plan->start, "start cell x,y (overrides the endpoints)");
  sub->add_option("--goal", plan->goal, "goal cell x,y (overrides the endpoints)");
  sub->add_option("--corner-rule", plan->corner_rule,
                  "collision model: allow, no_squeeze or no_corner_cut (default)");
  sub->add_option("--clearance", plan->clearance,
                  "collision model: cells from obstacle centres beyond half a cell (default 0)")
      ->transform(number_in(kFiniteRange));
  sub->add_flag("--json", plan->json, "print the result as JSON instead of text");
  sub->add_option("--json-out", plan->json_out, "also write the result JSON to this file");
  sub->add_flag("!--no-ascii", plan->ascii, "do not draw the map");
  return {sub, [plan] { return command_plan(*plan); }};
}

}  // namespace agv
