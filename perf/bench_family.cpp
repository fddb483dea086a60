// The A* family of issue 3 (perf/README.md "A* family"): each planner with its default
// parameters through the planner interface, and each shared post-processing step on its own, on
// uniform random maps (corner to corner, solvable under no_corner_cut, the strictest rule any of
// them uses). One iteration plans (or post-processes) the case's maps once; expansions_per_s is
// the planners' search_expansions (cells taken off the open list) per CPU second, plans_per_s the
// plan calls per CPU second.

#include <benchmark/benchmark.h>

#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "algos/postprocess/path_curves.h"
#include "algos/postprocess/path_simplify.h"
#include "algos/registry.h"
#include "core/line_of_sight.h"
#include "generators/map_generators.h"
#include "perf/bench_maps.h"

namespace agv {
namespace {

constexpr int kMapsPerCase = 4;

struct Case {
  std::string name;
  std::vector<MapInstance> maps;
  std::vector<std::vector<Point>> astar_paths;  // classic A* (no_corner_cut): post-processing input
};

Case uniform_case(int side, double density) {
  MapSpec spec = bench_uniform_spec(side, density, CornerRule::no_corner_cut);
  spec.max_attempts = 100000;
  Case c{bench_uniform_name(side, density), {}, {}};
  const auto astar = configure_planner("astar", {{"corner_rule", "no_corner_cut"}}, "bench");
  Scratch scratch;
  for (int i = 0; i < kMapsPerCase; ++i) {
    Rng rng(2025, static_cast<std::uint64_t>(side) * 1000 +
                      static_cast<std::uint64_t>(density * 100) * 10 +
                      static_cast<std::uint64_t>(i));
    c.maps.push_back(make_map(spec, rng));
    Rng plan_rng(1, 1);
    const MapInstance& m = c.maps.back();
    c.astar_paths.push_back(
        astar.planner->plan(PlanRequest{m.grid, m.start, m.goal, plan_rng, scratch}).path);
  }
  return c;
}

void run_planner(benchmark::State& state, const Case& c, const Planner& planner) {
  Scratch scratch;
  Rng rng(1, 1);
  std::int64_t expanded = 0, plans = 0;
  for (auto _ : state) {
    for (const MapInstance& m : c.maps) {
      const PlanResult r = planner.plan(PlanRequest{m.grid, m.start, m.goal, rng, scratch});
      if (!r.ok()) state.SkipWithError("plan failed");
      expanded += r.work.search_expansions.value_or(0);
      ++plans;
      benchmark::DoNotOptimize(r.path.data());
    }
  }
  state.counters["expansions_per_s"] =
      benchmark::Counter(static_cast<double>(expanded), benchmark::Counter::kIsRate);
  state.counters["plans_per_s"] =
      benchmark::Counter(static_cast<double>(plans), benchmark::Counter::kIsRate);
  state.counters["expanded_per_plan"] = benchmark::Counter(
      static_cast<double>(expanded) / static_cast<double>(std::max<std::int64_t>(1, plans)));
}

// A post-processing step: A*'s path of a map in, a polyline out.
using Step = std::function<std::vector<Point>(const Grid&, const std::vector<Point>&)>;

void run_step(benchmark::State& state, const Case& c, const Step& step) {
  std::int64_t paths = 0, points_in = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < c.maps.size(); ++i) {
      const std::vector<Point> out = step(c.maps[i].grid, c.astar_paths[i]);
      benchmark::DoNotOptimize(out.data());
      ++paths;
      points_in += static_cast<std::int64_t>(c.astar_paths[i].size());
    }
  }
  state.counters["paths_per_s"] =
      benchmark::Counter(static_cast<double>(paths), benchmark::Counter::kIsRate);
  state.counters["input_points_per_s"] =
      benchmark::Counter(static_cast<double>(points_in), benchmark::Counter::kIsRate);
}

