// Sweep throughput: runs per second of the quick config on 1 and 2 threads (and more where the
// machine has them), the figure a user planning a long sweep needs.
#include <benchmark/benchmark.h>

#include <fstream>
#include <thread>

#include "engine/plan/config_loader.h"
#include "engine/plan/sweep_config.h"
#include "engine/sweep/sweep_runner.h"

namespace {

agv::SweepConfig quick_config() {
  std::ifstream in(std::string(AGV_SOURCE_DIR) + "/configs/quick.json");
  return agv::parse_config(nlohmann::json::parse(in));
}

void bm_sweep(benchmark::State& state) {
  const agv::SweepConfig config = quick_config();
  agv::SweepOptions options;
  options.threads = static_cast<int>(state.range(0));
  std::int64_t runs = 0;
  for (auto _ : state) {
    const agv::SweepResults r = agv::run_sweep(config, options);
    for (const agv::CellResults& cell : r.cells)
      runs += static_cast<std::int64_t>(cell.runs.size());
    benchmark::DoNotOptimize(r.cells.data());
  }
  state.counters["runs_per_s"] =
      benchmark::Counter(static_cast<double>(runs), benchmark::Counter::kIsRate);
}

}  // namespace

int main(int argc, char** argv) {
  const int hw = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  auto* b = benchmark::RegisterBenchmark("sweep/quick", bm_sweep);
  for (int t = 1; t <= hw; t *= 2) b->Arg(t);
  if ((hw & (hw - 1)) != 0) b->Arg(hw);
  b->Unit(benchmark::kMillisecond)->UseRealTime();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
