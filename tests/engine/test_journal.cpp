// The files a sweep writes: paths checked before anything is written, journal writes checked,
// journal versions refused, report temporaries of dead processes removed (issue 15).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "core/version.h"
#include "engine/outputs/journal.h"
#include "engine/outputs/journal_lines.h"
#include "engine/outputs/report.h"
#include "engine/outputs/run_record.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/output_paths.h"
#include "engine/plan/sweep_config.h"
#include "engine/sweep/sweep_runner.h"
#include "tests/engine/scratch_dir.h"

namespace agv {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A scratch folder of its own per test, removed afterwards.
struct Scratch : test::ScratchDir {
  explicit Scratch(const std::string& name) : ScratchDir("journal_" + name) {}
};
using test::read_file;
using test::write_file;

// The message of the InputError `f` throws, or "no error".
template <class F>
std::string input_error(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

SweepConfig small_config() {
  return parse_config(json{{"name", "journal"},
                           {"sizes", {16}},
                           {"densities", {0.1}},
                           {"maps_per_cell", 6},
                           {"planners", {"astar", "dijkstra"}},
                           {"report", "unused.json"}});
}

// Restores RAII-style the file-size limit a test lowers (SIGXFSZ ignored meanwhile, so that a
// write past the limit fails with EFBIG instead of killing the test binary).
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    old_handler_ = ::signal(SIGXFSZ, SIG_IGN);
    rlimit lowered = saved_;
    lowered.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &lowered);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    ::signal(SIGXFSZ, old_handler_);
  }

 private:
  rlimit saved_{};
  sighandler_t old_handler_{};
};

TEST(OutputPaths, AnOutputIsNeverAnInputHoweverSpelled) {
  Scratch s("identity");
  write_file(s.path("c.json"), "{}");
  fs::create_directories(s.path("sub"));
  fs::create_symlink(s.path("c.json"), s.path("link.json"));
  const std::vector<InputPath> inputs = {{"config file", s.path("c.json")}};
  for (const std::string& out :
       {s.path("c.json"), s.path("sub/../c.json"), s.path("link.json"), s.path("./c.json")}) {
    const std::string msg = input_error([&] { check_paths(inputs, {{"--out", out}}); });
    EXPECT_NE(msg.find("--out \"" + out + "\": is the config file"), std::string::npos) << msg;
  }
  EXPECT_EQ(input_error([&] { check_paths(inputs, {{"--out", s.path("r.json")}}); }), "no error");
  EXPECT_EQ(read_file(s.path("c.json")), "{}");
}

TEST(OutputPaths, TwoOutputsCannotShareAFileEvenWhenItDoesNotExistYet) {
  Scratch s("outputs");
  const std::string msg = input_error([&] {
    check_paths({}, {{"--out", s.path("r.json")},
                     {"--runs-out", s.path("sub/../r.json"), OutputKind::new_journal}});
  });
  EXPECT_NE(msg.find("--runs-out"), std::string::npos) << msg;
  EXPECT_NE(msg.find("is also the --out"), std::string::npos) << msg;
}

TEST(OutputPaths, FoldersMustExistAndOutputsBeRegularFiles) {
  Scratch s("folders");
  fs::create_directories(s.path("dir.json"));
  const std::string missing = input_error([&] {
    check_paths({}, {{"report", s.path("nowhere/r.json")}});
  });
  EXPECT_NE(missing.find("report \"" + s.path("nowhere/r.json") + "\": its directory"),
            std::string::npos)
      << missing;
  EXPECT_NE(missing.find("does not exist"), std::string::npos) << missing;
  EXPECT_FALSE(fs::exists(s.path("nowhere")));
  const std::string dir = input_error([&] { check_paths({}, {{"--out", s.path("dir.json")}}); });
  EXPECT_NE(dir.find("is a directory, not a regular file"), std::string::npos) << dir;
  const std::string device = input_error([&] { check_paths({}, {{"--out", "/dev/null"}}); });
  EXPECT_NE(device.find("is a character device"), std::string::npos) << device;
}

