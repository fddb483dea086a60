#pragma once
// The journal as a sweep sink: a header when the journal starts (or a resume's file lacks this
// sweep's), then each finished map task's map record and run records as one write
// (engine/outputs/run_record.h), synced at the end of the runs (engine/outputs/journal.h
// JournalWriter).

#include <string>

#include "engine/outputs/journal.h"
#include "engine/outputs/sweep_sink.h"
#include "engine/plan/sweep_plan.h"

namespace agv {

// A map task's journal lines: its map record, then its runs' records.
std::string journal_lines(const SweepPlan& plan, std::int64_t task, const MapFacts& facts,
                          const std::vector<RecordedRun>& runs);

class JournalSink : public SweepSink {
 public:
  // append = false starts the file anew; true appends to a resumed journal. Throws JournalError.
  JournalSink(const std::string& path, bool append);

  const std::string& path() const { return writer_.path(); }
  void start(const SweepStart& start) override;
  void task_done(const TaskRuns& runs) override;
  void end_runs() override { writer_.finish(); }

 private:
  JournalWriter writer_;
  const SweepPlan* plan_ = nullptr;
};

}  // namespace agv
