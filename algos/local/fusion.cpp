#include "algos/local/fusion.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "algos/local/dwa.h"
#include "algos/local/dwa_world.h"
#include "algos/local/fusion_drive.h"
#include "core/line_of_sight.h"

namespace agv {

namespace {

// The options a fusion planner's parameters fill. Weights and smoothing keep the given value
// until finish_setup() resolves them against the score.
struct PlannerSetup {
  std::string global_name;                // empty: pure DWA
  std::optional<CornerRule> global_rule;  // nullopt: the planner's own
  double global_margin = -1.0;            // < 0: the planner's own
  bool goals_from_curve = false;          // local_goals: curve_samples (true) or key_nodes
  FusionOptions drive;
  WorldSpec world;
  DwaWeights given_weights;       // each < 0: the score's default
  std::optional<bool> smoothing;  // nullopt: auto (on for following_004)
  double sim_time_limit = 0.0;    // 0: auto
  std::uint32_t world_seed = 0;
};

// Fields of the nested option structs, for the declarations below.
template <auto member>
auto& drive_field(PlannerSetup& s) {
  return s.drive.*member;
}
template <auto member>
auto& dwa_field(PlannerSetup& s) {
  return s.drive.dwa.*member;
}
template <auto member>
auto& weight_field(PlannerSetup& s) {
  return s.given_weights.*member;
}
template <auto member>
auto& world_field(PlannerSetup& s) {
  return s.world.*member;
}

// One registration: dwa (no global planner) or a fusion of a grid planner and a DWA score.
struct FusionVariant {
  const char* name;
  const char* summary;
  const char* source;
  const char* global_default;  // nullptr: pure DWA
  DwaScore score;
};

constexpr FusionVariant kDwa{
    "dwa", "pure DWA toward the goal in a world with unknown and moving obstacles",
    "paper 003 section 3 (improved DWA alone: set score improved_003); docs/PLANNERS.md", nullptr,
    DwaScore::classic};
constexpr FusionVariant kAstarDwa{
    "fusion_astar_dwa", "classic A* global path + classic DWA (the papers' baseline)",
    "paper 003 sections 4-5 and paper 004 section 4 baseline; docs/PLANNERS.md", "astar",
    DwaScore::classic};
constexpr FusionVariant kAltDwa{"fusion_alt_dwa", "alternative A* global path + improved DWA",
                                "paper 003 sections 2-4 (eq. 13); docs/PLANNERS.md", "alt_astar",
                                DwaScore::improved_003};
constexpr FusionVariant kKinDwa{"fusion_kin_dwa",
                                "kinematic-constraint A* global path + following DWA",
                                "paper 004 sections 2-3 (eq. 13 PHead); docs/PLANNERS.md",
                                "kin_astar", DwaScore::following_004};

// The global planner's parameters, declared only by the fusion variants.
void declare_global(ParamDecls<PlannerSetup>& d, const char* global_default,
                    const std::vector<std::string>& grid_planners) {
  ChoiceTable<std::string> planners;
  for (const auto& name : grid_planners) planners.emplace_back(name, name);
  d.choice("global_planner", &PlannerSetup::global_name, std::string(global_default),
           std::move(planners),
           "registered grid planner that plans the global path on the known grid");
  d.choice("global_corner_rule", &PlannerSetup::global_rule,
           std::optional<CornerRule>(CornerRule::no_corner_cut),
           ChoiceTable<std::optional<CornerRule>>{{"planner_default", std::nullopt},
                                                  {"allow", CornerRule::allow},
                                                  {"no_squeeze", CornerRule::no_squeeze},
                                                  {"no_corner_cut", CornerRule::no_corner_cut}},
           "corner_rule forced on the global planner when it declares one (a disc robot cannot "
           "pass between diagonal obstacles); planner_default keeps the planner's own");
  d.number("global_margin", &PlannerSetup::global_margin, 0.6, -1.0, 5.0,
           "cells, a floor for the global planner's `shortcut_margin` when it declares one: the "
           "planner runs with the larger of its own default and this (obstacle centres margin + "
           "0.5 away from a shortcut, so 0.6 keeps a disc of 0.35 clear of obstacle corners: "
           "alt_astar's 0, which lets shortcuts graze them, and kin_astar's 0.5 become 0.6; a "
           "planner whose `shortcut` is none is unaffected); -1 = its own");
  d.choice("local_goals", &PlannerSetup::goals_from_curve, false,
           ChoiceTable<bool>{{"key_nodes", false}, {"curve_samples", true}},
           "where the DWA's local goals come from when the global planner smooths its path: "
           "key_nodes = its nodes before curve fitting (paper 004 section 3.4: the key nodes of "
           "the de-redundant path; the planner then runs with smoothing none), curve_samples = "
           "the key points of the sampled curve");
  d.number("key_point_tolerance", drive_field<&FusionOptions::key_point_tolerance>, 0.1, 0.0, 5.0,
           "cells: Ramer-Douglas-Peucker tolerance for the key points (local goals) of the "
           "global path; on cell-centre paths any value below 0.3 is exact collinear removal");
  d.number("waypoint_tolerance", drive_field<&FusionOptions::waypoint_tolerance>, 0.3, 0.01, 10.0,
           "cells: the local goal advances when the robot is this close");
  d.number("pass_radius", drive_field<&FusionOptions::pass_radius>, 0.6, 0.0, 10.0,
           "cells: the local goal also advances when the robot is this close to it and beyond "
           "it along the segment leading to it (an overshoot)");
  d.boolean("replan", drive_field<&FusionOptions::replan>, true,
            "replan the global path from the robot's cell when a newly seen unknown cell lies on "
            "the remaining global path (not in the papers)");
  d.boolean("turn_speed_limit", drive_field<&FusionOptions::turn_speed_limit>, true,
            "cap the speed so the robot can turn at the coming key points (w_max over one cell), "
            "braking at acc_v (not in the papers; algos/local/fusion_drive.h)");
  d.number("turn_distance", drive_field<&FusionOptions::turn_distance>, 1.0, 0.01, 100.0,
           "cells: the turn speed limit lets the robot turn by phi at w_max within this travel");
  d.choice("heading_aim", drive_field<&FusionOptions::aim_segment>, true,
           ChoiceTable<bool>{{"segment", true}, {"key_point", false}},
           "heading term aims at the key point itself, or at the point `lookahead` ahead on the "
           "segment leading to it (pure-pursuit style; keeps the robot on the path's line)");
  d.number("lookahead", drive_field<&FusionOptions::lookahead>, 0.75, 0.0, 100.0,
           "cells: aim point distance for heading_aim = segment");
  d.choice("heading_target", drive_field<&FusionOptions::heading_final>, false,
           ChoiceTable<bool>{{"local_goal", false}, {"final_goal", true}},
           "what the heading term aims at: the current key point (fusion, paper 003 Heading, "
           "paper 004 PHead) or the final goal (paper 004's 'traditional' heading)");
}

// The DWA's parameters, the robot's and the world's, declared by every variant.
void declare_dwa(ParamDecls<PlannerSetup>& d, DwaScore score_default) {
  d.choice("score", dwa_field<&DwaParams::score>, score_default,
           ChoiceTable<DwaScore>{{"classic", DwaScore::classic},
                                 {"improved_003", DwaScore::improved_003},
                                 {"following_004", DwaScore::following_004}},
           "DWA objective: classic (003 eq. 12), improved_003 (003 eq. 13), following_004 (004 "
           "eq. 13, with sigma smoothing)");
  d.number("v_max", dwa_field<&DwaParams::v_max>, 2.0, 0.01, 100.0, "m/s (paper 003 Table 2)");
  d.number("w_max", dwa_field<&DwaParams::w_max>, 0.7, 0.01, 100.0, "rad/s (paper 003 Table 2)");
  d.number("acc_v", dwa_field<&DwaParams::acc_v>, 0.4, 0.001, 1000.0, "m/s^2 (paper 003 Table 2)");
  d.number("acc_w", dwa_field<&DwaParams::acc_w>, 1.7, 0.001, 1000.0,
           "rad/s^2 (paper 003 Table 2)");
  d.number("predict_time", dwa_field<&DwaParams::predict_time>, 3.0, 0.01, 60.0,
           "s: rollout horizon T (paper 003 Table 2)");
  d.number("dt", dwa_field<&DwaParams::dt>, 0.1, 0.001, 10.0, "s: control period and rollout step");
  d.integer("v_samples", dwa_field<&DwaParams::v_samples>, 9, 1, 201,
            "linear velocity samples in the window");
  d.integer("w_samples", dwa_field<&DwaParams::w_samples>, 15, 1, 201,
            "angular velocity samples in the window");
  const char* weight_doc =
      "score weight; -1 = the score's default (classic and following_004: heading 0.2, velocity "
      "0.1, clearance 0.3; improved_003: 0.2, 0.4, 0.2, dynamic 0.35)";
  d.number("w_heading", weight_field<&DwaWeights::heading>, -1.0, -1.0, 1000.0, weight_doc);
  d.number("w_velocity", weight_field<&DwaWeights::velocity>, -1.0, -1.0, 1000.0, weight_doc);
  d.number("w_clearance", weight_field<&DwaWeights::clearance>, -1.0, -1.0, 1000.0, weight_doc);
  d.number("w_dynamic", weight_field<&DwaWeights::dynamic>, -1.0, -1.0, 1000.0, weight_doc);
  d.choice("smoothing", &PlannerSetup::smoothing, std::optional<bool>(),
           ChoiceTable<std::optional<bool>>{{"auto", std::nullopt}, {"on", true}, {"off", false}},
           "sigma smoothing of the objective over the velocity samples; auto = on for "
           "following_004 only");
  d.boolean("va_omega", dwa_field<&DwaParams::va_omega>, true,
            "apply eq. 10's |w| <= sqrt(2 dist a_w) besides the v bound");
  d.number("robot_radius", dwa_field<&DwaParams::robot_radius>, 0.3, 0.01, 0.49,
           "cells: the robot disc");
  d.number("safety_margin", dwa_field<&DwaParams::safety_margin>, 0.05, 0.0, 1.0,
           "cells: rollout points closer than robot_radius + this to an obstacle count as hits");
  d.choice("dist_mode", dwa_field<&DwaParams::dist_mode>, DwaParams::DistMode::collision,
           ChoiceTable<DwaParams::DistMode>{{"collision", DwaParams::DistMode::collision},
                                            {"clearance", DwaParams::DistMode::clearance}},
           "clearance terms: collision = arc length to the rollout's first hit, capped at "
           "dist_cap (Fox et al. 1997); clearance = minimum clearance over the rollout "
           "(algos/local/dwa.h)");
  d.number("dist_cap", dwa_field<&DwaParams::dist_cap>, 3.0, 0.01, 1000.0,
           "m: cap of the collision distance");
  d.number("dynamic_margin", dwa_field<&DwaParams::dynamic_margin>, 0.2, 0.0, 5.0,
           "cells added to moving obstacles' radius in the DWA (seen at their current position "
           "only)");
  d.number("static_clearance_cap", dwa_field<&DwaParams::static_clearance_cap>, 1.0, 0.01, 1.0,
           "cells (dist_mode clearance): cap of the clearance to known static obstacles");
  d.number("dynamic_clearance_cap", dwa_field<&DwaParams::dynamic_clearance_cap>, 2.0, 0.1, 100.0,
           "cells (dist_mode clearance): cap of the clearance to unknown and moving "
           "obstacles");
  d.number("sensor_range", drive_field<&FusionOptions::sensor_range>, 8.0, 0.0, 1e6,
           "cells: unknown cells (then remembered) and moving obstacles are seen within this "
           "range (8: beyond the 5 m braking distance from v_max at acc_v)");
  d.number("goal_tolerance", drive_field<&FusionOptions::goal_tolerance>, 0.5, 0.01, 10.0,
           "cells: reached when the robot centre is this close to the goal's");
  d.number("sim_time_limit", &PlannerSetup::sim_time_limit, 0.0, 0.0, 1e6,
           "s of simulated time before `timeout`; 0 = 30 s + 10 x reference path length / v_max");
  d.integer("stuck_steps", drive_field<&FusionOptions::stuck_steps>, 100, 1, 1000000,
            "consecutive control steps in which the robot does not move (no admissible moving "
            "velocity pair, or the DWA prefers to stand) before `stuck`; 100 = 10 s at dt 0.1, "
            "more than a half turn on the spot takes");
  d.integer("dynamic_obstacles", world_field<&WorldSpec::moving_obstacles>, 1, 0, 1000,
            "moving discs");
  d.number("dynamic_speed", world_field<&WorldSpec::moving_speed>, 0.5, 0.0, 100.0,
           "m/s of every moving disc");
  d.number("dynamic_radius", world_field<&WorldSpec::moving_radius>, 0.4, 0.05, 5.0, "cells");
  d.boolean("dynamic_yield", world_field<&WorldSpec::moving_yield>, false,
            "moving discs reflect off the robot as off a wall, so they never run into it (not in "
            "the papers: without it a disc also rams a robot that has stopped in a corridor)");
  d.boolean("predict_moving", drive_field<&FusionOptions::predict_moving>, false,
            "the DWA moves each seen disc at the velocity observed between its last two "
            "positions (the papers: current position only)");
  d.choice("dynamic_placement", world_field<&WorldSpec::moving_on_path>, true,
           ChoiceTable<bool>{{"on_path", true}, {"anywhere", false}},
           "moving discs start on the middle of the reference path, or anywhere free");
  d.integer("unknown_obstacles", world_field<&WorldSpec::unknown_obstacles>, 1, 0, 1000,
            "unknown static cells on or next to the reference path");
  d.integer("world_seed", &PlannerSetup::world_seed, 0, 0, 1000000,
            "selects another world on the same map");
}

ParamDecls<PlannerSetup> fusion_decls(const FusionVariant& variant,
                                      const std::vector<std::string>& grid_planners) {
  ParamDecls<PlannerSetup> d;
  if (variant.global_default != nullptr) declare_global(d, variant.global_default, grid_planners);
  declare_dwa(d, variant.score);
  return d;
}

// What follows from the declared values: the score's default weights and smoothing, the values
// the world shares with the loop, and pure DWA's fixed choices.
PlannerSetup finish_setup(PlannerSetup ps, bool has_global) {
  FusionOptions& s = ps.drive;
  DwaParams& d = s.dwa;
  d.weights = default_weights(d.score);
  const DwaWeights& given = ps.given_weights;
  if (given.heading >= 0.0) d.weights.heading = given.heading;
  if (given.velocity >= 0.0) d.weights.velocity = given.velocity;
  if (given.clearance >= 0.0) d.weights.clearance = given.clearance;
  if (given.dynamic >= 0.0) d.weights.dynamic = given.dynamic;
  d.smoothing = ps.smoothing.value_or(d.score == DwaScore::following_004);
  if (!has_global) {
    // Pure DWA: Fox's heading toward the goal itself, no path to slow down for.
    s.waypoint_tolerance = s.goal_tolerance;
    s.aim_segment = false;
    s.turn_speed_limit = false;
  }
  s.moving_yield = ps.world.moving_yield;
  ps.world.robot_radius = d.robot_radius;
  return ps;
}

// What the registry handed over when it built the fusion entries; a fusion planner is made only
// from such an entry, so it is set before any is made (and never changes after).
FusionRegistry& registry_view() {
  static FusionRegistry view;
  return view;
}

PlannerSetup setup_of(const FusionVariant& variant, const Params& params) {
  return finish_setup(fusion_decls(variant, registry_view().grid_planners).read(params),
                      variant.global_default != nullptr);
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
  explicit FusionPlanner(PlannerSetup setup) : s_(std::move(setup)) {
    // The reference path places the world's obstacles; it is the same for every planner.
    const PlannerLookup& lookup = registry_view().lookup;
    reference_ = lookup.make("astar", {{"corner_rule", "no_corner_cut"}}, "reference");
    if (s_.global_name.empty()) return;
    const PlannerInfo* info = lookup.find(s_.global_name);
    // The choices are the registered grid planners, so a validated name is always found.
    if (info == nullptr) throw std::logic_error("global_planner not validated: " + s_.global_name);
    nlohmann::json given = global_planner_params(*info, s_.global_rule, s_.global_margin);
    // Key nodes: the path before its curve is sampled, i.e. the planner without the curve step.
    const bool smooths = std::any_of(info->params.begin(), info->params.end(),
                                     [](const ParamSpec& p) { return p.name == "smoothing"; });
    if (!s_.goals_from_curve && smooths) given["smoothing"] = "none";
    global_ = lookup.make(s_.global_name, given, "global_planner");
  }

  PlanResult plan(const PlanRequest& req) const override {
    PlanResult result;
    const Grid& grid = req.grid;

    // 1. The world, from the map's reference path. Building it is the simulator's work, not the
    // planner's: its collision checks are taken back off this thread's count.
    std::int64_t t0 = thread_cpu_ns();
    const std::int64_t world_checks = collision_checks_on_thread();
    std::vector<Point> reference;
    if (PlanResult ref = reference_->plan(req); ref.ok()) reference = std::move(ref.path);
    Rng wrng = world_rng(grid, req.start, req.goal, s_.world_seed);
    DeadlinePoller world_poll(req.deadline, 1);
    DwaWorld world =
        DwaWorld::generate(grid, req.start, req.goal, reference, s_.world, wrng, &world_poll);
    count_collision_checks(world_checks - collision_checks_on_thread());
    result.phases.push_back({"world", thread_cpu_ns() - t0});
    if (world_poll.has_expired()) {
      PlanResult f = PlanResult::failed(Failure::limit, "time limit while building the world");
      f.rule = CornerRule::no_corner_cut;
      f.phases = std::move(result.phases);
      return f;
    }

    // 2. The global path and its key points (pure DWA: start and goal).
    std::vector<Point> global_path;
    std::vector<Point> keys = {centre(req.start), centre(req.goal)};
    result.rule = CornerRule::no_corner_cut;
    if (global_) {
      t0 = thread_cpu_ns();
      PlanResult g = global_->plan(req);
      result.phases.push_back({"global", thread_cpu_ns() - t0});
      result.work.search_expansions = g.work.search_expansions;
      result.rule = g.rule;
      if (!g.ok()) {
        PlanResult f =
            PlanResult::failed(g.failure, "global planner " + s_.global_name + ": " + g.message);
        f.rule = g.rule;
        f.work = result.work;
        f.phases = std::move(result.phases);
        return f;
      }
      global_path = std::move(g.path);
      keys = fusion_key_points(global_path, s_.drive.key_point_tolerance);
    }

    // 3. The control loop.
    FusionOptions options = s_.drive;
    const double ref_length =
        reference.empty() ? 2.0 * std::hypot(req.goal.x - req.start.x, req.goal.y - req.start.y)
                          : path_length_cells(reference);
    options.sim_time_limit = s_.sim_time_limit > 0.0
                                 ? s_.sim_time_limit
                                 : 30.0 + 10.0 * ref_length * grid.cell_edge() / options.dwa.v_max;
    t0 = thread_cpu_ns();
    DriveResult run = drive(options, req, world, std::move(keys), global_.get());
    const std::int64_t loop_ns = thread_cpu_ns() - t0;
    if (global_)
      result.work.search_expansions = result.work.search_expansions.value_or(0) + run.expansions;
    result.phases.push_back({"dwa", loop_ns});
    // Mean CPU time of one control step: timing, reported under `timing.phases`.
    result.phases.push_back({"cpu_ns_per_step", run.steps > 0 ? loop_ns / run.steps : 0});
    if (run.deadline_hit) {
      PlanResult f = PlanResult::failed(Failure::limit, "time limit during the control loop");
      f.rule = result.rule;
      f.work = result.work;
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

template <const FusionVariant& variant>
PlannerInfo make_info(const std::vector<std::string>& grid_planners) {
  PlannerInfo info;
  info.kind = PlannerKind::local;
  info.name = variant.name;
  info.summary = variant.summary;
  info.source = variant.source;
  if (variant.global_default != nullptr) {
    info.counters.emplace_back("search_expansions",
                               "the global planner's search expansions (replans included)");
    info.counters.emplace_back("collision_checks",
                               "one per rollout point the DWA tests, plus the global planner's "
                               "(replans included); the world's set-up is not counted");
  } else {
    info.counters.emplace_back(
        "collision_checks",
        "one per rollout point the DWA tests; the world's set-up is not counted");
  }
  info.stochastic = false;  // the world is drawn from the map, not from the run's stream
  info.params = fusion_decls(variant, grid_planners).specs();
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<FusionPlanner>(setup_of(variant, params));
  };
  return info;
}

const FusionVariant* find_variant(std::string_view name) {
  for (const FusionVariant* v : {&kDwa, &kAstarDwa, &kAltDwa, &kKinDwa})
    if (name == v->name) return v;
  return nullptr;
}

}  // namespace

PlannerInfo dwa_planner(const FusionRegistry& registry) {
  registry_view() = registry;
  return make_info<kDwa>({});
}

PlannerInfo fusion_astar_dwa_planner(const FusionRegistry& registry) {
  registry_view() = registry;
  return make_info<kAstarDwa>(registry.grid_planners);
}

PlannerInfo fusion_alt_dwa_planner(const FusionRegistry& registry) {
  registry_view() = registry;
  return make_info<kAltDwa>(registry.grid_planners);
}

PlannerInfo fusion_kin_dwa_planner(const FusionRegistry& registry) {
  registry_view() = registry;
  return make_info<kKinDwa>(registry.grid_planners);
}

nlohmann::json global_planner_params(const PlannerInfo& global, std::optional<CornerRule> rule,
                                     double margin) {
  nlohmann::json given = nlohmann::json::object();
  for (const auto& spec : global.params) {
    if (spec.name == "corner_rule" && rule) given["corner_rule"] = std::string(to_string(*rule));
    // A floor: a planner that keeps a wider clearance of its own (kin_astar) keeps it.
    if (spec.name == "shortcut_margin" && margin >= 0.0)
      given["shortcut_margin"] = std::max(spec.default_value.get<double>(), margin);
  }
  return given;
}

FusionOptions fusion_options(const std::string& planner, const nlohmann::json& given,
                             const std::vector<std::string>& grid_planners) {
  const FusionVariant* variant = find_variant(planner);
  if (variant == nullptr) throw std::invalid_argument("not a fusion planner: " + planner);
  return finish_setup(fusion_decls(*variant, grid_planners).resolve(given, planner),
                      variant->global_default != nullptr)
      .drive;
}

}  // namespace agv
