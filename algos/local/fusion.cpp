#include "algos/local/fusion.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "algos/local/dwa.h"
#include "algos/local/dwa_world.h"
#include "algos/local/fusion_drive.h"

namespace agv {

namespace {

// Grid planners a fusion run may take its global path from. A name here that is not (yet)
// registered is refused when the planner is configured.
const std::vector<std::string> kGlobalPlanners = {
    "astar",   "dijkstra",       "bidir_astar", "ma_star", "improved_astar",
    "improved_astar_internal", "alt_astar", "kin_astar"};

struct PlannerSetup {
  std::string global_name;  // empty: pure DWA
  std::string global_rule;  // planner_default or a corner rule name
  double global_margin = -1.0;  // < 0: the planner's own
  FusionOptions drive;
  WorldSpec world;
  double sim_time_limit = 0.0;  // 0: auto
  std::uint32_t world_seed = 0;
};

DwaScore score_of(const std::string& name) {
  if (name == "improved_003") return DwaScore::improved_003;
  if (name == "following_004") return DwaScore::following_004;
  return DwaScore::classic;
}

std::vector<ParamSpec> fusion_params(const char* global_default, DwaScore score_default) {
  std::vector<ParamSpec> ps;
  if (global_default != nullptr) {
    ps.push_back(ParamSpec::choice(
        "global_planner", global_default, kGlobalPlanners,
        "registered grid planner that plans the global path on the known grid"));
    ps.push_back(ParamSpec::choice(
        "global_corner_rule", "no_corner_cut",
        {"planner_default", "allow", "no_squeeze", "no_corner_cut"},
        "corner_rule forced on the global planner when it declares one (a disc robot cannot "
        "pass between diagonal obstacles); planner_default keeps the planner's own"));
    ps.push_back(ParamSpec::number(
        "global_margin", 0.6, -1.0, 5.0,
        "cells, set as the global planner's `margin` when it declares one (alt_astar's shortcut "
        "clearance: obstacle centres margin + 0.5 away, so margin 0.6 keeps a disc of 0.35 clear "
        "of obstacle corners; the planner's default 0 lets shortcuts graze them); -1 = its own"));
    ps.push_back(ParamSpec::number(
        "key_point_tolerance", 0.1, 0.0, 5.0,
        "cells: Ramer-Douglas-Peucker tolerance for the key points (local goals) of the global "
        "path; on cell-centre paths any value below 0.3 is exact collinear removal"));
    ps.push_back(ParamSpec::number("waypoint_tolerance", 0.3, 0.01, 10.0,
                                   "cells: the local goal advances when the robot is this close"));
    ps.push_back(ParamSpec::number(
        "pass_radius", 0.6, 0.0, 10.0,
        "cells: the local goal also advances when the robot is this close to it and beyond it "
        "along the segment leading to it (an overshoot)"));
    ps.push_back(ParamSpec::boolean(
        "replan", true,
        "replan the global path from the robot's cell when a newly seen unknown cell lies on "
        "the remaining global path (not in the papers)"));
    ps.push_back(ParamSpec::boolean(
        "turn_speed_limit", true,
        "cap the speed so the robot can turn at the coming key points (w_max over one cell), "
        "braking at acc_v (not in the papers; algos/local/fusion_drive.h)"));
    ps.push_back(ParamSpec::number(
        "turn_distance", 1.0, 0.01, 100.0,
        "cells: the turn speed limit lets the robot turn by phi at w_max within this travel"));
    ps.push_back(ParamSpec::choice(
        "heading_aim", "segment", {"segment", "key_point"},
        "heading term aims at the key point itself, or at the point `lookahead` ahead on the "
        "segment leading to it (pure-pursuit style; keeps the robot on the path's line)"));
    ps.push_back(ParamSpec::number("lookahead", 0.75, 0.0, 100.0,
                                   "cells: aim point distance for heading_aim = segment"));
    ps.push_back(ParamSpec::choice(
        "heading_target", "local_goal", {"local_goal", "final_goal"},
        "what the heading term aims at: the current key point (fusion, paper 003 Heading, "
        "paper 004 PHead) or the final goal (paper 004's 'traditional' heading)"));
  }
  const char* score_name = to_string(score_default);
  ps.push_back(ParamSpec::choice("score", score_name, {"classic", "improved_003", "following_004"},
                                 "DWA objective: classic (003 eq. 12), improved_003 (003 eq. 13), "
                                 "following_004 (004 eq. 13, with sigma smoothing)"));
  ps.push_back(ParamSpec::number("v_max", 2.0, 0.01, 100.0, "m/s (paper 003 Table 2)"));
  ps.push_back(ParamSpec::number("w_max", 0.7, 0.01, 100.0, "rad/s (paper 003 Table 2)"));
  ps.push_back(ParamSpec::number("acc_v", 0.4, 0.001, 1000.0, "m/s^2 (paper 003 Table 2)"));
  ps.push_back(ParamSpec::number("acc_w", 1.7, 0.001, 1000.0, "rad/s^2 (paper 003 Table 2)"));
  ps.push_back(ParamSpec::number("predict_time", 3.0, 0.01, 60.0,
                                 "s: rollout horizon T (paper 003 Table 2)"));
  ps.push_back(ParamSpec::number("dt", 0.1, 0.001, 10.0, "s: control period and rollout step"));
  ps.push_back(ParamSpec::integer("v_samples", 9, 1, 201, "linear velocity samples in the window"));
  ps.push_back(ParamSpec::integer("w_samples", 15, 1, 201, "angular velocity samples in the window"));
  const char* weight_doc = "score weight; -1 = the score's default (classic and following_004: "
                           "heading 0.2, velocity 0.1, clearance 0.3; improved_003: 0.2, 0.4, "
                           "0.2, dynamic 0.35)";
  for (const char* name : {"w_heading", "w_velocity", "w_clearance", "w_dynamic"})
    ps.push_back(ParamSpec::number(name, -1.0, -1.0, 1000.0, weight_doc));
  ps.push_back(ParamSpec::choice("smoothing", "auto", {"auto", "on", "off"},
                                 "sigma smoothing of the objective over the velocity samples; "
                                 "auto = on for following_004 only"));
  ps.push_back(ParamSpec::boolean("va_omega", true,
                                  "apply eq. 10's |w| <= sqrt(2 dist a_w) besides the v bound"));
  ps.push_back(ParamSpec::number("robot_radius", 0.3, 0.01, 0.49, "cells: the robot disc"));
  ps.push_back(ParamSpec::number(
      "safety_margin", 0.05, 0.0, 1.0,
      "cells: rollout points closer than robot_radius + this to an obstacle count as hits"));
  ps.push_back(ParamSpec::choice(
      "dist_mode", "collision", {"collision", "clearance"},
      "clearance terms: collision = arc length to the rollout's first hit, capped at dist_cap "
      "(Fox et al. 1997); clearance = minimum clearance over the rollout (algos/local/dwa.h)"));
  ps.push_back(ParamSpec::number("dist_cap", 3.0, 0.01, 1000.0, "m: cap of the collision distance"));
  ps.push_back(ParamSpec::number(
      "dynamic_margin", 0.2, 0.0, 5.0,
      "cells added to moving obstacles' radius in the DWA (seen at their current position only)"));
  ps.push_back(ParamSpec::number(
      "static_clearance_cap", 1.0, 0.01, 1.0,
      "cells (dist_mode clearance): cap of the clearance to known static obstacles"));
  ps.push_back(ParamSpec::number(
      "dynamic_clearance_cap", 2.0, 0.1, 100.0,
      "cells (dist_mode clearance): cap of the clearance to unknown and moving obstacles"));
  ps.push_back(ParamSpec::number(
      "sensor_range", 8.0, 0.0, 1e6,
      "cells: unknown cells (then remembered) and moving obstacles are seen within this range "
      "(8: beyond the 5 m braking distance from v_max at acc_v)"));
  ps.push_back(ParamSpec::number("goal_tolerance", 0.5, 0.01, 10.0,
                                 "cells: reached when the robot centre is this close to the goal's"));
  ps.push_back(ParamSpec::number(
      "sim_time_limit", 0.0, 0.0, 1e6,
      "s of simulated time before `timeout`; 0 = 30 s + 10 x reference path length / v_max"));
  ps.push_back(ParamSpec::integer(
      "stuck_steps", 100, 1, 1000000,
      "consecutive control steps in which the robot does not move (no admissible moving "
      "velocity pair, or the DWA prefers to stand) before `stuck`; 100 = 10 s at dt 0.1, "
      "more than a half turn on the spot takes"));
  ps.push_back(ParamSpec::integer("dynamic_obstacles", 1, 0, 1000, "moving discs"));
  ps.push_back(ParamSpec::number("dynamic_speed", 0.5, 0.0, 100.0, "m/s of every moving disc"));
  ps.push_back(ParamSpec::number("dynamic_radius", 0.4, 0.05, 5.0, "cells"));
  ps.push_back(ParamSpec::boolean(
      "dynamic_yield", false,
      "moving discs reflect off the robot as off a wall, so they never run into it (not in the "
      "papers: without it a disc also rams a robot that has stopped in a corridor)"));
  ps.push_back(ParamSpec::boolean(
      "predict_moving", false,
      "the DWA moves each seen disc at the velocity observed between its last two positions "
      "(the papers: current position only)"));
  ps.push_back(ParamSpec::choice("dynamic_placement", "on_path", {"on_path", "anywhere"},
                                 "moving discs start on the middle of the reference path, or "
                                 "anywhere free"));
  ps.push_back(ParamSpec::integer("unknown_obstacles", 1, 0, 1000,
                                  "unknown static cells on or next to the reference path"));
  ps.push_back(ParamSpec::integer("world_seed", 0, 0, 1000000,
                                  "selects another world on the same map"));
  return ps;
}

PlannerSetup setup_of(const Params& p, bool has_global) {
  PlannerSetup ps;
  FusionOptions& s = ps.drive;
  if (has_global) {
    ps.global_name = p.choice("global_planner");
    ps.global_rule = p.choice("global_corner_rule");
    ps.global_margin = p.number("global_margin");
    s.key_point_tolerance = p.number("key_point_tolerance");
    s.waypoint_tolerance = p.number("waypoint_tolerance");
    s.pass_radius = p.number("pass_radius");
    s.replan = p.boolean("replan");
    s.heading_final = p.choice("heading_target") == "final_goal";
    s.turn_speed_limit = p.boolean("turn_speed_limit");
    s.turn_distance = p.number("turn_distance");
    s.aim_segment = p.choice("heading_aim") == "segment";
    s.lookahead = p.number("lookahead");
  }
  DwaParams& d = s.dwa;
  d.score = score_of(p.choice("score"));
  d.v_max = p.number("v_max");
  d.w_max = p.number("w_max");
  d.acc_v = p.number("acc_v");
  d.acc_w = p.number("acc_w");
  d.predict_time = p.number("predict_time");
  d.dt = p.number("dt");
  d.v_samples = static_cast<int>(p.integer("v_samples"));
  d.w_samples = static_cast<int>(p.integer("w_samples"));
  d.weights = default_weights(d.score);
  if (p.number("w_heading") >= 0.0) d.weights.heading = p.number("w_heading");
  if (p.number("w_velocity") >= 0.0) d.weights.velocity = p.number("w_velocity");
  if (p.number("w_clearance") >= 0.0) d.weights.clearance = p.number("w_clearance");
  if (p.number("w_dynamic") >= 0.0) d.weights.dynamic = p.number("w_dynamic");
  const std::string& smoothing = p.choice("smoothing");
  d.smoothing = smoothing == "on" || (smoothing == "auto" && d.score == DwaScore::following_004);
  d.va_omega = p.boolean("va_omega");
  d.robot_radius = p.number("robot_radius");
  d.safety_margin = p.number("safety_margin");
  d.dist_mode = p.choice("dist_mode") == "clearance" ? DwaParams::DistMode::clearance
                                                     : DwaParams::DistMode::collision;
  d.dist_cap = p.number("dist_cap");
  d.dynamic_margin = p.number("dynamic_margin");
  d.static_clearance_cap = p.number("static_clearance_cap");
  d.dynamic_clearance_cap = p.number("dynamic_clearance_cap");
  s.sensor_range = p.number("sensor_range");
  s.goal_tolerance = p.number("goal_tolerance");
  if (!has_global) {
    // Pure DWA: Fox's heading toward the goal itself, no path to slow down for.
    s.waypoint_tolerance = s.goal_tolerance;
    s.aim_segment = false;
    s.turn_speed_limit = false;
  }
  ps.sim_time_limit = p.number("sim_time_limit");
  s.stuck_steps = static_cast<int>(p.integer("stuck_steps"));
  ps.world.moving_obstacles = static_cast<int>(p.integer("dynamic_obstacles"));
  ps.world.moving_speed = p.number("dynamic_speed");
  ps.world.moving_radius = p.number("dynamic_radius");
  ps.world.moving_on_path = p.choice("dynamic_placement") == "on_path";
  ps.world.moving_yield = s.moving_yield = p.boolean("dynamic_yield");
  s.predict_moving = p.boolean("predict_moving");
  ps.world.unknown_obstacles = static_cast<int>(p.integer("unknown_obstacles"));
  ps.world.robot_radius = d.robot_radius;
  ps.world_seed = static_cast<std::uint32_t>(p.integer("world_seed"));
  return ps;
}

// The world's random stream: a function of the map (cells, start, goal) and world_seed only,
// so every planner on a map meets the same world (see algos/local/dwa_world.h).
Rng world_rng(const Grid& grid, Cell start, Cell goal, std::uint32_t world_seed) {
  std::uint64_t h = stable_hash("fusion_world");
  const std::uint8_t* occ = grid.occupancy();
  for (int i = 0; i < grid.padded_size(); ++i) h = (h ^ occ[i]) * 0x100000001b3ULL;
  h = mix64(h ^ (static_cast<std::uint64_t>(grid.width()) << 32) ^
            static_cast<std::uint64_t>(grid.height()));
  h = mix64(h ^ (static_cast<std::uint64_t>(start.x) << 48) ^
            (static_cast<std::uint64_t>(start.y) << 32) ^
            (static_cast<std::uint64_t>(goal.x) << 16) ^ static_cast<std::uint64_t>(goal.y));
  return Rng(h, world_seed);
}

double path_length_cells(std::span<const Point> path) {
  double l = 0.0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    l += std::hypot(path[i + 1].x - path[i].x, path[i + 1].y - path[i].y);
  return l;
}

class FusionPlanner final : public Planner {
 public:
  FusionPlanner(const Params& params, bool has_global) : s_(setup_of(params, has_global)) {
    // The reference path places the world's obstacles; it is the same for every planner.
    reference_ =
        configure_planner("astar", {{"corner_rule", "no_corner_cut"}}, "reference").planner;
    if (!has_global) return;
    const PlannerInfo* info = find_planner(s_.global_name);
    if (info == nullptr)
      throw InputError("global_planner: \"" + s_.global_name +
                       "\" is not a registered planner in this build");
    nlohmann::json given = nlohmann::json::object();
    for (const auto& spec : info->params) {
      if (spec.name == "corner_rule" && s_.global_rule != "planner_default")
        given["corner_rule"] = s_.global_rule;
      if (spec.name == "margin" && s_.global_margin >= 0.0) given["margin"] = s_.global_margin;
    }
    global_ = configure_planner(s_.global_name, given, "global_planner").planner;
  }

