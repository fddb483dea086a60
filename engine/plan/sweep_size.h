#pragma once
// How much memory a sweep's results hold while it runs, estimated from the config alone, and the
// refusal of a config whose results would not fit (engine/plan/config_loader.h checks every
// config).

#include <string>

#include "engine/plan/sweep_config.h"

namespace agv {

// What a sweep holds in memory while it runs (engine/plan/sweep_results.h): its cells, a map slot
// and a to-do entry per map task, and either (bytes_kept: run --db, merge, export) a run slot per
// map task and planner, scheduled or not, with the phase times and extra metrics each run leaves in
// it, or (bytes: `run`, which releases finished cells) the slots of the cells in flight and what
// a released cell keeps of each run. Counted from the config alone, without expanding the plan,
// so a config too large to plan is refused as well.
struct SweepSize {
  double cells = 0;  // doubles: a hostile config's products must not overflow
  double map_tasks = 0;
  double run_slots = 0;
  double scheduled_runs = 0;
  double bytes = 0;       // estimate, finished cells released
  double bytes_kept = 0;  // estimate, every run's slot kept to the end
};
SweepSize sweep_size(const SweepConfig& config);
// The memory a sweep of this process can have: physical memory, the cgroup's memory.max, or what
// the address-space limit (RLIMIT_AS, `ulimit -v`) leaves above what is mapped already, whichever
// is lowest; 0 bytes when none is known. `source` says which, for messages.
struct UsableMemory {
  double bytes = 0.0;
  std::string source;  // "this machine has", "the container's memory.max is", ...
};
UsableMemory usable_memory();
// InputError naming maps_per_cell when the estimate exceeds half of usable_memory() (the
// rest is headroom: the maps, planner scratch and the report being built).
// every_slot_kept: judge bytes_kept (run --db, merge, export), else bytes (the loader, for every
// config).
void check_sweep_size(const SweepConfig& config, bool every_slot_kept = false);
// "1.5 GiB"
std::string bytes_text(double bytes);

}  // namespace agv
