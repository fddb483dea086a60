// The DWA local planner and the fusion planners against truth (docs/ARCHITECTURE.md "Style" item
// 11): the unicycle integration is the closed-form arc, the dynamic window stays inside V_m n V_d,
// every chosen velocity can stop before its rollout's first obstacle (V_a, checked against the
// exact distance transform), fusion reaches the goal without collision on random solvable maps, a
// head-on moving obstacle is avoided, runs are reproducible, and the engine's judge catches
// collisions injected into hand-made trajectories.
//
// Reached rates measured when these tests were written (100 maps per density 0.1 / 0.2 / 0.3,
// 20x20 uniform, corners, no moving and no unknown obstacles): fusion_astar_dwa 99 / 99 / 98 %,
// fusion_kin_dwa 100 / 99 / 100 %, fusion_alt_dwa (improved_003 with paper 003's weights,
// velocity 0.4) 96 / 83 / 81 % (with the classic score 97 / 99 / 100 %: the paper's heavy
// velocity weight drives the robot into the DWA's local minima), pure `dwa` 46 / 6 / 0 %.
// The literal reading (heading at the key point itself, no turn speed limit, waypoint
// tolerance 0.5; algos/local/fusion_drive.h) reached 82 / 51 / 29 %.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "algos/local/dwa.h"
#include "algos/local/dwa_rollout.h"
#include "algos/local/dwa_world.h"
#include "algos/local/fusion.h"
#include "algos/local/unicycle.h"
#include "algos/registry.h"
#include "core/cell_geometry.h"
#include "core/distance_transform.h"
#include "core/input_error.h"
#include "engine/judge/metrics.h"
#include "engine/judge/run_executor.h"
#include "engine/judge/trajectory_judge.h"
#include "generators/map_generators.h"
#include "tests/test_size.h"

