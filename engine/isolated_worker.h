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
// runner's own run_map_task (engine/map_task.h), answering with each run's record
// (engine/run_record.h) as soon as the run is done. The parent gives every run its own hard
// limit; after a fault it starts a fresh worker on the task's remaining planners. Workers are
// started with posix_spawn, which is safe from a multi-threaded parent (no fork of a process
// holding other threads' locks).

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "engine/run_executor.h"

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
  WorkerProcess(std::vector<std::string> command, std::int64_t memory_mb, std::string config_line);
  ~WorkerProcess();
  WorkerProcess(const WorkerProcess&) = delete;
  WorkerProcess& operator=(const WorkerProcess&) = delete;

  struct Reply {
    bool ok = false;  // record holds the worker's record
    nlohmann::json record;
    Outcome outcome = Outcome::crash;  // when !ok: timeout or crash
    std::string message;
    std::int64_t wall_ns = 0;
  };
  // Asks for the runs of `planners` (config indices, in this order) on map task `task`; starts
  // a worker first when none is running (none is after a reply that is not ok).
  void start_task(std::int64_t task, std::span<const std::size_t> planners);
  // The reply of the task's next run, within hard_limit_s of this call. A reply that is not ok
  // leaves no worker: the task's remaining planners need start_task again.
  Reply next_run(double hard_limit_s);

 private:
  using Clock = std::chrono::steady_clock;
  enum class ReadStatus { line, timeout, closed };
  // Throws std::runtime_error when the worker cannot start or refuses the config.
  void spawn();
  // The worker's next line, unless the deadline passes or the worker's stdout closes first.
  ReadStatus read_line(Clock::time_point deadline, std::string& line);
  void stop();  // kill and reap
  std::string describe_exit();

  std::vector<std::string> command_;
  std::int64_t memory_mb_;
  std::string config_line_;
  pid_t pid_ = -1;
  int to_child_ = -1;
  int from_child_ = -1;
  std::string buffer_;
};

// The worker side: `agvbench worker --memory-mb N` (or a test binary's equivalent). Returns the
// process exit code.
int worker_main(std::int64_t memory_mb);

}  // namespace agv
