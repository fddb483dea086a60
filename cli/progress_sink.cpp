#include "cli/progress_sink.h"

namespace agv {

void ProgressSink::start(const SweepStart& start) {
  meter_ = std::make_unique<ProgressMeter>(start.runs_to_do, true);
}

void ProgressSink::task_done(const TaskRuns& runs) {
  meter_->advance(static_cast<std::int64_t>(runs.runs.size()));
}

void ProgressSink::end_runs() { meter_->finish(); }

}  // namespace agv