namespace agv {
namespace {

// A registered fusion planner's control-loop options, its global planner one of the registry's.
FusionOptions options_for(const std::string& planner, const nlohmann::json& given) {
  return fusion_options(planner, given,
                        planner_names(planner_registry(), PlannerKind::grid_search));
}

MapInstance random_map(double density, int index, int size = 20) {
  MapSpec spec;
  spec.width = spec.height = size;
  spec.density = density;
  spec.require_solvable = true;
  spec.solvable_rule = CornerRule::no_corner_cut;
  Rng rng(0xD7A, static_cast<std::uint64_t>(density * 100) * 100000 + index);
  return make_map(spec, rng);
}

TEST(Unicycle, StepsComposeToTheClosedFormArc) {
  const Pose p0{3.0, 4.0, 0.7};
  for (const double w : {0.7, -0.35, 0.05, 1e-4}) {
    const double v = 1.3, t = 3.0;
    Pose p = p0;
    const int n = 300;
    for (int i = 0; i < n; ++i) p = unicycle_step(p, v, w, t / n);
    // x(t) = x0 + v/w (sin(th0 + w t) - sin th0), y(t) = y0 - v/w (cos(th0 + w t) - cos th0).
    const double x = p0.x + v / w * (std::sin(p0.theta + w * t) - std::sin(p0.theta));
    const double y = p0.y - v / w * (std::cos(p0.theta + w * t) - std::cos(p0.theta));
    EXPECT_NEAR(p.x, x, 1e-9) << "w " << w;
    EXPECT_NEAR(p.y, y, 1e-9) << "w " << w;
    EXPECT_NEAR(p.theta, p0.theta + w * t, 1e-12) << "w " << w;
  }
}

TEST(Unicycle, ZeroTurnRateIsAStraightLine) {
  Pose p{1.0, 2.0, -0.4};
  for (int i = 0; i < 50; ++i) p = unicycle_step(p, 2.0, 0.0, 0.1);
  EXPECT_NEAR(p.x, 1.0 + 10.0 * std::cos(-0.4), 1e-12);
  EXPECT_NEAR(p.y, 2.0 + 10.0 * std::sin(-0.4), 1e-12);
  EXPECT_EQ(p.theta, -0.4);
}

// Random states on random maps: pose with room around it, velocity inside V_m.
struct State {
  Pose pose;
  double v = 0.0, w = 0.0;
  Point goal;
};
State random_state(const Grid& grid, Rng& rng) {
  const DistanceTransform& dt = grid.distance_transform();
  State s;
  do {
    s.pose = {rng.uniform(0.0, grid.width()), rng.uniform(0.0, grid.height()),
              rng.uniform(-std::numbers::pi, std::numbers::pi)};
  } while (dt.clearance(position(s.pose)) < 0.45);
  s.v = rng.uniform(0.0, 2.0);
  s.w = rng.uniform(-0.7, 0.7);
  s.goal = {rng.uniform(0.0, grid.width()), rng.uniform(0.0, grid.height())};
  return s;
}

TEST(DynamicWindow, NeverLeavesLimitsOrReach) {
  DwaParams p;
  DwaScratch s;
  int checked = 0;
  for (int m = 0; m < 20; ++m) {
    const MapInstance map = random_map(0.2, m);
    Rng rng(7, m);
    for (int k = 0; k < 25; ++k) {
      const State st = random_state(map.grid, rng);
      DwaTarget target;
      target.goals = std::span<const Point>(&st.goal, 1);
      target.from = position(st.pose);
      const DwaDecision d = dwa_step(p, st.pose, st.v, st.w, target, DwaView{map.grid, {}, {}}, s);
      const double eps = 1e-12;
      for (int i = 0; i < d.samples; ++i) {
        // V_m (eq. 8, v_min = 0) and V_d (eq. 9).
        ASSERT_GE(s.v[i], -eps);
        ASSERT_LE(s.v[i], p.v_max + eps);
        ASSERT_LE(std::abs(s.w[i]), p.w_max + eps);
        ASSERT_LE(std::abs(s.v[i] - st.v), p.acc_v * p.dt + eps);
        ASSERT_LE(std::abs(s.w[i] - st.w), p.acc_w * p.dt + eps);
      }
      ASSERT_LE(std::abs(d.v - st.v), p.acc_v * p.dt + eps);
      ASSERT_LE(std::abs(d.w - st.w), p.acc_w * p.dt + eps);
      ASSERT_LE(d.v, p.v_max + eps);
      ASSERT_LE(std::abs(d.w), p.w_max + eps);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 500);
}

// The rollouts of every instruction-set level this CPU runs (algos/local/dwa_rollout.h) give the
// baseline's values bit for bit, with unknown cells, moving discs and several local goals.
TEST(DwaLevels, RolloutsAreTheSameAtEveryLevel) {
  const DwaRolloutKernel& baseline = *dwa_rollout_kernel(SimdPath::baseline);
  DwaParams p;
  p.v_samples = 7;  // 7 x 13 = 91 lanes: vector bodies and remainders at every width
  p.w_samples = 13;
  const StepShape shape{p.v_samples, p.w_samples, p.v_samples * p.w_samples,
                        static_cast<int>(std::lround(p.predict_time / p.dt))};
  int compared = 0;
  for (int m = 0; m < 12; ++m) {
    const MapInstance map = random_map(0.1 + 0.05 * (m % 4), m, 24);
    Rng rng(11, m);
    for (int k = 0; k < 10; ++k) {
      const State st = random_state(map.grid, rng);
      std::vector<Cell> unknown;
      std::vector<Disc> moving;
      for (int i = 0; i < k % 4; ++i) {
        unknown.push_back({rng.between(0, 23), rng.between(0, 23)});
        moving.push_back({{rng.uniform(0.0, 24.0), rng.uniform(0.0, 24.0)},
                          rng.uniform(0.2, 0.8),
                          {rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)}});
      }
      const std::vector<Point> goals = {st.goal, {rng.uniform(0.0, 24.0), rng.uniform(0.0, 24.0)}};
      DwaTarget target;
      target.goals = goals;
      target.from = position(st.pose);
      const DwaView view{map.grid, unknown, moving};
      DwaScratch ref;
      // dwa_step samples the pairs and sizes the scratch; the rollouts are then redone per level.
      dwa_step(p, st.pose, st.v, st.w, target, view, ref);
      ASSERT_EQ(ref.v.size(), static_cast<Eigen::Index>(shape.n));
      ASSERT_TRUE(baseline.roll_out(p, st.pose, shape, target, view, ref, nullptr));
      for (SimdPath path : kSimdPaths) {
        const DwaRolloutKernel* level = dwa_rollout_kernel(path);
        if (level == nullptr) continue;
        DwaScratch s = ref;
        ASSERT_TRUE(level->roll_out(p, st.pose, shape, target, view, s, nullptr));
        for (const auto field :
             {&DwaScratch::px, &DwaScratch::py, &DwaScratch::min_static, &DwaScratch::min_other,
              &DwaScratch::hit_static, &DwaScratch::hit_other, &DwaScratch::goal_index})
          for (int i = 0; i < shape.n; ++i)
            ASSERT_EQ(std::bit_cast<std::uint64_t>((s.*field)[i]),
                      std::bit_cast<std::uint64_t>((ref.*field)[i]))
                << simd_path_name(path) << " map " << m << " state " << k << " lane " << i;
        for (int i = 0; i < 50; ++i) {
          const double x = rng.uniform(-1.0, 25.0), y = rng.uniform(-1.0, 25.0);
          ASSERT_EQ(std::bit_cast<std::uint64_t>(level->capped_static_sq(map.grid, x, y)),
                    std::bit_cast<std::uint64_t>(baseline.capped_static_sq(map.grid, x, y)));
        }
        ++compared;
      }
    }
  }
  EXPECT_GE(compared, 120);  // the baseline against itself at least, on every state
}

TEST(DynamicWindow, ChosenVelocityCanStopBeforeItsFirstObstacle) {
  // V_a (eq. 10), checked independently: roll the chosen (v, w) out with the unicycle step,
  // find the first point closer than robot_radius + safety_margin to an obstacle by the exact
  // distance transform, and require the braking distance v^2 / (2 a_v) to fit before it.
  DwaParams p;
  DwaScratch s;
  int admissible = 0, with_obstacle = 0;
  for (int m = 0; m < 20; ++m) {
    const MapInstance map = random_map(0.3, m);
    const DistanceTransform& dt = map.grid.distance_transform();
    Rng rng(11, m);
    for (int k = 0; k < 25; ++k) {
      const State st = random_state(map.grid, rng);
      DwaTarget target;
      target.goals = std::span<const Point>(&st.goal, 1);
      target.from = position(st.pose);
      const DwaDecision d = dwa_step(p, st.pose, st.v, st.w, target, DwaView{map.grid, {}, {}}, s);
      if (!d.any_admissible) continue;
      ++admissible;
      Pose q = st.pose;
      double travelled = 0.0, free_run = std::numeric_limits<double>::infinity();
      const int steps = static_cast<int>(std::lround(p.predict_time / p.dt));
      for (int i = 1; i <= steps; ++i) {
        q = unicycle_step(q, d.v, d.w, p.dt);
        if (dt.clearance(position(q)) < p.robot_radius + p.safety_margin) {
          free_run = travelled;
          break;
        }
        travelled += d.v * p.dt;
      }
      if (std::isfinite(free_run)) ++with_obstacle;
      EXPECT_LE(d.v * d.v / (2.0 * p.acc_v), free_run + 1e-9)
          << "map " << m << " state " << k << " v " << d.v << " w " << d.w;
    }
  }
  EXPECT_GT(admissible, 200);  // random speeds near obstacles often leave no admissible pair
  EXPECT_GT(with_obstacle, 20) << "the check must meet obstacles to mean anything";
}

// Runs a planner through the engine (so its trajectory is judged) on `maps` random maps per
// density and returns the outcome counts.
std::map<std::string, int> outcomes(const std::string& planner, const nlohmann::json& params,
                                    double density, int maps) {
  const ConfiguredPlanner c = configure_planner(planner, params, "test");
  Scratch scratch;
  std::map<std::string, int> counts;
  for (int m = 0; m < maps; ++m) {
    const MapInstance map = random_map(density, m);
    MapReference ref(map.grid, map.start, map.goal);
    Rng rng(5, m);
    const RunOutput out = execute_run(*c.planner, ref, rng, scratch, Deadline::never(), {});
    ++counts[std::string(to_string(out.outcome))];
  }
  return counts;
}

std::string describe(const std::map<std::string, int>& counts) {
  std::string s;
  for (const auto& [name, n] : counts) s += name + "=" + std::to_string(n) + " ";
  return s;
}

TEST(Fusion, ReachesTheGoalOnRandomSolvableMaps) {
  // No moving and no unknown obstacles: the judge sees only the static grid.
  const nlohmann::json quiet = {{"dynamic_obstacles", 0}, {"unknown_obstacles", 0}};
  for (const char* planner : {"fusion_astar_dwa", "fusion_kin_dwa"}) {
    int reached = 0, runs = 0;
    for (const double density : {0.1, 0.2, 0.3}) {
      const auto counts = outcomes(planner, quiet, density, 60);
      std::printf("%s density %.1f: %s\n", planner, density, describe(counts).c_str());
      reached += counts.count("success") ? counts.at("success") : 0;
      runs += 60;
      for (const char* collision : {"collision_static", "collision_unknown", "collision_dynamic"})
        EXPECT_EQ(counts.count(collision), 0u) << planner << " density " << density;
      EXPECT_EQ(counts.count("invalid_path"), 0u) << planner << " density " << density;
    }
    EXPECT_GE(reached, 0.95 * runs) << planner;
  }
}

TEST(Fusion, AllThreeVariantsRunWithMovingAndUnknownObstacles) {
  // Defaults: one moving disc on the reference path, one unknown cell. Every run must end in a
  // counted outcome, and the planner's own account must agree with the judge (no
  // invalid_path: a claimed contact the judge cannot confirm would land there).
  for (const char* planner : {"fusion_astar_dwa", "fusion_alt_dwa", "fusion_kin_dwa", "dwa"}) {
    const auto counts = outcomes(planner, nlohmann::json::object(), 0.2, 20);
    std::printf("%s with moving and unknown obstacles: %s\n", planner, describe(counts).c_str());
    EXPECT_EQ(counts.count("invalid_path"), 0u) << planner;
    EXPECT_EQ(counts.count("crash"), 0u) << planner;
  }
}

TEST(Fusion, HeadOnMovingObstacleIsAvoidedByImprovedDwa) {
  const Grid grid(20, 20);
  const Cell start{2, 10}, goal{17, 10};
  const FusionOptions options = options_for("fusion_alt_dwa", nlohmann::json::object());
  int avoided = 0;
  for (const double offset : {0.0, 0.1, -0.2}) {
    // A disc of radius 0.4 on the robot's line, coming straight at it at 0.5 m/s.
    DwaWorld world(grid, {}, {MovingDisc{{13.5, 10.5 + offset}, {-0.5, 0.0}, 0.4}});
    Scratch scratch;
    Rng rng(1, 1);
    const PlanRequest req{grid, start, goal, rng, scratch};
    const DriveResult run = drive(options, req, world, {centre(start), centre(goal)}, nullptr);
    const TrajectoryVerdict verdict = judge_trajectory(grid, start, goal, *run.trajectory);
    EXPECT_EQ(verdict.outcome, Outcome::success) << "offset " << offset << ": " << verdict.message;
    avoided += verdict.outcome == Outcome::success;
    double gap = 1e9;
    for (const auto& [name, value] : verdict.metrics)
      if (name == "min_clearance_dynamic") gap = value;
    EXPECT_GE(gap, options.dwa.robot_radius) << "offset " << offset;
    EXPECT_LT(gap, 3.0) << "the obstacle must have come close enough to matter";
  }
  EXPECT_EQ(avoided, 3);
}

// min_clearance_static is exact: the minimum over every chord of the executed trajectory of the
// distance to the static and unknown cells, recomputed here chord by chord.
TEST(Fusion, JudgedStaticClearanceIsTheExactMinimumOverTheTrajectory) {
  const ConfiguredPlanner c = configure_planner(
      "fusion_astar_dwa", {{"unknown_obstacles", 2}, {"dynamic_obstacles", 0}}, "t");
  int checked = 0;
  const int maps = test::sized(12, 4);
  for (int m = 0; m < maps; ++m) {
    const MapInstance map = random_map(0.2, m);
    Scratch scratch;
    Rng rng(5, m);
    const PlanResult run = c.planner->plan({map.grid, map.start, map.goal, rng, scratch});
    ASSERT_TRUE(run.trajectory) << "map " << m;
    const Trajectory& tr = *run.trajectory;
    const TrajectoryVerdict verdict = judge_trajectory(map.grid, map.start, map.goal, tr);
    double judged = std::numeric_limits<double>::quiet_NaN();
    for (const auto& [name, value] : verdict.metrics)
      if (name == "min_clearance_static") judged = value;
    const DistanceTransform& dt = map.grid.distance_transform();
    double exact = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < tr.position.size(); ++i) {
      const Point a = tr.position[i], b = tr.position[i + 1];
      exact = std::min(exact, dt.segment_clearance(a, b));
      for (const Cell& u : tr.unknown_cells)
        exact = std::min(exact, segment_cell_distance(a, b, u));
    }
    EXPECT_DOUBLE_EQ(judged, exact * tr.cell_edge) << "map " << m;
    ++checked;
  }
  EXPECT_EQ(checked, maps);
}

std::size_t metric_index(std::string_view name) {
  for (std::size_t i = 0; i < kRunMetricNames.size(); ++i)
    if (kRunMetricNames[i] == name) return i;
  throw std::logic_error("no run metric " + std::string(name));
}

// Distance from p to the closed square of cell c.
double square_distance(Point p, Cell c) {
  const double dx = std::max({c.x - p.x, 0.0, p.x - (c.x + 1.0)});
  const double dy = std::max({c.y - p.y, 0.0, p.y - (c.y + 1.0)});
  return std::hypot(dx, dy);
}

TEST(Fusion, RunMetricsCoverTheUnknownCellsAndTakeTheSimulatedTime) {
  // The engine's per-run min_clearance and motion_time_s of a fusion run: the clearance counts
  // every static obstacle the robot met, the unknown cells included (they are not in the grid's
  // distance transform), and the motion time is the simulated time the run took.
  const std::size_t clearance = metric_index("min_clearance");
  const std::size_t clearance_m = metric_index("min_clearance_m");
  const std::size_t motion = metric_index("motion_time_s");
  int succeeded = 0, unknown_nearest = 0;
  for (const char* planner : {"dwa", "fusion_astar_dwa", "fusion_kin_dwa"}) {
    const ConfiguredPlanner c = configure_planner(planner, {{"unknown_obstacles", 2}}, "t");
    Scratch scratch;
    for (int m = 0; m < 16; ++m) {
      const MapInstance map = random_map(0.1, m, 32);
      MapReference ref(map.grid, map.start, map.goal);
      Rng rng(5, m);
      const RunOutput out = execute_run(*c.planner, ref, rng, scratch, Deadline::never(), {});
      if (out.outcome != Outcome::success) continue;
      ++succeeded;
      std::map<std::string, double> extra(out.result.extra.begin(), out.result.extra.end());
      const Trajectory& tr = *out.result.trajectory;
      EXPECT_EQ(out.metrics[motion], extra.at("sim_time_s")) << planner << " map " << m;
      EXPECT_EQ(out.metrics[motion], tr.t.back()) << planner << " map " << m;
      EXPECT_DOUBLE_EQ(out.metrics[clearance_m], extra.at("min_clearance_static"));
      EXPECT_DOUBLE_EQ(out.metrics[clearance], extra.at("min_clearance_static") / tr.cell_edge);
      // Never above the robot's distance, at any sample, to a grid obstacle or an unknown cell.
      const DistanceTransform& dt = map.grid.distance_transform();
      double grid_only = std::numeric_limits<double>::infinity();
      double unknown = std::numeric_limits<double>::infinity();
      for (const Point& p : tr.position) {
        grid_only = std::min(grid_only, dt.clearance(p));
        for (const Cell& u : tr.unknown_cells) unknown = std::min(unknown, square_distance(p, u));
      }
      EXPECT_LE(out.metrics[clearance], grid_only + 1e-12) << planner << " map " << m;
      EXPECT_LE(out.metrics[clearance], unknown + 1e-12) << planner << " map " << m;
      unknown_nearest += unknown < grid_only;
    }
  }
  EXPECT_GT(succeeded, 24);
  // Runs where an unknown cell is what the robot came nearest: the case the grid cannot see.
  EXPECT_GT(unknown_nearest, 0);
  std::printf("[measured] %d successful runs, %d nearest to an unknown cell\n", succeeded,
              unknown_nearest);
}

TEST(Fusion, LocalGoalsAreTheKeyNodesOrTheCurveSamples) {
  // fusion_kin_dwa's global planner is kin_astar (no_corner_cut, shortcut_margin raised to the
  // 0.6 floor). key_nodes (default, paper 004): the local goals are the key points of its path
  // before the B-spline; curve_samples: those of the sampled B-spline.
  const nlohmann::json quiet = {{"dynamic_obstacles", 0}, {"unknown_obstacles", 0}};
  nlohmann::json curve = quiet;
  curve["local_goals"] = "curve_samples";
  const ConfiguredPlanner nodes_run = configure_planner("fusion_kin_dwa", quiet, "t");
  const ConfiguredPlanner curve_run = configure_planner("fusion_kin_dwa", curve, "t");
  EXPECT_EQ(nodes_run.params.choice("local_goals"), "key_nodes");
  const nlohmann::json global = {{"corner_rule", "no_corner_cut"}, {"shortcut_margin", 0.6}};
  nlohmann::json polyline = global;
  polyline["smoothing"] = "none";
  const ConfiguredPlanner kin_nodes = configure_planner("kin_astar", polyline, "t");
  const ConfiguredPlanner kin_curve = configure_planner("kin_astar", global, "t");
  std::size_t node_goals = 0, curve_goals = 0;
  for (int m = 0; m < 12; ++m) {
    const MapInstance map = random_map(0.2, m);
    Scratch scratch;
    auto plan = [&](const ConfiguredPlanner& c) {
      Rng rng(5, m);
      return c.planner->plan({map.grid, map.start, map.goal, rng, scratch});
    };
    const PlanResult a = plan(nodes_run), b = plan(curve_run);
    ASSERT_TRUE(a.trajectory && b.trajectory) << "map " << m;
    const PlanResult pa = plan(kin_nodes), pb = plan(kin_curve);
    ASSERT_TRUE(pa.ok() && pb.ok()) << "map " << m;
    EXPECT_EQ(a.trajectory->key_points, fusion_key_points(pa.path, 0.1)) << "map " << m;
    EXPECT_EQ(b.trajectory->key_points, fusion_key_points(pb.path, 0.1)) << "map " << m;
    node_goals += a.trajectory->key_points.size();
    curve_goals += b.trajectory->key_points.size();
  }
  std::printf("[measured] fusion_kin_dwa local goals over 12 maps: key_nodes %zu, curve %zu\n",
              node_goals, curve_goals);
}

TEST(Fusion, SameSeedSameTrajectory) {
  const ConfiguredPlanner c = configure_planner("fusion_kin_dwa", nlohmann::json::object(), "t");
  for (int m = 0; m < test::sized(4, 2); ++m) {
    const MapInstance map = random_map(0.2, m);
    Scratch s1, s2;
    Rng r1(3, m), r2(3, m);
    const PlanResult a = c.planner->plan({map.grid, map.start, map.goal, r1, s1});
    // The second run reuses a scratch that has already served another map.
    c.planner->plan({random_map(0.3, 99).grid, map.start, map.goal, r2, s2});
    Rng r3(3, m);
    const PlanResult b = c.planner->plan({map.grid, map.start, map.goal, r3, s2});
    ASSERT_TRUE(a.trajectory && b.trajectory);
    EXPECT_EQ(a.trajectory->position, b.trajectory->position) << "map " << m;
    EXPECT_EQ(a.trajectory->heading, b.trajectory->heading) << "map " << m;
    ASSERT_EQ(a.trajectory->obstacles.size(), b.trajectory->obstacles.size());
    for (std::size_t j = 0; j < a.trajectory->obstacles.size(); ++j)
      EXPECT_EQ(a.trajectory->obstacles[j].centre, b.trajectory->obstacles[j].centre);
    EXPECT_EQ(a.trajectory->unknown_cells.size(), b.trajectory->unknown_cells.size());
  }
}

TEST(Fusion, WorldIsTheSameForEveryPlannerOnAMap) {
  // Paired comparisons need every fusion planner to meet the same obstacles on a map.
  const MapInstance map = random_map(0.2, 3);
  std::vector<std::vector<Cell>> unknown;
  std::vector<Point> first_disc;
  for (const char* name : {"fusion_astar_dwa", "fusion_alt_dwa", "fusion_kin_dwa", "dwa"}) {
    const ConfiguredPlanner c = configure_planner(name, nlohmann::json::object(), "t");
    Scratch scratch;
    Rng rng(stable_hash(name), 1);  // each planner has its own run stream
    const PlanResult r = c.planner->plan({map.grid, map.start, map.goal, rng, scratch});
    ASSERT_TRUE(r.trajectory) << name;
    unknown.push_back(r.trajectory->unknown_cells);
    ASSERT_FALSE(r.trajectory->obstacles.empty()) << name;
    first_disc.push_back(r.trajectory->obstacles[0].centre[0]);
  }
  for (std::size_t i = 1; i < unknown.size(); ++i) {
    EXPECT_EQ(unknown[i], unknown[0]);
    EXPECT_EQ(first_disc[i], first_disc[0]);
  }
}

TEST(Fusion, GlobalPlannerChoicesAreTheRegisteredGridPlanners) {
  // The registry's grid_search planners, in registry order; any other name (a sampling planner,
  // an unknown one) is refused by the parameter check, naming the field.
  std::vector<std::string> grid;
  for (const auto& info : planner_registry())
    if (info.kind == PlannerKind::grid_search) grid.push_back(info.name);
  ASSERT_FALSE(grid.empty());
  for (const char* fusion : {"fusion_astar_dwa", "fusion_alt_dwa", "fusion_kin_dwa"}) {
    const PlannerInfo* info = find_planner(fusion);
    ASSERT_NE(info, nullptr) << fusion;
    const auto spec = std::find_if(info->params.begin(), info->params.end(),
                                   [](const ParamSpec& p) { return p.name == "global_planner"; });
    ASSERT_NE(spec, info->params.end()) << fusion;
    EXPECT_EQ(spec->choices, grid) << fusion;
    for (const auto& name : grid)
      EXPECT_NO_THROW(configure_planner(fusion, {{"global_planner", name}}, "t")) << name;
  }
  for (const char* name : {"no_such", "rrt", "dwa"}) {
    try {
      configure_planner("fusion_astar_dwa", {{"global_planner", name}}, "planners[1]");
      ADD_FAILURE() << name << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("planners[1].params.global_planner"), std::string::npos)
          << e.what();
    }
  }
  const PlannerInfo* dwa = find_planner("dwa");
  ASSERT_NE(dwa, nullptr);
  for (const auto& spec : dwa->params) EXPECT_NE(spec.name, "global_planner");
}

