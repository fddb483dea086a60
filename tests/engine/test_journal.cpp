// The files a sweep writes: paths checked before anything is written, journal writes checked,
// journal versions refused, report temporaries of dead processes removed (issue 15).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "engine/config_loader.h"
#include "engine/journal.h"
#include "engine/output_paths.h"
#include "engine/report.h"
#include "engine/run_record.h"
#include "engine/sweep_config.h"
#include "engine/sweep_runner.h"

namespace agv {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A scratch folder of its own per test, removed afterwards.
class Scratch {
 public:
  explicit Scratch(const std::string& name)
      : dir_(fs::temp_directory_path() /
             ("agv_journal_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  ~Scratch() { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

 private:
  fs::path dir_;
};

void write_file(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

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
  // On one thread the first map's two records are written in one piece: room for them and a
  // little more, so the second map's write fails part-way.
  const std::string text = journal_text(s);
  const std::size_t first_map = text.find('\n', text.find('\n') + 1) + 1;
  const SweepConfig config = small_config();
  SweepOptions options;
  options.threads = 1;
  options.runs_path = s.path("j.jsonl");
  SweepResults res;
  {
    const FileSizeLimit limit(first_map + 100);
    res = run_sweep(config, options);
  }
  EXPECT_NE(res.journal_error.find("journal \"" + options.runs_path + "\""), std::string::npos)
      << res.journal_error;
  EXPECT_NE(res.journal_error.find("File too large"), std::string::npos) << res.journal_error;
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

TEST(JournalVersion, RecordsCarryTheToolAndTheVersion) {
  Scratch s("carry");
  const std::string text = journal_text(s);
  const json first = json::parse(text.substr(0, text.find('\n')));
  EXPECT_EQ(first.at("tool"), "agvbench");
  EXPECT_EQ(first.at("journal_version"), kJournalVersion);
}

TEST(JournalVersion, RestoreRefusesAForeignOrMissingVersionNamingFileAndLine) {
  Scratch s("foreign");
  const std::string text = journal_text(s);
  const std::size_t second = text.find('\n') + 1;
  const json record = json::parse(text.substr(second, text.find('\n', second) - second));
  const SweepConfig config = small_config();
  const auto refusal = [&](const json& edited) {
    const std::string path = s.path("edited.jsonl");
    write_file(path, text.substr(0, second) + edited.dump() + "\n");
    SweepResults res = empty_results(config);
    return input_error([&] { restore_journal(path, res); });
  };
  json foreign = record;
  foreign["journal_version"] = kJournalVersion + 1;
  const std::string newer = refusal(foreign);
  EXPECT_NE(newer.find("edited.jsonl:2:"), std::string::npos) << newer;
  EXPECT_NE(newer.find("journal_version " + std::to_string(kJournalVersion + 1)), std::string::npos)
      << newer;
  EXPECT_NE(
      newer.find("reads tool \"agvbench\", journal_version " + std::to_string(kJournalVersion)),
      std::string::npos)
      << newer;
  json unversioned = record;
  unversioned.erase("journal_version");
  unversioned.erase("tool");
  const std::string none = refusal(unversioned);
  EXPECT_NE(none.find("tool (none), journal_version (none)"), std::string::npos) << none;
  json other_tool = record;
  other_tool["tool"] = "otherbench";
  EXPECT_NE(refusal(other_tool).find("tool \"otherbench\""), std::string::npos);
  EXPECT_EQ(refusal(record), "no error");
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