TEST(OutputPaths, ANewJournalNeverTruncatesRecords) {
  Scratch s("journal");
  write_file(s.path("j.jsonl"), "{\"a\": 1}\n");
  write_file(s.path("empty.jsonl"), "");
  const std::string msg = input_error([&] {
    check_paths({}, {{"--runs-out", s.path("j.jsonl"), OutputKind::new_journal}});
  });
  EXPECT_NE(msg.find("already holds a journal"), std::string::npos) << msg;
  EXPECT_NE(msg.find("--resume"), std::string::npos) << msg;
  EXPECT_EQ(input_error([&] {
              check_paths({}, {{"--runs-out", s.path("empty.jsonl"), OutputKind::new_journal}});
            }),
            "no error");
  // Resumed, the same journal is appended to; it must exist.
  EXPECT_EQ(input_error([&] {
              check_paths({}, {{"--resume", s.path("j.jsonl"), OutputKind::appended}});
            }),
            "no error");
  const std::string absent = input_error([&] {
    check_paths({}, {{"--resume", s.path("none.jsonl"), OutputKind::appended}});
  });
  EXPECT_NE(absent.find("No such file"), std::string::npos) << absent;
}

TEST(JournalWriter, AFullDiskIsAnErrorNamingTheJournalAndTheOsError) {
  const int fd = ::open("/dev/full", O_WRONLY | O_CLOEXEC);
  ASSERT_GE(fd, 0);
  JournalWriter journal(fd, "full.jsonl");
  try {
    journal.write("{\"run\": 1}\n");
    FAIL() << "a write to /dev/full succeeded";
  } catch (const JournalError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("journal \"full.jsonl\""), std::string::npos) << msg;
    EXPECT_NE(msg.find("No space left on device"), std::string::npos) << msg;
  }
  // Once failed, always failed: no later record lands after a hole.
  EXPECT_THROW(journal.write("{\"run\": 2}\n"), JournalError);
  EXPECT_THROW(journal.finish(), JournalError);
}

// The text of small_config()'s journal, written without a limit.
std::string journal_text(const Scratch& s) {
  const SweepConfig config = small_config();
  SweepOptions options;
  options.threads = 1;
  options.runs_path = s.path("source.jsonl");
  run_sweep(config, options);
  return read_file(options.runs_path);
}

TEST(JournalWriter, AFileSizeLimitStopsTheSweepAndLeavesItIncomplete) {
  Scratch s("limit");
  // On one thread the header is written first, then the first map's record and its two runs'
  // in one piece: room for them and a little more, so the second map's write fails part-way.
  const std::string text = journal_text(s);
  std::size_t first_map = 0;
  for (int line = 0; line < 4; ++line) first_map = text.find('\n', first_map) + 1;
  const SweepConfig config = small_config();
  SweepOptions options;
  options.threads = 1;
  options.runs_path = s.path("j.jsonl");
  SweepResults res;
  {
    const FileSizeLimit limit(first_map + 100);
    res = run_sweep(config, options);
  }
  EXPECT_NE(res.sink_error.find("journal \"" + options.runs_path + "\""), std::string::npos)
      << res.sink_error;
  EXPECT_NE(res.sink_error.find("File too large"), std::string::npos) << res.sink_error;
  EXPECT_FALSE(res.complete);
  const Coverage coverage = coverage_of(res);
  EXPECT_LT(coverage.runs_present, coverage.runs_expected);
  // What the results count as done is what the journal holds; its torn last line is cut.
  SweepResults restored = empty_results(config);
  const JournalStats stats = restore_journal(options.runs_path, restored);
  EXPECT_EQ(coverage.runs_present, 2);
  EXPECT_EQ(stats.records, coverage.runs_present);
  EXPECT_EQ(stats.torn_lines, 1);
}

TEST(JournalVersion, TheHeaderCarriesTheToolAndTheVersion) {
  Scratch s("carry");
  const std::string text = journal_text(s);
  const json first = json::parse(text.substr(0, text.find('\n')));
  EXPECT_EQ(first.at("tool"), "agvbench");
  EXPECT_EQ(first.at("journal_version"), kJournalVersion);
  EXPECT_EQ(first.at("record"), "header");
  EXPECT_EQ(first.at("config_hash"), config_hash(small_config()));
}

