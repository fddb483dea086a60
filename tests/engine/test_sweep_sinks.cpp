// The sweep's sinks (engine/outputs/sweep_sink.h): the calls in their order and one at a time, a
// cell handed over once all its runs are in, a failing sink stopping the sweep with nothing lost
// unsaid, and the report and database sinks fed from the runs (issue 46, stage 2).
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/json_text.h"
#include "engine/outputs/database_sink.h"
#include "engine/outputs/report.h"
#include "engine/outputs/report_sink.h"
#include "engine/plan/config_loader.h"
#include "engine/sweep/sweep_runner.h"
#include "tests/engine/scratch_dir.h"

namespace agv {
namespace sink_tests {  // a name of its own: test files share a unity build
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Scratch : test::ScratchDir {
  explicit Scratch(const std::string& name) : ScratchDir("sinks_" + name) {}
};

// Two cells of four maps, A* on all of them and RRT (its iterations too few to succeed always,
// so some runs fail with a message) on the first two maps of each.
SweepConfig two_cells() {
  return parse_config({{"sizes", {16}},
                       {"densities", {0.1, 0.2}},
                       {"maps_per_cell", 4},
                       {"planners",
                        {"astar",
                         {{"name", "rrt"},
                          {"only", {{"maps_per_cell", 2}}},
                          {"params", {{"max_iterations", 10}}}}}}});
}

// Records what it is handed and checks each call against what came before.
class ProbeSink : public SweepSink {
 public:
  void start(const SweepStart& start) override {
    enter();
    EXPECT_EQ(calls, "");
    calls += "S";
    runs_to_do = start.runs_to_do;
    leave();
  }
  void task_done(const TaskRuns& runs) override {
    enter();
    EXPECT_EQ(calls, "S");
    ++tasks;
    runs_seen += static_cast<std::int64_t>(runs.runs.size());
    for (const RecordedRun& r : runs.runs)
      if (!r.message.empty()) ++messages;
    if (tasks == stop_after && stop != nullptr) *stop = true;
    if (tasks == fail_at) {
      leave();
      throw SinkError("probe: disk full");
    }
    leave();
  }
  void cell_done(const SweepCell& cell, const SweepResults& results) override {
    enter();
    cells.push_back(cell.index);
    // Every scheduled run of the cell is in its slot.
    for (int m = 0; m < cell.maps; ++m)
      for (std::size_t p = 0; p < results.labels.size(); ++p)
        if (m < results.maps_of(cell, p)) {
          EXPECT_TRUE(results.run(cell, m, p).done);
        }
    leave();
  }
  void end_runs() override { calls += "E"; }
  void finish(const SweepResults& results) override {
    EXPECT_EQ(calls, "SE");
    calls += "F";
    finished_complete = results.complete;
  }

  std::string calls;
  std::int64_t runs_to_do = 0, runs_seen = 0;
  int tasks = 0, messages = 0;
  std::vector<int> cells;
  bool finished_complete = false;
  int fail_at = -1;     // throws SinkError at this task
  int stop_after = -1;  // sets `stop` after this task
  std::atomic<bool>* stop = nullptr;

