// Fault isolation: deliberately faulty planners, compiled into this test binary only, run under
// `--isolate`-style worker processes (this binary is its own worker). Each fault costs exactly
// one run, recorded with its outcome within 1.25x the hard limit; every other run is present.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <string>
#include <thread>
#include <vector>

#include "algos/registry.h"
#include "engine/outputs/report.h"
#include "engine/plan/config_loader.h"
#include "engine/sweep/isolated_worker.h"
#include "engine/sweep/sweep_runner.h"
#include "engine/system/stray_children.h"

#if AGV_SANITIZED_BUILD  // tests/CMakeLists.txt: ASan, TSan or the fuzz tree, GCC or clang
constexpr bool kSanitized = true;  // sanitizers reserve terabytes of address space: no RLIMIT_AS
#else
constexpr bool kSanitized = false;
#endif

namespace agv {
namespace {

std::string g_self;

enum class Fault { hang, segfault, throws, hog, chatter, spawner };

// A planner that prints (a line that looks like a record, bytes that are not UTF-8) and reads
// stdin, then gives up with a message that is not UTF-8 either: none of it may reach the
// worker's channel.
PlanResult chatter() {
  std::cout << "{\"task_id\": \"forged\"}" << std::endl;
  std::printf("\xff\xfe not text\n");
  std::fflush(stdout);
  char c = 0;
  const ssize_t got = ::read(STDIN_FILENO, &c, 1);  // /dev/null in a worker: nothing
  return PlanResult::failed(Failure::limit, got > 0 ? "read the channel" : "gave up \xff");
}

// A planner that starts a process (which would sleep for a minute), notes its pid in
// $AGV_TEST_SPAWN_DIR, then hangs: the worker is killed at the hard limit, and the child with it.
[[noreturn]] void spawn_then_hang() {
  const pid_t child = ::fork();
  if (child == 0) {
    ::sleep(60);
    ::_exit(0);
  }
  if (const char* dir = std::getenv("AGV_TEST_SPAWN_DIR"); dir != nullptr && child > 0)
    std::ofstream(std::string(dir) + "/" + std::to_string(child)) << child;
  for (volatile bool spin = true; spin;) {
  }
  std::abort();
}

class FaultyPlanner : public Planner {
 public:
  explicit FaultyPlanner(Fault f) : fault_(f) {}
  // Faults on every run, so the expected counts are exact.
  PlanResult plan(const PlanRequest&) const override {
    switch (fault_) {
      case Fault::hang:
        for (volatile bool spin = true; spin;) {
        }
        break;
      case Fault::segfault:
        std::raise(SIGSEGV);
        break;
      case Fault::throws:
        throw std::runtime_error("deliberate failure");
      case Fault::hog: {
        std::vector<std::vector<char>> hog;
        for (;;) hog.emplace_back(std::size_t{64} << 20, char{1});
      }
      case Fault::chatter:
        return chatter();
      case Fault::spawner:
        spawn_then_hang();
    }
    return PlanResult::failed(Failure::invalid_input, "unreachable");
  }

