#pragma once
// The journal's records (reports/SCHEMA.md "Per-run records"), version 2: a header first (the
// sweep's config hash, seed, cell and planner tables, the metric order), then per map task one
// map record (its facts and the per-map references) followed by the task's run records. A run
// record holds only what no other place fixes: its cell and planner as indices into the header's
// tables, its map index, outcome, the metrics it defines as one array (which ones: a bit mask
// over the header's metric order), planning time and phases, and a failure's message. Metrics
// that are one operation on others, the cell's edge and the map's references (path_length_m,
// min_clearance_m, smoothness_mean and the three ratios) are left out when the
// reader rebuilds them bit for bit, and written otherwise. Doubles are written in shortest
// round-trip form (integral ones without ".0"), so a resumed or merged sweep restores every value
// exactly.
//
// Version 1 journals (one self-contained record per run) are still read: JournalDecoder decodes
// both into the same DecodedRecord.

#include <bitset>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/judge/metrics.h"
#include "engine/judge/run_executor.h"
#include "engine/plan/sweep_results.h"

namespace agv {

// The header names its writer and the journal's format; readers refuse another tool or version
// (reports/SCHEMA.md, "Per-run records"). Bump on any change of a record's keys or meaning.
inline constexpr const char* kJournalTool = "agvbench";
inline constexpr int kJournalVersion = 2;
// The older format this agvbench still reads (never writes).
inline constexpr int kJournalVersionV1 = 1;
// The agvbench version a header without an "agvbench" stamp (and a version 1 journal) was
// written by: every agvbench before the stamp was 0.1.1.
inline constexpr const char* kVersionBeforeStamps = "0.1.1";

// What a journal keeps of a map: its slot and the per-map references the ratios divide by (each
// only where the runs computed it).
struct MapFacts {
  MapSlot slot;
  std::optional<double> optimal_length;    // optimality_ratio's reference
  std::optional<double> any_angle_length;  // any_angle_ratio's
  std::optional<double> scen_optimum;      // scen_ratio's
};

// The per-map references the runs of `ref` have computed so far (none is computed here).
MapFacts map_facts_of(const MapSlot& slot, const MapReference& ref);

// The metric order of a version 2 run record's bit mask: the engine's run metrics
// (kRunMetricNames), then every other metric engine/judge/metric_specs.h declares. A metric outside
// it (a plugin's) travels by name under "extra".
const std::vector<std::string>& journal_metric_names();

// What the sweep keeps of a run executed in process (an isolated worker's run is kept as its
// record decoded).
RunSlot run_slot_of(const RunOutput& run);

// The header line (newline included) of a journal of this sweep.
std::string journal_header(const std::string& config_hash, const SweepConfig& config,
                           const SweepPlan& plan, const std::string& sweep_id);

// A map record (one line, newline included).
std::string map_record(const SweepCell& cell, int map_index, const MapFacts& facts);

// A run record (one line, newline included); `planner` is the config index.
std::string run_record(const SweepCell& cell, int map_index, std::size_t planner,
                       const RunSlot& slot, const std::string& message, const MapFacts& facts);

// Sets every derived metric of `metrics` that `explicit_metrics` does not mark (bit i: run
// metric i) from the others, the cell's edge and the map's references, as the engine computes
// it (engine/judge/metrics.cpp, engine/judge/run_executor.cpp); NaN where its inputs are undefined.
void rebuild_derived_metrics(RunMetrics& metrics,
                             std::bitset<kRunMetricNames.size()> explicit_metrics,
                             const MapFacts& facts, double cell_edge);

// The header of a version 2 journal, as read back.
struct JournalHeader {
  struct Cell {
    std::string key;
    double cell_edge = 1.0;
    std::string map_file;      // a map source's cell: the file's name
    std::string content_hash;  // and its content hash; empty for a generator's cell
  };
  struct Plugin {
    std::string name;
    std::string path;
    std::string sha256;
  };
  std::string config_hash;
  std::string sweep_id;                         // engine/outputs/sweep_identity.h; "" before ids
  std::string agvbench = kVersionBeforeStamps;  // the version that wrote the segment
  std::vector<Cell> cells;
  std::vector<std::string> planners;  // labels
  std::vector<std::string> metrics;   // the mask's order
  std::vector<Plugin> plugins;        // the sweep's plugins (none in a header before the stamp)
};

// One journal line, decoded.
struct DecodedRecord {
  enum class Kind { header, map, run };
  Kind kind = Kind::run;
  int version = kJournalVersion;
  std::string config_hash;                      // the record's (version 1) or its header's
  std::string agvbench = kVersionBeforeStamps;  // the agvbench version that wrote it
  std::string sweep_id;                         // a header's sweep ("" before ids)
  std::string cell;                             // key (map and run records)
  int map_index = 0;
  std::string planner;  // label (run records)
  MapFacts map;         // map records; a version 1 run's map (slot.done when it has one)
  RunSlot run;          // run records, derived metrics rebuilt
  std::string message;  // a failed run's, if any
  // A version 1 record's map file (map source cells), for naming a changed file.
  std::string map_file_hash;
  bool has_map_file = false;
};

// Decodes one file's lines in order: version 1 records, and version 2 headers with the map and
// run records after them (a header starts a segment of its own, so concatenated journals read
// as one). Throws InputError naming `where` (file:line) for a record of another tool or
// version, a version 2 record before any header, or a malformed record.
class JournalDecoder {
 public:
  // One record line (without its newline): the one place a record's JSON is parsed, whether it
  // comes from a journal, an isolated worker's channel or a test.
  DecodedRecord decode_line(std::string_view line, const std::string& where);
  // The current segment's header (nullptr before the first).
  const JournalHeader* header() const { return header_ ? &*header_ : nullptr; }

 private:
  DecodedRecord decode(const nlohmann::json& record, const std::string& where);
  DecodedRecord decode_header(const nlohmann::json& record, const std::string& where);
  DecodedRecord decode_map(const nlohmann::json& record, const std::string& where);
  DecodedRecord decode_run(const nlohmann::json& record, const std::string& where);
  DecodedRecord decode_v1(const nlohmann::json& record, const std::string& where);

  std::optional<JournalHeader> header_;
  // The segment's map facts by (cell index of the header, map index).
  std::map<std::pair<int, int>, MapFacts> maps_;
};

}  // namespace agv
