#include "engine/environment.h"

#include <unistd.h>

#include <fstream>
#include <string>
#include <thread>

#include "engine/build_info.h"
#include "engine/git_revision.h"

namespace agv {

namespace {

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      auto colon = line.find(':');
      if (colon != std::string::npos) {
        auto start = line.find_first_not_of(' ', colon + 1);
        return start == std::string::npos ? std::string() : line.substr(start);
      }
    }
  }
  return "unknown";
}

std::string host_name() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0) return "unknown";
  return buf;
}

std::string compiler() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("gcc ") + __VERSION__;
#else
  return "unknown";
#endif
}

}  // namespace

nlohmann::json environment_json(int threads) {
  return {{"compiler", compiler()},
          {"build", kBuildFlags},
          {"git_revision", kGitRevision},
          {"cpu_model", cpu_model()},
          {"hardware_threads", std::thread::hardware_concurrency()},
          {"threads", threads},
          {"host", host_name()}};
}

}  // namespace agv