TEST(JournalVersion, RestoreRefusesAForeignOrMissingVersionNamingFileAndLine) {
  Scratch s("foreign");
  const std::string text = journal_text(s);
  const std::size_t second = text.find('\n') + 1;
  const json header = json::parse(text.substr(0, second - 1));
  const SweepConfig config = small_config();
  const auto refusal = [&](const json& edited) {
    const std::string path = s.path("edited.jsonl");
    write_file(path, edited.dump() + "\n" + text.substr(second));
    SweepResults res = empty_results(config);
    return input_error([&] { restore_journal(path, res); });
  };
  json foreign = header;
  foreign["journal_version"] = kJournalVersion + 1;
  const std::string newer = refusal(foreign);
  EXPECT_NE(newer.find("edited.jsonl:1:"), std::string::npos) << newer;
  EXPECT_NE(newer.find("journal_version " + std::to_string(kJournalVersion + 1)), std::string::npos)
      << newer;
  EXPECT_NE(
      newer.find("reads tool \"agvbench\", journal_version " + std::to_string(kJournalVersion)),
      std::string::npos)
      << newer;
  json unversioned = header;
  unversioned.erase("journal_version");
  unversioned.erase("tool");
  const std::string none = refusal(unversioned);
  EXPECT_NE(none.find("edited.jsonl:1:"), std::string::npos) << none;
  EXPECT_NE(none.find("tool (none), journal_version (none)"), std::string::npos) << none;
  json other_tool = header;
  other_tool["tool"] = "otherbench";
  EXPECT_NE(refusal(other_tool).find("tool \"otherbench\""), std::string::npos);
  json other_config = header;
  other_config["config_hash"] = "0123456789abcdef";
  EXPECT_NE(refusal(other_config).find("edited.jsonl:1: journal was written by a different config"),
            std::string::npos);
  EXPECT_EQ(refusal(header), "no error");
}

TEST(JournalVersion, AResumeRefusesAJournalOfAnotherAgvbenchVersionAndAMergeTwoVersions) {
  Scratch s("stamp");
  const std::string text = journal_text(s);
  const std::size_t second = text.find('\n') + 1;
  json header = json::parse(text.substr(0, second - 1));
  EXPECT_EQ(header.at("agvbench"), AGVBENCH_VERSION);
  const SweepConfig config = small_config();
  header["agvbench"] = "0.0.9";
  const std::string older = s.path("older.jsonl");
  const std::string older_text = header.dump() + "\n" + text.substr(second);
  write_file(older, older_text);
  // Read alone (its own report, an export): one version's runs, accepted.
  SweepResults alone = empty_results(config);
  EXPECT_GT(restore_journal(older, alone).records, 0);
  // Resumed by this version: refused naming both, the journal as it was.
  SweepOptions options;
  options.threads = 1;
  options.resume_path = older;
  const std::string resumed = input_error([&] { run_sweep(config, options); });
  EXPECT_NE(
      resumed.find("older.jsonl:1: written by agvbench 0.0.9, this is agvbench " AGVBENCH_VERSION
                   ": resuming would mix two versions' runs"),
      std::string::npos)
      << resumed;
  EXPECT_EQ(read_file(older), older_text);
  // Merged with a journal of this version: refused.
  SweepResults both = empty_results(config);
  const std::string merged = input_error([&] {
    restore_journals({s.path("source.jsonl"), older}, both);
  });
  EXPECT_NE(merged.find("older.jsonl:1: written by agvbench 0.0.9, an earlier record by "
                        "agvbench " AGVBENCH_VERSION),
            std::string::npos)
      << merged;
  // A header from before the stamp was written by the one version there was.
  header.erase("agvbench");
  JournalDecoder decoder;
  EXPECT_EQ(decoder.decode_line(header.dump(), "h").agvbench, kVersionBeforeStamps);
}

// The journal's lines, parsed.
std::vector<json> journal_lines_of(const std::string& text) {
  std::vector<json> out;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = text.find('\n', at);
    out.push_back(json::parse(text.substr(at, end - at)));
    at = end + 1;
  }
  return out;
}

