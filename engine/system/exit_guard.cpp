#include "engine/system/exit_guard.h"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <mutex>

namespace agv {

namespace {

thread_local const char* t_foreign = nullptr;

void write_stderr(const char* text) {
  std::size_t left = std::strlen(text);
  while (left > 0) {
    const ssize_t n = ::write(STDERR_FILENO, text, left);
    if (n <= 0) return;
    text += n;
    left -= static_cast<std::size_t>(n);
  }
}

// Runs first of the exit handlers registered before the first scope (handlers run in reverse).
void on_exit() {
  if (t_foreign == nullptr) return;
  write_stderr("agvbench: ");
  write_stderr(t_foreign);
  write_stderr(
      " called exit() instead of returning to the engine: the process is ended with status 1 "
      "and what it was writing is incomplete\n");
  ::_exit(1);
}

}  // namespace

ForeignCodeScope::ForeignCodeScope(const char* what) : previous_(t_foreign) {
  static std::once_flag installed;
  std::call_once(installed, [] { std::atexit(on_exit); });
  t_foreign = what;
}

ForeignCodeScope::~ForeignCodeScope() { t_foreign = previous_; }

}  // namespace agv