 private:
  // No two calls at once, whichever thread makes them.
  void enter() { EXPECT_FALSE(busy_.exchange(true)); }
  void leave() { busy_ = false; }
  std::atomic<bool> busy_{false};
};

// The sweep on one thread, stopped as a first SIGINT would once `tasks` map tasks are done (the
// probe, added to the options' sinks, sets the stop flag).
SweepResults stopped_after(const SweepConfig& config, int tasks, SweepOptions options,
                           ProbeSink& probe) {
  std::atomic<bool> stop{false};
  probe.stop = &stop;
  probe.stop_after = tasks;
  options.threads = 1;
  options.stop = &stop;
  options.sinks.push_back(&probe);
  const SweepResults r = run_sweep(config, options);
  probe.stop = nullptr;
  return r;
}

std::int64_t count_rows(const std::string& db, const std::string& sql) {
  sqlite3* handle = nullptr;
  EXPECT_EQ(sqlite3_open_v2(db.c_str(), &handle, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
  sqlite3_stmt* stmt = nullptr;
  EXPECT_EQ(sqlite3_prepare_v2(handle, sql.c_str(), -1, &stmt, nullptr), SQLITE_OK);
  std::int64_t n = -1;
  if (sqlite3_step(stmt) == SQLITE_ROW) n = sqlite3_column_int64(stmt, 0);
  sqlite3_finalize(stmt);
  sqlite3_close(handle);
  return n;
}

TEST(SweepSinks, EveryTaskThenEveryCellOnceThenTheEndOneCallAtATime) {
  const SweepConfig config = two_cells();
  ProbeSink probe;
  SweepOptions options;
  options.threads = 2;
  options.sinks = {&probe};
  const SweepResults r = run_sweep(config, options);
  EXPECT_EQ(probe.calls, "SEF");
  EXPECT_EQ(probe.runs_to_do, 12);  // 8 maps of A*, 4 of RRT
  EXPECT_EQ(probe.runs_seen, 12);
  EXPECT_EQ(probe.tasks, 8);
  std::vector<int> cells = probe.cells;
  std::sort(cells.begin(), cells.end());
  EXPECT_EQ(cells, (std::vector<int>{0, 1}));
  EXPECT_TRUE(probe.finished_complete);
  EXPECT_TRUE(r.complete);
  EXPECT_GT(probe.messages, 0);
}

TEST(SweepSinks, AFailingSinkStopsTheSweepWhichEndsIncompleteNamingIt) {
  const SweepConfig config = two_cells();
  Scratch dir("failing");
  ProbeSink failing, after;
  failing.fail_at = 3;
  ReportSink report(config, dir.path("report.json"), true);
  SweepOptions options;
  options.threads = 1;
  options.sinks = {&failing, &after, &report};
  const SweepResults r = run_sweep(config, options);
  EXPECT_EQ(r.sink_error, "probe: disk full");
  EXPECT_FALSE(r.complete);
  EXPECT_EQ(after.tasks, 2);  // the task the failing sink lost went no further
  EXPECT_EQ(failing.calls, "SEF");
  // The report is written, incomplete, without the lost task's runs.
  std::ifstream in(dir.path("report.json"));
  const nlohmann::json written = nlohmann::json::parse(in);
  EXPECT_EQ(written.at("complete"), false);
  EXPECT_EQ(written, report.report());
}

TEST(SweepSinks, AnInterruptedSweepHandsOverNoCellItDidNotFinish) {
  const SweepConfig config = two_cells();
  ProbeSink probe;
  const SweepResults r = stopped_after(config, 2, {}, probe);
  EXPECT_TRUE(r.interrupted);
  EXPECT_EQ(probe.tasks, 2);
  EXPECT_TRUE(probe.cells.empty());
  EXPECT_EQ(probe.calls, "SEF");
  EXPECT_FALSE(probe.finished_complete);
}

// The database gets the report the report sink built and every failure's message, the restored
// ones of a resume included, with no journal read after the sweep.
TEST(SweepSinks, TheDatabaseHasEveryMessageAlsoAfterAResume) {
  const SweepConfig config = two_cells();
  Scratch dir("database");
  std::int64_t failures = 0;
  {
    ProbeSink probe;
    SweepOptions whole;
    whole.sinks = {&probe};
    run_sweep(config, whole);
    failures = probe.messages;
  }
  ASSERT_GT(failures, 0);
  // Half the sweep journaled, then resumed with the database.
  ProbeSink stopper;
  SweepOptions first;
  first.runs_path = dir.path("runs.jsonl");
  ASSERT_TRUE(stopped_after(config, 4, first, stopper).interrupted);
  ReportSink report(config, dir.path("report.json"), true);
  DatabaseSink database(config, dir.path("results.db"), "--db", report);
  SweepOptions resume;
  resume.resume_path = dir.path("runs.jsonl");
  resume.sinks = {&report, &database};
  const SweepResults r = run_sweep(config, resume);
  ASSERT_TRUE(r.complete);
  ASSERT_TRUE(database.experiment_id().has_value());
  EXPECT_GT(r.restored_runs, 0);
  EXPECT_EQ(count_rows(dir.path("results.db"), "select count(*) from runs"), 12);
  EXPECT_EQ(count_rows(dir.path("results.db"),
                       "select count(*) from runs where message like 'max_iterations%'"),
            failures);
}

// Released cells (issue 46 stage 3a): each finished cell is summarised into its digest and its
// run slots freed; the report, written one cell at a time, is byte for byte the document's text,
// and its non-timing part is that of a sweep that kept every slot, on 1 and 2 threads.
TEST(ReleasedCells, TheReportIsTheSameAsWhenEverySlotIsKept) {
  const SweepConfig config = two_cells();
  Scratch dir("released");
  json kept_part;
  {
    SweepOptions options;
    options.threads = 1;
    const SweepResults kept = run_sweep(config, options);
    kept_part = deterministic_part(build_report(config, kept));
    EXPECT_EQ(report_text(config, kept), json_text(build_report(config, kept), 1) + "\n");
  }
  for (const int threads : {1, 2}) {
    ReportSink report(config, dir.path("report.json"), false);
    ProbeSink probe;
    SweepOptions options;
    options.threads = threads;
    options.release_cells = true;
    options.sinks = {&report, &probe};
    const SweepResults r = run_sweep(config, options);
    for (const auto& cell : r.plan.cells) EXPECT_TRUE(r.released(cell)) << cell.key;
    EXPECT_THROW(static_cast<void>(r.run(0, 0)), std::logic_error);
    const std::string written = test::read_file(dir.path("report.json"));
    EXPECT_EQ(written, json_text(build_report(config, r), 1) + "\n");
    EXPECT_EQ(deterministic_part(json::parse(written)), kept_part) << threads << " threads";
    EXPECT_TRUE(r.complete);
    EXPECT_EQ(coverage_of(r).runs_present, 12);
  }
}

// A sweep cut short keeps the slots of the cells it did not finish and releases the others; the
// resume of its journal gives the uninterrupted report.
TEST(ReleasedCells, AnInterruptedSweepResumesToTheSameReport) {
  const SweepConfig config = two_cells();
  Scratch dir("released_resume");
  json whole;
  {
    SweepOptions options;
    whole = deterministic_part(build_report(config, run_sweep(config, options)));
  }
  ProbeSink stopper;
  SweepOptions first;
  first.release_cells = true;
  first.runs_path = dir.path("runs.jsonl");
  const SweepResults cut = stopped_after(config, 5, first, stopper);  // cell 0 done, 1 begun
  ASSERT_TRUE(cut.interrupted);
  EXPECT_TRUE(cut.released(cut.plan.cells[0]));
  EXPECT_FALSE(cut.released(cut.plan.cells[1]));
  EXPECT_EQ(coverage_of(cut).runs_present, 6 + 2);  // cell 0: 6 runs; cell 1's first map: 2
  SweepOptions resume;
  resume.resume_path = dir.path("runs.jsonl");
  resume.release_cells = true;
  const SweepResults r = run_sweep(config, resume);
  EXPECT_TRUE(r.complete);
  // Cell 0, complete in the journal, was released as it was read; cell 1 once it was run.
  for (const auto& cell : r.plan.cells) EXPECT_TRUE(r.released(cell)) << cell.key;
  EXPECT_EQ(deterministic_part(build_report(config, r)), whole);
  // The journal restored alone (merge's way): every cell released, the same report.
  SweepResults merged = empty_results(config);
  restore_journal(dir.path("runs.jsonl"), merged, nullptr, &config);
  update_completeness(merged);
  for (const auto& cell : merged.plan.cells) EXPECT_TRUE(merged.released(cell)) << cell.key;
  EXPECT_EQ(deterministic_part(json::parse(report_text(config, merged))), whole);
}

// merge (issue 46 stage 3b): the shards' journals read in turn release every cell and give the
// whole sweep's report.
TEST(ReleasedCells, ShardJournalsMergeCellByCellToTheWholeReport) {
  const SweepConfig config = two_cells();
  Scratch dir("shards");
  const json whole = deterministic_part(build_report(config, run_sweep(config, SweepOptions{})));
  std::vector<std::string> journals;
  for (int shard = 0; shard < 2; ++shard) {
    SweepOptions options;
    options.shard_index = shard;
    options.shard_count = 2;
    options.release_cells = true;
    options.runs_path = dir.path("shard" + std::to_string(shard) + ".jsonl");
    run_sweep(config, options);
    journals.push_back(options.runs_path);
  }
  SweepResults merged = empty_results(config);
  restore_journals(journals, merged, &config);
  update_completeness(merged);
  EXPECT_TRUE(merged.complete);
  for (const auto& cell : merged.plan.cells) EXPECT_TRUE(merged.released(cell)) << cell.key;
  EXPECT_EQ(deterministic_part(json::parse(report_text(config, merged))), whole);
}

}  // namespace
}  // namespace sink_tests
}  // namespace agv
