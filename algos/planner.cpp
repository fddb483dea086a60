#include "algos/planner.h"

#include <atomic>
#include <ctime>
#include <string>

#include "core/line_of_sight.h"

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

struct Deadline::PollCounter {
  explicit PollCounter(std::int64_t limit) : allowed(limit) {}
  const std::int64_t allowed;
  // Atomic: copies may be polled from the threads of one planner's parallel phases.
  std::atomic<std::int64_t> polls{0};
};

Deadline Deadline::after_polls(std::int64_t polls) {
  Deadline d = never();
  d.counter_ = std::make_shared<PollCounter>(polls);
  return d;
}

bool Deadline::count_poll() const {
  return counter_->polls.fetch_add(1, std::memory_order_relaxed) >= counter_->allowed;
}

std::int64_t Deadline::polls() const {
  return counter_ != nullptr ? counter_->polls.load(std::memory_order_relaxed) : 0;
}

std::vector<std::pair<const char*, std::int64_t>> work_counter_values(const WorkCounters& w) {
  const std::array<const std::optional<std::int64_t>*, kWorkCounterNames.size()> values = {
      &w.search_expansions, &w.samples, &w.ant_steps, &w.pso_evaluations, &w.collision_checks};
  std::vector<std::pair<const char*, std::int64_t>> out;
  for (std::size_t i = 0; i < values.size(); ++i)
    if (values[i]->has_value()) out.emplace_back(kWorkCounterNames[i], **values[i]);
  return out;
}

namespace {

PlanResult plan_checked_query(const Planner& planner, const PlanRequest& request) {
  const Grid& grid = request.grid;
  // Two cell tests on the happy path: this runs inside every run's timed region, so the
  // message is built only for a refusal.
  const auto refuse = [](const char* what, Cell cell, const char* why) {
    return PlanResult::failed(Failure::invalid_input, std::string(what) + " (" +
                                                          std::to_string(cell.x) + "," +
                                                          std::to_string(cell.y) + ") " + why);
  };
  for (const auto& [cell, what] :
       {std::pair{request.start, "start"}, std::pair{request.goal, "goal"}}) {
    if (!grid.in_bounds(cell)) return refuse(what, cell, "is outside the grid");
    if (grid.blocked(cell)) return refuse(what, cell, "is an obstacle cell");
  }
  return planner.plan(request);
}

}  // namespace

PlanResult plan_checked(const Planner& planner, const PlanRequest& request) {
  // Here, not in each planner, so none can forget it; a sub-planner's checks (a fusion planner's
  // global planner, HMA*'s MA*) fall inside the difference.
  const std::int64_t checks_before = collision_checks_on_thread();
  PlanResult result = plan_checked_query(planner, request);
  if (planner.counts_collision_checks())
    result.work.collision_checks = collision_checks_on_thread() - checks_before;
  return result;
}

std::int64_t thread_cpu_ns() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

}  // namespace agv
