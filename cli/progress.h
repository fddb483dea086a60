#pragma once
// Progress of a long sweep on stderr, in runs. On a terminal: one line redrawn a few times a
// second. Elsewhere (Slurm, nohup, a pipe, a file) a redrawn line would be noise, and silence
// would leave an hours-long sweep's log empty until it ends: a plain line at each 5 % of the
// runs and at least every 30 s, with done/total, runs per second and the ETA. Debian packages no
// C++ progress-bar library, hence these few lines.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <thread>

namespace agv {

class ProgressMeter {
 public:
  // A line at each kLogStepPercent of the runs, and after kLogInterval without one.
  static constexpr int kLogStepPercent = 5;
  static constexpr std::chrono::seconds kLogInterval{30};

  // enabled = false: silent. Writes to `out` (stderr by default), a terminal's line when `out`
  // is a terminal, log lines otherwise.
  ProgressMeter(std::int64_t total, bool enabled, std::FILE* out = stderr);
  ~ProgressMeter();
  ProgressMeter(const ProgressMeter&) = delete;
  ProgressMeter& operator=(const ProgressMeter&) = delete;

  // n runs more are done; called from any thread.
  void advance(std::int64_t n = 1);
  // Stops the meter: clears a terminal's line, or logs the last count if it is not logged yet.
  void finish();

 private:
  void draw() const;
  void log_line_locked(std::int64_t done);

  std::int64_t total_;
  bool enabled_;
  bool terminal_ = false;
  std::FILE* out_;
  std::atomic<std::int64_t> done_{0};
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_line_;
  std::int64_t last_logged_ = -1;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace agv
