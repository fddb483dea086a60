#include "engine/progress.h"

#include <unistd.h>

#include <cstdio>

namespace agv {

ProgressMeter::ProgressMeter(std::int64_t total, bool enabled)
    : total_(total),
      enabled_(enabled && isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()) {
  if (!enabled_) return;
  thread_ = std::thread([this] {
    std::unique_lock lock(mutex_);
    while (!stop_) {
      draw();
      wake_.wait_for(lock, std::chrono::milliseconds(250));
    }
  });
}

ProgressMeter::~ProgressMeter() { finish(); }

void ProgressMeter::finish() {
  if (!enabled_) return;
  {
    std::lock_guard lock(mutex_);
    if (stop_) return;
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
}

void ProgressMeter::draw() const {
  const std::int64_t done = done_.load(std::memory_order_relaxed);
  const double frac = total_ > 0 ? static_cast<double>(done) / static_cast<double>(total_) : 1.0;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double eta = frac > 0.0 ? elapsed * (1.0 - frac) / frac : 0.0;
  constexpr int kWidth = 30;
  char bar[kWidth + 1];
  const int filled = static_cast<int>(frac * kWidth);
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '.';
  bar[kWidth] = '\0';
  std::fprintf(stderr, "\r[%s] %5.1f%%  %lld/%lld maps  %.0fs elapsed, ~%.0fs left\033[K", bar,
               100.0 * frac, static_cast<long long>(done), static_cast<long long>(total_), elapsed,
               eta);
  std::fflush(stderr);
}

}  // namespace agv
