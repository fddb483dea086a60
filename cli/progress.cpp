#include "cli/progress.h"

#include <unistd.h>

namespace agv {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Which 5 % step `done` has reached (0 .. 20).
std::int64_t step_of(std::int64_t done, std::int64_t total) {
  if (total <= 0) return 0;
  return done * (100 / ProgressMeter::kLogStepPercent) / total;
}

}  // namespace

ProgressMeter::ProgressMeter(std::int64_t total, bool enabled, std::FILE* out)
    : total_(total),
      enabled_(enabled),
      terminal_(enabled && isatty(fileno(out)) != 0),
      out_(out),
      start_(std::chrono::steady_clock::now()),
      last_line_(start_) {
  if (!enabled_) return;
  thread_ = std::thread([this] {
    std::unique_lock lock(mutex_);
    while (!stop_) {
      if (terminal_) {
        draw();
        wake_.wait_for(lock, std::chrono::milliseconds(250));
      } else {
        // The threshold lines come from advance(); this one keeps a slow sweep's log alive.
        if (std::chrono::steady_clock::now() - last_line_ >= kLogInterval)
          log_line_locked(done_.load(std::memory_order_relaxed));
        wake_.wait_for(lock, std::chrono::seconds(1));
      }
    }
  });
}

ProgressMeter::~ProgressMeter() { finish(); }

void ProgressMeter::advance(std::int64_t n) {
  const std::int64_t before = done_.fetch_add(n, std::memory_order_relaxed);
  if (!enabled_ || terminal_) return;
  if (step_of(before + n, total_) == step_of(before, total_)) return;
  std::lock_guard lock(mutex_);
  // Another thread may have logged a later count meanwhile: print the newest one only.
  const std::int64_t done = done_.load(std::memory_order_relaxed);
  if (step_of(done, total_) > step_of(last_logged_, total_) || last_logged_ < 0)
    log_line_locked(done);
}

void ProgressMeter::log_line_locked(std::int64_t done) {
  const double elapsed = seconds_since(start_);
  const double rate = elapsed > 0.0 ? static_cast<double>(done) / elapsed : 0.0;
  const double pct =
      total_ > 0 ? 100.0 * static_cast<double>(done) / static_cast<double>(total_) : 100.0;
  char eta[32] = "-";
  if (rate > 0.0)
    std::snprintf(eta, sizeof eta, "%.0f s", static_cast<double>(total_ - done) / rate);
  std::fprintf(
      out_, "agvbench: progress %lld/%lld runs (%.1f%%), %.1f runs/s, %.0f s elapsed, ETA %s\n",
      static_cast<long long>(done), static_cast<long long>(total_), pct, rate, elapsed, eta);
  std::fflush(out_);
  last_logged_ = done;
  last_line_ = std::chrono::steady_clock::now();
}

void ProgressMeter::finish() {
  if (!enabled_) return;
  {
    std::lock_guard lock(mutex_);
    if (stop_) return;
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
  if (terminal_) {
    std::fprintf(out_, "\r\033[K");
    std::fflush(out_);
    return;
  }
  std::lock_guard lock(mutex_);
  const std::int64_t done = done_.load(std::memory_order_relaxed);
  if (done != last_logged_) log_line_locked(done);
}

void ProgressMeter::draw() const {
  const std::int64_t done = done_.load(std::memory_order_relaxed);
  const double frac = total_ > 0 ? static_cast<double>(done) / static_cast<double>(total_) : 1.0;
  const double elapsed = seconds_since(start_);
  const double eta = frac > 0.0 ? elapsed * (1.0 - frac) / frac : 0.0;
  const double rate = elapsed > 0.0 ? static_cast<double>(done) / elapsed : 0.0;
  constexpr int kWidth = 30;
  char bar[kWidth + 1];
  const int filled = static_cast<int>(frac * kWidth);
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '.';
  bar[kWidth] = '\0';
  std::fprintf(out_,
               "\r[%s] %5.1f%%  %lld/%lld runs  %.0f runs/s  %.0f s elapsed, ETA %.0f s\033[K", bar,
               100.0 * frac, static_cast<long long>(done), static_cast<long long>(total_), rate,
               elapsed, eta);
  std::fflush(out_);
}

}  // namespace agv