TEST(JournalFormat, AHeaderThenOneRecordPerMapThenItsRunsNothingRepeated) {
  Scratch s("format");
  const std::string text = journal_text(s);
  const std::vector<json> lines = journal_lines_of(text);
  const SweepConfig config = small_config();
  ASSERT_FALSE(lines.empty());
  const json& header = lines[0];
  EXPECT_EQ(header.at("seed"), config.seed);
  ASSERT_EQ(header.at("cells").size(), 1U);
  EXPECT_EQ(header.at("cells")[0].at("cell"), "uniform/16x16/0.1");
  EXPECT_EQ(header.at("cells")[0].at("size"), json({16, 16}));
  EXPECT_EQ(header.at("planners").size(), 2U);
  const auto metrics = header.at("metrics").get<std::vector<std::string>>();
  EXPECT_EQ(metrics, journal_metric_names());
  std::size_t maps = 0;
  std::size_t runs = 0;
  std::set<std::pair<int, int>> seen_maps;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const json& r = lines[i];
    EXPECT_FALSE(r.contains("tool") || r.contains("journal_version") || r.contains("config_hash"))
        << r;
    if (r.value("record", "") == "map") {
      ++maps;
      EXPECT_TRUE(r.contains("obstacle_fraction") && r.contains("rejections")) << r;
      EXPECT_TRUE(r.contains("optimal_length")) << "the successful runs computed it: " << r;
      EXPECT_TRUE(seen_maps.insert({r.at("cell").get<int>(), r.at("map_index").get<int>()}).second)
          << "one map record per map: " << r;
      continue;
    }
    ++runs;
    // The map's record comes first, in the same write.
    EXPECT_TRUE(seen_maps.count({r.at("cell").get<int>(), r.at("map_index").get<int>()})) << r;
    for (const char* key : {"task_id", "seed", "generator", "size", "density", "map", "timing",
                            "planner_name", "config_hash"})
      EXPECT_FALSE(r.contains(key)) << key << " in " << r;
    ASSERT_EQ(r.at("outcome"), "success") << r;
    const auto mask = r.at("mask").get<std::uint64_t>();
    const json& values = r.at("metrics");
    std::size_t next = 0;
    for (std::size_t bit = 0; bit < metrics.size(); ++bit) {
      if ((mask >> bit & 1) == 0) continue;
      const json& v = values.at(next++);
      const std::string& name = metrics[bit];
      // Rebuilt by the reader: never written.
      for (const char* derived : {"path_length_m", "min_clearance_m", "smoothness_mean",
                                  "optimality_ratio", "any_angle_ratio", "scen_ratio"})
        EXPECT_NE(name, derived);
      if (name == "waypoints" || name == "turns" || name == "collision_checks" ||
          name == "search_expansions") {
        EXPECT_TRUE(v.is_number_integer()) << name << " " << v;
      }
    }
    EXPECT_EQ(next, values.size());
    EXPECT_EQ(text.find("null"), std::string::npos);
  }
  EXPECT_EQ(maps, 6U);
  EXPECT_EQ(runs, 12U);
}

// Every slot of `a` equals `b`'s bit for bit (metrics, time, phases and extras by name).
void expect_same_slots(const SweepResults& a, const SweepResults& b) {
  for (std::int64_t t = 0; t < a.plan.map_tasks(); ++t) {
    EXPECT_EQ(a.map(t).done, b.map(t).done);
    EXPECT_EQ(a.map(t).rejections, b.map(t).rejections);
    EXPECT_EQ(a.map(t).obstacle_fraction, b.map(t).obstacle_fraction);
    for (std::size_t p = 0; p < a.labels.size(); ++p) {
      const RunSlot& x = a.run(t, p);
      const RunSlot& y = b.run(t, p);
      ASSERT_EQ(x.done, y.done) << t << " " << p;
      EXPECT_EQ(x.outcome, y.outcome);
      EXPECT_EQ(x.plan_time_ns, y.plan_time_ns);
      for (std::size_t m = 0; m < x.metrics.size(); ++m) {
        std::uint64_t bx = 0;
        std::uint64_t by = 0;
        std::memcpy(&bx, &x.metrics[m], sizeof bx);
        std::memcpy(&by, &y.metrics[m], sizeof by);
        if (!(std::isnan(x.metrics[m]) && std::isnan(y.metrics[m]))) {
          EXPECT_EQ(bx, by) << kRunMetricNames[m] << " " << x.metrics[m] << " " << y.metrics[m];
        }
      }
      std::map<std::string, double> ex(x.extra.begin(), x.extra.end());
      std::map<std::string, double> ey(y.extra.begin(), y.extra.end());
      EXPECT_EQ(ex, ey);
      std::map<std::string, std::int64_t> px;
      std::map<std::string, std::int64_t> py;
      for (const auto& ph : x.phases) px[ph.name] = ph.ns;
      for (const auto& ph : y.phases) py[ph.name] = ph.ns;
      EXPECT_EQ(px, py);
    }
  }
}