 private:
  Fault fault_;
};

template <Fault F>
std::unique_ptr<Planner> make_faulty(const Params&) {
  return std::make_unique<FaultyPlanner>(F);
}

PlannerInfo faulty(const std::string& name, Fault f) {
  PlannerInfo info;
  info.name = name;
  info.summary = "deliberately faulty test planner";
  switch (f) {
    case Fault::chatter:
      info.make = make_faulty<Fault::chatter>;
      break;
    case Fault::spawner:
      info.make = make_faulty<Fault::spawner>;
      break;
    case Fault::hang:
      info.make = [](const Params&) -> std::unique_ptr<Planner> {
        return std::make_unique<FaultyPlanner>(Fault::hang);
      };
      break;
    case Fault::segfault:
      info.make = [](const Params&) -> std::unique_ptr<Planner> {
        return std::make_unique<FaultyPlanner>(Fault::segfault);
      };
      break;
    case Fault::throws:
      info.make = [](const Params&) -> std::unique_ptr<Planner> {
        return std::make_unique<FaultyPlanner>(Fault::throws);
      };
      break;
    case Fault::hog:
      info.make = [](const Params&) -> std::unique_ptr<Planner> {
        return std::make_unique<FaultyPlanner>(Fault::hog);
      };
      break;
  }
  return info;
}

void register_faulty_planners() {
  add_planner_for_testing(faulty("test_hang", Fault::hang));
  add_planner_for_testing(faulty("test_segfault", Fault::segfault));
  add_planner_for_testing(faulty("test_throw", Fault::throws));
  add_planner_for_testing(faulty("test_hog", Fault::hog));
  add_planner_for_testing(faulty("test_chatter", Fault::chatter));
  add_planner_for_testing(faulty("test_spawner", Fault::spawner));
}

SweepConfig faulty_config(std::vector<std::string> faulty_names) {
  nlohmann::json planners = nlohmann::json::array({"astar"});
  for (auto& n : faulty_names) planners.push_back(n);
  planners.push_back("dijkstra");
  return parse_config({{"sizes", {16}},
                       {"densities", {0.1}},
                       {"maps_per_cell", 4},
                       {"time_limit_s", 0.5},
                       {"planners", planners}});
}

SweepOptions isolated(double hard_limit_s) {
  SweepOptions o;
  o.threads = 2;
  o.isolation.enabled = true;
  o.isolation.hard_limit_s = hard_limit_s;
  o.isolation.memory_mb = kSanitized ? 0 : 256;
  o.isolation.command = {g_self, "--agv-worker"};
  return o;
}

std::array<std::int64_t, kOutcomeCount> outcomes(const SweepResults& r, std::size_t planner) {
  std::array<std::int64_t, kOutcomeCount> n{};
  for (std::int64_t t = 0; t < r.plan.map_tasks(); ++t) {
    EXPECT_TRUE(r.run(t, planner).done);
    ++n[static_cast<int>(r.run(t, planner).outcome)];
  }
  return n;
}

TEST(Isolation, EveryFaultCostsOneRunAndIsRecorded) {
  std::vector<std::string> names = {"test_hang", "test_segfault", "test_throw"};
  if (!kSanitized) names.push_back("test_hog");
  const SweepConfig config = faulty_config(names);
  const double hard = 2.0;  // room for the hog to reach its cap on a loaded machine
  SweepOptions options = isolated(hard);
  options.runs_path =
      (std::filesystem::temp_directory_path() / ("agv_faults_" + std::to_string(::getpid())))
          .string();
  const auto t0 = std::chrono::steady_clock::now();
  const SweepResults r = run_sweep(config, options);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_TRUE(r.complete);
  // astar and dijkstra (first and last) are untouched by their neighbours' faults.
  EXPECT_EQ(outcomes(r, 0)[static_cast<int>(Outcome::success)], 4);
  EXPECT_EQ(outcomes(r, names.size() + 1)[static_cast<int>(Outcome::success)], 4);
  // Every faulty run fails, every time, with the outcome of its fault.
  const auto hang = outcomes(r, 1);
  EXPECT_EQ(hang[static_cast<int>(Outcome::timeout)], 4);
  EXPECT_EQ(outcomes(r, 2)[static_cast<int>(Outcome::crash)], 4);
  EXPECT_EQ(outcomes(r, 3)[static_cast<int>(Outcome::crash)], 4);
  if (!kSanitized) {
    const auto hog = outcomes(r, 4);
    EXPECT_EQ(hog[static_cast<int>(Outcome::oom)], 4)
        << "timeouts " << hog[static_cast<int>(Outcome::timeout)] << ", crashes "
        << hog[static_cast<int>(Outcome::crash)];
  }
  // A run that timed out spun on the CPU until it was killed: its planning time is the worker's
  // CPU time, like every other run's (never more than the wall-clock wait, the hard limit and
  // the kill's latency).
  for (std::int64_t t = 0; t < r.plan.map_tasks(); ++t) {
    const RunSlot& s = r.run(t, 1);
    if (s.outcome == Outcome::timeout) {
      EXPECT_GT(s.plan_time_ns, 0);
      EXPECT_LE(static_cast<double>(s.plan_time_ns) / 1e9, 1.25 * hard);
    }
  }
  // Each lost run's message gives the wall-clock wait beside that CPU time.
  std::ifstream in(options.runs_path);
  int lost = 0, with_clocks = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.find("killed at the hard limit") == std::string::npos &&
        line.find("worker killed by signal") == std::string::npos)
      continue;
    ++lost;
    if (line.find(" (wall ") != std::string::npos && line.find(", CPU ") != std::string::npos)
      ++with_clocks;
  }
  EXPECT_GE(lost, 8);  // the hangs and the segfaults at least
  EXPECT_EQ(with_clocks, lost);
  std::filesystem::remove(options.runs_path);
  std::cout << "isolated sweep with " << hang[static_cast<int>(Outcome::timeout)] << " hangs took "
            << wall << " s\n";
}

