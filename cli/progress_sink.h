#pragma once
// The progress display as a sweep sink: a ProgressMeter (cli/progress.h) over the runs this call
// executes, advanced as each map task's runs finish.

#include <memory>

#include "cli/progress.h"
#include "engine/outputs/sweep_sink.h"

namespace agv {

class ProgressSink : public SweepSink {
 public:
  void start(const SweepStart& start) override;
  void task_done(const TaskRuns& runs) override;
  void end_runs() override;

 private:
  std::unique_ptr<ProgressMeter> meter_;
};

}  // namespace agv