TEST(JournalFormat, RestoredSlotsEqualTheRunsBitForBit) {
  Scratch s("exact");
  // Planners with extras, failures with messages and a scenario of many metrics.
  const SweepConfig config =
      parse_config(json{{"name", "exact"},
                        {"generators", {"uniform", "maze"}},
                        {"sizes", {16, 24}},
                        {"densities", {0.1, 0.3}},
                        {"maps_per_cell", 3},
                        {"planners",
                         {"astar",
                          "hma_star",
                          "prm",
                          "aco",
                          {{"name", "rrt"}, {"params", {{"max_iterations", 40}}}}}},
                        {"report", "unused.json"}});
  SweepOptions options;
  options.threads = 2;
  options.runs_path = s.path("j.jsonl");
  const SweepResults ran = run_sweep(config, options);
  SweepResults restored = empty_results(config);
  RunMessages messages;
  const JournalStats stats = restore_journal(options.runs_path, restored, &messages);
  EXPECT_EQ(stats.records, coverage_of(ran).runs_present);
  EXPECT_TRUE(stats.has_header);
  expect_same_slots(ran, restored);
  EXPECT_FALSE(messages.empty()) << "rrt's limit failures carry their message";
  EXPECT_EQ(deterministic_part(build_report(config, ran)),
            deterministic_part(build_report(config, restored)));
}

TEST(JournalFormat, AResumeAfterATornLineAppendsTheRestAndGivesTheSameReport) {
  Scratch s("torn");
  const std::string text = journal_text(s);
  const SweepConfig config = small_config();
  SweepResults whole = empty_results(config);
  restore_journal(s.path("source.jsonl"), whole);
  // The header, two maps' writes and half of a line of the third.
  std::size_t cut = 0;
  for (int line = 0; line < 7; ++line) cut = text.find('\n', cut) + 1;
  cut += 20;
  const std::string path = s.path("resumed.jsonl");
  write_file(path, text.substr(0, cut));
  SweepOptions options;
  options.threads = 2;
  options.resume_path = path;
  const SweepResults resumed = run_sweep(config, options);
  EXPECT_EQ(resumed.restored_runs, 4);
  const std::string after = read_file(path);
  EXPECT_EQ(after.substr(0, cut - 20), text.substr(0, cut - 20)) << "the torn line is cut";
  std::size_t headers = 0;
  std::size_t runs = 0;
  for (const json& r : journal_lines_of(after)) {
    headers += r.contains("journal_version") ? 1 : 0;
    runs += r.contains("planner") ? 1 : 0;
  }
  EXPECT_EQ(headers, 1U) << "a resume appends to the header it found";
  EXPECT_EQ(runs, 12U);
  SweepResults again = empty_results(config);
  restore_journal(path, again);
  EXPECT_EQ(deterministic_part(build_report(config, resumed)),
            deterministic_part(build_report(config, whole)));
  EXPECT_EQ(deterministic_part(build_report(config, again)),
            deterministic_part(build_report(config, whole)));
}

