// The planner contract (docs/ARCHITECTURE.md), checked for every planner in planner_registry():
// a planner's registry line is all it takes to be covered. Every call goes through
// plan_checked(), the callers' one entry point, and every result is judged by the engine's own
// execute_run() (validator, or trajectory judge for a simulated robot), never re-implemented here.
//
// On small random maps of every generator and several densities (solvable under no_corner_cut,
// the strictest rule, so every planner has a path):
// - a returned path is confirmed by the engine, a claimed no_path is never wrong, and a planner
//   that proves there is no path (PlannerInfo::proves_no_path) never gives up with limit;
// - start == goal succeeds with the one-point path at the start cell's centre;
// - a walled-off goal gives no_path (proves_no_path) or limit (the others give up);
// - an expired deadline gives limit; one that expires at poll n + 1 of a run that would poll more
//   gives limit after at most kFurtherPolls more polls (Deadline::after_polls, deterministic);
// - with parameters that make every phase of a plan long (many samples, iterations, a large maze,
//   a shortcut and a curve), every phase the plan reports polls the deadline: for each phase
//   some poll expires inside it, and the plan then stops there with limit within kFurtherPolls
//   more polls and no more work than the whole plan's;
// - a start or goal outside the grid or on an obstacle gives invalid_input;
// - the same seed gives the same result, twice in a row and with a fresh Scratch;
// - the waypoint count a planner reports is that of the path it returns (or of the polyline
//   its curve was fitted to).

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "algos/planner.h"
#include "algos/registry.h"
#include "engine/judge/run_executor.h"
#include "generators/map_generators.h"
#include "tests/test_size.h"

namespace agv {
namespace {

// Polls a planner may make after the first one that answered "expired": a sub-search that a
// fusion planner started polls once more before the control loop's own poll stops the run.
constexpr std::int64_t kFurtherPolls = 2;
// Maps, per planner, on which a deadline is made to expire mid-plan.
constexpr int kMidPlanMaps = 3;

MapInstance contract_map(int i) {
  static const char* const kGenerators[] = {"uniform", "blocks", "maze", "rooms"};
  static const int kSides[] = {12, 16, 20};
  static const double kDensities[] = {0.1, 0.2, 0.3};
  MapSpec spec;
  spec.generator = kGenerators[i % 4];
  spec.width = kSides[i % 3];
  spec.height = kSides[(i / 3) % 3];
  spec.density = kDensities[(i / 4) % 3];
  if (spec.generator == "rooms") spec.params = {{"room_size", 6}};
  spec.endpoints = (i % 2 == 0) ? EndpointMode::corners : EndpointMode::random;
  spec.min_distance = 6.0;
  spec.require_solvable = true;
  spec.solvable_rule = CornerRule::no_corner_cut;
  Rng rng(20261201, static_cast<std::uint64_t>(i));
  return make_map(spec, rng);
}

// The small maps every check runs on.
const std::vector<MapInstance>& small_maps() {
  static const std::vector<MapInstance> maps = [] {
    std::vector<MapInstance> v;
    // Six in a sanitized tree: still every generator, side and endpoint mode.
    for (int i = 0; i < test::sized(12, 6); ++i) v.push_back(contract_map(i));
    return v;
  }();
  return maps;
}

// Small maps first, then nearly perfect mazes (96 and 160 cells a side) large enough that a grid
// search polls its deadline several times (search_core.h polls every 1024 expansions): the mid-plan
// check takes the first maps on which the planner polls at least twice.
const std::vector<MapInstance>& mid_plan_maps() {
  static const std::vector<MapInstance> maps = [] {
    std::vector<MapInstance> v = small_maps();
    for (int i = 0; i < 8; ++i) {
      MapSpec spec;
      spec.generator = "maze";
      spec.width = i < 4 ? 96 : 160;
      spec.height = i < 4 ? 96 : 160;
      spec.density = i % 2 ? 0.45 : 0.47;  // nearly a perfect maze: one long winding path
      spec.endpoints = EndpointMode::corners;
      spec.require_solvable = true;
      Rng rng(20261202, static_cast<std::uint64_t>(i));
      v.push_back(make_map(spec, rng));
    }
    return v;
  }();
  return maps;
}

// The map with every neighbour of the goal blocked: no path under any corner rule, nor for a
// straight segment (every way into the goal cell crosses a blocked neighbour).
MapInstance walled_goal(const MapInstance& m) {
  MapInstance walled = m;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const Cell c{m.goal.x + dx, m.goal.y + dy};
      if ((dx != 0 || dy != 0) && walled.grid.in_bounds(c)) walled.grid.set_blocked(c, true);
    }
  return walled;
}

std::string describe(const MapInstance& m, int i) {
  return "map " + std::to_string(i) + " (" + std::to_string(m.grid.width()) + "x" +
         std::to_string(m.grid.height()) + ", start " + std::to_string(m.start.x) + "," +
         std::to_string(m.start.y) + ", goal " + std::to_string(m.goal.x) + "," +
         std::to_string(m.goal.y) + ")";
}

TEST(DeadlineAfterPolls, CountsPollsOverAllCopies) {
  const Deadline d = Deadline::after_polls(3);
  const Deadline copy = d;  // as a planner hands the request's deadline to a sub-planner
  EXPECT_FALSE(d.expired());
  EXPECT_FALSE(copy.expired());
  EXPECT_FALSE(d.expired());
  EXPECT_TRUE(copy.expired());
  EXPECT_TRUE(d.expired());  // and stays expired
  EXPECT_EQ(d.polls(), 5);
  EXPECT_EQ(copy.polls(), 5);
  EXPECT_TRUE(Deadline::after_polls(0).expired());
  EXPECT_EQ(Deadline::never().polls(), 0);
  EXPECT_FALSE(Deadline::never().expired());
}

// The registry's names: the parameter, so that test names and failure messages name the planner.
std::vector<std::string> registered() {
  std::vector<std::string> v;
  for (const PlannerInfo& info : planner_registry()) v.push_back(info.name);
  return v;
}

class PlannerContract : public testing::TestWithParam<std::string> {
 protected:
  const PlannerInfo& info() const { return *find_planner(GetParam()); }
  const Planner& planner() {
    if (!configured_.planner)
      configured_ = configure_planner(info().name, nlohmann::json::object(), "contract");
    return *configured_.planner;
  }

