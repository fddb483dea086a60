#include "engine/outputs/journal_sink.h"

namespace agv {

std::string journal_lines(const SweepPlan& plan, std::int64_t task, const MapFacts& facts,
                          const std::vector<RecordedRun>& runs) {
  const SweepCell& cell = plan.cell_of(task);
  const int map_index = plan.map_index_of(task);
  std::string lines = map_record(cell, map_index, facts);
  for (const RecordedRun& r : runs)
    lines += run_record(cell, map_index, r.planner, r.slot, r.message, facts);
  return lines;
}

JournalSink::JournalSink(const std::string& path, bool append) : writer_(path, append) {}

void JournalSink::start(const SweepStart& start) {
  plan_ = &start.results.plan;
  // A resumed journal whose last segment is this sweep's goes on as it is; a new one, an empty
  // file, a version 1 journal or a header a kill cut short gets a header of its own.
  if (!start.restored.has_header)
    writer_.write(journal_header(start.results.config_hash, start.config, start.results.plan,
                                 start.results.sweep_id));
}

void JournalSink::task_done(const TaskRuns& runs) {
  // A task an interruption cut before its first run left nothing to record.
  if (runs.runs.empty()) return;
  if (runs.journal_lines != nullptr) {
    writer_.write(*runs.journal_lines);
  } else {
    writer_.write(journal_lines(*plan_, runs.task, runs.facts, runs.runs));
  }
}

}  // namespace agv