TEST(Fusion, GlobalMarginIsAFloorForTheGlobalPlannersShortcutMargin) {
  // astar declares shortcut_margin (default 0) and corner_rule.
  const PlannerInfo* astar = find_planner("astar");
  ASSERT_NE(astar, nullptr);
  const nlohmann::json raised = global_planner_params(*astar, CornerRule::no_corner_cut, 0.6);
  EXPECT_DOUBLE_EQ(raised.at("shortcut_margin").get<double>(), 0.6);
  EXPECT_EQ(raised.at("corner_rule"), "no_corner_cut");
  // -1 and planner_default leave the planner's own values.
  EXPECT_EQ(global_planner_params(*astar, std::nullopt, -1.0), nlohmann::json::object());
  // A planner with a wider clearance of its own keeps it; one that declares neither gets neither.
  PlannerInfo wide;
  wide.params = {ParamSpec::number("shortcut_margin", 1.0, 0.0, 10.0, "clearance")};
  EXPECT_DOUBLE_EQ(global_planner_params(wide, CornerRule::allow, 0.6).at("shortcut_margin"), 1.0);
  EXPECT_FALSE(global_planner_params(wide, CornerRule::allow, 0.6).contains("corner_rule"));
  PlannerInfo bare;
  bare.params = {ParamSpec::number("margin", 0.0, 0.0, 10.0, "another meaning")};
  EXPECT_EQ(global_planner_params(bare, CornerRule::allow, 0.6), nlohmann::json::object());
}

