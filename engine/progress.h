#pragma once
// A one-line progress meter on stderr for long sweeps, redrawn a few times a second from its
// own thread; silent when stderr is not a terminal (CI logs, pipes). Debian packages no C++
// progress-bar library, hence these few lines.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>

namespace agv {

class ProgressMeter {
 public:
  ProgressMeter(std::int64_t total, bool enabled);
  ~ProgressMeter();
  ProgressMeter(const ProgressMeter&) = delete;
  ProgressMeter& operator=(const ProgressMeter&) = delete;

  void advance(std::int64_t n = 1) { done_.fetch_add(n, std::memory_order_relaxed); }
  // Stops the meter and clears its line.
  void finish();

 private:
  void draw() const;

  std::int64_t total_;
  bool enabled_;
  std::atomic<std::int64_t> done_{0};
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace agv
