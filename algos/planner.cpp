#include "algos/planner.h"

#include <ctime>

namespace agv {

const char* to_string(Failure f) {
  switch (f) {
    case Failure::none:
      return "none";
    case Failure::no_path:
      return "no_path";
    case Failure::limit:
      return "limit";
    case Failure::invalid_path:
      return "invalid_path";
    case Failure::invalid_input:
      return "invalid_input";
  }
  return "unknown";
}

std::int64_t thread_cpu_ns() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

}  // namespace agv
