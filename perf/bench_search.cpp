// Grid search throughput (perf/README.md "Grid search"): A* and Dijkstra, through the planner
// interface, on uniform random maps (corner to corner) and on the five MovingAI maps of the full
// sets (a fixed subset of each .scen spanning its buckets), found as the tests find them
// (tests/movingai_data.h); without them, on the random maps alone. One iteration runs the case's
// whole query set; expansions_per_s is the expansion count of those searches over the iteration
// time.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "algos/registry.h"
#include "generators/map_generators.h"
#include "generators/movingai.h"
#include "perf/bench_maps.h"
#include "tests/movingai_data.h"

namespace agv {
namespace {

struct Query {
  Cell start;
  Cell goal;
};

struct Case {
  std::string name;
  std::string corner_rule;
  Grid grid;
  std::vector<Query> queries;
};

constexpr std::size_t kQueriesPerMap = 100;

Case uniform_case(int side, double density) {
  Rng rng(2024, static_cast<std::uint64_t>(side) * 100 + static_cast<std::uint64_t>(density * 10));
  MapInstance map = make_map(bench_uniform_spec(side, density, CornerRule::allow), rng);
  return {bench_uniform_name(side, density), "allow", std::move(map.grid), {{map.start, map.goal}}};
}

// Every k-th scenario in file order (files list buckets in increasing order), so the subset
// spans short and long queries alike.
Case movingai_case(const std::string& dir, const std::string& map_file, const std::string& suffix) {
  Case c{map_file.substr(0, map_file.find('.')) + suffix,
         "no_corner_cut",
         read_map(dir + "/" + map_file),
         {}};
  const auto scen = read_scen(dir + "/" + map_file + ".scen");
  const std::size_t step = std::max<std::size_t>(1, scen.size() / kQueriesPerMap);
  for (std::size_t i = step / 2; i < scen.size() && c.queries.size() < kQueriesPerMap; i += step)
    c.queries.push_back({scen[i].start, scen[i].goal});
  return c;
}

void run_case(benchmark::State& state, const Case& c, const Planner& planner) {
  Scratch scratch;
  Rng rng(1, 1);
  std::int64_t expanded = 0;
  for (auto _ : state) {
    for (const Query& q : c.queries) {
      const PlanResult r = planner.plan(PlanRequest{c.grid, q.start, q.goal, rng, scratch});
      if (!r.ok()) state.SkipWithError("search failed");
      expanded += r.work.search_expansions.value_or(0);
      benchmark::DoNotOptimize(r.path.data());
    }
  }
  state.counters["expansions_per_s"] =
      benchmark::Counter(static_cast<double>(expanded), benchmark::Counter::kIsRate);
  state.counters["expansions_per_query"] = benchmark::Counter(
      static_cast<double>(expanded) /
      static_cast<double>(state.iterations() * static_cast<std::int64_t>(c.queries.size())));
}

}  // namespace
}  // namespace agv

int main(int argc, char** argv) {
  using namespace agv;
  benchmark::Initialize(&argc, argv);
  static std::vector<std::unique_ptr<Case>> cases;
  for (int side : {64, 256, 1024})
    for (double density : {0.1, 0.3})
      cases.push_back(std::make_unique<Case>(uniform_case(side, density)));
  const std::string sets = testdata::movingai_sets();
  if (!sets.empty() && !std::filesystem::is_directory(sets)) {
    std::fprintf(stderr, "bench_search: AGVBENCH_MOVINGAI_DIR=%s is not a folder\n", sets.c_str());
    return 2;
  }
  if (!sets.empty()) {
    for (const char* map : {"arena2.map", "random512-10-0.map", "maze512-1-0.map", "8room_000.map",
                            "Berlin_0_512.map"})
      cases.push_back(std::make_unique<Case>(movingai_case(sets, map, "")));
  } else {
    std::fprintf(stderr, "bench_search: %s; the MovingAI cases are left out\n",
                 testdata::kNoSetsReason);
  }

  static std::vector<ConfiguredPlanner> planners;
  planners.reserve(2 * cases.size());
  for (const char* planner : {"astar", "dijkstra"}) {
    for (const auto& c : cases) {
      planners.push_back(configure_planner(planner, {{"corner_rule", c->corner_rule}}, "bench"));
      const Planner* p = planners.back().planner.get();
      const Case* cp = c.get();
      benchmark::RegisterBenchmark((std::string(planner) + "/" + c->name).c_str(),
                                   [cp, p](benchmark::State& s) { run_case(s, *cp, *p); })
          ->Unit(benchmark::kMillisecond);
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