  PlanResult plan(const PlanRequest& req) const override {
    PlanResult result;
    const Grid& grid = req.grid;

    // 1. The world, from the map's reference path.
    std::int64_t t0 = thread_cpu_ns();
    std::vector<Point> reference;
    if (PlanResult ref = reference_->plan(req); ref.ok()) reference = std::move(ref.path);
    Rng wrng = world_rng(grid, req.start, req.goal, s_.world_seed);
    DwaWorld world = DwaWorld::generate(grid, req.start, req.goal, reference, s_.world, wrng);
    result.phases.push_back({"world", thread_cpu_ns() - t0});

    // 2. The global path and its key points (pure DWA: start and goal).
    std::vector<Point> global_path;
    std::vector<Point> keys = {centre(req.start), centre(req.goal)};
    result.rule = CornerRule::no_corner_cut;
    if (global_) {
      t0 = thread_cpu_ns();
      PlanResult g = global_->plan(req);
      result.phases.push_back({"global", thread_cpu_ns() - t0});
      result.expanded_nodes = g.expanded_nodes;
      result.rule = g.rule;
      if (!g.ok()) {
        PlanResult f = PlanResult::failed(g.failure, "global planner " + s_.global_name + ": " +
                                                         g.message);
        f.rule = g.rule;
        f.expanded_nodes = g.expanded_nodes;
        f.phases = std::move(result.phases);
        return f;
      }
      global_path = std::move(g.path);
      keys = fusion_key_points(global_path, s_.drive.key_point_tolerance);
    }

    // 3. The control loop.
    FusionOptions options = s_.drive;
    const double ref_length = reference.empty() ? 2.0 * std::hypot(req.goal.x - req.start.x,
                                                                   req.goal.y - req.start.y)
                                                : path_length_cells(reference);
    options.sim_time_limit =
        s_.sim_time_limit > 0.0
            ? s_.sim_time_limit
            : 30.0 + 10.0 * ref_length * grid.cell_edge() / options.dwa.v_max;
    t0 = thread_cpu_ns();
    DriveResult run = drive(options, req, world, std::move(keys), global_.get());
    const std::int64_t loop_ns = thread_cpu_ns() - t0;
    result.expanded_nodes += run.expanded_nodes;
    result.phases.push_back({"dwa", loop_ns});
    // Mean CPU time of one control step: timing, reported under `timing.phases`.
    result.phases.push_back({"cpu_ns_per_step", run.steps > 0 ? loop_ns / run.steps : 0});
    if (run.deadline_hit) {
      PlanResult f = PlanResult::failed(Failure::limit, "time limit during the control loop");
      f.rule = result.rule;
      f.expanded_nodes = result.expanded_nodes;
      f.phases = std::move(result.phases);
      return f;
    }

    Trajectory& tr = *run.trajectory;
    tr.global_path = std::move(global_path);
    result.extra.emplace_back("key_points", static_cast<double>(tr.key_points.size()));
    result.extra.emplace_back("replans", static_cast<double>(run.replans));
    result.failure = tr.end_reason == "reached" ? Failure::none : Failure::no_path;
    if (!result.ok()) result.message = "run ended: " + tr.end_reason;
    result.path = tr.position;
    result.trajectory = std::move(run.trajectory);
    return result;
  }

