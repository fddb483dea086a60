#pragma once
// Fault isolation (`agvbench run --isolate`): runs execute in child worker processes, each with
// an address-space cap (RLIMIT_AS), under a hard wall-clock limit enforced by the parent. A
// planner that hangs, crashes, throws or exhausts memory costs one run (outcome timeout, crash
// or oom) and one worker restart; the sweep goes on.
//
// Protocol, one JSON object per line over the worker's stdin/stdout: the parent sends the config
// as run ({"config": ...}) once, and the worker answers {"ready": true}, or {"fatal": message}
// when it cannot take that config (a failed sweep, not a crashed run); then the parent requests
// map tasks, {"task": t, "planners": [p, ...]}, and the worker runs them with the in-process
// runner's own run_map_task (engine/sweep/map_task.h), answering as soon as each run is done with
// the two journal lines of it, its map record and its run record (engine/outputs/run_record.h): the
// channel speaks the journal's format, decoded by the journal's one decoder. The parent gives every
// run its own hard limit; after a fault it starts a fresh worker on the task's remaining planners.
// Workers are started with posix_spawn, which is safe from a multi-threaded parent (no fork of a
// process holding other threads' locks).
//
// Interruption (README "Long sweeps", Interruption): each worker runs in a process group of
// its own, so a terminal's Ctrl-C (SIGINT to the foreground process group) reaches the parent
// alone, which lets the runs in flight finish. When the parent is asked to cut them short
// (`cut_short` set), it kills the worker; such a run, like one whose worker died of SIGINT,
// SIGTERM, SIGHUP or SIGQUIT (a signal sent to it, not a fault of the planner), is answered as
// cut: it is not a result, is not recorded, and runs again on resume.

#include <sys/types.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/judge/run_executor.h"

namespace agv {

struct IsolationOptions {
  bool enabled = false;
  double hard_limit_s = 0.0;      // per run; 0 = twice the config's time_limit_s + 1 s
  std::int64_t memory_mb = 4096;  // RLIMIT_AS of each worker
  // The worker program: default this executable's `worker` subcommand. Tests pass their own
  // binary, whose registry has deliberately faulty planners.
  std::vector<std::string> command;
};

class WorkerProcess {
 public:
  // `cut_short`, when given, is polled while a run is awaited: once it is set the worker is
  // killed and the run answered as cut.
  WorkerProcess(std::vector<std::string> command, std::int64_t memory_mb, std::string config_line,
                const std::atomic<bool>* cut_short = nullptr);
  ~WorkerProcess();
  WorkerProcess(const WorkerProcess&) = delete;
  WorkerProcess& operator=(const WorkerProcess&) = delete;

  struct Reply {
    bool ok = false;  // the worker's records of the run, decoded by the caller
    std::string map_line;
    std::string run_line;
    Outcome outcome = Outcome::crash;  // when !ok: timeout or crash
    // When !ok: an interruption ended the run (see above), so it has no outcome to record.
    bool cut = false;
    std::string message;
    std::int64_t wall_ns = 0;  // the parent's wait for the reply
    // When !ok: the worker's CPU time during that wait (its process CPU clock, or for a worker
    // that died what wait4 reports), -1 when it could not be read: a lost run's planning time,
    // the clock every other run's is measured on.
    std::int64_t cpu_ns = -1;
  };
  // Asks for the runs of `planners` (config indices, in this order) on map task `task`; starts
  // a worker first when none is running (none is after a reply that is not ok).
  void start_task(std::int64_t task, std::span<const std::size_t> planners);
  // The reply of the task's next run, within hard_limit_s of this call. A reply that is not ok
  // leaves no worker: the task's remaining planners need start_task again.
  Reply next_run(double hard_limit_s);
  // Kills the worker (its group) and reaps it; the next start_task starts a fresh one.
  void stop();

 private:
  using Clock = std::chrono::steady_clock;
  enum class ReadStatus { line, timeout, closed, cut };
  // Throws std::runtime_error when the worker cannot start or refuses the config, and
  // RunsCut when cut_short is set before it is ready.
  void spawn();
  // The worker's next line, unless the deadline passes, the worker's stdout closes or
  // cut_short is set first.
  ReadStatus read_line(Clock::time_point deadline, std::string& line);
  // Reaps the exited worker; `interrupted` tells whether a signal that asks a process to stop
  // (not a fault) ended it, `cpu_ns` the CPU time it used in all (-1 if unknown).
  std::string describe_exit(bool& interrupted, std::int64_t& cpu_ns);
  // The running worker's CPU time so far (its process CPU clock), -1 if it cannot be read.
  std::int64_t cpu_time_ns() const;
  bool cut_requested() const { return cut_short_ != nullptr && cut_short_->load(); }

  std::vector<std::string> command_;
  std::int64_t memory_mb_;
  std::string config_line_;
  const std::atomic<bool>* cut_short_;
  pid_t pid_ = -1;
  int to_child_ = -1;
  int from_child_ = -1;
  std::string buffer_;
};

// The worker side: `agvbench worker --memory-mb N` (or a test binary's equivalent). Returns the
// process exit code.
int worker_main(std::int64_t memory_mb);

// Thrown by WorkerProcess when a stop request cut it short before a run began: nothing to record.
struct RunsCut : std::runtime_error {
  RunsCut() : std::runtime_error("cut short by a stop request") {}
};

}  // namespace agv
