#include "engine/journal.h"

#include <cmath>
#include <filesystem>
#include <limits>

#include "core/input_error.h"
#include "engine/run_record.h"

namespace agv {

using nlohmann::json;

JournalWriter::JournalWriter(const std::string& path, bool append) {
  if (path.empty()) return;
  namespace fs = std::filesystem;
  const fs::path p(path);
  if (p.has_parent_path()) fs::create_directories(p.parent_path());
  if (append && fs::exists(p)) {
    // Cut a torn last line: keep everything up to the last newline.
    std::ifstream in(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto last = text.rfind('\n');
    const std::uintmax_t keep = last == std::string::npos ? 0 : last + 1;
    if (keep != text.size()) fs::resize_file(p, keep);
  }
  out_.open(path, append ? std::ios::out | std::ios::app : std::ios::out | std::ios::trunc);
  if (!out_) throw InputError("cannot open journal \"" + path + "\" for writing");
}

void JournalWriter::write(const std::string& lines) {
  std::lock_guard lock(mutex_);
  out_ << lines;
  out_.flush();
}

namespace {

double number_or_nan(const json& v) {
  return v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

RecordRestorer::RecordRestorer(const std::string& config_hash, SweepResults& results)
    : config_hash_(config_hash), results_(results) {
  for (const auto& c : results.plan.cells) cell_index_[c.key] = c.index;
  for (std::size_t p = 0; p < results.labels.size(); ++p) planner_index_[results.labels[p]] = p;
}

bool RecordRestorer::restore(const json& rec, const std::string& where) {
  try {
    const json tool = rec.value("tool", json());
    const json version = rec.value("journal_version", json());
    if (tool != kJournalTool || version != kJournalVersion)
      throw InputError(where + ": not a record of this agvbench's journal format (it says tool " +
                       (tool.is_null() ? std::string("(none)") : tool.dump()) +
                       ", journal_version " +
                       (version.is_null() ? std::string("(none)") : version.dump()) +
                       "; this agvbench reads tool \"" + kJournalTool + "\", journal_version " +
                       std::to_string(kJournalVersion) + ")");
    const std::string hash = rec.at("config_hash").get<std::string>();
    if (hash != config_hash_)
      throw InputError(where + ": journal was written by a different config (hash " + hash +
                       ", this config " + config_hash_ + ")");
    const auto cell = cell_index_.find(rec.at("cell").get<std::string>());
    if (cell == cell_index_.end()) throw InputError(where + ": unknown cell");
    const auto planner = planner_index_.find(rec.at("planner").get<std::string>());
    if (planner == planner_index_.end()) throw InputError(where + ": unknown planner label");
    const int map_index = rec.at("map_index").get<int>();
    if (map_index < 0 || map_index >= results_.plan.maps_per_cell)
      throw InputError(where + ": map_index out of range");
    const std::int64_t task =
        static_cast<std::int64_t>(cell->second) * results_.plan.maps_per_cell + map_index;
    if (!results_.scheduled(task, planner->second))
      throw InputError(where + ": planner \"" + planner->first +
                       "\" is not scheduled on this map (outside its \"only\" scope)");
    RunSlot& slot = results_.run(task, planner->second);
    if (slot.done) return false;
    const auto outcome = outcome_from_string(rec.at("outcome").get<std::string>());
    if (!outcome) throw InputError(where + ": unknown outcome");
    slot.outcome = *outcome;
    slot.metrics.fill(std::numeric_limits<double>::quiet_NaN());
    slot.extra.clear();
    for (const auto& [name, value] : rec.at("metrics").items()) {
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
    slot.phases.clear();
    for (const auto& [name, ns] : timing.at("phases").items())
      slot.phases.push_back({name, ns.get<std::int64_t>()});
    slot.done = true;
    MapSlot& ms = results_.maps[static_cast<std::size_t>(task)];
    const json& map = rec.at("map");
    if (map.contains("rejections")) {
      ms.rejections = map.at("rejections").get<int>();
      ms.obstacle_fraction = map.at("obstacle_fraction").get<double>();
      ms.done = true;
    }
    return true;
  } catch (const json::exception& e) {
    throw InputError(where + ": malformed journal record (" + e.what() + ")");
  }
}

JournalStats restore_journal(const std::string& path, const std::string& config_hash,
                             SweepResults& results) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open journal");
  RecordRestorer restorer(config_hash, results);
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
    if (restorer.restore(rec, where)) {
      ++stats.records;
    } else {
      ++stats.duplicates;
    }
  }
  return stats;
}

}  // namespace agv
