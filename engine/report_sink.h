#pragma once
// The report as a sweep sink: built once from the final results (engine/report.h) and written
// atomically, also when the sweep was interrupted or a sink failed (then marked incomplete). The
// sinks after it may read the report it built (the SQLite database does: one build a sweep).

#include <nlohmann/json.hpp>
#include <string>

#include "engine/sweep_config.h"
#include "engine/sweep_sink.h"

namespace agv {

class ReportSink : public SweepSink {
 public:
  ReportSink(const SweepConfig& config, std::string path);

  // Throws std::runtime_error naming the report and the OS error; when another sink failed
  // before, the message names both failures.
  void finish(const SweepResults& results) override;
  // The report finish() built (null before).
  const nlohmann::json& report() const { return report_; }

 private:
  const SweepConfig& config_;
  std::string path_;
  nlohmann::json report_;
};

}  // namespace agv
