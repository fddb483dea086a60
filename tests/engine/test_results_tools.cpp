// The tools around a report: the SQLite export, the before/after comparison, the Mann-Whitney
// test it uses, and the progress lines of a log.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <string>

#include "cli/progress.h"
#include "core/input_error.h"
#include "engine/judge/statistics.h"
#include "engine/outputs/report.h"
#include "engine/outputs/report_compare.h"
#include "engine/outputs/results_db.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/sweep_config.h"
#include "engine/sweep/sweep_runner.h"
#include "engine/system/environment.h"

namespace agv {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// R 4.3: wilcox.test(x, y, exact = FALSE, correct = TRUE)$p.value.
TEST(MannWhitney, MatchesRsNormalApproximation) {
  const std::vector<double> a = {1, 2, 3}, b = {4, 5, 6};
  const MannWhitneyResult r = mann_whitney_u(a, b);
  EXPECT_DOUBLE_EQ(r.u, 0.0);
  EXPECT_NEAR(r.p, 0.0808556, 1e-7);  // R prints 0.08086
  // With ties: x = c(1, 2, 2, 3), y = c(2, 3, 3, 4, 5): mid-ranks 1, 3, 3, 6 for x, so W = 3;
  // two groups of three ties.
  const std::vector<double> x = {1, 2, 2, 3}, y = {2, 3, 3, 4, 5};
  const MannWhitneyResult t = mann_whitney_u(x, y);
  EXPECT_DOUBLE_EQ(t.u, 3.0);
  // sigma^2 = 4*5/12 * (10 - (3^3-3 + 3^3-3)/(9*8)) = 15.5556; z = (3 - 10 + 0.5) / 3.944
  const double sigma = std::sqrt(20.0 / 12.0 * (10.0 - 48.0 / 72.0));
  const double z = (3.0 - 10.0 + 0.5) / sigma;
  EXPECT_NEAR(t.p, std::erfc(-z / std::sqrt(2.0)), 1e-12);
  EXPECT_TRUE(std::isnan(mann_whitney_u({}, b).p));
  const std::vector<double> same = {2, 2, 2};
  EXPECT_EQ(mann_whitney_u(same, same).p, 1.0);
}

// Symmetry on many random samples: swapping the samples mirrors U and keeps p; a shift of one
// sample far beyond the other gives U = 0 or nx*ny.
TEST(MannWhitney, SwappingSamplesMirrorsUAndKeepsP) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> size(1, 40), value(0, 30);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<double> x(static_cast<std::size_t>(size(rng))),
        y(static_cast<std::size_t>(size(rng)));
    for (double& v : x) v = value(rng);
    for (double& v : y) v = value(rng);
    const MannWhitneyResult a = mann_whitney_u(x, y), b = mann_whitney_u(y, x);
    const double nxny = static_cast<double>(x.size() * y.size());
    EXPECT_NEAR(a.u + b.u, nxny, 1e-9);
    EXPECT_NEAR(a.p, b.p, 1e-12);
    EXPECT_GE(a.p, 0.0);
    EXPECT_LE(a.p, 1.0);
    for (double& v : y) v += 1000;
    EXPECT_DOUBLE_EQ(mann_whitney_u(x, y).u, 0.0);
  }
}

// The progress lines of a log: one per 5 % step, in order, the last one total/total.
TEST(Progress, LogsALineAtEachFivePercentWhenNotATerminal) {
  for (const std::int64_t total : {100, 4321, 7}) {
    std::FILE* out = std::tmpfile();
    ASSERT_NE(out, nullptr);
    {
      ProgressMeter meter(total, true, out);
      for (std::int64_t i = 0; i < total; ++i) meter.advance();
      meter.finish();
    }
    std::rewind(out);
    std::vector<long long> done;
    char line[512];
    while (std::fgets(line, sizeof line, out)) {
      long long d = 0, t = 0;
      ASSERT_EQ(std::sscanf(line, "agvbench: progress %lld/%lld runs", &d, &t), 2) << line;
      EXPECT_EQ(t, total);
      EXPECT_NE(std::string(line).find("runs/s"), std::string::npos);
      EXPECT_NE(std::string(line).find("ETA"), std::string::npos);
      done.push_back(d);
    }
    std::fclose(out);
    ASSERT_FALSE(done.empty());
    EXPECT_TRUE(std::is_sorted(done.begin(), done.end()));
    EXPECT_EQ(done.back(), total);
    // Every 5 % step has its line (with 7 runs some steps share one).
    std::set<long long> steps;
    for (long long d : done) steps.insert(d * 20 / total);
    if (total >= 20) {
      for (long long s = 1; s <= 20; ++s)
        EXPECT_TRUE(steps.count(s)) << "step " << s << " of " << total;
      EXPECT_EQ(done.size(), 20u);
    }
  }
}