TEST(Fusion, OptionsFollowTheDeclaredParameters) {
  // Defaults per variant: the score's weights, sigma smoothing for following_004 only.
  const FusionOptions kin = options_for("fusion_kin_dwa", nlohmann::json::object());
  EXPECT_EQ(kin.dwa.score, DwaScore::following_004);
  EXPECT_TRUE(kin.dwa.smoothing);
  EXPECT_DOUBLE_EQ(kin.dwa.weights.clearance, default_weights(DwaScore::following_004).clearance);
  const FusionOptions alt = options_for("fusion_alt_dwa", nlohmann::json::object());
  EXPECT_EQ(alt.dwa.score, DwaScore::improved_003);
  EXPECT_FALSE(alt.dwa.smoothing);
  EXPECT_DOUBLE_EQ(alt.dwa.weights.dynamic, 0.35);
  EXPECT_TRUE(alt.aim_segment);
  EXPECT_TRUE(alt.turn_speed_limit);
  // Given values reach their fields; a weight of -1 keeps the score's default.
  const FusionOptions given = options_for("fusion_astar_dwa", {{"w_velocity", 0.5},
                                                               {"w_heading", -1.0},
                                                               {"smoothing", "on"},
                                                               {"heading_aim", "key_point"},
                                                               {"heading_target", "final_goal"},
                                                               {"dist_mode", "clearance"},
                                                               {"dynamic_yield", true},
                                                               {"stuck_steps", 7},
                                                               {"v_samples", 3},
                                                               {"lookahead", 2.5}});
  EXPECT_DOUBLE_EQ(given.dwa.weights.velocity, 0.5);
  EXPECT_DOUBLE_EQ(given.dwa.weights.heading, default_weights(DwaScore::classic).heading);
  EXPECT_TRUE(given.dwa.smoothing);
  EXPECT_FALSE(given.aim_segment);
  EXPECT_TRUE(given.heading_final);
  EXPECT_EQ(given.dwa.dist_mode, DwaParams::DistMode::clearance);
  EXPECT_TRUE(given.moving_yield);
  EXPECT_EQ(given.stuck_steps, 7);
  EXPECT_EQ(given.dwa.v_samples, 3);
  EXPECT_DOUBLE_EQ(given.lookahead, 2.5);
  // Pure DWA: heading at the goal itself, no turn speed limit, the goal tolerance for passing.
  const FusionOptions dwa = options_for("dwa", {{"goal_tolerance", 0.7}});
  EXPECT_FALSE(dwa.aim_segment);
  EXPECT_FALSE(dwa.turn_speed_limit);
  EXPECT_DOUBLE_EQ(dwa.waypoint_tolerance, 0.7);
  // A fusion-only parameter is unknown to pure DWA; errors name the field.
  try {
    options_for("dwa", {{"lookahead", 1.0}});
    ADD_FAILURE() << "dwa accepted lookahead";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dwa.lookahead"), std::string::npos) << e.what();
  }
  EXPECT_THROW(options_for("fusion_alt_dwa", {{"robot_radius", 0.6}}), InputError);
}

