#pragma once
// The per-run JSON Lines records double as a journal: each map task's records are appended and
// flushed as soon as the task finishes, so an interrupted or killed sweep loses at most the runs
// in flight. Resume and merge read journals back into the sweep's slots; the values round-trip
// exactly (doubles in shortest round-trip form, derived metrics rebuilt bit for bit: see
// engine/outputs/run_record.h), so statistics computed from a resumed or merged sweep equal those
// of an uninterrupted one.

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/outputs/gzip_members.h"
#include "engine/outputs/journal_lines.h"
#include "engine/outputs/run_record.h"
#include "engine/outputs/sink_error.h"
#include "engine/plan/sweep_results.h"

namespace agv {

// A journal write, flush or sync that failed: the message names the journal and the OS error.
class JournalError : public SinkError {
 public:
  using SinkError::SinkError;
};

// Appends records with write(2), each write checked and retried until whole, and fsync'd at
// least every kSyncInterval and at finish(): a full disk or a file-size limit is an error
// naming the journal, never a silently shorter journal.
class JournalWriter {
 public:
  // Records between two syncs are lost only if the machine itself goes down; a killed process
  // loses nothing written. Measured on configs/quick.json (480 map tasks, 3.9 MB of records,
  // about 30 s on 2 threads, ext4): an fsync per write took about 6 ms each, 2.9 s in all under
  // the journal's lock (some 10%); once a second, about 30 fsyncs, under 1%.
  static constexpr std::chrono::milliseconds kSyncInterval{1000};

  JournalWriter() = default;
  // append = false truncates; append = true first cuts a torn tail (a record cut short by a
  // kill) so the next record starts on a line of its own. A journal is gzip-compressed, a member
  // per write (engine/outputs/gzip_members.h), when the file already is, or when it is new or empty
  // and its name ends in ".gz". Throws JournalError.
  JournalWriter(const std::string& path, bool append);
  // Writes to an open descriptor (owned from now on); `name` names it in messages.
  JournalWriter(int fd, std::string name);
  JournalWriter(const JournalWriter&) = delete;
  JournalWriter& operator=(const JournalWriter&) = delete;
  ~JournalWriter();

  bool enabled() const { return fd_ >= 0; }
  const std::string& path() const { return path_; }
  // Appends whole lines. Throws JournalError; after a failure every later write throws too (a
  // journal with a hole would restore as if the missing runs had never been run).
  void write(const std::string& lines);
  // Syncs and closes; throws JournalError. A no-op when not enabled or already finished.
  void finish();

 private:
  [[noreturn]] void fail(const std::string& doing, int error);
  void sync_locked();

  int fd_ = -1;
  std::string path_;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point last_sync_{};
  bool unsynced_ = false;
  std::string failure_;                     // the first failure, repeated by later writes
  std::unique_ptr<GzipMemberWriter> gzip_;  // a gzip journal: a member per write
};

// A run's failure message, by (map task, planner index): journals carry it, the slots do not.
using RunMessages = std::map<std::pair<std::int64_t, std::size_t>, std::string>;

struct JournalStats {
  std::int64_t records = 0;     // runs restored
  std::int64_t torn_lines = 0;  // a partial last line, ignored
  std::int64_t duplicates = 0;  // records of a run already restored (ignored)
  // Whether the file's last segment is a version 2 journal of this config (its header read):
  // a resume appends to it as it is; otherwise it first writes a header of its own.
  bool has_header = false;
  std::string sweep_id;  // that last segment's sweep ("" when none: a resume starts a segment)
};

// Restores decoded records into a sweep's slots (shared by resume, merge, export and the
// isolated runner).
class RecordRestorer {
 public:
  // Records of the results' config (its config_hash); failure messages go to `messages` when
  // given.
  explicit RecordRestorer(SweepResults& results, RunMessages* messages = nullptr);
  // Every record must have been written by agvbench `version` (a resume: this build's); without
  // it, by one version, whichever the first record names (a merge or an export). A run of one
  // version restored beside a run of another would mix two builds' results in one report.
  void require_version(std::string version) {
    version_ = std::move(version);
    version_required_ = true;
  }
  // A header checks the config; a run is stored. Returns false when the run was already
  // restored (a duplicate). Throws InputError naming `where` for a record of another config
  // (naming a changed map file where that is why) or of a cell, map or planner this sweep lacks.
  bool restore(const DecodedRecord& record, const std::string& where);
  // From now on, each cell whose every scheduled run is restored is released (its digest kept,
  // its run slots freed: engine/outputs/report.h digest_cell), so restoring a long sweep's journal
  // holds only the cells it left unfinished. A record of a released cell is then a duplicate.
  void release_complete_cells(const SweepConfig& config);

 private:
  void check_version(const DecodedRecord& record, const std::string& where);

  std::string config_hash_;
  std::string version_;  // what every record must be stamped with ("" until the first)
  bool version_required_ = false;
  SweepResults& results_;
  RunMessages* messages_;
  std::map<std::string, int> cell_index_;
  std::map<std::string, std::size_t> planner_index_;
  const SweepConfig* release_config_ = nullptr;
  std::vector<std::int64_t> missing_;  // by cell: scheduled runs not restored yet
};

// A journal's records in order, decoded (engine/outputs/run_record.h), `where` naming file and
// line.
class JournalRecordReader {
 public:
  // Throws InputError for a file that is not a regular file or cannot be read.
  explicit JournalRecordReader(const std::string& path);
  // The next record; false at the end. Throws InputError for a malformed line other than a torn
  // tail, or what the decoder refuses.
  bool next(DecodedRecord& record, std::string& where);
  // torn_lines (once next() returned false) and has_header; records and duplicates stay 0.
  const JournalStats& stats() const { return stats_; }
  // The current segment's header (nullptr before the first, and for version 1 records).
  const JournalHeader* header() const { return decoder_.header(); }

 private:
  std::string path_;
  JournalLineReader reader_;
  JournalDecoder decoder_;
  JournalStats stats_;
  std::int64_t line_no_ = 0;
};

// Calls `f(record, where)` for every record of the journal at `path` in order, `where` naming
// file and line. A torn last line (a record a kill cut short, even when it parses) is skipped and
// counted in the returned torn_lines (records stays 0). Throws InputError for an unreadable file,
// a malformed line other than a torn last one, or what the decoder refuses
// (engine/outputs/run_record.h).
JournalStats for_each_journal_record(
    const std::string& path,
    const std::function<void(const DecodedRecord&, const std::string&)>& f);

// Reads every record of `path` into `results` (empty_results of the config), and the failure
// messages into `messages` when given; with `release`, the config, each cell completed is
// released as it completes (RecordRestorer::release_complete_cells). Throws InputError for what
// for_each_journal_record refuses, a record of another config (hash mismatch; a changed map file is
// named, and so is a changed plugin), one of another agvbench version than the journal's first
// record, or one naming a cell, map or planner this sweep lacks.
JournalStats restore_journal(const std::string& path, SweepResults& results,
                             RunMessages* messages = nullptr, const SweepConfig* release = nullptr);
// restore_journal for a resume: every record must have been written by this agvbench's version
// (RecordRestorer::require_version), which the runs appended to it will be.
JournalStats restore_journal_to_resume(const std::string& path, SweepResults& results,
                                       RunMessages* messages, const SweepConfig* release);

// The same of several journals read in turn, a block of records from each (merge: the shards'
// journals of one sweep advance through its cells together, so with `release` each cell is
// released as soon as every shard's part of it is read).
void restore_journals(const std::vector<std::string>& paths, SweepResults& results,
                      const SweepConfig* release = nullptr);

}  // namespace agv
