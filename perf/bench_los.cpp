// Line-of-sight throughput (perf/README.md "Line of sight"): segments checked per second by the
// reference walk (segment_free_reference), the word-parallel check (segment_free) and its
// batched form (segments_free) at the process's instruction-set level, and the batched kernel of
// every level this CPU runs (`batched-LEVEL`, core/simd_path.h), at several segment lengths and
// obstacle densities, in `cells` mode and in paper 000's circles(r_obs) mode. One iteration checks
// a fixed set of random segments of one length on a 256 x 256 uniform map; `free` is the fraction
// that is free.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "core/grid.h"
#include "core/input_error.h"
#include "core/line_of_sight.h"
#include "core/line_of_sight_batch.h"
#include "core/line_of_sight_kernel.h"
#include "core/rng.h"
#include "core/simd_path.h"

namespace agv {
namespace {

constexpr int kSide = 256;
constexpr int kSegments = 4096;

struct Case {
  Grid grid;
  std::vector<Point> a, b;
  SightRule rule;
};

// Random segments of exactly `length` cells, both endpoints inside the map: half from cell
// centres in lattice directions (shortcut and key-point checks), half general (PSO particles).
std::unique_ptr<Case> make_case(double length, double density, const SightRule& rule) {
  auto c = std::make_unique<Case>();
  Rng rng(42, static_cast<std::uint64_t>(length * 1000 + density * 100));
  c->grid = Grid(kSide, kSide);
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x)
      if (rng.uniform01() < density) c->grid.set_blocked(x, y, true);
  c->rule = rule;
  while (static_cast<int>(c->a.size()) < kSegments) {
    Point p{rng.uniform(0.0, kSide), rng.uniform(0.0, kSide)};
    double angle = rng.uniform(0.0, 6.283185307179586);
    if (c->a.size() % 2 == 0) {
      p = centre({rng.between(0, kSide - 1), rng.between(0, kSide - 1)});
      angle = std::atan2(rng.between(-3, 3), rng.between(-3, 3));
    }
    const Point q{p.x + length * std::cos(angle), p.y + length * std::sin(angle)};
    if (q.x < 0 || q.y < 0 || q.x > kSide || q.y > kSide) continue;
    c->a.push_back(p);
    c->b.push_back(q);
  }
  return c;
}

enum class Mode { reference, fast, batched, level };

// `level`: the batched kernel of that level, called directly (no collision counting).
void run(benchmark::State& state, const Case& c, Mode mode, const SightKernel* level) {
  std::vector<std::uint8_t> out(c.a.size());
  std::int64_t checked = 0;
  std::int64_t free = 0;
  for (auto _ : state) {
    if (mode == Mode::batched) {
      segments_free(c.grid, c.a, c.b, c.rule, out);
    } else if (mode == Mode::level) {
      level->segments(c.grid, c.a, c.b, c.rule, out);
    } else {
      for (std::size_t i = 0; i < c.a.size(); ++i)
        out[i] = mode == Mode::fast ? segment_free(c.grid, c.a[i], c.b[i], c.rule)
                                    : segment_free_reference(c.grid, c.a[i], c.b[i], c.rule);
    }
    benchmark::DoNotOptimize(out.data());
    checked += static_cast<std::int64_t>(out.size());
    for (std::uint8_t o : out) free += o;
  }
  state.counters["segments_per_s"] =
      benchmark::Counter(static_cast<double>(checked), benchmark::Counter::kIsRate);
  state.counters["free"] = static_cast<double>(free) / static_cast<double>(checked);
}

}  // namespace
}  // namespace agv

int main(int argc, char** argv) {
  using namespace agv;
  benchmark::Initialize(&argc, argv);
  static std::vector<std::unique_ptr<Case>> cases;
  const struct {
    const char* name;
    SightRule rule;
  } rules[] = {{"cells", SightRule::cells(CornerRule::no_corner_cut)},
               {"circles", SightRule::circles(std::sqrt(0.5), CornerRule::allow)}};
  struct Variant {
    std::string name;
    Mode mode;
    const SightKernel* level = nullptr;
  };
  std::vector<Variant> variants = {
      {"reference", Mode::reference}, {"fast", Mode::fast}, {"batched", Mode::batched}};
  for (SimdPath path : kSimdPaths)
    if (const SightKernel* k = sight_kernel(path))
      variants.push_back({"batched-" + std::string(simd_path_name(path)), Mode::level, k});
  try {
    std::fprintf(stderr, "bench_los: the process runs the %s level\n",
                 std::string(simd_path_name(active_simd_path())).c_str());
  } catch (const InputError& e) {  // AGVBENCH_SIMD names no level this machine runs
    std::fprintf(stderr, "bench_los: %s\n", e.what());
    return 2;
  }
  for (const auto& r : rules)
    for (double density : {0.0, 0.1, 0.3})
      for (double length : {2.0, 8.0, 32.0, 128.0}) {
        cases.push_back(make_case(length, density, r.rule));
        const Case* c = cases.back().get();
        for (const Variant& v : variants) {
          char name[96];
          std::snprintf(name, sizeof name, "%s/%s/d%.1f/len%g", v.name.c_str(), r.name, density,
                        length);
          benchmark::RegisterBenchmark(name, [c, v](benchmark::State& s) {
            run(s, *c, v.mode, v.level);
          })->Unit(benchmark::kMicrosecond);
        }
      }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
