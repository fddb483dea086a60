#include "engine/outputs/results_db.h"

#include <sqlite3.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "core/input_error.h"
#include "core/json_text.h"
#include "core/rng.h"
#include "engine/outputs/journal.h"
#include "engine/outputs/report.h"
#include "engine/outputs/run_record.h"

namespace agv {

using nlohmann::json;

namespace {

// The layout (reports/SCHEMA.md "SQLite database"). Metrics are rows of a narrow table, not
// columns: the metric set is open (every planner may report extras, and plugins add planners),
// a column per metric would change the layout whenever a planner gains one and leave most cells
// NULL, and `metric` as a column is what lets one query group or filter by metric. The view
// run_values gives the common per-run columns joined with their names.
constexpr const char* kSchemaSql = R"sql(
CREATE TABLE IF NOT EXISTS experiments (
  experiment_id INTEGER PRIMARY KEY,
  name TEXT NOT NULL,
  config_hash TEXT NOT NULL,
  runs_digest TEXT NOT NULL,
  config_json TEXT NOT NULL,
  environment_json TEXT NOT NULL,
  created_utc TEXT NOT NULL,
  source TEXT NOT NULL CHECK (source IN ('run', 'export')),
  report_schema_version INTEGER NOT NULL,
  journal_version INTEGER NOT NULL,
  seed INTEGER NOT NULL,
  baseline TEXT NOT NULL,
  maps_per_cell INTEGER NOT NULL,
  time_limit_s REAL NOT NULL,
  complete INTEGER NOT NULL,
  runs_expected INTEGER NOT NULL,
  runs_present INTEGER NOT NULL,
  UNIQUE (config_hash, runs_digest)
);
CREATE TABLE IF NOT EXISTS planners (
  experiment_id INTEGER NOT NULL REFERENCES experiments (experiment_id),
  planner_id INTEGER NOT NULL,
  label TEXT NOT NULL,
  name TEXT NOT NULL,
  params_json TEXT NOT NULL,
  is_baseline INTEGER NOT NULL,
  PRIMARY KEY (experiment_id, planner_id),
  UNIQUE (experiment_id, label)
);
CREATE TABLE IF NOT EXISTS cells (
  experiment_id INTEGER NOT NULL REFERENCES experiments (experiment_id),
  cell_id INTEGER NOT NULL,
  cell TEXT NOT NULL,
  generator TEXT NOT NULL,
  width INTEGER NOT NULL,
  height INTEGER NOT NULL,
  density REAL NOT NULL,
  maps INTEGER NOT NULL,
  rejections INTEGER NOT NULL,
  PRIMARY KEY (experiment_id, cell_id),
  UNIQUE (experiment_id, cell)
);
CREATE TABLE IF NOT EXISTS runs (
  run_id INTEGER PRIMARY KEY,
  experiment_id INTEGER NOT NULL REFERENCES experiments (experiment_id),
  cell_id INTEGER NOT NULL,
  planner_id INTEGER NOT NULL,
  map_index INTEGER NOT NULL,
  task_id TEXT NOT NULL,
  outcome TEXT NOT NULL,
  message TEXT,
  plan_time_ns INTEGER NOT NULL,
  obstacle_fraction REAL,
  UNIQUE (experiment_id, cell_id, planner_id, map_index)
);
CREATE INDEX IF NOT EXISTS runs_by_planner ON runs (experiment_id, planner_id, cell_id);
CREATE TABLE IF NOT EXISTS run_metrics (
  run_id INTEGER NOT NULL REFERENCES runs (run_id),
  metric TEXT NOT NULL,
  value REAL NOT NULL,
  PRIMARY KEY (run_id, metric)
) WITHOUT ROWID;
CREATE INDEX IF NOT EXISTS run_metrics_by_metric ON run_metrics (metric, run_id);
CREATE TABLE IF NOT EXISTS run_phases (
  run_id INTEGER NOT NULL REFERENCES runs (run_id),
  phase TEXT NOT NULL,
  ns INTEGER NOT NULL,
  PRIMARY KEY (run_id, phase)
) WITHOUT ROWID;
CREATE TABLE IF NOT EXISTS paired (
  experiment_id INTEGER NOT NULL REFERENCES experiments (experiment_id),
  cell_id INTEGER NOT NULL,
  planner_id INTEGER NOT NULL,
  baseline_id INTEGER NOT NULL,
  metric TEXT NOT NULL,
  timing INTEGER NOT NULL,
  pairs INTEGER NOT NULL,
  better TEXT NOT NULL,
  wins INTEGER NOT NULL,
  ties INTEGER NOT NULL,
  losses INTEGER NOT NULL,
  ratio TEXT NOT NULL,
  geo_mean_ratio REAL,
  ci95_lo REAL,
  ci95_hi REAL,
  ratios_excluded INTEGER NOT NULL,
  mean_difference REAL,
  difference_ci95_lo REAL,
  difference_ci95_hi REAL,
  wilcoxon_p REAL,
  wilcoxon_exact INTEGER NOT NULL,
  PRIMARY KEY (experiment_id, cell_id, planner_id, metric)
);
CREATE VIEW IF NOT EXISTS run_values AS
  SELECT r.run_id, r.experiment_id, e.name AS experiment, c.cell, c.generator, c.width,
         c.height, c.density, p.label AS planner, p.name AS planner_name, r.map_index,
         r.outcome, r.plan_time_ns, m.metric, m.value
  FROM runs r
  JOIN experiments e ON e.experiment_id = r.experiment_id
  JOIN cells c ON c.experiment_id = r.experiment_id AND c.cell_id = r.cell_id
  JOIN planners p ON p.experiment_id = r.experiment_id AND p.planner_id = r.planner_id
  LEFT JOIN run_metrics m ON m.run_id = r.run_id;
)sql";

class Statement;

// How long a write waits for another connection's transaction: 10 s, or AGVBENCH_SQLITE_WAIT_MS.
int busy_wait_ms() {
  const char* env = std::getenv("AGVBENCH_SQLITE_WAIT_MS");
  if (env == nullptr || *env == '\0') return 10000;
  char* end = nullptr;
  const long v = std::strtol(env, &end, 10);
  if (*end != '\0' || v < 0 || v > 3'600'000)
    throw InputError(std::string("AGVBENCH_SQLITE_WAIT_MS: \"") + env +
                     "\" is not a whole number of milliseconds in [0, 3600000]");
  return static_cast<int>(v);
}

// One open database; every failure names the file and SQLite's message.
class Database {
 public:
  // read_only: for the check before a sweep, which must not create the file.
  Database(const std::string& path, const std::string& option, bool read_only = false)
      : path_(path), option_(option), wait_ms_(busy_wait_ms()) {  // first: no handle left open
    const int flags = read_only ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
    if (sqlite3_open_v2(path.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
      const std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
      sqlite3_close(db_);
      db_ = nullptr;
      throw InputError(option + " \"" + path + "\": cannot be opened: " + message);
    }
    sqlite3_busy_timeout(db_, wait_ms_);  // another writer's transaction: wait, then fail
  }
  ~Database() { sqlite3_close(db_); }
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  sqlite3* handle() const { return db_; }
  const std::string& path() const { return path_; }
  // "--sqlite \"PATH\"": how messages name the database.
  std::string named() const { return option_ + " \"" + path_ + "\""; }

  // A damaged file is bad input (exit 2); another connection's lock, or any other failure, a
  // runtime one (exit 1). Each says what was going on and SQLite's own words.
  [[noreturn]] void fail(const std::string& doing) const {
    const int code = sqlite3_errcode(db_) & 0xff;  // the primary code of an extended one
    const std::string sqlite = std::string("SQLite: ") + sqlite3_errmsg(db_);
    if (code == SQLITE_CORRUPT || code == SQLITE_NOTADB)
      throw InputError(named() + ": is a damaged SQLite database (" + sqlite + "; " + doing +
                       "); left as it is");
    if (code == SQLITE_BUSY || code == SQLITE_LOCKED) {
      char waited[32];
      std::snprintf(waited, sizeof waited, "%g", wait_ms_ / 1000.0);
      throw std::runtime_error(named() + ": is locked by another connection, still after " +
                               waited + " s of waiting (" + sqlite + "; " + doing +
                               "); run again once it is done");
    }
    throw std::runtime_error(named() + ": " + doing + ": " + sqlite3_errmsg(db_));
  }
  void exec(const char* sql, const char* doing) {
    if (sqlite3_exec(db_, sql, nullptr, nullptr, nullptr) != SQLITE_OK) fail(doing);
  }
  // A single integer of a one-row query (a PRAGMA); a file that is not a database fails here.
  std::int64_t integer(const char* sql);

 private:
  std::string path_;
  std::string option_;
  int wait_ms_;  // how long SQLite waits for another connection (AGVBENCH_SQLITE_WAIT_MS)
  sqlite3* db_ = nullptr;
};

class Statement {
 public:
  Statement(Database& db, const char* sql) : db_(db) {
    if (sqlite3_prepare_v2(db.handle(), sql, -1, &stmt_, nullptr) != SQLITE_OK)
      db.fail("cannot prepare a statement");
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int i, std::int64_t v) {
    check(sqlite3_bind_int64(stmt_, i, v));
    return *this;
  }
  Statement& bind(int i, int v) { return bind(i, static_cast<std::int64_t>(v)); }
  Statement& bind(int i, std::size_t v) { return bind(i, static_cast<std::int64_t>(v)); }
  Statement& bind(int i, bool v) { return bind(i, static_cast<std::int64_t>(v ? 1 : 0)); }
  // NaN and infinities are NULL: undefined, as in the report.
  Statement& bind(int i, double v) {
    check(std::isfinite(v) ? sqlite3_bind_double(stmt_, i, v) : sqlite3_bind_null(stmt_, i));
    return *this;
  }
  Statement& bind(int i, const std::string& v) {
    check(sqlite3_bind_text(stmt_, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT));
    return *this;
  }
  Statement& bind_null(int i) {
    check(sqlite3_bind_null(stmt_, i));
    return *this;
  }
  // A JSON number or null.
  Statement& bind_json(int i, const json& v) {
    if (v.is_number_integer()) return bind(i, v.get<std::int64_t>());
    if (v.is_number()) return bind(i, v.get<double>());
    if (v.is_boolean()) return bind(i, v.get<bool>());
    if (v.is_string()) return bind(i, v.get<std::string>());
    return bind_null(i);
  }
  // Runs an INSERT (or any statement without rows) and resets it for the next bindings.
  void run() {
    if (sqlite3_step(stmt_) != SQLITE_DONE) db_.fail("write failed");
    sqlite3_reset(stmt_);
    sqlite3_clear_bindings(stmt_);
  }
  // Steps a query: true while there is a row.
  bool row() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc != SQLITE_DONE) db_.fail("query failed");
    return false;
  }
  std::int64_t column_integer(int i) const { return sqlite3_column_int64(stmt_, i); }

