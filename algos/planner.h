#pragma once
// The one virtual boundary of the engine: a planner is called once per query with the map, the
// query, its RNG, reusable scratch space and a deadline, and returns the common result. Outcomes
// ("no path", "hit the limit") are data in the result; exceptions are for misuse and bugs.

#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/corner_rule.h"
#include "core/grid.h"
#include "core/rng.h"

namespace agv {

enum class Failure { none, no_path, limit, invalid_path, invalid_input };
const char* to_string(Failure f);

// Cooperative time limit: planners poll expired() every few hundred expansions or iterations
// (docs/ARCHITECTURE.md "Style" item 7) and give up with Failure::limit. A planner may copy the
// request's deadline into a sub-request (a fusion planner's global planner): copies share one
// limit.
class Deadline {
 public:
  using Clock = std::chrono::steady_clock;
  static Deadline never() { return Deadline(Clock::time_point::max()); }
  static Deadline after(std::chrono::nanoseconds budget) { return Deadline(Clock::now() + budget); }
  // For tests: answers "not expired" to the first `polls` calls of expired(), counted over this
  // deadline and all its copies, and "expired" to every later one, so a test can stop a planner
  // mid-plan at a reproducible point and count how many polls it makes after that.
  static Deadline after_polls(std::int64_t polls);
  explicit Deadline(Clock::time_point at) : at_(at) {}

  bool expired() const {
    // A clock deadline pays one well-predicted null test for the poll-counted kind.
    if (counter_ != nullptr) [[unlikely]]
      return count_poll();
    return at_ != Clock::time_point::max() && Clock::now() >= at_;
  }
  // after_polls() deadlines: the calls of expired() so far, over all copies; 0 for a clock one.
  std::int64_t polls() const;

 private:
  struct PollCounter;
  bool count_poll() const;

  Clock::time_point at_;
  std::shared_ptr<PollCounter> counter_;  // set only by after_polls()
};

// A deadline polled on every `interval`-th call of expired() (the first call included), its
// expiry remembered: for loops of shared steps that return no failure of their own (the
// post-processing of algos/postprocess/, a world's set-up), whose caller then asks
// has_expired() whether the step was cut short. Once expired it polls no more.
class DeadlinePoller {
 public:
  DeadlinePoller(Deadline deadline, std::int64_t interval)
      : deadline_(std::move(deadline)), interval_(interval) {}
  bool expired() {
    if (!expired_ && calls_++ % interval_ == 0) expired_ = deadline_.expired();
    return expired_;
  }
  bool has_expired() const { return expired_; }

 private:
  Deadline deadline_;
  std::int64_t interval_;
  std::int64_t calls_ = 0;
  bool expired_ = false;
};
// For steps that may run without a deadline (tests, benchmarks): nullptr never expires.
inline bool poll_expired(DeadlinePoller* poller) { return poller != nullptr && poller->expired(); }

// CPU time of one named phase of a plan call (search, post-processing, smoothing, ...).
struct PhaseTime {
  std::string name;
  std::int64_t ns = 0;
};

// What a planner that drives a simulated robot through a world with moving obstacles executed
// (the DWA fusion planners, algos/local/fusion.h), for the engine to judge: collisions, reaching
// the goal and the fusion metrics are decided from this record by engine/judge/trajectory_judge.h,
// never taken from the planner. Positions in continuous cell coordinates, times in seconds.
struct DynamicTrack {
  double radius = 0.0;        // cells
  std::vector<Point> centre;  // at each Trajectory::t
};
struct Trajectory {
  std::vector<double> t;        // t[0] = 0, one entry per control step boundary
  std::vector<Point> position;  // robot centre at t[i]
  std::vector<double> heading;  // rad, at t[i]
  std::vector<double> v, w;     // command held over [t[i], t[i+1]): m/s, rad/s (size - 1)
  double robot_radius = 0.0;    // cells
  double goal_tolerance = 0.0;  // cells: reached when the centre is this close to the goal's
  double cell_edge = 1.0;       // metres per cell
  std::vector<DynamicTrack> obstacles;
  std::vector<Cell> unknown_cells;  // static obstacles the global planner did not see
  std::vector<Point> global_path;   // the global plan the run started from (for pictures)
  std::vector<Point> key_points;    // its key points, the DWA's successive local goals
  std::string end_reason;           // the planner's account: reached, timeout, stuck or contact
};

// Work counters named for what they count (docs/METRICS.md "Work counters"); a planner sets
// only those its kind defines, and the engine reports only those, so no comparison pairs counts of
// different things. collision_checks is defined for every planner: plan_checked() sets it.
struct WorkCounters {
  std::optional<std::int64_t> search_expansions;  // nodes taken off an open list
  std::optional<std::int64_t> samples;            // points drawn (sampling planners)
  std::optional<std::int64_t> ant_steps;          // ACO: moves of all ants
  std::optional<std::int64_t> pso_evaluations;    // fitness evaluations of a swarm
  std::optional<std::int64_t> collision_checks;   // segment and point / cell tests
  bool operator==(const WorkCounters&) const = default;
};
// Every counter's metric name, in the order above.
inline constexpr std::array<const char*, 5> kWorkCounterNames = {
    "search_expansions", "samples", "ant_steps", "pso_evaluations", "collision_checks"};
// The defined counters, in that order, under their metric names.
std::vector<std::pair<const char*, std::int64_t>> work_counter_values(const WorkCounters& w);

struct PlanResult {
  // The outcome: none = a path was found. A result starts as no_path, so a planner that returns
  // without saying it succeeded has not.
  Failure failure = Failure::no_path;
  bool ok() const { return failure == Failure::none; }
  std::string message;  // why, for failures; empty on success
  // Waypoints in continuous cell coordinates (cell centre = x + 0.5), start first, goal last.
  std::vector<Point> path;
  // Collision rule the path is validated under (the planner's own neighbour rule).
  CornerRule rule = CornerRule::allow;
  // The work counters the planner defines (docs/METRICS.md "Work counters").
  WorkCounters work;
  // Waypoints before curve sampling (docs/METRICS.md waypoints), for planners whose path is a
  // sampled curve; -1 when the path's own points are the waypoints.
  std::int64_t waypoints_before_sampling = -1;
  // Planner-specific scalar metrics (aggregated like the engine's, under these names).
  std::vector<std::pair<std::string, double>> extra;
  // CPU time per phase; the engine reports these under `timing`.
  std::vector<PhaseTime> phases;
  // Set only by planners that simulate a robot (fusion planners): the engine then judges this
  // trajectory instead of validating `path` against the grid (engine/judge/run_executor.cpp).
  std::shared_ptr<const Trajectory> trajectory;

