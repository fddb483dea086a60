#pragma once
// One JSON Lines record per run: enough to replay the run (config hash, cell, seed, map index,
// planner label and parameters) and to rebuild its slot in the sweep (outcome, metrics, timing).

#include <nlohmann/json.hpp>
#include <string>

#include "engine/run_executor.h"
#include "engine/sweep_results.h"

namespace agv {

// Every record names its writer and the journal's format; resume and merge refuse a record of
// another tool or version (reports/SCHEMA.md, "Per-run records"). Bump on any change of a
// record's keys or of their meaning.
inline constexpr const char* kJournalTool = "agvbench";
inline constexpr int kJournalVersion = 1;

// What the sweep keeps of a run executed in process (an isolated worker's run is kept as its
// record decoded: engine/journal.h).
RunSlot run_slot_of(const RunOutput& run);

nlohmann::json run_record(const std::string& config_hash, std::uint64_t seed, const SweepCell& cell,
                          int map_index, const PlannerEntry& planner, const MapSlot& map,
                          const RunOutput& run);

}  // namespace agv