 private:
  void check(int rc) const {
    if (rc != SQLITE_OK) db_.fail("cannot bind a value");
  }
  Database& db_;
  sqlite3_stmt* stmt_ = nullptr;
};

std::int64_t Database::integer(const char* sql) {
  sqlite3_stmt* stmt = nullptr;
  int rc = sqlite3_prepare_v2(db_, sql, -1, &stmt, nullptr);
  if (rc == SQLITE_OK) rc = sqlite3_step(stmt);
  // A query that did not give its row (locked, damaged) would read as 0: a misdiagnosis.
  const std::int64_t v = rc == SQLITE_ROW ? sqlite3_column_int64(stmt, 0) : 0;
  sqlite3_finalize(stmt);
  if ((rc & 0xff) == SQLITE_NOTADB)
    throw InputError(named() + ": is not an SQLite database (left as it is)");
  if (rc != SQLITE_ROW) fail("reading the database header");
  return v;
}

// A new (empty) database gets the layout; an existing one must be agvbench's, of a layout this
// build knows. Anything else is refused before a row is written.
// Whether the database is empty (a new file): true; agvbench's of this layout: false; else
// InputError.
bool check_layout(Database& db) {
  const std::int64_t app = db.integer("PRAGMA application_id");
  const std::int64_t version = db.integer("PRAGMA user_version");
  const std::int64_t objects = db.integer("SELECT count(*) FROM sqlite_master");
  if (objects == 0 && app == 0) return true;
  if (app != kResultsDbApplicationId)
    throw InputError(db.named() +
                     ": is an SQLite database of another application (application_id " +
                     std::to_string(app) + ", holding " + std::to_string(objects) +
                     " tables/indexes); agvbench appends only to its own databases");
  if (version != kResultsDbVersion)
    throw InputError(db.named() + ": holds agvbench database layout " + std::to_string(version) +
                     "; this agvbench writes layout " + std::to_string(kResultsDbVersion) +
                     " (export into a new database)");
  return false;
}