TEST(Environment, RecordsTheUtcDateAndTheLoadAverage) {
  const json env = environment_json(1);
  const std::string date = env.at("date_utc").get<std::string>();
  ASSERT_EQ(date.size(), 20u);
  EXPECT_EQ(date[4], '-');
  EXPECT_EQ(date[10], 'T');
  EXPECT_EQ(date.back(), 'Z');
  ASSERT_TRUE(env.at("load_average").is_array());
  EXPECT_EQ(env.at("load_average").size(), 3u);
  // Environment, not results: the determinism comparison leaves both out.
  const json report = {{"environment", env}, {"cells", json::array()}};
  EXPECT_FALSE(deterministic_part(report).contains("environment"));
}

json tiny_config(std::uint64_t seed, const std::string& astar_heuristic = "") {
  json astar = "astar";
  if (!astar_heuristic.empty())
    astar = {{"name", "astar"}, {"params", {{"heuristic", astar_heuristic}}}};
  return {{"name", "tiny"},
          {"seed", seed},
          {"generators", {"uniform", "blocks"}},
          {"sizes", {20}},
          {"densities", {0.1, 0.3}},
          {"maps_per_cell", 5},
          {"planners", {"dijkstra", astar, "ma_star"}},
          {"baseline", "dijkstra"}};
}

struct Sweep {
  SweepConfig config;
  SweepResults results;
  json report;
};

Sweep run_tiny(const json& config_json) {
  Sweep s;
  s.config = parse_config(config_json);
  SweepOptions options;
  options.threads = 1;
  s.results = run_sweep(s.config, options);
  s.report = build_report(s.config, s.results);
  return s;
}

TEST(Compare, TwoRunsOfOneConfigHaveNoNonTimingDifference) {
  const Sweep a = run_tiny(tiny_config(3)), b = run_tiny(tiny_config(3));
  const ReportComparison c = compare_reports(a.report, b.report, nullptr, nullptr, std::nullopt);
  EXPECT_TRUE(c.differences.empty());
  EXPECT_TRUE(c.parameter_changes.empty());
  EXPECT_EQ(c.timing.size(), 3u * 4u);  // planners x cells
  EXPECT_EQ(c.exit_code(), 0);
  // A report against itself: every ratio exactly 1.
  const ReportComparison self = compare_reports(a.report, a.report, nullptr, nullptr, 0.0);
  EXPECT_DOUBLE_EQ(self.overall_ratio, 1.0);
  EXPECT_EQ(self.exit_code(), 0);
}

// compare reads a sweep's journals by the hash of the report's config: the journals' own, also
// for a config with "sources" commentary (which the hash leaves out).
TEST(Compare, AReportNamesItsJournalsConfigHashAlsoWithSources) {
  json with_sources = tiny_config(3);
  with_sources["sources"] = {{"paper", "000"}};
  const Sweep s = run_tiny(with_sources);
  EXPECT_EQ(report_config_hash(s.report), config_hash(s.config));
  EXPECT_EQ(report_config_hash(s.report), s.results.config_hash);
}

