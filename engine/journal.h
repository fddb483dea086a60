#pragma once
// The per-run JSON Lines records double as a journal: each map task's records are appended and
// flushed as soon as the task finishes, so an interrupted or killed sweep loses at most the runs
// in flight. Resume and merge read journals back into the sweep's slots; the values round-trip
// exactly (doubles are written with 17 significant digits), so statistics computed from a
// resumed or merged sweep equal those of an uninterrupted one.

#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/sweep_runner.h"

namespace agv {

// Appends records, one flush per write.
class JournalWriter {
 public:
  JournalWriter() = default;
  // append = false truncates; append = true first cuts a torn last line (a record cut short by
  // a kill) so the next record starts on a line of its own.
  JournalWriter(const std::string& path, bool append);
  bool enabled() const { return out_.is_open(); }
  void write(const std::string& lines);

 private:
  std::ofstream out_;
  std::mutex mutex_;
};

struct JournalStats {
  std::int64_t records = 0;
  std::int64_t torn_lines = 0;  // a partial last line, ignored
  std::int64_t duplicates = 0;  // records of a run already restored (ignored)
};

// Restores records into a sweep's slots (shared by resume, merge and the isolated runner).
class RecordRestorer {
 public:
  RecordRestorer(const std::string& config_hash, SweepResults& results);
  // Returns false when the run was already restored (a duplicate). Throws InputError naming
  // `where` for a record of another config or of a cell, map or planner this sweep lacks.
  bool restore(const nlohmann::json& record, const std::string& where);

 private:
  std::string config_hash_;
  SweepResults& results_;
  std::map<std::string, int> cell_index_;
  std::map<std::string, std::size_t> planner_index_;
};

// Reads every record of `path` into `results` (whose plan and labels must be set). Throws
// InputError for an unreadable file, a malformed line other than a torn last one, a record of
// another config (hash mismatch) or one naming a cell, map or planner this sweep lacks.
JournalStats restore_journal(const std::string& path, const std::string& config_hash,
                             SweepResults& results);

}  // namespace agv