void check_or_create_layout(Database& db) {
  if (check_layout(db)) {
    db.exec("BEGIN IMMEDIATE", "cannot start a transaction");
    db.exec(kSchemaSql, "cannot create the tables");
    db.exec(("PRAGMA application_id = " + std::to_string(kResultsDbApplicationId)).c_str(),
            "cannot set the application id");
    db.exec(("PRAGMA user_version = " + std::to_string(kResultsDbVersion)).c_str(),
            "cannot set the layout version");
    db.exec("COMMIT", "cannot commit the tables");
  }
}

// FNV-1a over the runs' identities, outcomes and planning times: two exports of one journal give
// the same digest, two runs of one config (different timings) do not.
std::string runs_digest(const SweepResults& r) {
  std::uint64_t h = 1469598103934665603ULL;
  auto mix = [&h](std::uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      h ^= (v >> (8 * i)) & 0xffU;
      h *= 1099511628211ULL;
    }
  };
  for (std::int64_t task = 0; task < r.plan.map_tasks(); ++task) {
    for (std::size_t p = 0; p < r.labels.size(); ++p) {
      const RunSlot& s = r.run(task, p);
      if (!s.done) continue;
      mix(static_cast<std::uint64_t>(task));
      mix(p);
      mix(static_cast<std::uint64_t>(s.outcome));
      mix(static_cast<std::uint64_t>(s.plan_time_ns));
    }
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

std::int64_t insert_experiment(Database& db, const ExperimentRecord& e, const std::string& hash,
                               const std::string& digest) {
  const SweepConfig& c = *e.config;
  const json& report = *e.report;
  Statement s(db,
              "INSERT INTO experiments (name, config_hash, runs_digest, config_json, "
              "environment_json, created_utc, source, report_schema_version, journal_version, "
              "seed, baseline, maps_per_cell, time_limit_s, complete, runs_expected, "
              "runs_present) VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)");
  s.bind(1, c.name)
      .bind(2, hash)
      .bind(3, digest)
      .bind(4, json_text(report.at("config")))
      .bind(5, json_text(e.environment))
      .bind(6, e.environment.value("date_utc", std::string()))
      .bind(7, e.source)
      .bind(8, kReportSchemaVersion)
      .bind(9, kJournalVersion)
      .bind(10, static_cast<std::int64_t>(c.seed))
      .bind(11, c.baseline)
      .bind(12, c.maps_per_cell)
      .bind(13, c.time_limit_s)
      .bind(14, report.at("complete").get<bool>())
      .bind_json(15, report.at("coverage").at("runs_expected"))
      .bind_json(16, report.at("coverage").at("runs_present"));
  s.run();
  return sqlite3_last_insert_rowid(db.handle());
}

void insert_planners_and_cells(Database& db, std::int64_t id, const ExperimentRecord& e) {
  const SweepConfig& c = *e.config;
  const json& config = e.report->at("config");
  Statement planner(db,
                    "INSERT INTO planners (experiment_id, planner_id, label, name, params_json, "
                    "is_baseline) VALUES (?,?,?,?,?,?)");
  const std::size_t base = baseline_index(c);
  for (std::size_t p = 0; p < c.planners.size(); ++p) {
    planner.bind(1, id)
        .bind(2, p)
        .bind(3, c.planners[p].label)
        .bind(4, c.planners[p].name)
        .bind(5, json_text(config.at("planners").at(p).at("params")))
        .bind(6, p == base)
        .run();
  }
  Statement cell(db,
                 "INSERT INTO cells (experiment_id, cell_id, cell, generator, width, height, "
                 "density, maps, rejections) VALUES (?,?,?,?,?,?,?,?,?)");
  const json& cells = e.report->at("cells");  // in plan order
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const json& rc = cells[i];
    const SweepCell& sc = e.results->plan.cells.at(i);
    cell.bind(1, id)
        .bind(2, sc.index)
        .bind(3, sc.key)
        .bind(4, sc.generator)
        .bind(5, sc.size.width)
        .bind(6, sc.size.height)
        .bind(7, sc.density)
        .bind_json(8, rc.at("maps"))
        .bind_json(9, rc.at("rejections"))
        .run();
  }
}

