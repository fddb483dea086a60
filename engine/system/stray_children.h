#pragma once
// No process outlives its sweep (issue 49 class 1). A planner run in an isolated worker may start
// a child that leaves the worker's process group (setsid()), which killing the group cannot
// reach. Linux's answer used here is the child subreaper (prctl PR_SET_CHILD_SUBREAPER): once
// agvbench is one, a process orphaned anywhere below it is handed to agvbench instead of to init,
// and agvbench kills and reaps every child of its own that is not a live worker each time a
// worker ends. Chosen over a PID namespace (needs CAP_SYS_ADMIN or a user namespace, which a
// container or a cluster node may refuse) and a cgroup per worker (needs a delegated cgroup
// tree): the subreaper needs no privilege and no set-up, and a worker killed with SIGKILL
// (its hard limit) cannot escape it, since the orphans go to agvbench whatever killed their
// parent. A process that double-forks before its parent dies is adopted the same way.
// Only children outside agvbench's own process group are taken for strays: workers are spawned
// in groups of their own, so all they leave behind is outside it, while a child a program
// embedding the engine started itself stays in the program's group and is left alone (one it
// moved to a group or session of its own is not told apart from a stray).

#include <sys/types.h>

namespace agv {

// Makes this process a child subreaper (once; idempotent). Returns false where Linux refuses.
bool adopt_orphans();

// Registers a worker being started or ended: while `f` runs, no sweep of strays happens, so a
// worker another thread is spawning is never taken for a stray.
class LiveWorkers {
 public:
  static void add(pid_t pid);
  static void remove(pid_t pid);
  // Kills (SIGKILL) and reaps every child of this process outside its process group that is
  // not a registered worker, until none is left (a killed stray's own children are handed to us in
  // turn).
  static void kill_strays();
  // Holds the registry while a worker is spawned and registered.
  class SpawnLock {
   public:
    SpawnLock();
    ~SpawnLock();
    SpawnLock(const SpawnLock&) = delete;
    SpawnLock& operator=(const SpawnLock&) = delete;
  };
};

}  // namespace agv