// What a planner prints or reads never reaches the worker protocol: its runs are recorded with
// its own outcome (limit, the message's bad bytes replaced), no run is a crash, and the sweep
// equals an in-process one.
TEST(Isolation, PlannerOutputNeverReachesTheChannel) {
  const SweepConfig config = faulty_config({"test_chatter"});
  const SweepResults r = run_sweep(config, isolated(10.0));
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(outcomes(r, 1)[static_cast<int>(Outcome::limit)], 4);
  EXPECT_EQ(outcomes(r, 0)[static_cast<int>(Outcome::success)], 4);
  EXPECT_EQ(outcomes(r, 2)[static_cast<int>(Outcome::success)], 4);
}

// Whatever a planner starts dies with its worker: killed at the hard limit, the worker's whole
// process group goes.
TEST(Isolation, AWorkersChildrenDieWithIt) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("agv_spawn_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  ::setenv("AGV_TEST_SPAWN_DIR", dir.c_str(), 1);
  const SweepConfig config = faulty_config({"test_spawner"});
  const SweepResults r = run_sweep(config, isolated(1.0));
  ::unsetenv("AGV_TEST_SPAWN_DIR");
  EXPECT_EQ(outcomes(r, 1)[static_cast<int>(Outcome::timeout)], 4);
  int children = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    ++children;
    const std::string pid = entry.path().filename().string();
    // Gone, or a zombie waiting for init to reap it: never still running (its sleep is 60 s).
    // A SIGKILL takes effect a moment after it is sent: up to 5 s for the last one.
    char state = 'R';
    for (int tries = 0; tries < 500 && state != 'Z' && state != 'X'; ++tries) {
      if (tries > 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
      std::ifstream stat("/proc/" + pid + "/stat");
      std::string text;
      if (!std::getline(stat, text)) {
        state = 'X';  // no such process
        break;
      }
      const std::size_t paren = text.rfind(')');
      state = paren != std::string::npos && paren + 2 < text.size() ? text[paren + 2] : 'X';
    }
    EXPECT_TRUE(state == 'Z' || state == 'X') << "child " << pid << " is in state " << state;
  }
  EXPECT_EQ(children, 4);
  fs::remove_all(dir);
}

// engine/system/stray_children.h: a child that left this process's group (setsid(), as a stray
// of a worker does) is killed and reaped; a child in the group (one a program embedding the
// engine started itself) is left alone.
TEST(Isolation, StraysOutsideOurGroupAreKilledOurOwnChildrenAreNot) {
  const pid_t own = ::fork();
  if (own == 0) {
    ::pause();
    ::_exit(0);
  }
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t stray = ::fork();
  if (stray == 0) {
    ::setsid();
    const char c = 'x';
    (void)!::write(ready[1], &c, 1);
    ::pause();
    ::_exit(0);
  }
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);  // the stray has left our group
  ::close(ready[0]);
  ::close(ready[1]);
  LiveWorkers::kill_strays();
  int status = 0;
  EXPECT_EQ(::waitpid(stray, &status, WNOHANG), -1);  // reaped already
  EXPECT_EQ(::waitpid(own, &status, WNOHANG), 0);     // still running
  ::kill(own, SIGKILL);
  ::waitpid(own, &status, 0);
}

