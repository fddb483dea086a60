// The any-angle reference (perf/README.md "Any-angle reference", core/any_angle.h): the bound of
// one start/goal query per map, as the engine computes it once per map, on uniform maps of the
// sweep sizes and larger (corner to corner, solvable under no_corner_cut), under allow and
// no_corner_cut.
//
// One iteration computes the bound of every map (query) of the case once with one reused
// scratch. Counters: maps_per_s (queries per CPU second), nodes_per_map (graph nodes: start,
// goal and the bend points of the start's component).

#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "core/any_angle.h"
#include "generators/map_generators.h"
#include "perf/bench_maps.h"

namespace agv {
namespace {

struct Query {
  const Grid* grid;
  Cell start;
  Cell goal;
};

struct Case {
  std::string name;
  std::vector<std::unique_ptr<Grid>> grids;
  std::vector<Query> queries;
};

Case uniform_case(int side, double density, int maps) {
  const MapSpec spec = bench_uniform_spec(side, density, CornerRule::no_corner_cut);
  Case c{bench_uniform_name(side, density), {}, {}};
  for (int i = 0; i < maps; ++i) {
    Rng rng(2026, static_cast<std::uint64_t>(density * 10) * 1000 + static_cast<std::uint64_t>(i));
    MapInstance m = make_map(spec, rng);
    c.grids.push_back(std::make_unique<Grid>(std::move(m.grid)));
    c.queries.push_back({c.grids.back().get(), m.start, m.goal});
  }
  return c;
}

void run_case(benchmark::State& state, const Case& c, CornerRule rule) {
  AnyAngleScratch scratch;
  std::int64_t maps = 0;
  std::int64_t nodes = 0;
  for (auto _ : state) {
    for (const Query& q : c.queries) {
      const auto length = any_angle_length(*q.grid, q.start, q.goal, rule, scratch);
      benchmark::DoNotOptimize(length);
      nodes += static_cast<std::int64_t>(scratch.node.size());
      ++maps;
    }
  }
  using benchmark::Counter;
  state.counters["maps_per_s"] = Counter(static_cast<double>(maps), Counter::kIsRate);
  state.counters["nodes_per_map"] = Counter(static_cast<double>(nodes) / static_cast<double>(maps));
}

}  // namespace
}  // namespace agv

int main(int argc, char** argv) {
  using namespace agv;
  benchmark::Initialize(&argc, argv);
  static std::vector<std::unique_ptr<Case>> cases;
  for (int side : {16, 32, 64, 128})
    for (double density : {0.1, 0.2, 0.3})
      cases.push_back(std::make_unique<Case>(uniform_case(side, density, 8)));
  // One large map: the search looks at every bend point of the component per expansion.
  cases.push_back(std::make_unique<Case>(uniform_case(512, 0.1, 1)));
  for (CornerRule rule : {CornerRule::no_corner_cut, CornerRule::allow}) {
    for (const auto& c : cases) {
      const Case* cp = c.get();
      benchmark::RegisterBenchmark((std::string(to_string(rule)) + "/" + c->name).c_str(),
                                   [cp, rule](benchmark::State& s) { run_case(s, *cp, rule); })
          ->Unit(benchmark::kMillisecond);
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