TEST(Compare, AnAStarParameterChangeIsListedUnderAStarOnly) {
  const Sweep a = run_tiny(tiny_config(3)), b = run_tiny(tiny_config(3, "octile"));
  const ReportComparison c = compare_reports(a.report, b.report, nullptr, nullptr, std::nullopt);
  ASSERT_EQ(c.parameter_changes.size(), 1u);
  EXPECT_NE(c.parameter_changes[0].find("astar: heuristic \"euclidean\" -> \"octile\""),
            std::string::npos)
      << c.parameter_changes[0];
  ASSERT_FALSE(c.differences.empty());
  bool expansions = false;
  for (const ValueDifference& d : c.differences) {
    EXPECT_EQ(d.planner, "astar") << d.cell << " " << d.metric << " " << d.field;
    EXPECT_NE(d.before, d.after);
    expansions = expansions || d.metric == "search_expansions";
  }
  EXPECT_TRUE(expansions);
  EXPECT_EQ(c.exit_code(), 1);
}

// Each kind of non-timing change is found and named where it is.
TEST(Compare, EveryChangedValueIsFoundWithItsPlannerCellAndMetric) {
  const Sweep a = run_tiny(tiny_config(3));
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 40; ++trial) {
    json b = a.report;
    json& cell = b["cells"][rng() % b["cells"].size()];
    json& planner = cell["planners"][rng() % cell["planners"].size()];
    std::vector<std::string> metrics;
    for (const auto& [name, v] : planner["metrics"].items()) metrics.push_back(name);
    const std::string metric = metrics[rng() % metrics.size()];
    planner["metrics"][metric]["count"] = planner["metrics"][metric]["count"].get<int>() + 1;
    // A timing change alongside is no difference.
    planner["timing"]["plan_time_ns"]["mean"] = 1.0;
    const ReportComparison c = compare_reports(a.report, b, nullptr, nullptr, std::nullopt);
    ASSERT_EQ(c.differences.size(), 1u);
    EXPECT_EQ(c.differences[0].planner, planner["planner"].get<std::string>());
    EXPECT_EQ(c.differences[0].cell, cell["cell"].get<std::string>());
    EXPECT_EQ(c.differences[0].metric, metric);
    EXPECT_EQ(c.differences[0].field, "count");
    EXPECT_EQ(c.exit_code(), 1);
  }
}

TEST(Compare, ConfigsThatDifferBeyondPlannerParametersAreBadInput) {
  const Sweep a = run_tiny(tiny_config(3)), b = run_tiny(tiny_config(4));
  try {
    compare_reports(a.report, b.report, nullptr, nullptr, std::nullopt);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("seed 3 -> 4"), std::string::npos) << e.what();
  }
  json not_report = {{"tool", "other"}};
  EXPECT_THROW(compare_reports(a.report, not_report, nullptr, nullptr, std::nullopt), InputError);
  json old = a.report;
  old["schema_version"] = 1;
  EXPECT_THROW(compare_reports(old, a.report, nullptr, nullptr, std::nullopt), InputError);
}

// Paired timing: the runs of each planner and cell pair up by map; a sweep slowed three times
// in every run is a regression beyond 50 % with a small p, and not one below 250 %.
TEST(Compare, PairedTimesGiveTheGeometricMeanRatioAndAWilcoxonTest) {
  const Sweep a = run_tiny(tiny_config(3));
  RunTimes before, after;
  std::mt19937_64 rng(9);
  for (const json& cell : a.report["cells"])
    for (const json& p : cell["planners"])
      for (int m = 0; m < 5; ++m) {
        const std::int64_t ns = 1000 + static_cast<std::int64_t>(rng() % 1000);
        const auto key =
            std::make_pair(cell["cell"].get<std::string>(), p["planner"].get<std::string>());
        before[key][m] = ns;
        after[key][m] = 3 * ns;
      }
  const ReportComparison c = compare_reports(a.report, a.report, &before, &after, 50.0);
  ASSERT_EQ(c.timing.size(), 12u);
  for (const TimingComparison& t : c.timing) {
    EXPECT_EQ(t.test, TimingTest::wilcoxon);
    EXPECT_EQ(t.pairs, 5u);
    EXPECT_NEAR(t.ratio, 3.0, 1e-12);
    EXPECT_NEAR(t.p, 0.0625, 1e-12);  // 5 pairs, all one sign: 2 / 2^5
    EXPECT_FALSE(t.regression);       // p = 0.0625 is not below 0.05
  }
  EXPECT_NEAR(c.overall_ratio, 3.0, 1e-12);
  ASSERT_EQ(c.planner_ratios.size(), 3u);
  for (const auto& [label, ratio] : c.planner_ratios) EXPECT_NEAR(ratio, 3.0, 1e-12) << label;
  EXPECT_TRUE(c.overall_regression);
  EXPECT_EQ(c.exit_code(), 1);
  EXPECT_EQ(compare_reports(a.report, a.report, &before, &after, 250.0).exit_code(), 0);
  // Runs that do not pair up (a map missing after): the U test on what there is.
  after[{c.timing.front().cell, c.timing.front().planner}].erase(0);
  const ReportComparison u = compare_reports(a.report, a.report, &before, &after, std::nullopt);
  EXPECT_EQ(u.timing.front().test, TimingTest::mann_whitney);
  EXPECT_EQ(u.timing.front().runs_after, 4u);
  EXPECT_EQ(u.exit_code(), 0);  // timing never fails without --fail-on-regression
}

