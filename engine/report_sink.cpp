#include "engine/report_sink.h"

#include <stdexcept>
#include <utility>

#include "engine/report.h"

namespace agv {

ReportSink::ReportSink(const SweepConfig& config, std::string path)
    : config_(config), path_(std::move(path)) {}

void ReportSink::finish(const SweepResults& results) {
  report_ = build_report(config_, results);
  try {
    write_json_atomic(report_, path_);
  } catch (const std::runtime_error& e) {
    if (results.sink_error.empty()) throw;
    throw std::runtime_error(results.sink_error + "; and the report: " + e.what());
  }
}

}  // namespace agv
