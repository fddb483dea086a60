// Our sampling baselines beside OMPL's (perf/README.md "OMPL side by side"): rrt, birrt and prm
// against ompl_rrt, ompl_rrtconnect and ompl_prm (algos/ompl/, OMPL 1.5 through the one adapter),
// through the same planner interface on the same 64x64 uniform and blocks maps (corner to
// corner, solvable under no_corner_cut), every edge judged by the same line-of-sight test.
// OMPL's tree planners run with their default range (a fifth of the map's diagonal) and with our
// step of 2 cells.
//
// One iteration plans every map of the case once; each plan gets a fresh Rng seeded from the map
// index, so every iteration does the same work. Counters: s_per_plan (CPU time per plan), success
// (fraction of plans that found a path), path_length (mean length in cells of the paths found),
// samples_per_plan (the `samples` work counter).

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "algos/registry.h"
#include "generators/map_generators.h"
#include "perf/bench_maps.h"

namespace agv {
namespace {

constexpr int kMapsPerCase = 8;

BenchCase make_case(const std::string& generator, int side, double density) {
  return bench_case(generator, side, density, kMapsPerCase, 2026);
}

double length(const std::vector<Point>& path) {
  double sum = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i)
    sum += std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
  return sum;
}

void run_case(benchmark::State& state, const BenchCase& c, const Planner& planner) {
  Scratch scratch;
  std::int64_t samples = 0, plans = 0, successes = 0;
  double total_length = 0.0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < c.maps.size(); ++i) {
      const MapInstance& m = c.maps[i];
      Rng rng(7, i);
      const PlanResult r =
          plan_checked(planner, PlanRequest{m.grid, m.start, m.goal, rng, scratch});
      samples += r.work.samples.value_or(0);
      if (r.ok()) {
        ++successes;
        total_length += length(r.path);
      }
      ++plans;
      benchmark::DoNotOptimize(r.path.data());
    }
  }
  using benchmark::Counter;
  const auto n = static_cast<double>(plans);
  // Seconds of CPU per plan (the benchmark's time is per iteration, kMapsPerCase plans).
  state.counters["s_per_plan"] = Counter(n, Counter::kIsRate | Counter::kInvert);
  state.counters["success"] = Counter(static_cast<double>(successes) / n);
  state.counters["path_length"] =
      Counter(successes > 0 ? total_length / static_cast<double>(successes) : 0.0);
  state.counters["samples_per_plan"] = Counter(static_cast<double>(samples) / n);
}

}  // namespace
}  // namespace agv

int main(int argc, char** argv) {
  using namespace agv;
  benchmark::Initialize(&argc, argv);
  static std::vector<std::unique_ptr<BenchCase>> cases;
  for (double density : {0.1, 0.3})
    cases.push_back(std::make_unique<BenchCase>(make_case("uniform", 64, density)));
  cases.push_back(std::make_unique<BenchCase>(make_case("blocks", 64, 0.2)));

  struct Variant {
    std::string label;
    std::string planner;
    nlohmann::json params;
  };
  const std::vector<Variant> variants = {
      {"rrt", "rrt", nlohmann::json::object()},
      {"ompl_rrt", "ompl_rrt", nlohmann::json::object()},
      {"ompl_rrt_range2", "ompl_rrt", {{"range", 2.0}}},
      {"birrt", "birrt", nlohmann::json::object()},
      {"ompl_rrtconnect", "ompl_rrtconnect", nlohmann::json::object()},
      {"ompl_rrtconnect_range2", "ompl_rrtconnect", {{"range", 2.0}}},
      {"prm", "prm", nlohmann::json::object()},
      {"ompl_prm", "ompl_prm", nlohmann::json::object()},
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
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