std::vector<std::pair<std::string, Step>> steps() {
  const SightRule cells = SightRule::cells(CornerRule::no_corner_cut);
  const SightRule margin = SightRule::margin(1.0, CornerRule::no_corner_cut);
  const SightRule circles = SightRule::circles(0.70710678118654752, CornerRule::no_corner_cut);
  auto collinear_first = [](const std::vector<Point>& p) {
    std::vector<Point> q = p;
    remove_collinear(q);
    return q;
  };
  return {
      {"collinear", [=](const Grid&, const std::vector<Point>& p) { return collinear_first(p); }},
      {"turning_points_r0.71",
       [=](const Grid& g, const std::vector<Point>& p) {
         std::vector<Point> q = collinear_first(p);
         remove_turning_points(g, q, circles);
         return q;
       }},
      {"greedy",
       [=](const Grid& g, const std::vector<Point>& p) {
         std::vector<Point> q = collinear_first(p);
         shortcut_greedy(g, q, cells);
         return q;
       }},
      {"forward_keys_midpoints",
       [=](const Grid& g, const std::vector<Point>& p) {
         std::vector<Point> q = p;
         insert_midpoints(q);
         forward_key_points(g, q, cells);
         return q;
       }},
      {"from_goal_dsafe1",
       [=](const Grid& g, const std::vector<Point>& p) {
         std::vector<Point> q = p;
         remove_redundant_from_goal(g, q, margin);
         return q;
       }},
      {"direct_midpoint",
       [=](const Grid& g, const std::vector<Point>& p) {
         std::vector<Point> q = p;
         shortcut_direct_midpoint(g, q, cells);
         return q;
       }},
      {"avoid_obstacles",
       [=](const Grid& g, const std::vector<Point>& p) {
         std::vector<Point> q = p;
         insert_midpoints(q);
         forward_key_points(g, q, cells);
         avoid_obstacles(g, q, cells);
         return q;
       }},
      {"bezier_on_greedy",
       [=](const Grid& g, const std::vector<Point>& p) {
         std::vector<Point> q = collinear_first(p);
         shortcut_greedy(g, q, cells);
         return bezier_corners(g, q, cells);
       }},
      {"bspline_on_from_goal",
       [=](const Grid& g, const std::vector<Point>& p) {
         const std::vector<int> kept = greedy_keep(g, p, margin, true);
         return bspline_smooth(g, p, kept, cells);
       }},
  };
}

}  // namespace
}  // namespace agv

int main(int argc, char** argv) {
  using namespace agv;
  benchmark::Initialize(&argc, argv);
  static std::vector<std::unique_ptr<Case>> cases;
  for (int side : {64, 256})
    for (double density : {0.1, 0.3})
      cases.push_back(std::make_unique<Case>(uniform_case(side, density)));

  static std::vector<ConfiguredPlanner> planners;
  const char* names[] = {"astar",          "ma_star",   "improved_astar_internal",
                         "improved_astar", "alt_astar", "kin_astar",
                         "bidir_astar"};
  for (const char* name : names) planners.push_back(configure_planner(name, {}, "bench"));
  for (std::size_t k = 0; k < std::size(names); ++k) {
    for (const auto& c : cases) {
      const Planner* p = planners[k].planner.get();
      const Case* cp = c.get();
      benchmark::RegisterBenchmark((std::string(names[k]) + "/" + c->name).c_str(),
                                   [cp, p](benchmark::State& s) { run_planner(s, *cp, *p); })
          ->Unit(benchmark::kMicrosecond);
    }
  }
  static const auto all_steps = steps();
  for (const auto& [step_name, step] : all_steps) {
    for (const auto& c : cases) {
      const Case* cp = c.get();
      const Step* sp = &step;
      benchmark::RegisterBenchmark(("post/" + step_name + "/" + c->name).c_str(),
                                   [cp, sp](benchmark::State& s) { run_step(s, *cp, *sp); })
          ->Unit(benchmark::kMicrosecond);
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