// --runs-out J.jsonl.gz (issue 46 stage 4b): the same lines as a plain journal, gzip-compressed a
// member per write; a member cut short is left out and cut by a resume, which then gives the
// uninterrupted report; bytes that are not gzip further on are damage, named.
TEST(JournalFormat, AGzipJournalHoldsThePlainLinesAndResumesAfterATornMember) {
  Scratch s("gzip");
  const std::string plain = journal_text(s);
  const SweepConfig config = small_config();
  SweepOptions options;
  options.threads = 1;
  options.runs_path = s.path("runs.jsonl.gz");
  const SweepResults full = run_sweep(config, options);
  const std::string packed = read_file(options.runs_path);
  ASSERT_GE(packed.size(), 2U);
  EXPECT_EQ(static_cast<unsigned char>(packed[0]), 0x1f);
  EXPECT_EQ(static_cast<unsigned char>(packed[1]), 0x8b);
  EXPECT_LT(packed.size(), plain.size());
  // The same lines but for the runs' times and the sweep's id.
  const auto untimed = [](const std::string& lines) {
    std::vector<json> out = journal_lines_of(lines);
    for (json& r : out) {
      r.erase("plan_time_ns");
      r.erase("phases");
      r.erase("sweep_id");
    }
    return out;
  };
  std::string text, line;
  JournalLineReader reader(options.runs_path);
  while (reader.next(line)) text += line + "\n";
  EXPECT_EQ(untimed(text), untimed(plain));
  EXPECT_FALSE(reader.torn());
  EXPECT_EQ(reader.intact_bytes(), packed.size());
  // Cut in the middle of a member: the whole members before it are read, the rest run again.
  const std::string torn = s.path("torn.jsonl.gz");
  write_file(torn, packed.substr(0, packed.size() * 2 / 3));
  SweepResults restored = empty_results(config);
  const JournalStats stats = restore_journal(torn, restored);
  EXPECT_EQ(stats.torn_lines, 1);
  EXPECT_GT(stats.records, 0);
  EXPECT_LT(stats.records, 12);
  SweepOptions resume;
  resume.threads = 2;
  resume.resume_path = torn;
  const SweepResults resumed = run_sweep(config, resume);
  EXPECT_EQ(resumed.restored_runs, stats.records);
  EXPECT_EQ(deterministic_part(build_report(config, resumed)),
            deterministic_part(build_report(config, full)));
  JournalLineReader after(torn);
  std::int64_t runs = 0;
  while (after.next(line)) runs += line.find("\"planner\"") != std::string::npos ? 1 : 0;
  EXPECT_FALSE(after.torn()) << "the torn member is cut before the resume appends";
  EXPECT_EQ(runs, 12);
  // Bytes that are not gzip inside the chain are damage, not a torn tail.
  const std::string damaged = s.path("damaged.jsonl.gz");
  write_file(damaged, packed.substr(0, 40) + std::string(64, 'x') + packed.substr(40));
  SweepResults none = empty_results(config);
  const std::string why = input_error([&] { restore_journal(damaged, none); });
  EXPECT_NE(why.find("damaged gzip data"), std::string::npos) << why;
  EXPECT_NE(why.find(damaged), std::string::npos) << why;
}

TEST(JournalFormat, AVersion1JournalIsReadAndResumedWithAVersion2Segment) {
  // tests/data/journal_v1: a version 1 journal of its config, written by agvbench at e70d28e.
  Scratch s("v1");
  const std::string dir = std::string(AGV_SOURCE_DIR) + "/tests/data/journal_v1/";
  const SweepConfig config = load_config(dir + "config.json");
  const SweepResults fresh = run_sweep(config, {});
  const json want = deterministic_part(build_report(config, fresh));
  SweepResults merged = empty_results(config);
  RunMessages messages;
  const JournalStats stats = restore_journal(dir + "journal.jsonl", merged, &messages);
  EXPECT_EQ(stats.records, 36);
  EXPECT_FALSE(stats.has_header);
  EXPECT_EQ(messages.size(), 12U);
  EXPECT_EQ(deterministic_part(build_report(config, merged)), want);
  // Resumed: the rest is appended after a version 2 header; the file reads back whole.
  const std::string v1 = read_file(dir + "journal.jsonl");
  std::size_t cut = 0;
  for (int line = 0; line < 20; ++line) cut = v1.find('\n', cut) + 1;
  const std::string path = s.path("v1.jsonl");
  write_file(path, v1.substr(0, cut));
  SweepOptions options;
  options.resume_path = path;
  const SweepResults resumed = run_sweep(config, options);
  EXPECT_EQ(resumed.restored_runs, 20);
  EXPECT_EQ(deterministic_part(build_report(config, resumed)), want);
  SweepResults again = empty_results(config);
  EXPECT_EQ(restore_journal(path, again).records, 36);
  EXPECT_EQ(deterministic_part(build_report(config, again)), want);
}

