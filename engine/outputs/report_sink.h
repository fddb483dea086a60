#pragma once
// The report as a sweep sink: made once from the final results (engine/outputs/report.h) and
// written atomically, also when the sweep was interrupted or a sink failed (then marked
// incomplete). The sinks after it may read the document it built (the SQLite database does: one
// build a sweep) when it keeps it; otherwise it writes the text one cell at a time (report_text),
// never holding the whole document.

#include <nlohmann/json.hpp>
#include <string>

#include "engine/outputs/sweep_sink.h"
#include "engine/plan/sweep_config.h"

namespace agv {

class ReportSink : public SweepSink {
 public:
  ReportSink(const SweepConfig& config, std::string path, bool keep_document);

  // Throws std::runtime_error naming the report and the OS error; when another sink failed
  // before, the message names both failures.
  void finish(const SweepResults& results) override;
  // The report finish() built when it keeps it (null otherwise).
  const nlohmann::json& report() const { return report_; }

 private:
  const SweepConfig& config_;
  std::string path_;
  bool keep_document_;
  nlohmann::json report_;
};

}  // namespace agv
