#include "engine/outputs/database_sink.h"

#include <utility>

#include "engine/outputs/results_db.h"
#include "engine/system/environment.h"

namespace agv {

DatabaseSink::DatabaseSink(const SweepConfig& config, std::string path, std::string option,
                           const ReportSink& report)
    : config_(config), path_(std::move(path)), option_(std::move(option)), report_(report) {}

void DatabaseSink::start(const SweepStart& start) { messages_ = start.restored_messages; }

void DatabaseSink::task_done(const TaskRuns& runs) {
  for (const RecordedRun& r : runs.runs)
    if (!r.message.empty()) messages_[{runs.task, r.planner}] = r.message;
}

void DatabaseSink::finish(const SweepResults& results) {
  if (results.interrupted || !results.sink_error.empty()) return;
  experiment_id_ = append_experiment(path_, {&config_, &results, &report_.report(), &messages_,
                                             "run", environment_json(results.threads), option_});
}

}  // namespace agv
