#pragma once
// The SQLite database as a sweep sink (`run --db`, engine/outputs/results_db.h): the finished sweep
// is appended as one experiment, with the failure messages of its runs (gathered as the runs
// finish, and from the journal a resume restored) and the report the report sink built. An
// interrupted sweep, or one a sink failed, is not appended: its resume is (the same runs and more).

#include <cstdint>
#include <optional>
#include <string>

#include "engine/outputs/journal.h"
#include "engine/outputs/report_sink.h"
#include "engine/outputs/sweep_sink.h"

namespace agv {

class DatabaseSink : public SweepSink {
 public:
  // `report` comes before this sink in the list; `option` names the database in messages.
  DatabaseSink(const SweepConfig& config, std::string path, std::string option,
               const ReportSink& report);

  void start(const SweepStart& start) override;
  void task_done(const TaskRuns& runs) override;
  // Throws what append_experiment throws (engine/outputs/results_db.h).
  void finish(const SweepResults& results) override;
  // The experiment appended by finish(), if it was.
  std::optional<std::int64_t> experiment_id() const { return experiment_id_; }

 private:
  const SweepConfig& config_;
  std::string path_;
  std::string option_;
  const ReportSink& report_;
  RunMessages messages_;
  std::optional<std::int64_t> experiment_id_;
};

}  // namespace agv
