#include "engine/journal.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/input_error.h"
#include "core/json_text.h"
#include "core/text_file.h"
#include "engine/run_record.h"

namespace agv {

using nlohmann::json;

JournalWriter::JournalWriter(const std::string& path, bool append) : path_(path) {
  if (path.empty()) return;
  namespace fs = std::filesystem;
  if (append) {
    // Cut a torn last line: keep everything up to the last newline.
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(path, ec);
    if (!ec && size > 0) {
      std::ifstream in(path, std::ios::binary);
      const std::string text((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
      const auto last = text.rfind('\n');
      const std::uintmax_t keep = last == std::string::npos ? 0 : last + 1;
      if (keep != text.size()) {
        fs::resize_file(path, keep, ec);
        if (ec) fail("cannot cut its torn last line", ec.value());
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
  std::size_t done = 0;
  while (done < lines.size()) {
    const ssize_t n = ::write(fd_, lines.data() + done, lines.size() - done);
    if (n < 0 && errno == EINTR) continue;
    // A zero-byte write of a non-empty buffer makes no progress: treated as a full disk.
    if (n <= 0)
      fail("write failed after " + std::to_string(done) + " of " + std::to_string(lines.size()) +
               " bytes",
           n < 0 ? errno : ENOSPC);
    done += static_cast<std::size_t>(n);
  }
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

namespace {

double number_or_nan(const json& v) {
  return v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

RecordRestorer::RecordRestorer(SweepResults& results)
    : config_hash_(results.config_hash), results_(results) {
  for (const auto& c : results.plan.cells) cell_index_[c.key] = c.index;
  for (std::size_t p = 0; p < results.labels.size(); ++p) planner_index_[results.labels[p]] = p;
}

bool RecordRestorer::restore(const json& rec, const std::string& where) {
  try {
    const json tool = rec.value("tool", json());
    const json version = rec.value("journal_version", json());
    if (tool != kJournalTool || version != kJournalVersion)
      throw InputError(where + ": not a record of this agvbench's journal format (it says tool " +
                       (tool.is_null() ? std::string("(none)") : json_text(tool)) +
                       ", journal_version " +
                       (version.is_null() ? std::string("(none)") : json_text(version)) +
                       "; this agvbench reads tool \"" + kJournalTool + "\", journal_version " +
                       std::to_string(kJournalVersion) + ")");
    const std::string hash = rec.at("config_hash").get<std::string>();
    if (hash != config_hash_) refuse_changed_map_file(rec, where);
    if (hash != config_hash_)
      throw InputError(where + ": journal was written by a different config (hash " + hash +
                       ", this config " + config_hash_ + ")");
    const auto cell = cell_index_.find(rec.at("cell").get<std::string>());
    if (cell == cell_index_.end()) throw InputError(where + ": unknown cell");
    const auto planner = planner_index_.find(rec.at("planner").get<std::string>());
    if (planner == planner_index_.end()) throw InputError(where + ": unknown planner label");
    const int map_index = rec.at("map_index").get<int>();
    const SweepCell& sweep_cell = results_.plan.cells[static_cast<std::size_t>(cell->second)];
    if (map_index < 0 || map_index >= sweep_cell.maps)
      throw InputError(where + ": map_index out of range");
    const std::int64_t task = results_.plan.task_of(sweep_cell, map_index);
    if (!results_.scheduled(task, planner->second))
      throw InputError(where + ": planner \"" + planner->first +
                       "\" is not scheduled on this map (outside its \"only\" scope)");
    if (results_.run(task, planner->second).done) return false;
    results_.store(task, planner->second, slot_of_record(rec, where), map_slot_of_record(rec));
    return true;
  } catch (const json::exception& e) {
    throw InputError(where + ": malformed journal record (" + e.what() + ")");
  }
}

RunSlot RecordRestorer::slot_of_record(const json& rec, const std::string& where) {
  RunSlot slot;
  const auto outcome = outcome_from_string(rec.at("outcome").get<std::string>());
  if (!outcome) throw InputError(where + ": unknown outcome");
  slot.outcome = *outcome;
  slot.metrics.fill(std::numeric_limits<double>::quiet_NaN());
  // This engine writes every one of its metrics, null where undefined: a record without one was
  // written by an agvbench that measures others (the journal format alone does not say), and
  // mixing its values in would report two definitions under one name.
  const json& metrics = rec.at("metrics");
  for (const auto name : kRunMetricNames)
    if (!metrics.contains(name))
      throw InputError(where + ": no metric \"" + std::string(name) +
                       "\": written by an agvbench that measures other metrics than this one "
                       "(which writes each of its " +
                       std::to_string(kRunMetricNames.size()) +
                       " on every record, null when undefined); start a new journal");
  for (const auto& [name, value] : metrics.items()) {
    bool known = false;
    for (std::size_t i = 0; i < kRunMetricNames.size(); ++i) {
      if (kRunMetricNames[i] == name) {
        slot.metrics[i] = number_or_nan(value);
        known = true;
      }
    }
    if (!known) slot.extra.emplace_back(name, number_or_nan(value));
  }
  const json& timing = rec.at("timing");
  slot.plan_time_ns = timing.at("plan_time_ns").get<std::int64_t>();
  for (const auto& [name, ns] : timing.at("phases").items())
    slot.phases.push_back({name, ns.get<std::int64_t>()});
  return slot;
}

MapSlot RecordRestorer::map_slot_of_record(const json& rec) {
  MapSlot ms;
  const json& map = rec.at("map");
  if (map.contains("rejections")) {
    ms.rejections = map.at("rejections").get<int>();
    ms.obstacle_fraction = map.at("obstacle_fraction").get<double>();
    ms.done = true;
  }
  return ms;
}

void RecordRestorer::refuse_changed_map_file(const json& rec, const std::string& where) const {
  if (!rec.is_object() || !rec.contains("map_file") || !rec.at("map_file").is_object()) return;
  const auto c = cell_index_.find(rec.value("cell", std::string()));
  if (c == cell_index_.end()) return;
  const SweepCell& now = results_.plan.cells[static_cast<std::size_t>(c->second)];
  const std::string then = rec.at("map_file").value("content_hash", std::string());
  if (now.file != nullptr && then != now.file->content_hash)
    throw InputError(where + ": map file " + now.file->path +
                     " changed since the journal was written (content hash " + then + " then, " +
                     now.file->content_hash +
                     " now): a changed map file is another sweep; start a new journal");
}

JournalStats restore_journal(const std::string& path, SweepResults& results) {
  const std::string& config_hash = results.config_hash;
  require_regular_file(path, "journal");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("journal \"" + path + "\": " + std::strerror(errno));
  RecordRestorer restorer(results);
  JournalStats stats;
  std::string line;
  std::int64_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    // A last line without its newline was cut by a kill even when it parses. The writer cuts
    // the journal back to its last newline, so its run must not count as restored (it would
    // then be missing from the journal): it is run again.
    if (in.eof()) {
      if (!line.empty()) ++stats.torn_lines;
      break;
    }
    if (line.empty()) continue;
    const std::string where = path + ":" + std::to_string(line_no);
    // Records are written whole, newline included: a complete line that does not parse is a
    // damaged journal, not a kill's doing.
    json rec = json::parse(line, nullptr, false);
    if (rec.is_discarded() || !rec.is_object())
      throw InputError(where + ": malformed journal record");
    try {
      if (restorer.restore(rec, where)) {
        ++stats.records;
      } else {
        ++stats.duplicates;
      }
    } catch (const InputError&) {
      // A journal of another config: when a map file changed, name it, whichever record of the
      // journal belongs to its cell.
      if (rec.value("config_hash", json()) == json(config_hash)) throw;
      std::int64_t later_no = line_no;
      while (std::getline(in, line)) {
        ++later_no;
        const json later = json::parse(line, nullptr, false);
        restorer.refuse_changed_map_file(later, path + ":" + std::to_string(later_no));
      }
      throw;
    }
  }
  return stats;
}

}  // namespace agv