  static PlanResult failed(Failure why, std::string message) {
    PlanResult r;
    r.failure = why;
    r.message = std::move(message);
    return r;
  }
};

// Per-thread CPU clock: planning time is the work of this thread alone, whatever the others do.
std::int64_t thread_cpu_ns();

// Adds the CPU time from construction to destruction to `result.phases` under `name`.
class PhaseTimer {
 public:
  PhaseTimer(PlanResult& result, const char* name)
      : result_(result), name_(name), start_(thread_cpu_ns()) {}
  ~PhaseTimer() { result_.phases.push_back({name_, thread_cpu_ns() - start_}); }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  PlanResult& result_;
  const char* name_;
  std::int64_t start_;
};

// Reusable per-thread buffers. Each planner keeps its buffers in a type of its own; get<T>()
// creates one T per Scratch on first use and returns the same object on every later call, so a
// worker thread allocates nothing in steady state.
class Scratch {
 public:
  template <class T>
  T& get() {
    const void* key = &kKey<T>;
    for (auto& slot : slots_)
      if (slot.key == key) return *static_cast<T*>(slot.object.get());
    slots_.push_back({key, std::unique_ptr<void, void (*)(void*)>(
                               new T(), [](void* p) { delete static_cast<T*>(p); })});
    return *static_cast<T*>(slots_.back().object.get());
  }

 private:
  template <class T>
  static constexpr char kKey = 0;
  struct Slot {
    const void* key;
    std::unique_ptr<void, void (*)(void*)> object;
  };
  std::vector<Slot> slots_;
};

struct PlanRequest {
  const Grid& grid;
  Cell start;
  Cell goal;
  Rng& rng;
  Scratch& scratch;
  Deadline deadline = Deadline::never();
};

class Planner {
 public:
  virtual ~Planner() = default;
  // Thread-safe: a planner object holds only its configuration; per-call state lives in
  // request.scratch. Start and goal are in bounds and free: callers go through plan_checked().
  virtual PlanResult plan(const PlanRequest& request) const = 0;
  // false: plan_checked leaves work.collision_checks undefined for this planner, whose count is
  // not a function of its request and seed (ompl_bitstar, docs/PLANNERS.md "OMPL planners"), so
  // no report holds a work counter that differs between two runs of one sweep.
  virtual bool counts_collision_checks() const { return true; }
};

// The one entry point for callers (engine runs, `agvbench plan` and `scen`, tests): refuses a
// start or goal outside the grid or on an obstacle with Failure::invalid_input, naming which,
// and otherwise returns planner.plan(request). Either way it sets result.work.collision_checks to
// the checks made on this thread during the call (core/line_of_sight.h), sub-planners included,
// for every planner that counts them (Planner::counts_collision_checks).
PlanResult plan_checked(const Planner& planner, const PlanRequest& request);

}  // namespace agv
