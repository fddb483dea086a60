#pragma once
// The sweep report: one JSON document (schema in reports/SCHEMA.md). Every value that depends on
// timing lives under a key named `timing`, the machine under `environment`; everything else is a
// pure function of the config and its seed.

#include <nlohmann/json.hpp>
#include <string>

#include "engine/plan/sweep_results.h"

namespace agv {

inline constexpr int kReportSchemaVersion = 2;

// Cells released during the sweep enter by their digests.
nlohmann::json build_report(const SweepConfig& config, const SweepResults& results);

// json_text(build_report(...), 1) and a newline, the report file's text, made one cell at a time:
// no more than one cell's document exists at once (a released cell's from its digest).
std::string report_text(const SweepConfig& config, const SweepResults& results);

// What stays of a finished cell once its run slots are freed (engine/plan/sweep_results.h): its
// report entry, coverage and summary-table tallies, as build_report and summary_table would make
// them.
CellDigest digest_cell(const SweepConfig& config, const SweepResults& results,
                       const SweepCell& cell);

// A statistic as the report writes it: null where it is not finite (JSON has no NaN or inf).
nlohmann::json number_or_null(double v);

// The document, indented by one, written with write_file_atomic (engine/system/file_writes.h).
void write_json_atomic(const nlohmann::json& document, const std::string& path);

// The report without `timing` and `environment` keys at any depth: what must be byte-identical
// between runs of the same config on any thread count.
nlohmann::json deterministic_part(const nlohmann::json& report);

// A short table for the terminal: one line per planner over the whole sweep.
std::string summary_table(const SweepConfig& config, const SweepResults& results);

}  // namespace agv
