#pragma once
// A sweep's results as rows of an SQLite database (reports/SCHEMA.md "SQLite database"), so
// they can be queried by planner, cell and metric without hand-written parsing, as OMPL's
// benchmark databases are. One database holds any number of sweeps, one experiment each; a
// database is created or appended to, never truncated.

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "engine/outputs/journal.h"
#include "engine/plan/sweep_results.h"

namespace agv {

// The database layout's version (PRAGMA user_version); bump on any change of a table or of the
// meaning of a column. The application id marks the file as agvbench's ("AGVB").
inline constexpr int kResultsDbVersion = 1;
inline constexpr std::int32_t kResultsDbApplicationId = 0x41475642;

struct ExperimentRecord {
  const SweepConfig* config = nullptr;
  const SweepResults* results = nullptr;
  const nlohmann::json* report = nullptr;  // build_report(config, results): cells and pairs
  const RunMessages* messages = nullptr;   // may be null
  std::string source;                      // "run" or "export"
  nlohmann::json environment;              // the machine that wrote the rows
  std::string option = "--sqlite";         // names the database in messages ("--db" for run)
};

// Appends the experiment in one transaction and returns its experiment_id. The sweep is named
// by its config hash and a digest of its runs (outcomes and planning times): the same sweep
// exported twice is refused with InputError naming the experiment that holds it, and nothing
// is written. Throws InputError for a file that is not an SQLite database, one of another
// application or of a newer layout; std::runtime_error (naming the database and SQLite's
// message) for a failed write, after which the database is as it was.
std::int64_t append_experiment(const std::string& db_path, const ExperimentRecord& experiment);

// Before a sweep or an export spends its time: InputError unless PATH is missing, empty, or an
// agvbench database of this layout (what append_experiment would refuse). Reads only.
void check_results_db(const std::string& path, const std::string& option);

}  // namespace agv
