#include "engine/outputs/report_sink.h"

#include <stdexcept>
#include <utility>

#include "engine/outputs/report.h"
#include "engine/system/file_writes.h"

namespace agv {

ReportSink::ReportSink(const SweepConfig& config, std::string path, bool keep_document)
    : config_(config), path_(std::move(path)), keep_document_(keep_document) {}

void ReportSink::finish(const SweepResults& results) {
  if (keep_document_) report_ = build_report(config_, results);
  try {
    if (keep_document_)
      write_json_atomic(report_, path_);
    else
      write_file_atomic(report_text(config_, results), path_);
  } catch (const std::runtime_error& e) {
    if (results.sink_error.empty()) throw;
    throw std::runtime_error(results.sink_error + "; and the report: " + e.what());
  }
}

}  // namespace agv