std::int64_t count(const std::string& db, const std::string& sql) {
  sqlite3* h = nullptr;
  EXPECT_EQ(sqlite3_open_v2(db.c_str(), &h, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
  sqlite3_stmt* s = nullptr;
  EXPECT_EQ(sqlite3_prepare_v2(h, sql.c_str(), -1, &s, nullptr), SQLITE_OK) << sqlite3_errmsg(h);
  std::int64_t v = -1;
  if (sqlite3_step(s) == SQLITE_ROW) v = sqlite3_column_int64(s, 0);
  sqlite3_finalize(s);
  sqlite3_close(h);
  return v;
}

TEST(ResultsDb, TwoSweepsTwoExperimentsEveryRunOnceAndNoDuplicate) {
  const fs::path dir = fs::temp_directory_path() / ("agv_db_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string db = (dir / "r.db").string();
  const Sweep a = run_tiny(tiny_config(3)), b = run_tiny(tiny_config(5));
  const json env = environment_json(1);
  EXPECT_EQ(append_experiment(db, {&a.config, &a.results, &a.report, nullptr, "run", env}), 1);
  EXPECT_EQ(append_experiment(db, {&b.config, &b.results, &b.report, nullptr, "export", env}), 2);
  EXPECT_EQ(count(db, "select count(*) from experiments"), 2);
  EXPECT_EQ(count(db, "select count(*) from runs"), 2 * 4 * 5 * 3);
  EXPECT_EQ(count(db, "select count(*) from runs where experiment_id = 2"), 4 * 5 * 3);
  // Every finite metric of every run, once.
  std::int64_t metrics = 0;
  for (const SweepResults* r : {&a.results, &b.results})
    for (const CellResults& cell : r->cells)
      for (const RunSlot& s : cell.runs) {
        for (double v : s.metrics) metrics += std::isfinite(v) ? 1 : 0;
        for (const auto& [n, v] : s.extra) metrics += std::isfinite(v) ? 1 : 0;
      }
  EXPECT_EQ(count(db, "select count(*) from run_metrics"), metrics);
  // The successes per planner and cell are the report's.
  for (const json& cell : a.report["cells"])
    for (const json& p : cell["planners"])
      EXPECT_EQ(count(db,
                      "select count(*) from run_values where experiment_id = 1 and metric = "
                      "'path_length' and outcome = 'success' and cell = '" +
                          cell["cell"].get<std::string>() + "' and planner = '" +
                          p["planner"].get<std::string>() + "'"),
                p["successes"].get<std::int64_t>());
  EXPECT_EQ(count(db, "select count(*) from paired where timing = 1"), 2 * 4 * 2);
  // The same sweep again: refused, nothing written.
  EXPECT_THROW(append_experiment(db, {&a.config, &a.results, &a.report, nullptr, "run", env}),
               InputError);
  EXPECT_EQ(count(db, "select count(*) from experiments"), 2);
  EXPECT_EQ(count(db, "select count(*) from runs"), 2 * 4 * 5 * 3);
  // Another application's database and a file that is no database are left alone.
  const std::string text = (dir / "notes.txt").string();
  std::ofstream(text) << "my notes\n";
  EXPECT_THROW(append_experiment(text, {&a.config, &a.results, &a.report, nullptr, "run", env}),
               InputError);
  std::ifstream in(text);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "my notes");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace agv