void insert_runs(Database& db, std::int64_t id, const ExperimentRecord& e,
                 const std::string& hash) {
  const SweepResults& r = *e.results;
  const SweepConfig& c = *e.config;
  Statement run(db,
                "INSERT INTO runs (experiment_id, cell_id, planner_id, map_index, task_id, "
                "outcome, message, plan_time_ns, obstacle_fraction) VALUES (?,?,?,?,?,?,?,?,?)");
  Statement metric(db, "INSERT INTO run_metrics (run_id, metric, value) VALUES (?,?,?)");
  Statement phase(db, "INSERT INTO run_phases (run_id, phase, ns) VALUES (?,?,?)");
  for (std::int64_t task = 0; task < r.plan.map_tasks(); ++task) {
    const SweepCell& cell = r.plan.cell_of(task);
    const int map_index = r.plan.map_index_of(task);
    const MapSlot& map = r.map(task);
    for (std::size_t p = 0; p < r.labels.size(); ++p) {
      const RunSlot& s = r.run(task, p);
      if (!s.done) continue;
      run.bind(1, id)
          .bind(2, cell.index)
          .bind(3, p)
          .bind(4, map_index)
          .bind(5, task_id(hash, cell, map_index, c.planners[p].label))
          .bind(6, std::string(to_string(s.outcome)));
      const auto message = e.messages ? e.messages->find({task, p}) : RunMessages::const_iterator{};
      if (e.messages && message != e.messages->end()) {
        run.bind(7, message->second);
      } else {
        run.bind_null(7);
      }
      run.bind(8, s.plan_time_ns);
      if (map.done) {
        run.bind(9, map.obstacle_fraction);
      } else {
        run.bind_null(9);
      }
      run.run();
      const std::int64_t run_id = sqlite3_last_insert_rowid(db.handle());
      for (std::size_t i = 0; i < kRunMetricNames.size(); ++i)
        if (std::isfinite(s.metrics[i]))
          metric.bind(1, run_id)
              .bind(2, std::string(kRunMetricNames[i]))
              .bind(3, s.metrics[i])
              .run();
      for (const auto& [name, value] : s.extra)
        if (std::isfinite(value)) metric.bind(1, run_id).bind(2, name).bind(3, value).run();
      for (const auto& ph : s.phases) phase.bind(1, run_id).bind(2, ph.name).bind(3, ph.ns).run();
    }
  }
}

