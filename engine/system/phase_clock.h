#pragma once
// Where a sweep's CPU goes besides its planners (perf/bench_sweep, perf/README.md "Planner
// throughput"): the thread CPU time of the engine's own phases, summed over every thread of the
// process. Off unless a measurement switches it on: a phase scope then costs two reads of the
// thread's CPU clock, otherwise one relaxed load. Timing only: nothing a run records depends on it.

#include <array>
#include <cstdint>

namespace agv {

enum class EnginePhase : int {
  map,        // generating (or querying) a task's map
  reference,  // the per-map references: optimal lengths (Dijkstra), the any-angle bound
  planner,    // the planners' calls (the plan_time_ns of every run)
  judge,      // after a planner returned: contract checks, validation, metrics (reference included)
  record,     // storing a finished run in its slot; a finished task's journal lines
  sinks,      // a finished map task to the sinks, under their lock: the journal's write, the
              // cell's statistics when it completes the cell (released cells), progress
  count
};

using PhaseTotals = std::array<std::int64_t, static_cast<int>(EnginePhase::count)>;

void enable_phase_clock(bool on);
bool phase_clock_enabled();
// Nanoseconds per phase since the last reset, over all threads.
PhaseTotals phase_clock_totals();
void reset_phase_clock();
// Adds `ns` to a phase (the planner phase takes the runs' own timings).
void add_phase_time(EnginePhase phase, std::int64_t ns);

// Adds the thread CPU time from construction to destruction to `phase`, when the clock is on.
class PhaseScope {
 public:
  explicit PhaseScope(EnginePhase phase);
  ~PhaseScope();
  PhaseScope(const PhaseScope&) = delete;
  PhaseScope& operator=(const PhaseScope&) = delete;

 private:
  EnginePhase phase_;
  std::int64_t start_ = -1;  // -1: the clock was off
};

}  // namespace agv