 private:
  PlannerSetup s_;
  std::unique_ptr<Planner> reference_;
  std::unique_ptr<Planner> global_;
};

PlannerInfo make_info(const char* name, const char* summary, const char* source,
                      const char* global_default, DwaScore score) {
  PlannerInfo info;
  info.kind = PlannerKind::local;
  info.name = name;
  info.summary = summary;
  info.source = source;
  info.expanded_nodes_meaning = global_default != nullptr
                                    ? "the global planner's expanded nodes (replans included)"
                                    : "0 (no global search)";
  info.stochastic = false;  // the world is drawn from the map, not from the run's stream
  info.params = fusion_params(global_default, score);
  if (global_default != nullptr) {
    info.make = [](const Params& params) -> std::unique_ptr<Planner> {
      return std::make_unique<FusionPlanner>(params, true);
    };
  } else {
    info.make = [](const Params& params) -> std::unique_ptr<Planner> {
      return std::make_unique<FusionPlanner>(params, false);
    };
  }
  return info;
}

}  // namespace

PlannerInfo dwa_planner() {
  return make_info("dwa", "pure DWA toward the goal in a world with unknown and moving obstacles",
                   "paper 003 section 3 (improved DWA alone: set score improved_003); PLANNERS.md",
                   nullptr, DwaScore::classic);
}

PlannerInfo fusion_astar_dwa_planner() {
  return make_info("fusion_astar_dwa", "classic A* global path + classic DWA (the papers' baseline)",
                   "paper 003 sections 4-5 and paper 004 section 4 baseline; PLANNERS.md", "astar",
                   DwaScore::classic);
}

PlannerInfo fusion_alt_dwa_planner() {
  return make_info("fusion_alt_dwa", "alternative A* global path + improved DWA",
                   "paper 003 sections 2-4 (eq. 13); PLANNERS.md", "alt_astar",
                   DwaScore::improved_003);
}

PlannerInfo fusion_kin_dwa_planner() {
  return make_info("fusion_kin_dwa", "kinematic-constraint A* global path + following DWA",
                   "paper 004 sections 2-3 (eq. 13 PHead); PLANNERS.md", "kin_astar",
                   DwaScore::following_004);
}

FusionOptions fusion_options(const Params& params, bool has_global) {
  return setup_of(params, has_global).drive;
}

}  // namespace agv
