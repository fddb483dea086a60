#include "algos/sampling/birrt.h"

#include <memory>
#include <utility>

#include "algos/sampling/rrt_tree.h"
#include "algos/sampling/sampling_params.h"

namespace agv {

namespace {

struct BirrtScratch {
  RrtTree from_start;
  RrtTree from_goal;
};

class BirrtPlanner final : public Planner {
 public:
  explicit BirrtPlanner(const RrtSettings& settings) : settings_(settings) {}

  PlanResult plan(const PlanRequest& request) const override {
    const Grid& grid = request.grid;
    PlanResult result;
    result.rule = settings_.sight.corners;
    if (request.start == request.goal) {
      result.failure = Failure::none;
      result.path = {centre(request.start)};
      result.work.samples = 0;
      return result;
    }
    auto& scratch = request.scratch.get<BirrtScratch>();
    RrtTree* a = &scratch.from_start;  // the tree that extends this iteration
    RrtTree* b = &scratch.from_goal;   // the tree that connects
    const double width = grid.width();
    const double height = grid.height();
    int meet_a = -1;
    int meet_b = -1;
    long long iterations = 0;
    long long connect_steps = 0;
    bool timed_out = false;
    {
      PhaseTimer timer(result, "search");
      a->reset(grid, centre(request.start), settings_.index);
      b->reset(grid, centre(request.goal), settings_.index);
      for (; iterations < settings_.max_iterations; ++iterations) {
        if (iterations % kSamplingDeadlineInterval == 0 && request.deadline.expired()) {
          timed_out = true;
          break;
        }
        // Goal bias here means: aim at the other tree's root.
        const Point target =
            request.rng.chance(settings_.goal_bias)
                ? b->point(0)
                : Point{request.rng.uniform(0.0, width), request.rng.uniform(0.0, height)};
        const Extension e = a->extend(grid, target, settings_.step, settings_.sight);
        if (e.status != ExtendStatus::trapped) {
          const Point q = a->point(e.node);
          // CONNECT: ends within ceil(distance / step) extensions, each one step closer, which
          // with a small step on a large map is many: the deadline is polled among them too.
          Extension c;
          do {
            if (++connect_steps % kSamplingDeadlineInterval == 0 && request.deadline.expired()) {
              timed_out = true;
              break;
            }
            c = b->extend(grid, q, settings_.step, settings_.sight);
          } while (c.status == ExtendStatus::advanced);
          if (timed_out) break;
          if (c.status == ExtendStatus::reached) {
            meet_a = e.node;
            meet_b = c.node;
            break;
          }
        }
        std::swap(a, b);
      }
    }
    // The iteration where the trees met drew its target before the loop stopped.
    result.work.samples = iterations + (meet_a >= 0 ? 1 : 0);
    result.extra.emplace_back("iterations", static_cast<double>(iterations));
    if (meet_a < 0) {
      result.failure = Failure::limit;
      result.message = timed_out ? "deadline passed before the trees met"
                                 : "max_iterations samples drawn without the trees meeting";
      return result;
    }
    // Both meeting nodes hold the same point: start tree root -> meet, then the goal tree from
    // the meeting node's parent back to its root.
    const bool a_is_start = a == &scratch.from_start;
    const int meet_start = a_is_start ? meet_a : meet_b;
    const int meet_goal = a_is_start ? meet_b : meet_a;
    result.failure = Failure::none;
    scratch.from_start.append_path_from_root(meet_start, result.path);
    for (int n = scratch.from_goal.parent(meet_goal); n >= 0; n = scratch.from_goal.parent(n))
      result.path.push_back(scratch.from_goal.point(n));
    return result;
  }

 private:
  RrtSettings settings_;
};

}  // namespace

PlannerInfo birrt_planner() {
  PlannerInfo info;
  info.kind = PlannerKind::sampling;
  info.name = "birrt";
  info.summary = "Bi-RRT (RRT-Connect): start and goal trees alternate extend / connect";
  info.source =
      "docs/PLANNERS.md Baselines; paper 000 Tables III-XIII (Bi-RRT column); Kuffner & LaValle "
      "2000";
  info.counters = {
      {"samples", "targets drawn, one per iteration (goal-biased ones included)"},
      {"collision_checks", "segments tested: one per extension step of either tree that moves"}};
  info.stochastic = true;
  info.proves_no_path = false;  // gives up with limit after its budget
  static const ParamDecls<RrtSettings> decls = rrt_decls();
  info.params = decls.specs();
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<BirrtPlanner>(decls.read(params));
  };
  return info;
}

}  // namespace agv
