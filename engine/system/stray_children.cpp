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
#include <sstream>
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

struct ProcessIds {
  pid_t parent = -1;
  pid_t group = -1;
};

// The parent and process group of `pid` from /proc/PID/stat (fields 4 and 5, after the
// parenthesised name, which may hold spaces and parentheses itself); parent -1 when gone.
ProcessIds ids_of(const std::string& pid) {
  std::ifstream in("/proc/" + pid + "/stat");
  std::string stat;
  ProcessIds ids;
  if (!std::getline(in, stat)) return ids;
  const auto close = stat.rfind(')');
  if (close == std::string::npos || close + 2 > stat.size()) return ids;
  std::istringstream fields(stat.substr(close + 2));  // "S ppid pgrp ..."
  std::string state;
  long parent = -1, group = -1;
  if (fields >> state >> parent >> group) {
    ids.parent = static_cast<pid_t>(parent);
    ids.group = static_cast<pid_t>(group);
  }
  return ids;
}

// This process's children that may be strays: outside its own process group. A worker and
// everything it starts live in the worker's group or, after setsid(), a session of their own;
// a child the embedding program started itself (a host of the library) stays in ours.
std::vector<pid_t> stray_candidates() {
  std::vector<pid_t> out;
  const pid_t me = ::getpid();
  const pid_t my_group = ::getpgrp();
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/proc", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    const ProcessIds ids = ids_of(name);
    if (ids.parent == me && ids.group != my_group)
      out.push_back(static_cast<pid_t>(std::stol(name)));
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
    for (const pid_t pid : stray_candidates()) {
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
