#pragma once
// The sweep report: one JSON document (schema in reports/SCHEMA.md). Every value that depends on
// timing lives under a key named `timing`, the machine under `environment`; everything else is a
// pure function of the config and its seed.

#include <nlohmann/json.hpp>
#include <string>

#include "engine/sweep_results.h"

namespace agv {

inline constexpr int kReportSchemaVersion = 2;

nlohmann::json build_report(const SweepConfig& config, const SweepResults& results);

// A statistic as the report writes it: null where it is not finite (JSON has no NaN or inf).
nlohmann::json number_or_null(double v);

// The document, indented by one, written with write_file_atomic (engine/file_writes.h).
void write_json_atomic(const nlohmann::json& document, const std::string& path);

// The report without `timing` and `environment` keys at any depth: what must be byte-identical
// between runs of the same config on any thread count.
nlohmann::json deterministic_part(const nlohmann::json& report);

// A short table for the terminal: one line per planner over the whole sweep.
std::string summary_table(const SweepConfig& config, const SweepResults& results);

}  // namespace agv