  // The engine's judgement of one run from `start` to `goal` on `m`, seed fixed per map.
  RunOutput judged(const MapInstance& m, int i, Cell start, Cell goal, Deadline deadline,
                   Scratch& scratch) {
    MapReference ref(m.grid, start, goal);
    Rng rng(7, static_cast<std::uint64_t>(i));
    return execute_run(planner(), ref, rng, scratch, std::move(deadline), MotionTimeParams{});
  }
  RunOutput judged(const MapInstance& m, int i, Deadline deadline = Deadline::never()) {
    return judged(m, i, m.start, m.goal, std::move(deadline), scratch_);
  }

  PlanResult planned(const MapInstance& m, int i, Cell start, Cell goal, Scratch& scratch,
                     Deadline deadline = Deadline::never()) {
    Rng rng(7, static_cast<std::uint64_t>(i));
    return plan_checked(planner(),
                        PlanRequest{m.grid, start, goal, rng, scratch, std::move(deadline)});
  }

  Scratch scratch_;

 private:
  ConfiguredPlanner configured_;
};

TEST_P(PlannerContract, ReturnedPathsAreConfirmedByTheEngine) {
  int found = 0;
  for (std::size_t i = 0; i < small_maps().size(); ++i) {
    const MapInstance& m = small_maps()[i];
    const RunOutput out = judged(m, static_cast<int>(i));
    SCOPED_TRACE(describe(m, static_cast<int>(i)) + ": " + std::string(to_string(out.outcome)) +
                 " " + out.message);
    // The planner's claim and the engine's verdict agree; a failure is never a malformed path.
    EXPECT_EQ(out.result.ok(), out.outcome == Outcome::success);
    EXPECT_NE(out.outcome, Outcome::invalid_path);
    EXPECT_NE(out.outcome, Outcome::invalid_input);
    EXPECT_NE(out.outcome, Outcome::crash);
    // A claimed no_path on these solvable maps is wrong; a planner that proves there is no path
    // has no budget to give up on.
    EXPECT_NE(out.outcome, Outcome::missed_path);
    if (info().proves_no_path) {
      EXPECT_NE(to_string(out.result.failure), std::string("limit"));
    }
    found += out.outcome == Outcome::success;
  }
  // Every planner solves some of these easy maps: a planner that never succeeds has no contract
  // checked at all.
  EXPECT_GT(found, 0);
}

TEST_P(PlannerContract, StartEqualsGoalGivesTheStart) {
  for (std::size_t i = 0; i < small_maps().size(); ++i) {
    const MapInstance& m = small_maps()[i];
    const RunOutput out =
        judged(m, static_cast<int>(i), m.start, m.start, Deadline::never(), scratch_);
    SCOPED_TRACE(describe(m, static_cast<int>(i)) + ": " + std::string(to_string(out.outcome)) +
                 " " + out.message);
    EXPECT_EQ(out.outcome, Outcome::success);
    ASSERT_FALSE(out.result.path.empty());
    EXPECT_EQ(out.result.path.front(), centre(m.start));
    EXPECT_EQ(out.result.path.back(), centre(m.start));
  }
}

// The counter its kind must define (docs/METRICS.md "Work counters"); nullptr: none beyond
// collision_checks.
const char* kind_counter(const PlannerInfo& info) {
  switch (info.kind) {
    case PlannerKind::grid_search:
      return "search_expansions";
    case PlannerKind::sampling:
      return "samples";
    case PlannerKind::swarm:
      return info.name == "aco" ? "ant_steps" : "pso_evaluations";
    case PlannerKind::local:
      return nullptr;
  }
  return nullptr;
}

std::vector<std::string> declared_counters(const PlannerInfo& info) {
  std::vector<std::string> v;
  for (const auto& [name, meaning] : info.counters) {
    EXPECT_FALSE(meaning.empty()) << name;
    v.push_back(name);
  }
  std::sort(v.begin(), v.end());
  return v;
}

std::vector<std::string> reported_counters(const PlanResult& r) {
  std::vector<std::string> v;
  for (const auto& [name, value] : work_counter_values(r.work)) {
    EXPECT_GE(value, 0) << name;
    v.push_back(name);
  }
  std::sort(v.begin(), v.end());
  return v;
}

// Every planner reports exactly the counters its registry entry declares, on every run it returns
// from (start == goal included): collision_checks always (but for the one planner whose count is
// not reproducible, which neither declares nor reports it), positive on every non-trivial query
// (the start's neighbourhood, a first segment or a rollout is always checked), its kind's counter,
// and each declared counter positive on some map. The engine reports them under their names.
TEST_P(PlannerContract, ReportsTheWorkCountersItDeclares) {
  const std::vector<std::string> declared = declared_counters(info());
  const bool counts_checks = planner().counts_collision_checks();
  // docs/PLANNERS.md "OMPL planners": BIT*'s count differs between two plans of one seed.
  EXPECT_EQ(counts_checks, info().name != "ompl_bitstar");
  EXPECT_EQ(std::binary_search(declared.begin(), declared.end(), "collision_checks"),
            counts_checks);
  if (const char* own = kind_counter(info())) {
    EXPECT_TRUE(std::binary_search(declared.begin(), declared.end(), std::string(own))) << own;
  }
  std::vector<std::int64_t> most(kWorkCounterNames.size(), 0);
  for (std::size_t i = 0; i < small_maps().size(); ++i) {
    const MapInstance& m = small_maps()[i];
    SCOPED_TRACE(describe(m, static_cast<int>(i)));
    const PlanResult r = planned(m, static_cast<int>(i), m.start, m.goal, scratch_);
    EXPECT_EQ(reported_counters(r), declared);
    EXPECT_EQ(r.work.collision_checks.has_value(), counts_checks);
    if (counts_checks) {
      EXPECT_GT(r.work.collision_checks.value_or(0), 0);
    }
    for (std::size_t c = 0; c < kWorkCounterNames.size(); ++c)
      for (const auto& [name, value] : work_counter_values(r.work))
        if (name == std::string(kWorkCounterNames[c])) most[c] = std::max(most[c], value);
    const PlanResult trivial = planned(m, static_cast<int>(i), m.start, m.start, scratch_);
    EXPECT_EQ(reported_counters(trivial), declared);
    // The engine: the same counts, as run metrics under the counters' names.
    const RunOutput out = judged(m, static_cast<int>(i));
    for (const auto& [counter, value] : work_counter_values(out.result.work)) {
      // A named copy for the lambda: clang 14 (the ASan tree's compiler) cannot capture a
      // structured binding.
      const char* const name = counter;
      const auto it = std::find_if(out.result.extra.begin(), out.result.extra.end(),
                                   [&](const auto& e) { return e.first == name; });
      ASSERT_NE(it, out.result.extra.end()) << name;
      EXPECT_EQ(it->second, static_cast<double>(value)) << name;
    }
    for (const char* name : kWorkCounterNames) {
      const bool is_declared = std::binary_search(declared.begin(), declared.end(), name);
      const auto n = std::count_if(out.result.extra.begin(), out.result.extra.end(),
                                   [&](const auto& e) { return e.first == name; });
      EXPECT_EQ(n, is_declared ? 1 : 0) << name;
    }
  }
  for (std::size_t c = 0; c < kWorkCounterNames.size(); ++c)
    if (std::binary_search(declared.begin(), declared.end(), kWorkCounterNames[c])) {
      EXPECT_GT(most[c], 0) << kWorkCounterNames[c];
    }
}

TEST_P(PlannerContract, WalledOffGoalGivesItsDocumentedFailure) {
  const Failure expected = info().proves_no_path ? Failure::no_path : Failure::limit;
  for (std::size_t i = 0; i < small_maps().size(); i += 3) {
    const MapInstance m = walled_goal(small_maps()[i]);
    const RunOutput out = judged(m, static_cast<int>(i));
    SCOPED_TRACE(describe(m, static_cast<int>(i)) + ": " + out.result.message);
    EXPECT_EQ(to_string(out.result.failure), std::string(to_string(expected)));
    EXPECT_NE(out.outcome, Outcome::success);
    EXPECT_NE(out.outcome, Outcome::invalid_path);
  }
}

TEST_P(PlannerContract, ExpiredDeadlineGivesLimit) {
  for (std::size_t i = 0; i < small_maps().size(); ++i) {
    const MapInstance& m = small_maps()[i];
    const PlanResult r = planned(m, static_cast<int>(i), m.start, m.goal, scratch_,
                                 Deadline(Deadline::Clock::now()));
    SCOPED_TRACE(describe(m, static_cast<int>(i)) + ": " + r.message);
    EXPECT_EQ(to_string(r.failure), std::string("limit"));
  }
}

TEST_P(PlannerContract, DeadlineExpiringMidPlanGivesLimitPromptly) {
  int checked = 0;
  for (std::size_t i = 0; i < mid_plan_maps().size() && checked < kMidPlanMaps; ++i) {
    const MapInstance& m = mid_plan_maps()[i];
    const int seed = static_cast<int>(i);
    // The polls of the whole run, under a counting deadline that never expires.
    const Deadline counting = Deadline::after_polls(std::numeric_limits<std::int64_t>::max());
    planned(m, seed, m.start, m.goal, scratch_, counting);
    const std::int64_t total = counting.polls();
    if (total < 2) continue;
    ++checked;
    for (const std::int64_t allowed : {std::int64_t{1}, total / 2, total - 1}) {
      const Deadline deadline = Deadline::after_polls(allowed);
      const PlanResult r = planned(m, seed, m.start, m.goal, scratch_, deadline);
      SCOPED_TRACE(describe(m, seed) + ": expires at poll " + std::to_string(allowed + 1) + " of " +
                   std::to_string(total) + ": " + r.message);
      EXPECT_EQ(to_string(r.failure), std::string("limit"));
      EXPECT_GT(deadline.polls(), allowed);  // the expiring poll was made
      EXPECT_LE(deadline.polls(), allowed + 1 + kFurtherPolls);
    }
  }
  // Without a run long enough to poll twice this check would have checked nothing.
  EXPECT_EQ(checked, kMidPlanMaps);
}

// The planner's parameters for a long plan: every budget large (within its range) and, for a path
// planner, its most expensive shortcut and a curve, so that every phase it has does real work.
nlohmann::json long_plan_params(const PlannerInfo& info) {
  nlohmann::json params = nlohmann::json::object();
  for (const ParamSpec& spec : info.params) {
    const auto has = [&](const char* choice) {
      return std::find(spec.choices.begin(), spec.choices.end(), choice) != spec.choices.end();
    };
    // Within the declared range (LazyPRM*'s budget stops at 5000).
    const auto large = [&](double n) { return static_cast<long long>(std::min(n, spec.max)); };
    if (spec.name == "samples") params["samples"] = large(20000);
    if (spec.name == "max_iterations") params["max_iterations"] = large(50000);
    if (spec.name == "step") params["step"] = 0.5;
    if (info.kind == PlannerKind::local) continue;  // a fusion's `smoothing` is its DWA's
    if (spec.name == "shortcut" && has("greedy")) params["shortcut"] = "greedy";
    if (spec.name == "smoothing" && has("bspline")) params["smoothing"] = "bspline";
  }
  return params;
}

// The phase a plan cut short was in: the last it reports (cpu_ns_per_step is a fusion run's
// per-step statistic, reported with the phases after its control loop's, not a phase).
std::string last_phase(const PlanResult& r) {
  for (auto it = r.phases.rbegin(); it != r.phases.rend(); ++it)
    if (it->name != "cpu_ns_per_step") return it->name;
  return "";
}

TEST_P(PlannerContract, DeadlineCutsEveryPhaseOfALongPlan) {
  const ConfiguredPlanner configured =
      configure_planner(info().name, long_plan_params(info()), "contract");
  // The largest nearly perfect maze of mid_plan_maps(): one long winding path.
  const MapInstance& m = mid_plan_maps().back();
  const int seed = 1;
  const auto plan = [&](Deadline deadline) {
    Rng rng(7, static_cast<std::uint64_t>(seed));
    return plan_checked(*configured.planner,
                        PlanRequest{m.grid, m.start, m.goal, rng, scratch_, std::move(deadline)});
  };
  const Deadline counting = Deadline::after_polls(std::numeric_limits<std::int64_t>::max());
  const PlanResult full = plan(counting);
  const std::int64_t total = counting.polls();
  std::vector<std::string> phases;
  for (const PhaseTime& p : full.phases)
    if (p.name != "cpu_ns_per_step") phases.push_back(p.name);
  SCOPED_TRACE(describe(m, seed) + ", parameters " + long_plan_params(info()).dump() + ", " +
               std::to_string(total) + " polls, phases " + nlohmann::json(phases).dump());
  ASSERT_FALSE(phases.empty());
  ASSERT_GE(total, static_cast<std::int64_t>(phases.size()));

  // The run cut at poll allowed + 1: limit, promptly, with no more work than the whole run.
  const auto cut = [&](std::int64_t allowed) {
    const Deadline deadline = Deadline::after_polls(allowed);
    PlanResult r = plan(deadline);
    SCOPED_TRACE("expires at poll " + std::to_string(allowed + 1) + " of " + std::to_string(total) +
                 " in phase " + last_phase(r) + ": " + r.message);
    EXPECT_EQ(to_string(r.failure), std::string("limit"));
    EXPECT_GT(deadline.polls(), allowed);
    EXPECT_LE(deadline.polls(), allowed + 1 + kFurtherPolls);
    for (const auto& [name, value] : work_counter_values(r.work))
      for (const auto& [full_name, full_value] : work_counter_values(full.work))
        if (std::string(name) == full_name) {
          EXPECT_LE(value, full_value) << name;
        }
    return r;
  };
  const auto phase_index = [&](const PlanResult& r) {
    const auto it = std::find(phases.begin(), phases.end(), last_phase(r));
    return static_cast<std::size_t>(it - phases.begin());  // phases.size(): none of them
  };
  // A cut later in the run is in the same phase or a later one (the run up to the expiring poll
  // is the uncut run's), so a binary search finds the first poll of each phase; it must lie in
  // that phase, not in the next: every phase polls.
  for (std::size_t p = 0; p < phases.size(); ++p) {
    std::int64_t lo = 0, hi = total - 1;  // the first allowed whose cut is in phase >= p
    while (lo < hi) {
      const std::int64_t mid = lo + (hi - lo) / 2;
      if (phase_index(cut(mid)) >= p)
        hi = mid;
      else
        lo = mid + 1;
    }
    EXPECT_EQ(last_phase(cut(lo)), phases[p]) << "phase " << phases[p] << " never polls";
  }
}

TEST_P(PlannerContract, EndpointOutsideTheGridOrBlockedIsRefused) {
  const MapInstance& m = small_maps()[0];
  MapInstance blocked_start = m, blocked_goal = m;
  blocked_start.grid.set_blocked(m.start, true);
  blocked_goal.grid.set_blocked(m.goal, true);
  const Cell outside[] = {{-1, 0}, {0, -1}, {m.grid.width(), 0}, {0, m.grid.height()}};
  struct Query {
    const MapInstance* map;
    Cell start, goal;
  };
  std::vector<Query> queries = {{&blocked_start, m.start, m.goal},
                                {&blocked_goal, m.start, m.goal}};
  for (const Cell c : outside) {
    queries.push_back({&m, c, m.goal});
    queries.push_back({&m, m.start, c});
  }
  for (const Query& q : queries) {
    SCOPED_TRACE("start " + std::to_string(q.start.x) + "," + std::to_string(q.start.y) +
                 ", goal " + std::to_string(q.goal.x) + "," + std::to_string(q.goal.y));
    const PlanResult r = planned(*q.map, 0, q.start, q.goal, scratch_);
    EXPECT_EQ(to_string(r.failure), std::string("invalid_input"));
    EXPECT_FALSE(r.message.empty());
    // The refusal names the endpoint: the start when it is the one off the free grid.
    const bool start_bad = !q.map->grid.in_bounds(q.start) || q.map->grid.blocked(q.start);
    EXPECT_EQ(r.message.rfind(start_bad ? "start (" : "goal (", 0), 0U) << r.message;
    const RunOutput out = judged(*q.map, 0, q.start, q.goal, Deadline::never(), scratch_);
    EXPECT_EQ(out.outcome, Outcome::invalid_input);
  }
}

void expect_same(const PlanResult& a, const PlanResult& b) {
  EXPECT_EQ(to_string(a.failure), std::string(to_string(b.failure)));
  EXPECT_EQ(a.message, b.message);
  EXPECT_EQ(a.path, b.path);
  EXPECT_EQ(a.rule, b.rule);
  EXPECT_EQ(a.work, b.work);
  EXPECT_EQ(a.waypoints_before_sampling, b.waypoints_before_sampling);
  EXPECT_EQ(a.extra, b.extra);
  ASSERT_EQ(a.trajectory == nullptr, b.trajectory == nullptr);
  if (a.trajectory) {
    EXPECT_EQ(a.trajectory->position, b.trajectory->position);
    EXPECT_EQ(a.trajectory->end_reason, b.trajectory->end_reason);
  }
}

TEST_P(PlannerContract, SameSeedSameResult) {
  for (std::size_t i = 0; i < small_maps().size(); i += 2) {
    const MapInstance& m = small_maps()[i];
    const int seed = static_cast<int>(i);
    SCOPED_TRACE(describe(m, seed));
    const PlanResult first = planned(m, seed, m.start, m.goal, scratch_);
    const PlanResult again = planned(m, seed, m.start, m.goal, scratch_);
    Scratch fresh;
    const PlanResult fresh_result = planned(m, seed, m.start, m.goal, fresh);
    expect_same(first, again);
    expect_same(first, fresh_result);
  }
}

// More small maps of every generator and density, for the counts below.
const std::vector<MapInstance>& count_maps() {
  static const std::vector<MapInstance> maps = [] {
    std::vector<MapInstance> v;
    for (int i = 0; i < test::sized(48, 16); ++i) v.push_back(contract_map(100 + i));
    return v;
  }();
  return maps;
}

double extra_value(const PlanResult& r, const std::string& name) {
  for (const auto& [key, value] : r.extra)
    if (key == name) return value;
  return -1.0;
}

TEST_P(PlannerContract, WaypointCountIsThatOfThePathReturned) {
  // waypoints_before_sampling (the engine's waypoints and motion time when >= 0) must describe
  // the path returned: -1 or its point count, unless the path is a sampled curve, where it is
  // the vertex count of the polyline the curve was fitted to, i.e. of the same planner's path
  // with `smoothing: none` (the curve is the last step, after every random draw).
  // A fusion planner's `smoothing` is its DWA objective's, and its path the executed positions.
  const bool local = info().kind == PlannerKind::local;
  std::vector<std::string> curves;
  for (const ParamSpec& spec : info().params)
    if (spec.name == "smoothing" && !local)
      for (const std::string& mode : spec.choices)
        if (mode != "none") curves.push_back(mode);
  auto with = [&](const char* smoothing) {
    return configure_planner(info().name, {{"smoothing", smoothing}}, "contract");
  };
  int checked = 0;
  for (std::size_t i = 0; i < count_maps().size(); ++i) {
    const MapInstance& m = count_maps()[i];
    const int seed = static_cast<int>(i);
    SCOPED_TRACE(describe(m, seed));
    auto plan_with = [&](const Planner& p) {
      Rng rng(7, static_cast<std::uint64_t>(seed));
      return plan_checked(p, PlanRequest{m.grid, m.start, m.goal, rng, scratch_});
    };
    const PlanResult plain =
        curves.empty() ? plan_with(planner()) : plan_with(*with("none").planner);
    if (!plain.ok()) continue;
    const std::int64_t n = static_cast<std::int64_t>(plain.path.size());
    EXPECT_TRUE(plain.waypoints_before_sampling == -1 || plain.waypoints_before_sampling == n)
        << plain.waypoints_before_sampling << " for a path of " << n << " points";
    // key_points of a path planner counts the same waypoints (a fusion run's are its local goals).
    if (!local && extra_value(plain, "key_points") >= 0.0) {
      EXPECT_EQ(extra_value(plain, "key_points"), static_cast<double>(n));
    }
    for (const std::string& mode : curves) {
      const PlanResult curve = plan_with(*with(mode.c_str()).planner);
      ASSERT_TRUE(curve.ok()) << mode;
      EXPECT_EQ(curve.waypoints_before_sampling, n) << mode;
      if (extra_value(curve, "key_points") >= 0.0) {
        EXPECT_EQ(extra_value(curve, "key_points"), static_cast<double>(n)) << mode;
      }
    }
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

INSTANTIATE_TEST_SUITE_P(Registry, PlannerContract, testing::ValuesIn(registered()),
                         [](const testing::TestParamInfo<std::string>& p) { return p.param; });

// What a plugin's planners must pass when it loads (engine/plan/plugins.cpp): the built-ins pass it
// too.
TEST(PlannerDeclarations, EveryBuiltInPassesThePluginCheck) {
  for (const PlannerInfo& info : planner_registry())
    EXPECT_NO_THROW(check_param_specs(info.params, info.name)) << info.name;
}

}  // namespace
}  // namespace agv