void insert_paired(Database& db, std::int64_t id, const ExperimentRecord& e) {
  const SweepConfig& c = *e.config;
  auto planner_id = [&c](const std::string& label) {
    for (std::size_t p = 0; p < c.planners.size(); ++p)
      if (c.planners[p].label == label) return p;
    throw std::logic_error("paired result of an unknown planner");
  };
  Statement s(db,
              "INSERT INTO paired (experiment_id, cell_id, planner_id, baseline_id, metric, "
              "timing, pairs, better, wins, ties, losses, ratio, geo_mean_ratio, ci95_lo, "
              "ci95_hi, ratios_excluded, mean_difference, difference_ci95_lo, "
              "difference_ci95_hi, wilcoxon_p, wilcoxon_exact) "
              "VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)");
  const json& cells = e.report->at("cells");
  for (std::size_t ci = 0; ci < cells.size(); ++ci) {
    for (const json& pair : cells[ci].at("paired")) {
      const std::size_t planner = planner_id(pair.at("planner").get<std::string>());
      const std::size_t baseline = planner_id(pair.at("baseline").get<std::string>());
      auto insert = [&](const std::string& metric, const json& cmp, bool timing) {
        s.bind(1, id)
            .bind(2, ci)
            .bind(3, planner)
            .bind(4, baseline)
            .bind(5, metric)
            .bind(6, timing)
            .bind_json(7, cmp.at("pairs"))
            .bind_json(8, cmp.at("better"))
            .bind_json(9, cmp.at("wins"))
            .bind_json(10, cmp.at("ties"))
            .bind_json(11, cmp.at("losses"))
            .bind_json(12, cmp.at("ratio"))
            .bind_json(13, cmp.at("geo_mean_ratio"))
            .bind_json(14, cmp.at("ci95").at(0))
            .bind_json(15, cmp.at("ci95").at(1))
            .bind_json(16, cmp.at("ratios_excluded"))
            .bind_json(17, cmp.at("mean_difference"))
            .bind_json(18, cmp.at("difference_ci95").at(0))
            .bind_json(19, cmp.at("difference_ci95").at(1))
            .bind_json(20, cmp.at("wilcoxon_p"))
            .bind_json(21, cmp.at("wilcoxon_exact"))
            .run();
      };
      for (const auto& [metric, cmp] : pair.at("metrics").items()) insert(metric, cmp, false);
      for (const auto& [metric, cmp] : pair.at("timing").items()) insert(metric, cmp, true);
    }
  }
}

}  // namespace