// A kinematically consistent straight run: v m/s along +x from `start`'s centre, n steps.
Trajectory straight_run(Cell start, double v, int n) {
  Trajectory tr;
  tr.robot_radius = 0.3;
  tr.goal_tolerance = 0.5;
  Pose p{start.x + 0.5, start.y + 0.5, 0.0};
  for (int i = 0; i <= n; ++i) {
    tr.t.push_back(0.1 * i);
    tr.position.push_back(position(p));
    tr.heading.push_back(p.theta);
    if (i < n) {
      tr.v.push_back(v);
      tr.w.push_back(0.0);
      p = unicycle_step(p, v, 0.0, 0.1);
    }
  }
  return tr;
}

TEST(Judge, FlagsInjectedCollisions) {
  Grid grid(20, 20);
  const Cell start{1, 10}, goal{11, 10};
  Trajectory clean = straight_run(start, 1.0, 100);  // 10 cells along row 10, to the goal
  clean.end_reason = "reached";
  EXPECT_EQ(judge_trajectory(grid, start, goal, clean).outcome, Outcome::success);

  // Static: a cell on the row.
  Grid blocked = grid;
  blocked.set_blocked(6, 10, true);
  EXPECT_EQ(judge_trajectory(blocked, start, goal, clean).outcome, Outcome::collision_static);
  // Grazing: a cell beside the row, 0.5 from the centre line, passes; the same cell with a
  // robot radius above 0.5 does not.
  Grid beside = grid;
  beside.set_blocked(6, 11, true);
  EXPECT_EQ(judge_trajectory(beside, start, goal, clean).outcome, Outcome::success);
  Trajectory fat = clean;
  fat.robot_radius = 0.51;
  EXPECT_EQ(judge_trajectory(beside, start, goal, fat).outcome, Outcome::collision_static);

  // Unknown: the same cell as an unknown obstacle.
  Trajectory unknown = clean;
  unknown.unknown_cells = {{6, 10}};
  EXPECT_EQ(judge_trajectory(grid, start, goal, unknown).outcome, Outcome::collision_unknown);

  // Dynamic: a disc crossing the row at x = 7.5 as the robot passes.
  Trajectory crossing = clean;
  DynamicTrack track;
  track.radius = 0.2;
  for (std::size_t i = 0; i < clean.t.size(); ++i) {
    const double t = clean.t[i];
    track.centre.push_back({7.5, 10.5 + 4.0 * (t - 6.05)});  // passes y = 10.5 at t = 6.05 s
  }
  crossing.obstacles = {track};
  const TrajectoryVerdict hit = judge_trajectory(grid, start, goal, crossing);
  EXPECT_EQ(hit.outcome, Outcome::collision_dynamic) << hit.message;
  // Shifted far away in time, the same disc misses.
  Trajectory missing = clean;
  for (auto& c : track.centre) c.x = 15.5;
  missing.obstacles = {track};
  EXPECT_EQ(judge_trajectory(grid, start, goal, missing).outcome, Outcome::success);

  // The planner's account is checked too.
  Trajectory short_run = straight_run(start, 1.0, 50);
  short_run.end_reason = "reached";
  EXPECT_EQ(judge_trajectory(grid, start, goal, short_run).outcome, Outcome::invalid_path);
  short_run.end_reason = "timeout";
  EXPECT_EQ(judge_trajectory(grid, start, goal, short_run).outcome, Outcome::sim_timeout);
  short_run.end_reason = "stuck";
  EXPECT_EQ(judge_trajectory(grid, start, goal, short_run).outcome, Outcome::stuck);
  short_run.end_reason = "contact";
  EXPECT_EQ(judge_trajectory(grid, start, goal, short_run).outcome, Outcome::invalid_path);
  Trajectory teleport = clean;
  teleport.position[40].y += 0.01;
  EXPECT_EQ(judge_trajectory(grid, start, goal, teleport).outcome, Outcome::invalid_path);
  Trajectory elsewhere = clean;
  EXPECT_EQ(judge_trajectory(grid, {2, 10}, goal, elsewhere).outcome, Outcome::invalid_path);
}

