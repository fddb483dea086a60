#pragma once
// Code the engine calls but did not write (a planner, a plugin's loading code) may call exit():
// the process would end with that code's status, 0 as like as not, and no report, the sweep
// seemingly done. While such code runs on a thread, a ForeignCodeScope names it there; an exit()
// on that thread then ends the process with one line naming it and exit status 1 (in an isolated
// worker: a run recorded as a crash), before any other exit handler runs.

namespace agv {

class ForeignCodeScope {
 public:
  // `what` must outlive the scope ("a planner", or a plugin's description).
  explicit ForeignCodeScope(const char* what);
  ~ForeignCodeScope();
  ForeignCodeScope(const ForeignCodeScope&) = delete;
  ForeignCodeScope& operator=(const ForeignCodeScope&) = delete;

 private:
  const char* previous_;
};

}  // namespace agv