std::int64_t append_experiment(const std::string& db_path, const ExperimentRecord& e) {
  Database db(db_path, e.option);
  check_or_create_layout(db);
  const std::string& hash = e.results->config_hash;
  const std::string digest = runs_digest(*e.results);
  db.exec("PRAGMA foreign_keys = ON", "cannot enable foreign keys");
  // One transaction: a failure (full disk, a kill) leaves the database as it was.
  db.exec("BEGIN IMMEDIATE", "cannot start a transaction");
  try {
    Statement existing(db,
                       "SELECT experiment_id FROM experiments WHERE config_hash = ? AND "
                       "runs_digest = ?");
    existing.bind(1, hash).bind(2, digest);
    if (existing.row()) {
      const std::int64_t other = existing.column_integer(0);
      throw InputError(db.named() + ": experiment " + std::to_string(other) +
                       " already holds this sweep (config hash " + hash +
                       ", the same runs and planning times); nothing was written");
    }
    const std::int64_t id = insert_experiment(db, e, hash, digest);
    insert_planners_and_cells(db, id, e);
    insert_runs(db, id, e, hash);
    insert_paired(db, id, e);
    db.exec("COMMIT", "cannot commit");
    return id;
  } catch (...) {
    sqlite3_exec(db.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

void check_results_db(const std::string& path, const std::string& option) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || st.st_size == 0) return;  // created when written
  Database db(path, option, true);
  check_layout(db);
}

}  // namespace agv
