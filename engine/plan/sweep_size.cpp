#include "engine/plan/sweep_size.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <set>
#include <string>
#include <thread>

#include "core/input_error.h"
#include "engine/plan/sweep_results.h"

namespace agv {

namespace {

// What a finished run holds beyond its slots: the phase times and extra metrics in its RunSlot
// (40 bytes each, plus the allocator's header) and its share of the report's statistics inputs.
// Measured (maximum resident set of `agvbench run`, 2,000 against 200,000 maps of astar on
// 16x16, one thread): 461 bytes more per run, of which the slots' sizeof is 192 (RunSlot 168,
// MapSlot and the to-do entry 24); the rest, about 270, is rounded up here for planners with
// more phases or extra metrics.
constexpr double kRunHeapBytes = 320.0;
// A SweepCell with its key and the map spec's parameters on the heap.
constexpr double kCellBytes = sizeof(SweepCell) + 256.0;
// A map task's MapSlot and its entry in the to-do list.
constexpr double kMapTaskBytes = sizeof(MapSlot) + sizeof(std::int64_t);
// What a released cell keeps of each run to the end (engine/outputs/report.h digest_cell): the
// summary tallies (planning time; the path lengths paired with the baseline's) and its share of the
// report entry. Measured (perf/README.md "Ten million runs"): 57 bytes a run at the peak of a
// 10,000,000-run sweep, map slots included; rounded up.
constexpr double kReleasedRunBytes = 64.0;
// Above this share of the memory the sweep is refused: the rest is for the maps, the planners'
// scratch, the report being built and whatever else the machine runs.
constexpr double kMemoryShare = 0.5;

}  // namespace

SweepSize sweep_size(const SweepConfig& config) {
  SweepSize size;
  // Map sources: a cell per file, a map per query (scen) or maps_per_cell; counted apart, and
  // every planner counted on all of their maps (an upper bound under "only" scopes).
  double generated = 0.0, file_cells = 0.0, file_maps = 0.0;
  double largest_cell = config.maps_per_cell;  // maps
  for (const auto& g : config.generators) {
    if (!g.files) {
      ++generated;
      continue;
    }
    for (const auto& f : g.files->files) {
      ++file_cells;
      const double maps = g.files->queries == QuerySource::scen
                              ? static_cast<double>(f.queries.size())
                              : config.maps_per_cell;
      file_maps += maps;
      largest_cell = std::max(largest_cell, maps);
    }
  }
  size.cells = generated * static_cast<double>(config.sizes.size()) *
               static_cast<double>(config.densities.size());
  size.map_tasks = size.cells * config.maps_per_cell + file_maps;
  size.scheduled_runs = file_maps * static_cast<double>(config.planners.size());
  size.cells += file_cells;
  size.run_slots = size.map_tasks * static_cast<double>(config.planners.size());
  // A scoped planner runs on the cells its lists leave (each a subset of the sweep's axis, so
  // their product) and on the first maps of each, as scoped_maps counts them.
  const auto listed = [](const auto& only, std::size_t all) {
    return only.empty() ? static_cast<double>(all)
                        : static_cast<double>(std::set(only.begin(), only.end()).size());
  };
  for (const auto& p : config.planners) {
    const int maps = p.only.maps_in(config.maps_per_cell);
    size.scheduled_runs += listed(p.only.generators, static_cast<std::size_t>(generated)) *
                           listed(p.only.sizes, config.sizes.size()) *
                           listed(p.only.densities, config.densities.size()) * maps;
  }
  const double per_map = size.cells * kCellBytes + size.map_tasks * kMapTaskBytes;
  const double slot_bytes = static_cast<double>(sizeof(RunSlot));
  size.bytes_kept = per_map + size.run_slots * slot_bytes + size.scheduled_runs * kRunHeapBytes;
  // Released cells: the slots of the cells in flight (one a thread and one more finishing), the
  // largest cell's each, and what every released cell keeps of its runs.
  const unsigned hardware = std::max(1U, std::thread::hardware_concurrency());
  const double threads = config.threads > 0 ? config.threads : hardware;
  const double in_flight = std::min(size.cells, threads + 1.0);
  const double planners = static_cast<double>(config.planners.size());
  size.bytes = per_map + in_flight * largest_cell * planners * (slot_bytes + kRunHeapBytes) +
               size.scheduled_runs * kReleasedRunBytes;
  size.bytes = std::min(size.bytes, size.bytes_kept);
  return size;
}

namespace {

// The address space this process has mapped already (/proc/self/statm's first field).
double mapped_bytes(double page_size) {
  std::ifstream statm("/proc/self/statm");
  double pages = 0.0;
  return statm >> pages ? pages * page_size : 0.0;
}

}  // namespace

UsableMemory usable_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  UsableMemory m;
  m.source = "this machine has";
  if (pages > 0 && page_size > 0)
    m.bytes = static_cast<double>(pages) * static_cast<double>(page_size);
  const auto lower = [&m](double limit, const char* source) {
    if (limit > 0 && (m.bytes == 0.0 || limit < m.bytes)) m = {limit, source};
  };
  // A container's limit (cgroup v2); "max" when there is none.
  std::ifstream cgroup("/sys/fs/cgroup/memory.max");
  double limit = 0.0;
  if (cgroup >> limit) lower(limit, "the container's memory.max is");
  // Past RLIMIT_AS an allocation throws bad_alloc mid-sweep: the estimate must see it first.
  struct rlimit as {};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY && page_size > 0) {
    const double left =
        static_cast<double>(as.rlim_cur) - mapped_bytes(static_cast<double>(page_size));
    lower(std::max(left, 1.0), "the address-space limit (ulimit -v) leaves");
  }
  return m;
}

std::string bytes_text(double bytes) {
  static constexpr const char* kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  std::size_t unit = 0;
  while (bytes >= 1024.0 && unit + 1 < std::size(kUnits)) {
    bytes /= 1024.0;
    ++unit;
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g %s", bytes, kUnits[unit]);
  return buf;
}

void check_sweep_size(const SweepConfig& config, bool every_slot_kept) {
  const SweepSize size = sweep_size(config);
  const double bytes = every_slot_kept ? size.bytes_kept : size.bytes;
  const UsableMemory memory = usable_memory();
  if (memory.bytes <= 0.0 || bytes <= kMemoryShare * memory.bytes) return;
  char counts[160];
  std::snprintf(counts, sizeof counts,
                " maps in each of %.0f cells for %zu planners make %.4g run slots, about ",
                size.cells, config.planners.size(), size.run_slots);
  throw InputError("maps_per_cell: " + std::to_string(config.maps_per_cell) + counts +
                   bytes_text(bytes) + " held while the sweep runs" +
                   (every_slot_kept ? " (every run's slot kept to the end)" : "") + "; " +
                   memory.source + " " + bytes_text(memory.bytes) +
                   " and a sweep may use half of it: lower maps_per_cell (or "
                   "the number of sizes, densities, generators or planners)");
}

}  // namespace agv