TEST(Isolation, ThrowIsACrashEvenWithoutIsolation) {
  const SweepConfig config = faulty_config({"test_throw"});
  SweepOptions o;
  o.threads = 2;
  const SweepResults r = run_sweep(config, o);
  EXPECT_EQ(outcomes(r, 1)[static_cast<int>(Outcome::crash)], 4);
  EXPECT_EQ(outcomes(r, 0)[static_cast<int>(Outcome::success)], 4);
}

TEST(Isolation, IsolatedReportEqualsInProcessReport) {
  // With a scoped planner: the worker reads the scope back from the config as run.
  const SweepConfig config = parse_config(
      {{"sizes", {20}},
       {"densities", {0.1, 0.3}},
       {"maps_per_cell", 6},
       {"planners",
        {"astar",
         "dijkstra",
         {{"name", "ma_star"}, {"only", {{"densities", {0.3}}, {"maps_per_cell", 4}}}}}}});
  const auto a = deterministic_part(build_report(config, run_sweep(config, isolated(10.0))));
  SweepOptions o;
  o.threads = 2;
  const auto b = deterministic_part(build_report(config, run_sweep(config, o)));
  EXPECT_EQ(a.dump(), b.dump());
}

// A worker that cannot take the sweep is a failed sweep with the worker's reason, not a run
// recorded as a crash on every map.
TEST(Isolation, WorkerThatCannotStartFailsTheSweep) {
  const SweepConfig config = faulty_config({});
  auto message = [&](std::vector<std::string> command) {
    SweepOptions o = isolated(10.0);
    o.isolation.command = std::move(command);
    try {
      run_sweep(config, o);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(
      message({"/bin/false"}).find("isolation worker failed to start: worker exited with code 1"),
      std::string::npos);
  const std::string refused =
      message({"/bin/sh", "-c", "read config; echo '{\"fatal\": \"planners[1]: refused\"}'"});
  EXPECT_NE(refused.find("isolation worker failed to start: planners[1]: refused"),
            std::string::npos)
      << refused;
}

// A worker whose replies are not records (here a script: ready, then two lines of garbage a run)
// costs each run a crash with the reason in its journal record; the sweep goes on.
TEST(Isolation, AGarbledReplyIsACrashOfItsRun) {
  const SweepConfig config = faulty_config({});
  SweepOptions o = isolated(10.0);
  o.isolation.command = {"/bin/sh", "-c",
                         "read config; echo '{\"ready\": true}'; "
                         "while read request; do echo 'not a record'; echo '{}'; done"};
  const std::string journal =
      (std::filesystem::temp_directory_path() / ("agv_garbled_" + std::to_string(::getpid())))
          .string();
  o.runs_path = journal;
  const SweepResults r = run_sweep(config, o);
  EXPECT_TRUE(r.complete);
  for (std::size_t p = 0; p < config.planners.size(); ++p)
    EXPECT_EQ(outcomes(r, p)[static_cast<int>(Outcome::crash)], 4);
  std::ifstream in(journal);
  std::string line;
  int garbled = 0;
  while (std::getline(in, line))
    if (line.find("worker sent a malformed record") != std::string::npos) ++garbled;
  EXPECT_EQ(garbled, 8);
  std::filesystem::remove(journal);
}

}  // namespace
}  // namespace agv

int main(int argc, char** argv) {
  agv::register_faulty_planners();
  if (argc >= 2 && std::strcmp(argv[1], "--agv-worker") == 0) {
    long long memory = 0;
    if (argc >= 4 && std::strcmp(argv[2], "--memory-mb") == 0) memory = std::atoll(argv[3]);
    return agv::worker_main(memory);
  }
  agv::g_self = "/proc/self/exe";
  char buf[4096];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n > 0) agv::g_self.assign(buf, static_cast<std::size_t>(n));
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
