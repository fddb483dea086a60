#include "algos/sampling/rrt.h"

#include <cmath>
#include <memory>

#include "algos/sampling/rrt_tree.h"
#include "algos/sampling/sampling_params.h"

namespace agv {

namespace {

struct RrtScratch {
  RrtTree tree;
};

struct RrtOptions {
  RrtSettings settings;
  double goal_radius = 0.0;  // cells; 0 = the step size
};

const ParamDecls<RrtOptions>& rrt_options_decls() {
  static const ParamDecls<RrtOptions> decls = [] {
    ParamDecls<RrtOptions> d;
    d.include(&RrtOptions::settings, rrt_decls())
        .number("goal_radius", &RrtOptions::goal_radius, 0.0, 0.0, 1e6,
                "a new node within this distance (cells) of the goal is joined to it directly "
                "when that segment is free; 0 = the step size");
    return d;
  }();
  return decls;
}

class RrtPlanner final : public Planner {
 public:
  explicit RrtPlanner(const RrtOptions& options)
      : settings_(options.settings), goal_radius_(options.goal_radius) {}

  PlanResult plan(const PlanRequest& request) const override {
    const Grid& grid = request.grid;
    const Point start = centre(request.start);
    const Point goal = centre(request.goal);
    PlanResult result;
    result.rule = settings_.sight.corners;
    if (request.start == request.goal) {
      result.failure = Failure::none;
      result.path = {start};
      result.work.samples = 0;
      return result;
    }
    RrtTree& tree = request.scratch.get<RrtScratch>().tree;
    const double radius = goal_radius_ > 0.0 ? goal_radius_ : settings_.step;
    const double width = grid.width();
    const double height = grid.height();
    int reached = -1;
    long long iterations = 0;
    bool timed_out = false;
    {
      PhaseTimer timer(result, "search");
      tree.reset(grid, start, settings_.index);
      for (; iterations < settings_.max_iterations; ++iterations) {
        if (iterations % kSamplingDeadlineInterval == 0 && request.deadline.expired()) {
          timed_out = true;
          break;
        }
        // Uniform over the whole map, obstacles included (the classic RRT sample space): a
        // sample inside an obstacle still pulls the tree towards it.
        const Point target =
            request.rng.chance(settings_.goal_bias)
                ? goal
                : Point{request.rng.uniform(0.0, width), request.rng.uniform(0.0, height)};
        const Extension e = tree.extend(grid, target, settings_.step, settings_.sight);
        if (e.status == ExtendStatus::trapped) continue;
        const Point p = tree.point(e.node);
        if (p == goal) {
          reached = e.node;
          break;
        }
        if (std::hypot(goal.x - p.x, goal.y - p.y) <= radius &&
            segment_free(grid, p, goal, settings_.sight)) {
          reached = tree.add(goal, e.node);
          break;
        }
      }
    }
    // The iteration that reached the goal drew its target before the loop stopped.
    result.work.samples = iterations + (reached >= 0 ? 1 : 0);
    result.extra.emplace_back("iterations", static_cast<double>(iterations));
    if (reached < 0) {
      result.failure = Failure::limit;
      result.message = timed_out ? "deadline passed before the tree reached the goal"
                                 : "max_iterations samples drawn without reaching the goal";
      return result;
    }
    result.failure = Failure::none;
    tree.append_path_from_root(reached, result.path);
    return result;
  }

 private:
  RrtSettings settings_;
  double goal_radius_;
};

}  // namespace

PlannerInfo rrt_planner() {
  PlannerInfo info;
  info.kind = PlannerKind::sampling;
  info.name = "rrt";
  info.summary = "RRT: one tree from the start, fixed-step extension, goal bias";
  info.source = "docs/PLANNERS.md Baselines; paper 000 Tables III-XIII (RRT column); LaValle 1998";
  info.counters = {
      {"samples", "targets drawn, one per iteration (goal-biased ones included)"},
      {"collision_checks",
       "segments tested: one per extension that moves (a target on a tree node needs none), "
       "one per goal connection tried"}};
  info.stochastic = true;
  info.proves_no_path = false;  // gives up with limit after its budget
  info.params = rrt_options_decls().specs();
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<RrtPlanner>(rrt_options_decls().read(params));
  };
  return info;
}

}  // namespace agv
