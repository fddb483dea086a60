#include "engine/outputs/journal.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/input_error.h"
#include "core/json_text.h"
#include "core/text_file.h"
#include "core/version.h"
#include "engine/outputs/journal_lines.h"
#include "engine/outputs/report.h"
#include "engine/outputs/run_record.h"
#include "engine/plan/plugins.h"
#include "engine/system/file_writes.h"

namespace agv {

using nlohmann::json;

JournalWriter::JournalWriter(const std::string& path, bool append) : path_(path) {
  if (path.empty()) return;
  namespace fs = std::filesystem;
  if (journal_is_gzip(path)) gzip_ = std::make_unique<GzipMemberWriter>();
  if (append) {
    // Cut a torn tail (a line without its newline, a gzip member cut short): keep every whole
    // line or member.
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(path, ec);
    if (!ec && size > 0) {
      JournalLineReader reader(path);
      std::string line;
      while (reader.next(line)) {
      }
      if (reader.intact_bytes() != size) {
        fs::resize_file(path, reader.intact_bytes(), ec);
        if (ec) fail("cannot cut its torn tail", ec.value());
      }
    }
  }
  const int flags = O_WRONLY | O_CREAT | O_CLOEXEC | (append ? O_APPEND : O_TRUNC);
  fd_ = ::open(path.c_str(), flags, 0644);
  if (fd_ < 0) fail("cannot open it for writing", errno);
  last_sync_ = std::chrono::steady_clock::now();
}

JournalWriter::JournalWriter(int fd, std::string name) : fd_(fd), path_(std::move(name)) {
  last_sync_ = std::chrono::steady_clock::now();
}

JournalWriter::~JournalWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void JournalWriter::fail(const std::string& doing, int error) {
  failure_ = "journal \"" + path_ + "\": " + doing + ": " + std::strerror(error);
  throw JournalError(failure_);
}

void JournalWriter::sync_locked() {
  if (::fsync(fd_) != 0) fail("fsync failed", errno);
  unsynced_ = false;
  last_sync_ = std::chrono::steady_clock::now();
}

void JournalWriter::write(const std::string& lines) {
  std::lock_guard lock(mutex_);
  if (!failure_.empty()) throw JournalError(failure_);
  const std::string member = gzip_ ? gzip_->member(lines) : std::string();
  const std::string_view bytes = gzip_ ? std::string_view(member) : std::string_view(lines);
  std::size_t done = 0;
  if (const int error = write_whole(fd_, bytes, done); error != 0)
    fail("write failed after " + std::to_string(done) + " of " + std::to_string(bytes.size()) +
             " bytes",
         error);
  unsynced_ = true;
  if (std::chrono::steady_clock::now() - last_sync_ >= kSyncInterval) sync_locked();
}

void JournalWriter::finish() {
  std::lock_guard lock(mutex_);
  if (fd_ < 0) return;
  if (!failure_.empty()) throw JournalError(failure_);
  if (unsynced_) sync_locked();
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("close failed", errno);
}

RecordRestorer::RecordRestorer(SweepResults& results, RunMessages* messages)
    : config_hash_(results.config_hash), results_(results), messages_(messages) {
  for (const auto& c : results.plan.cells) cell_index_[c.key] = c.index;
  for (std::size_t p = 0; p < results.labels.size(); ++p) planner_index_[results.labels[p]] = p;
}

void RecordRestorer::check_version(const DecodedRecord& rec, const std::string& where) {
  if (version_.empty()) version_ = rec.agvbench;
  if (rec.agvbench == version_) return;
  throw InputError(
      where + ": written by agvbench " + rec.agvbench + ", " +
      (version_required_ ? "this is agvbench " + version_ + ": resuming"
                         : "an earlier record by agvbench " + version_ + ": restoring both") +
      " would mix two versions' runs in one report (their results may differ); " +
      (version_required_
           ? "finish the sweep with agvbench " + rec.agvbench + ", or start a new journal"
           : "give journals of one version"));
}

bool RecordRestorer::restore(const DecodedRecord& rec, const std::string& where) {
  // A version 2 segment's records are its header's; a version 1 record stands alone.
  if (rec.kind == DecodedRecord::Kind::header || rec.version == kJournalVersionV1)
    check_version(rec, where);
  if (rec.kind == DecodedRecord::Kind::map) return true;
  if (rec.config_hash != config_hash_)
    throw InputError(where + ": journal was written by a different config (hash " +
                     rec.config_hash + ", this config " + config_hash_ + ")");
  if (rec.kind == DecodedRecord::Kind::header) {
    results_.add_sweep(rec.sweep_id);
    return true;
  }
  const auto cell = cell_index_.find(rec.cell);
  if (cell == cell_index_.end()) throw InputError(where + ": unknown cell");
  const auto planner = planner_index_.find(rec.planner);
  if (planner == planner_index_.end()) throw InputError(where + ": unknown planner label");
  const SweepCell& sweep_cell = results_.plan.cells[static_cast<std::size_t>(cell->second)];
  if (rec.map_index < 0 || rec.map_index >= sweep_cell.maps)
    throw InputError(where + ": map_index out of range");
  const std::int64_t task = results_.plan.task_of(sweep_cell, rec.map_index);
  if (!results_.scheduled(task, planner->second))
    throw InputError(where + ": planner \"" + planner->first +
                     "\" is not scheduled on this map (outside its \"only\" scope)");
  if (results_.released(sweep_cell) || results_.run(task, planner->second).done) return false;
  results_.store(task, planner->second, rec.run, rec.map.slot);
  if (messages_ != nullptr && !rec.message.empty())
    messages_->emplace(std::make_pair(task, planner->second), rec.message);
  if (release_config_ != nullptr && --missing_[static_cast<std::size_t>(sweep_cell.index)] == 0)
    results_.release(sweep_cell, digest_cell(*release_config_, results_, sweep_cell));
  return true;
}

void RecordRestorer::release_complete_cells(const SweepConfig& config) {
  release_config_ = &config;
  missing_.assign(results_.plan.cells.size(), 0);
  for (const auto& cell : results_.plan.cells) {
    const Coverage c = cell_coverage_of(results_, cell);
    missing_[static_cast<std::size_t>(cell.index)] = c.runs_expected - c.runs_present;
  }
}

JournalRecordReader::JournalRecordReader(const std::string& path)
    : path_((require_regular_file(path, "journal"), path)), reader_(path) {}

bool JournalRecordReader::next(DecodedRecord& record, std::string& where) {
  std::string line;
  while (reader_.next(line)) {
    ++line_no_;
    if (line.empty()) continue;
    where = path_ + ":" + std::to_string(line_no_);
    // Records are written whole, newline included: a complete line that does not parse is a
    // damaged journal, not a kill's doing.
    record = decoder_.decode_line(line, where);
    // A segment from before sweep ids is not continued: a resume gives its runs a header with
    // their sweep's id.
    if (record.kind == DecodedRecord::Kind::header) {
      stats_.has_header = !record.sweep_id.empty();
      stats_.sweep_id = record.sweep_id;
    } else if (record.version == kJournalVersionV1) {
      stats_.has_header = false;
      stats_.sweep_id.clear();
    }
    return true;
  }
  // A torn tail (a last line without its newline, a gzip member cut short) was cut by a kill
  // even when it parses. The writer cuts the journal back before it, so its runs must not count
  // as restored (they would then be missing from the journal): they are run again.
  if (reader_.torn()) stats_.torn_lines = 1;
  return false;
}

JournalStats for_each_journal_record(
    const std::string& path,
    const std::function<void(const DecodedRecord&, const std::string&)>& f) {
  JournalRecordReader reader(path);
  DecodedRecord record;
  std::string where;
  while (reader.next(record, where)) f(record, where);
  return reader.stats();
}

namespace {

// A header's plugins against those loaded now (by name: a name is one plugin in a process).
void check_plugins(const JournalHeader& then, const std::string& where) {
  const std::vector<PluginRecord> now = loaded_plugins();
  for (const auto& p : then.plugins) {
    const auto same = std::find_if(now.begin(), now.end(),
                                   [&p](const PluginRecord& n) { return n.name == p.name; });
    if (same == now.end())
      throw InputError(where + ": plugin \"" + p.name + "\" (" + p.path +
                       ") was loaded by the journal's sweep and is not now: another sweep; start "
                       "a new journal");
    if (same->sha256 != p.sha256)
      throw InputError(where + ": plugin \"" + p.name + "\" (" + same->path +
                       ") changed since the journal was written (sha256 " + p.sha256 + " then, " +
                       same->sha256 +
                       " now): a changed plugin is another sweep; start a new "
                       "journal");
  }
}

// A journal of another config: when a map file or a plugin changed, its message names the file
// (a changed map file or plugin is another config), whichever record of the journal belongs to
// its cell.
void refuse_changed_inputs(const std::string& path, const SweepResults& results) {
  std::map<std::string, const SweepCell*> cells;
  for (const auto& c : results.plan.cells) cells[c.key] = &c;
  const auto check = [&cells](const std::string& key, const std::string& then,
                              const std::string& where) {
    const auto c = cells.find(key);
    if (c == cells.end() || c->second->file == nullptr) return;
    const std::string& now = c->second->file->content_hash;
    if (then != now)
      throw InputError(where + ": map file " + c->second->file->path +
                       " changed since the journal was written (content hash " + then + " then, " +
                       now +
                       " now): a changed map file is another sweep; start a "
                       "new journal");
  };
  try {
    JournalDecoder decoder;
    JournalLineReader reader(path);
    std::string line;
    std::int64_t line_no = 0;
    while (reader.next(line)) {
      ++line_no;
      const std::string where = path + ":" + std::to_string(line_no);
      const DecodedRecord d = decoder.decode_line(line, where);
      if (d.kind == DecodedRecord::Kind::header) {
        for (const auto& c : decoder.header()->cells)
          if (!c.content_hash.empty()) check(c.key, c.content_hash, where);
        check_plugins(*decoder.header(), where);
      } else if (d.has_map_file) {
        check(d.cell, d.map_file_hash, where);
      }
    }
  } catch (const InputError& e) {
    const std::string why = e.what();
    if (why.find("changed since the journal was written") != std::string::npos ||
        why.find("was loaded by the journal's sweep") != std::string::npos)
      throw;
    // Anything else the first reading reports itself.
  }
}

JournalStats restore_with(RecordRestorer& restorer, const std::string& path,
                          SweepResults& results) {
  JournalStats restored;
  try {
    JournalStats stats =
        for_each_journal_record(path, [&](const DecodedRecord& rec, const std::string& where) {
          if (rec.kind != DecodedRecord::Kind::run) {
            restorer.restore(rec, where);
          } else if (restorer.restore(rec, where)) {
            ++restored.records;
          } else {
            ++restored.duplicates;
          }
        });
    stats.records = restored.records;
    stats.duplicates = restored.duplicates;
    return stats;
  } catch (const InputError& e) {
    if (std::string(e.what()).find("written by a different config") != std::string::npos)
      refuse_changed_inputs(path, results);
    throw;
  }
}

}  // namespace

JournalStats restore_journal(const std::string& path, SweepResults& results, RunMessages* messages,
                             const SweepConfig* release) {
  RecordRestorer restorer(results, messages);
  if (release != nullptr) restorer.release_complete_cells(*release);
  return restore_with(restorer, path, results);
}

JournalStats restore_journal_to_resume(const std::string& path, SweepResults& results,
                                       RunMessages* messages, const SweepConfig* release) {
  RecordRestorer restorer(results, messages);
  restorer.require_version(AGVBENCH_VERSION);
  if (release != nullptr) restorer.release_complete_cells(*release);
  return restore_with(restorer, path, results);
}

void restore_journals(const std::vector<std::string>& paths, SweepResults& results,
                      const SweepConfig* release) {
  RecordRestorer restorer(results);
  if (release != nullptr) restorer.release_complete_cells(*release);
  std::vector<std::unique_ptr<JournalRecordReader>> readers;
  for (const auto& path : paths) readers.push_back(std::make_unique<JournalRecordReader>(path));
  // A block of records from each journal in turn: the journals of a sharded sweep advance
  // through the cells together, so each cell completes, and is released, while the rest are
  // still being read (one after the other, every cell would wait for the last shard).
  constexpr int kBlock = 256;
  DecodedRecord record;
  std::string where;
  for (std::size_t open = readers.size(); open > 0;) {
    for (std::size_t i = 0; i < readers.size(); ++i) {
      if (!readers[i]) continue;
      try {
        int n = 0;
        while (n < kBlock && readers[i]->next(record, where)) {
          restorer.restore(record, where);
          ++n;
        }
        if (n < kBlock) {
          readers[i].reset();
          --open;
        }
      } catch (const InputError& e) {
        if (std::string(e.what()).find("written by a different config") != std::string::npos)
          refuse_changed_inputs(paths[i], results);
        throw;
      }
    }
  }
}

}  // namespace agv