TEST(Judge, ClearanceCountsTheUnknownCellsAndMotionTimeIsSimulated) {
  const Grid grid(20, 20);
  const Cell start{1, 10}, goal{11, 10};
  Trajectory tr = straight_run(start, 1.0, 100);  // 10 s along row 10
  tr.end_reason = "reached";
  tr.unknown_cells = {{6, 11}};  // 0.5 below the robot's line
  const TrajectoryVerdict v = judge_trajectory(grid, start, goal, tr);
  ASSERT_EQ(v.outcome, Outcome::success) << v.message;
  EXPECT_NEAR(v.min_clearance, 0.5, 1e-12);
  EXPECT_NEAR(v.sim_time_s, 10.0, 1e-12);
  // The grid alone sees 1.5 (the left wall), and eq. 5.2e adds 0.1 s per recorded position.
  PathMetrics m = compute_path_metrics(grid, tr.position);
  EXPECT_NEAR(m.min_clearance, 1.5, 1e-12);
  EXPECT_NEAR(m.motion_time_s, 10.0 + 101 * 0.1, 1e-9);
  apply_trajectory_verdict(v, 2.0, m);
  EXPECT_NEAR(m.min_clearance, 0.5, 1e-12);
  EXPECT_NEAR(m.min_clearance_m, 1.0, 1e-12);
  EXPECT_NEAR(m.motion_time_s, 10.0, 1e-12);
}

TEST(Judge, MetricsComeFromTheTrajectory) {
  const Grid grid(20, 20);
  const Cell start{1, 10}, goal{11, 10};
  Trajectory tr = straight_run(start, 1.0, 100);
  tr.end_reason = "reached";
  const TrajectoryVerdict v = judge_trajectory(grid, start, goal, tr);
  std::map<std::string, double> m(v.metrics.begin(), v.metrics.end());
  EXPECT_NEAR(m.at("travelled_length"), 10.0, 1e-9);
  EXPECT_NEAR(m.at("sim_time_s"), 10.0, 1e-9);
  EXPECT_EQ(m.at("control_steps"), 100.0);
  EXPECT_NEAR(m.at("min_clearance_static"), 1.5, 1e-9);  // the start, 1.5 from the left wall
  EXPECT_EQ(m.count("min_clearance_dynamic"), 0u);
  EXPECT_EQ(m.at("heading_change_sum"), 0.0);
  EXPECT_EQ(m.at("mean_abs_w"), 0.0);
}

}  // namespace
}  // namespace agv
