#include "engine/system/environment.h"

#include <unistd.h>

#include <cstdlib>
#include <ctime>
#include <fstream>
#include <string>
#include <thread>

#include "core/simd_path.h"
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

// 1, 5 and 15 minute load averages; null where the system does not say.
nlohmann::json load_average() {
  double load[3] = {};
  if (getloadavg(load, 3) != 3) return nullptr;
  return {load[0], load[1], load[2]};
}

}  // namespace

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buf;
}

std::string version_text() {
  return std::string("agvbench ") + AGV_VERSION + " (git " + kGitRevision + ", " + compiler() + ")";
}

nlohmann::json environment_json(int threads) {
  return {{"compiler", compiler()},
          {"build", kBuildFlags},
          {"git_revision", kGitRevision},
          {"cpu_model", cpu_model()},
          {"simd", std::string(simd_path_name(active_simd_path()))},
          {"hardware_threads", std::thread::hardware_concurrency()},
          {"threads", threads},
          {"host", host_name()},
          {"date_utc", utc_now_iso8601()},
          {"load_average", load_average()}};
}

}  // namespace agv
