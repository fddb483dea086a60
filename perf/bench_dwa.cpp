// The DWA local planner (perf/README.md "DWA"): one control step, and whole fusion runs.
//
// dwa_step/...: one iteration evaluates one DWA control step at each of 32 states taken from a
// fusion run on a 20x20 uniform map (density 0.2), so the rollouts meet real obstacle layouts.
// Counter pair_steps_per_s = velocity samples x rollout steps per second (each is one rollout
// point checked against the static grid, the unknown cells and the moving discs), plus
// control_steps_per_s. Cases: the defaults (9 x 15 samples, T = 3 s at dt = 0.1 s: 135 pairs x
// 30 steps), a finer 21 x 41 window, and the defaults with 2 unknown cells and 3 moving discs
// in view.
//
// fusion_run/...: whole runs of a fusion planner (defaults: one moving disc, one unknown cell)
// on eight 20x20 uniform maps at density 0.2; counters runs_per_s and control_steps_per_s.

#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "algos/local/dwa.h"
#include "algos/registry.h"
#include "generators/map_generators.h"

namespace agv {
namespace {

constexpr int kMaps = 8;
constexpr std::size_t kStates = 32;

MapInstance bench_map(int index) {
  MapSpec spec;
  spec.width = spec.height = 20;
  spec.density = 0.2;
  spec.require_solvable = true;
  Rng rng(4004, static_cast<std::uint64_t>(index));
  return make_map(spec, rng);
}

struct StepCase {
  MapInstance map;
  std::vector<Pose> poses;
  std::vector<double> v, w;
  Point goal;
};

// States along a fusion run (no moving or unknown obstacles) on map 0.
StepCase step_case() {
  StepCase c{bench_map(0), {}, {}, {}, {}};
  const ConfiguredPlanner p = configure_planner(
      "fusion_astar_dwa", {{"dynamic_obstacles", 0}, {"unknown_obstacles", 0}}, "bench");
  Scratch scratch;
  Rng rng(1, 1);
  const PlanResult r = p.planner->plan({c.map.grid, c.map.start, c.map.goal, rng, scratch});
  const Trajectory& tr = *r.trajectory;
  const std::size_t n = tr.v.size();
  for (std::size_t k = 0; k < kStates; ++k) {
    const std::size_t i = 1 + k * (n - 1) / kStates;
    c.poses.push_back({tr.position[i].x, tr.position[i].y, tr.heading[i]});
    c.v.push_back(tr.v[i - 1]);
    c.w.push_back(tr.w[i - 1]);
  }
  c.goal = centre(c.map.goal);
  return c;
}

void dwa_steps(benchmark::State& state, const StepCase& c, DwaParams p, bool crowded) {
  DwaScratch scratch;
  const std::vector<Cell> unknown = {{10, 9}, {12, 6}};
  const std::vector<Disc> moving = {
      {{8.5, 8.5}, 0.4, {}}, {{14.2, 5.1}, 0.4, {}}, {{4.0, 15.0}, 0.4, {}}};
  const DwaView view{c.map.grid, crowded ? std::span<const Cell>(unknown) : std::span<const Cell>(),
                     crowded ? std::span<const Disc>(moving) : std::span<const Disc>()};
  std::int64_t pair_steps = 0, steps = 0;
  for (auto _ : state) {
    for (std::size_t k = 0; k < c.poses.size(); ++k) {
      DwaTarget target;
      target.goals = std::span<const Point>(&c.goal, 1);
      target.from = position(c.poses[k]);
      const DwaDecision d = dwa_step(p, c.poses[k], c.v[k], c.w[k], target, view, scratch);
      pair_steps += static_cast<std::int64_t>(d.samples) * d.rollout_steps;
      ++steps;
      benchmark::DoNotOptimize(d.v);
    }
  }
  using benchmark::Counter;
  state.counters["pair_steps_per_s"] = Counter(static_cast<double>(pair_steps), Counter::kIsRate);
  state.counters["control_steps_per_s"] = Counter(static_cast<double>(steps), Counter::kIsRate);
}

void fusion_runs(benchmark::State& state, const std::vector<MapInstance>& maps,
                 const Planner& planner) {
  Scratch scratch;
  std::int64_t runs = 0, steps = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < maps.size(); ++i) {
      Rng rng(9, i);
      const PlanResult r =
          planner.plan(PlanRequest{maps[i].grid, maps[i].start, maps[i].goal, rng, scratch});
      if (r.trajectory) steps += static_cast<std::int64_t>(r.trajectory->v.size());
      ++runs;
      benchmark::DoNotOptimize(r.path.data());
    }
  }
  using benchmark::Counter;
  state.counters["runs_per_s"] = Counter(static_cast<double>(runs), Counter::kIsRate);
  state.counters["control_steps_per_s"] = Counter(static_cast<double>(steps), Counter::kIsRate);
}

}  // namespace
}  // namespace agv

int main(int argc, char** argv) {
  using namespace agv;
  benchmark::Initialize(&argc, argv);
  static const StepCase step = step_case();
  DwaParams defaults;
  DwaParams fine;
  fine.v_samples = 21;
  fine.w_samples = 41;
  benchmark::RegisterBenchmark("dwa_step/default_9x15", [defaults](benchmark::State& s) {
    dwa_steps(s, step, defaults, false);
  })->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("dwa_step/fine_21x41", [fine](benchmark::State& s) {
    dwa_steps(s, step, fine, false);
  })->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("dwa_step/crowded_9x15", [defaults](benchmark::State& s) {
    dwa_steps(s, step, defaults, true);
  })->Unit(benchmark::kMicrosecond);

  static std::vector<MapInstance> maps;
  for (int i = 0; i < kMaps; ++i) maps.push_back(bench_map(i));
  static std::vector<ConfiguredPlanner> planners;
  for (const char* name : {"fusion_astar_dwa", "fusion_kin_dwa"}) {
    if (find_planner(name) == nullptr) continue;
    planners.push_back(configure_planner(name, nlohmann::json::object(), "bench"));
    const Planner* p = planners.back().planner.get();
    benchmark::RegisterBenchmark((std::string("fusion_run/") + name + "/uniform20_d0.2").c_str(),
                                 [p](benchmark::State& s) { fusion_runs(s, maps, *p); })
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
