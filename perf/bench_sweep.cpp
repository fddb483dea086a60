// Sweep throughput: runs per second of the quick config on 1 and 2 threads (and more where the
// machine has them), the figure a user planning a long sweep needs; and where a sweep's CPU goes
// (`sweep/phases`): per run, the microseconds of the engine's phases (engine/system/phase_clock.h)
// beside the planners', of the config given with --config (default configs/quick.json;
// perf/README.md "Planner throughput" runs it on configs/default.json). With --journal PATH (a
// file that must not exist yet) the phases run as `agvbench run --runs-out PATH` does: the
// journal written and each finished cell released, so `sinks_us` is what a run costs under the
// sinks' lock.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>

#include "algos/planner.h"
#include "engine/outputs/report.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/sweep_config.h"
#include "engine/sweep/sweep_runner.h"
#include "engine/system/phase_clock.h"

namespace {

std::string g_config = std::string(AGV_SOURCE_DIR) + "/configs/quick.json";
std::string g_journal;  // --journal: "" = none

agv::SweepConfig bench_config() { return agv::load_config(g_config); }

// The runs done (planner scopes counted: a slot outside a planner's "only" is no run).
std::int64_t runs_of(const agv::SweepResults& r) { return agv::coverage_of(r).runs_present; }

void bm_sweep(benchmark::State& state) {
  const agv::SweepConfig config = bench_config();
  agv::SweepOptions options;
  options.threads = static_cast<int>(state.range(0));
  std::int64_t runs = 0;
  for (auto _ : state) {
    const agv::SweepResults r = agv::run_sweep(config, options);
    runs += runs_of(r);
    benchmark::DoNotOptimize(r.cells.data());
  }
  state.counters["runs_per_s"] =
      benchmark::Counter(static_cast<double>(runs), benchmark::Counter::kIsRate);
}

std::int64_t process_cpu_ns() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  const auto ns = [](const timeval& t) {
    return static_cast<std::int64_t>(t.tv_sec) * 1'000'000'000 +
           static_cast<std::int64_t>(t.tv_usec) * 1000;
  };
  return ns(u.ru_utime) + ns(u.ru_stime);
}

// One sweep with the phase clock on, then its report built: µs of CPU per run by phase. `other`
// is the process CPU neither a phase nor the report accounts for (scheduling, the sweep's set-up,
// allocation outside the scopes); `engine_pct` is everything but the planners, in % of the
// process CPU.
void bm_phases(benchmark::State& state) {
  const agv::SweepConfig config = bench_config();
  agv::SweepOptions options;
  options.threads = static_cast<int>(state.range(0));
  options.runs_path = g_journal;
  options.release_cells = !g_journal.empty();
  for (auto _ : state) {
    if (!g_journal.empty()) std::remove(g_journal.c_str());
    agv::reset_phase_clock();
    agv::enable_phase_clock(true);
    const std::int64_t cpu0 = process_cpu_ns();
    const agv::SweepResults r = agv::run_sweep(config, options);
    const std::int64_t t0 = agv::thread_cpu_ns();
    const nlohmann::json report = agv::build_report(config, r);
    const std::int64_t report_ns = agv::thread_cpu_ns() - t0;
    const std::int64_t cpu = process_cpu_ns() - cpu0;
    agv::enable_phase_clock(false);
    benchmark::DoNotOptimize(report.size());
    const agv::PhaseTotals t = agv::phase_clock_totals();
    const auto runs = static_cast<double>(runs_of(r));
    const auto phase = [&t](agv::EnginePhase p) { return t[static_cast<std::size_t>(p)]; };
    const std::int64_t reference = phase(agv::EnginePhase::reference);
    const std::int64_t judge = phase(agv::EnginePhase::judge) - reference;  // reference nested
    const std::int64_t planner = phase(agv::EnginePhase::planner);
    const std::int64_t accounted = phase(agv::EnginePhase::map) + reference + planner + judge +
                                   phase(agv::EnginePhase::record) +
                                   phase(agv::EnginePhase::sinks) + report_ns;
    const auto us = [runs](std::int64_t ns) { return static_cast<double>(ns) / 1e3 / runs; };
    state.counters["runs"] = runs;
    state.counters["cpu_us_per_run"] = us(cpu);
    state.counters["planner_us"] = us(planner);
    state.counters["map_us"] = us(phase(agv::EnginePhase::map));
    state.counters["reference_us"] = us(reference);
    state.counters["judge_us"] = us(judge);
    state.counters["record_us"] = us(phase(agv::EnginePhase::record));
    state.counters["sinks_us"] = us(phase(agv::EnginePhase::sinks));
    state.counters["report_us"] = us(report_ns);
    state.counters["other_us"] = us(cpu - accounted);
    state.counters["engine_pct"] =
        100.0 * static_cast<double>(cpu - planner) / static_cast<double>(cpu);
  }
}

}  // namespace

int main(int argc, char** argv) {
  // --config PATH and --journal PATH (ours), the rest for Google Benchmark.
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--config") == 0 && i + 1 < argc) {
      g_config = argv[++i];
    } else if (std::strcmp(argv[i], "--journal") == 0 && i + 1 < argc) {
      g_journal = argv[++i];
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  // Each iteration starts its journal anew: never over a file the user had.
  if (!g_journal.empty() && std::ifstream(g_journal).good()) {
    std::fprintf(stderr, "bench_sweep: --journal %s: the file exists; give a new path\n",
                 g_journal.c_str());
    return 2;
  }
  const int hw = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  auto* b = benchmark::RegisterBenchmark("sweep/run", bm_sweep);
  for (int t = 1; t <= hw; t *= 2) b->Arg(t);
  if ((hw & (hw - 1)) != 0) b->Arg(hw);
  b->Unit(benchmark::kMillisecond)->UseRealTime();
  benchmark::RegisterBenchmark("sweep/phases", bm_phases)
      ->Arg(hw)
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
