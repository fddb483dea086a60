// The papers' baselines (perf/README.md "Baselines"): PRM, RRT, RRT-Connect and ant colony through
// the planner interface on 64x64 uniform maps (the papers' corner-to-corner protocol, solvable
// under no_corner_cut) at densities 0.1 and 0.3, plus the RRT nearest-neighbour index alone.
//
// One iteration plans every map of the case once; each plan gets a fresh Rng seeded from the map
// index, so every iteration does the same work. Counters: plans_per_s, work_per_s (its kind's
// work counter per second: samples for PRM, RRT and RRT-Connect, ant_steps for ACO; docs/METRICS.md
// "Work counters"), work_per_plan and success (fraction of plans that found a path).

#include <benchmark/benchmark.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "algos/registry.h"
#include "algos/sampling/rrt_tree.h"
#include "generators/map_generators.h"
#include "perf/bench_maps.h"

namespace agv {
namespace {

constexpr int kMapsPerCase = 8;

BenchCase uniform_case(int side, double density) {
  return bench_case("uniform", side, density, kMapsPerCase, 2025);
}

void run_case(benchmark::State& state, const BenchCase& c, const Planner& planner) {
  Scratch scratch;
  std::int64_t work = 0;
  std::int64_t plans = 0;
  std::int64_t successes = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < c.maps.size(); ++i) {
      const MapInstance& m = c.maps[i];
      Rng rng(7, i);
      const PlanResult r = planner.plan(PlanRequest{m.grid, m.start, m.goal, rng, scratch});
      work += r.work.samples.value_or(0) + r.work.ant_steps.value_or(0);
      successes += r.ok() ? 1 : 0;
      ++plans;
      benchmark::DoNotOptimize(r.path.data());
    }
  }
  using benchmark::Counter;
  state.counters["plans_per_s"] = Counter(static_cast<double>(plans), Counter::kIsRate);
  state.counters["work_per_s"] = Counter(static_cast<double>(work), Counter::kIsRate);
  state.counters["work_per_plan"] = Counter(static_cast<double>(work) / static_cast<double>(plans));
  state.counters["success"] = Counter(static_cast<double>(successes) / static_cast<double>(plans));
}

// The RRT tree's nearest-neighbour index alone: grow a tree of state.range(0) nodes on a 64x64
// map, one nearest query per insertion (the RRT pattern). bucket_side: 0 = adaptive (the
// planners' setting), > 0 fixed; ignored by the k-d tree.
void nearest_index(benchmark::State& state, NearestIndex index, double bucket_side) {
  const Grid grid(64, 64);
  const auto nodes = static_cast<int>(state.range(0));
  RrtTree tree;
  std::int64_t queries = 0;
  for (auto _ : state) {
    Rng rng(5, 5);
    tree.reset(grid, {32.0, 32.0}, index, bucket_side);
    for (int n = 1; n < nodes; ++n) {
      const Point q{rng.uniform(0.0, 64.0), rng.uniform(0.0, 64.0)};
      const int near = tree.nearest(q);
      tree.add(q, near);
    }
    queries += nodes - 1;
    benchmark::DoNotOptimize(tree.size());
  }
  state.counters["queries_per_s"] =
      benchmark::Counter(static_cast<double>(queries), benchmark::Counter::kIsRate);
}

}  // namespace
}  // namespace agv

int main(int argc, char** argv) {
  using namespace agv;
  benchmark::Initialize(&argc, argv);
  static std::vector<std::unique_ptr<BenchCase>> cases;
  for (double density : {0.1, 0.3})
    cases.push_back(std::make_unique<BenchCase>(uniform_case(64, density)));

  struct Variant {
    std::string label;
    std::string planner;
    nlohmann::json params;
  };
  const std::vector<Variant> variants = {
      {"prm", "prm", nlohmann::json::object()},
      {"rrt", "rrt", nlohmann::json::object()},
      {"rrt_kdtree", "rrt", {{"nn_index", "kdtree"}}},
      {"birrt", "birrt", nlohmann::json::object()},
      {"birrt_kdtree", "birrt", {{"nn_index", "kdtree"}}},
      {"aco", "aco", nlohmann::json::object()},
  };
  static std::vector<ConfiguredPlanner> planners;
  planners.reserve(variants.size() * cases.size());
  for (const Variant& v : variants) {
    for (const auto& c : cases) {
      planners.push_back(configure_planner(v.planner, v.params, "bench"));
      const Planner* p = planners.back().planner.get();
      const BenchCase* cp = c.get();
      benchmark::RegisterBenchmark((v.label + "/" + c->name).c_str(), [cp, p](benchmark::State& s) {
        run_case(s, *cp, *p);
      })->Unit(benchmark::kMillisecond);
    }
  }
  for (const double side : {0.0, 1.0, 2.0, 4.0, 8.0}) {
    char name[64];
    if (side > 0.0)
      std::snprintf(name, sizeof name, "nearest/buckets_side%.0f", side);
    else
      std::snprintf(name, sizeof name, "nearest/buckets_adaptive");
    benchmark::RegisterBenchmark(
        name, [side](benchmark::State& s) { nearest_index(s, NearestIndex::buckets, side); })
        ->Arg(100)
        ->Arg(1000)
        ->Arg(10000)
        ->Unit(benchmark::kMicrosecond);
  }
  benchmark::RegisterBenchmark(
      "nearest/kdtree", [](benchmark::State& s) { nearest_index(s, NearestIndex::kdtree, 0.0); })
      ->Arg(100)
      ->Arg(1000)
      ->Arg(10000)
      ->Unit(benchmark::kMicrosecond);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
