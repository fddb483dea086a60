#include "engine/system/stray_children.h"

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace agv {

namespace {

std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}
std::set<pid_t>& registry() {
  static std::set<pid_t> live;
  return live;
}

// The parent of `pid` from /proc/PID/stat (field 4, after the parenthesised name, which may hold
// spaces and parentheses itself); -1 when gone.
pid_t parent_of(const std::string& pid) {
  std::ifstream in("/proc/" + pid + "/stat");
  std::string stat;
  if (!std::getline(in, stat)) return -1;
  const auto close = stat.rfind(')');
  if (close == std::string::npos || close + 4 > stat.size()) return -1;
  std::size_t at = close + 2;  // ") S ppid"
  at = stat.find(' ', at);
  if (at == std::string::npos) return -1;
  try {
    return static_cast<pid_t>(std::stol(stat.substr(at + 1)));
  } catch (...) {
    return -1;
  }
}

std::vector<pid_t> my_children() {
  std::vector<pid_t> out;
  const pid_t me = ::getpid();
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/proc", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    if (parent_of(name) == me) out.push_back(static_cast<pid_t>(std::stol(name)));
  }
  return out;
}

}  // namespace

bool adopt_orphans() {
  static const bool adopted = ::prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) == 0;
  return adopted;
}

void LiveWorkers::add(pid_t pid) { registry().insert(pid); }

void LiveWorkers::remove(pid_t pid) {
  const std::lock_guard<std::mutex> lock(registry_mutex());
  registry().erase(pid);
}

void LiveWorkers::kill_strays() {
  const std::lock_guard<std::mutex> lock(registry_mutex());
  for (int round = 0; round < 100; ++round) {
    bool any = false;
    for (const pid_t pid : my_children()) {
      if (registry().count(pid) != 0) continue;
      any = true;
      ::kill(pid, SIGKILL);
      int status = 0;
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
    }
    if (!any) return;
  }
}

LiveWorkers::SpawnLock::SpawnLock() { registry_mutex().lock(); }
LiveWorkers::SpawnLock::~SpawnLock() { registry_mutex().unlock(); }

}  // namespace agv