TEST(JournalFormat, AMalformedRecordIsRefusedNamingFileAndLine) {
  Scratch s("malformed");
  const std::string text = journal_text(s);
  const std::vector<json> lines = journal_lines_of(text);
  const SweepConfig config = small_config();
  // Line `n` (1-based) replaced by `edited`.
  const auto refusal = [&](std::size_t n, const json& edited) {
    std::string out;
    for (std::size_t i = 0; i < lines.size(); ++i)
      out += (i + 1 == n ? edited : lines[i]).dump() + "\n";
    const std::string path = s.path("edited.jsonl");
    write_file(path, out);
    SweepResults res = empty_results(config);
    return input_error([&] { restore_journal(path, res); });
  };
  json run = lines[2];
  ASSERT_TRUE(run.contains("planner"));
  json fewer = run;
  fewer["metrics"].erase(fewer["metrics"].size() - 1);
  EXPECT_NE(refusal(3, fewer).find("edited.jsonl:3: \"metrics\" holds fewer values than its mask"),
            std::string::npos);
  json cell = run;
  cell["cell"] = 7;
  EXPECT_NE(refusal(3, cell).find("edited.jsonl:3: \"cell\" 7 is not an index of the header's"),
            std::string::npos);
  json kind = lines[1];
  kind["record"] = "mystery";
  EXPECT_NE(refusal(2, kind).find("edited.jsonl:2: unknown record kind \"mystery\""),
            std::string::npos);
  json outcome = run;
  outcome["outcome"] = "splendid";
  EXPECT_NE(refusal(3, outcome).find("edited.jsonl:3: unknown outcome"), std::string::npos);
  json no_time = run;
  no_time.erase("plan_time_ns");
  EXPECT_NE(refusal(3, no_time).find("edited.jsonl:3: malformed journal record"),
            std::string::npos);
  // A run record without a header before it.
  const std::string path = s.path("headless.jsonl");
  write_file(path, text.substr(text.find('\n') + 1));
  SweepResults res = empty_results(config);
  EXPECT_NE(input_error([&] {
              restore_journal(path, res);
            }).find("headless.jsonl:1: not a record of this agvbench's journal format"),
            std::string::npos);
}

// A process id that is no longer alive: a child that has exited and been reaped.
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

TEST(ReportWrite, TemporariesOfDeadWritersAreRemovedThoseOfLiveOnesKept) {
  Scratch s("stale");
  const std::string report = s.path("r.json");
  const std::string stale = report + ".tmp." + std::to_string(dead_pid());
  const std::string live = report + ".tmp." + std::to_string(::getppid());
  const std::string other = s.path("other.json.tmp.1");
  for (const auto& p : {stale, live, other}) write_file(p, "{");
  write_json_atomic(json{{"a", 1}}, report);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(other));
  EXPECT_EQ(json::parse(read_file(report))["a"], 1);
}

TEST(ReportWrite, AFailedWriteNamesTheReportAndTheOsErrorAndKeepsTheOldOne) {
  Scratch s("failed");
  const std::string report = s.path("r.json");
  write_json_atomic(json{{"old", true}}, report);
  json big = json::array();
  for (int i = 0; i < 1000; ++i) big.push_back("a string that makes the report long");
  std::string msg;
  {
    const FileSizeLimit limit(1000);
    try {
      write_json_atomic(big, report);
    } catch (const std::runtime_error& e) {
      msg = e.what();
    }
  }
  EXPECT_NE(msg.find("cannot write \"" + report + "\""), std::string::npos) << msg;
  EXPECT_NE(msg.find("File too large"), std::string::npos) << msg;
  EXPECT_EQ(json::parse(read_file(report))["old"], true);
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(fs::path(report).parent_path()))
    files += e.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 1U) << "the temporary was left behind";
}

TEST(ReportWrite, TextThatIsNotUtf8IsWrittenNotRefused) {
  Scratch s("utf8");
  const std::string report = s.path("r.json");
  write_json_atomic(json{{"map", std::string("caf\xe9.map")}}, report);
  const json back = json::parse(read_file(report));
  EXPECT_EQ(back["map"], "caf\xef\xbf\xbd.map");  // U+FFFD for the stray byte
}

}  // namespace
}  // namespace agv
