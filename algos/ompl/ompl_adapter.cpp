#include "algos/ompl/ompl_adapter.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/samplers/informed/RejectionInfSampler.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/util/Console.h>

#include <limits>
#include <mutex>
#include <utility>
#include <vector>

#include "algos/sampling/sampling_params.h"

namespace agv {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

// What the OMPL objects of one run share with it: the map and test, the run's Rng (seeds of the
// samplers allocated during the run) and the sample count. Outlives every OMPL object of the run.
class Termination;
struct RunContext {
  const Grid& grid;
  SightRule sight;
  Rng& rng;
  const Termination* stop = nullptr;
  std::int64_t samples = 0;
  bool stopped() const;
};

Point point_of(const ob::State* s) {
  const auto* v = s->as<ob::RealVectorStateSpace::StateType>();
  return {v->values[0], v->values[1]};
}

// OMPL's uniform sampler, its generator seeded from the run and every draw counted (the
// `samples` work counter).
class SeededSampler final : public ob::RealVectorStateSampler {
 public:
  SeededSampler(const ob::StateSpace* space, RunContext& run)
      : ob::RealVectorStateSampler(space), run_(run) {
    rng_.setLocalSeed(run.rng.next_u32());
  }
  void sampleUniform(ob::State* state) override {
    ++run_.samples;
    ob::RealVectorStateSampler::sampleUniform(state);
  }
  void sampleUniformNear(ob::State* state, const ob::State* near, double distance) override {
    ++run_.samples;
    ob::RealVectorStateSampler::sampleUniformNear(state, near, distance);
  }
  void sampleGaussian(ob::State* state, const ob::State* mean, double std_dev) override {
    ++run_.samples;
    ob::RealVectorStateSampler::sampleGaussian(state, mean, std_dev);
  }

 private:
  RunContext& run_;
};

// The map as a 2D real vector space whose default sampler is the seeded one: every sampler a
// planner or an informed sampler allocates (allocStateSampler, allocDefaultStateSampler) is ours.
class GridSpace final : public ob::RealVectorStateSpace {
 public:
  explicit GridSpace(RunContext& run) : ob::RealVectorStateSpace(2), run_(run) {
    ob::RealVectorBounds bounds(2);
    bounds.setLow(0.0);
    bounds.setHigh(0, run.grid.width());
    bounds.setHigh(1, run.grid.height());
    setBounds(bounds);
  }
  ob::StateSamplerPtr allocDefaultStateSampler() const override {
    return std::make_shared<SeededSampler>(this, run_);
  }

 private:
  RunContext& run_;
};

// A state is valid when the point passes the validator's test (a point is the segment p-p).
class PointValidity final : public ob::StateValidityChecker {
 public:
  PointValidity(const ob::SpaceInformationPtr& si, const RunContext& run)
      : ob::StateValidityChecker(si), run_(run) {}
  bool isValid(const ob::State* state) const override {
    const Point p = point_of(state);
    return segment_free(run_.grid, p, p, run_.sight);
  }

 private:
  const RunContext& run_;
};

// A motion is valid when its segment passes the validator's test.
class SegmentValidity final : public ob::MotionValidator {
 public:
  SegmentValidity(const ob::SpaceInformationPtr& si, const RunContext& run)
      : ob::MotionValidator(si), run_(run) {}
  bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
    // After the deadline every motion is refused untested: the run ends as limit anyway, and
    // loops that do not evaluate the termination condition (LazyPRM's solution construction
    // removes invalid edges until start and goal part) end quickly.
    if (run_.stopped()) return false;
    if (segment_free(run_.grid, point_of(s1), point_of(s2), run_.sight)) {
      ++valid_;
      return true;
    }
    ++invalid_;
    return false;
  }
  // The last valid state is reported conservatively as s1 (time 0): the shared test answers
  // free or not, and a planner only uses the pair to extend by a shorter valid motion.
  bool checkMotion(const ob::State* s1, const ob::State* s2,
                   std::pair<ob::State*, double>& last_valid) const override {
    if (checkMotion(s1, s2)) return true;
    if (last_valid.first != nullptr) si_->copyState(last_valid.first, s1);
    last_valid.second = 0.0;
    return false;
  }

 private:
  const RunContext& run_;
};

// Path length whose informed sampler is rejection sampling on the space's (seeded) sampler.
class SeededPathLength final : public ob::PathLengthOptimizationObjective {
 public:
  using ob::PathLengthOptimizationObjective::PathLengthOptimizationObjective;
  ob::InformedSamplerPtr allocInformedStateSampler(const ob::ProblemDefinitionPtr& problem,
                                                   unsigned int max_calls) const override {
    return std::make_shared<ob::RejectionInfSampler>(problem, max_calls);
  }
};

// The run's termination: the iteration budget (evaluations of the condition) or the deadline,
// polled on the first evaluation and every kSamplingDeadlineInterval-th after it; once expired it
// stays expired and polls no more.
class Termination {
 public:
  Termination(const Deadline& deadline, long long budget) : deadline_(deadline), budget_(budget) {}
  bool operator()() {
    if (expired_) return true;
    if (evaluations_ % kSamplingDeadlineInterval == 0 && deadline_.expired()) {
      expired_ = true;
      return true;
    }
    return ++evaluations_ > budget_;
  }
  bool expired() const { return expired_; }
  long long evaluations() const { return evaluations_; }

 private:
  const Deadline& deadline_;
  long long budget_;
  long long evaluations_ = 0;
  bool expired_ = false;
};

bool RunContext::stopped() const { return stop != nullptr && stop->expired(); }

// OMPL's console is silenced once per process: a sweep would print every planner's set-up lines.
void silence_ompl() {
  static std::once_flag once;
  std::call_once(once, [] { ompl::msg::setLogLevel(ompl::msg::LOG_NONE); });
}

// PRM and PRM* grown one milestone at a time on this thread (PRM::solve grows in a second thread
// and looks for a solution every millisecond, so what it returns depends on timing). PRM stops
// at the first milestone after which start and goal are in one component; PRM* grows all
// `samples` milestones and returns the best path of its roadmap.
class RoadmapPrm final : public og::PRM {
 public:
  RoadmapPrm(const ob::SpaceInformationPtr& si, bool star, std::uint32_t seed) : og::PRM(si, star) {
    rng_.setLocalSeed(seed);
  }

  // An exact path, or nullptr (budget spent without one, or `stop` fired).
  ob::PathPtr grow(long long samples, bool first_solution, Termination& stop) {
    checkValidity();
    while (const ob::State* st = pis_.nextStart())
      startM_.push_back(addMilestone(si_->cloneState(st)));
    if (const ob::State* st = pis_.nextGoal()) goalM_.push_back(addMilestone(si_->cloneState(st)));
    if (startM_.empty() || goalM_.empty()) return nullptr;
    if (!sampler_) sampler_ = si_->allocValidStateSampler();
    bestCost_ = opt_->infiniteCost();
    ob::State* work = si_->allocState();
    ob::PathPtr path;
    const unsigned long first = milestoneCount();
    for (long long i = 0; i < samples && !stop.expired(); ++i) {
      const unsigned long target = first + static_cast<unsigned long>(i) + 1;
      growRoadmap(ob::PlannerTerminationCondition(
                      [&] { return stop.expired() || milestoneCount() >= target || stop(); }),
                  work);
      if (first_solution && !stop.expired() && maybeConstructSolution(startM_, goalM_, path)) break;
    }
    si_->freeState(work);
    grown_ = milestoneCount() - first;
    if (stop.expired()) return nullptr;
    if (!first_solution) maybeConstructSolution(startM_, goalM_, path);  // the best, if any
    return path;
  }
  // Milestones the last grow() added besides start and goal.
  unsigned long grown() const { return grown_; }

 private:
  unsigned long grown_ = 0;
};

class OmplPlanner final : public Planner {
 public:
  OmplPlanner(const OmplEntry& entry, const OmplOptions& options)
      : entry_(entry), options_(options) {}

  bool counts_collision_checks() const override { return entry_.reproducible_checks; }

  PlanResult plan(const PlanRequest& request) const override {
    silence_ompl();
    PlanResult result;
    result.rule = options_.sight.corners;
    result.work.samples = 0;
    if (request.start == request.goal) {
      result.failure = Failure::none;
      result.path = {centre(request.start)};
      return result;
    }
    RunContext run{request.grid, options_.sight, request.rng};
    const bool roadmap = entry_.driver == OmplDriver::roadmap;
    Termination stop(request.deadline,
                     roadmap ? std::numeric_limits<long long>::max() : options_.max_iterations);
    run.stop = &stop;
    ob::PathPtr path;
    double grown = 0.0;  // roadmap: milestones grown (start and goal not counted)
    {
      PhaseTimer timer(result, "search");
      auto space = std::make_shared<GridSpace>(run);
      auto si = std::make_shared<ob::SpaceInformation>(space);
      si->setStateValidityChecker(std::make_shared<PointValidity>(si, run));
      si->setMotionValidator(std::make_shared<SegmentValidity>(si, run));
      si->setup();
      auto problem = std::make_shared<ob::ProblemDefinition>(si);
      ob::ScopedState<ob::RealVectorStateSpace> start(space), goal(space);
      const Point s = centre(request.start), g = centre(request.goal);
      start[0] = s.x;
      start[1] = s.y;
      goal[0] = g.x;
      goal[1] = g.y;
      problem->setStartAndGoalStates(start, goal);
      auto objective = std::make_shared<SeededPathLength>(si);
      objective->setCostThreshold(entry_.first_solution ? objective->infiniteCost()
                                                        : ob::Cost(0.0));
      problem->setOptimizationObjective(objective);

      const std::uint32_t seed = request.rng.next_u32();
      ob::PlannerPtr planner;
      if (roadmap) {
        auto prm = std::make_shared<RoadmapPrm>(si, !entry_.first_solution, seed);
        prm->setProblemDefinition(problem);
        if (entry_.configure != nullptr) entry_.configure(*prm, options_);
        prm->setup();
        path = prm->grow(options_.samples, entry_.first_solution, stop);
        grown = static_cast<double>(prm->grown());
      } else {
        planner = entry_.make(si, seed);
        planner->setProblemDefinition(problem);
        if (entry_.configure != nullptr) entry_.configure(*planner, options_);
        planner->setup();
        const ob::PlannerStatus status =
            planner->solve(ob::PlannerTerminationCondition([&] { return stop(); }));
        if (status == ob::PlannerStatus::EXACT_SOLUTION && problem->hasExactSolution())
          path = problem->getSolutionPath();
      }
      if (path != nullptr && !stop.expired())
        for (const ob::State* state : path->as<og::PathGeometric>()->getStates())
          result.path.push_back(point_of(state));
      // OMPL 1.5's LazyPRM frees its roadmap's states in clear() but not in its destructor
      // (ompl/ompl#833, fixed in 1.6 by ompl/ompl#909): without this every ompl_lazyprmstar run
      // leaks its milestones. The path's points are copied above; clear() is harmless for the rest.
      if (planner != nullptr) planner->clear();
    }
    result.work.samples = run.samples;
    // Iterations: of the roadmap's growth loop (one milestone each), or of the planner's main loop.
    result.extra.emplace_back("iterations",
                              roadmap ? grown : static_cast<double>(stop.evaluations()));
    if (stop.expired()) {
      result.path.clear();
      result.failure = Failure::limit;
      result.message = "deadline passed before the planner finished";
      return result;
    }
    if (result.path.empty()) {
      result.failure = Failure::limit;
      result.message = roadmap ? "the roadmap does not connect start and goal after `samples` "
                                 "milestones"
                               : "no exact solution within max_iterations";
      return result;
    }
    result.failure = Failure::none;
    return result;
  }

 private:
  const OmplEntry& entry_;
  OmplOptions options_;
};

}  // namespace

ParamDecls<OmplOptions> ompl_iteration_decls(long long default_iterations) {
  ParamDecls<OmplOptions> d;
  d.integer("max_iterations", &OmplOptions::max_iterations, default_iterations, 1, 100000000,
            "iterations before giving up with failure `limit`: evaluations of OMPL's termination "
            "condition (one per iteration of the planner's main loop); an optimizing planner "
            "runs them all and returns its best path");
  return d;
}

ParamDecls<OmplOptions> ompl_sight_decls() {
  ParamDecls<OmplOptions> d;
  d.include(&OmplOptions::sight, segment_sight_decls(CornerRule::no_corner_cut));
  return d;
}

PlannerInfo ompl_planner_info(const OmplEntry& entry,
                              std::unique_ptr<Planner> (*make)(const Params& params)) {
  PlannerInfo info;
  info.kind = PlannerKind::sampling;
  info.name = entry.name;
  info.summary = entry.summary;
  info.source = entry.source;
  info.counters = {{"samples",
                    "states drawn by OMPL's state samplers (valid-state and informed samplers "
                    "included, each attempt counted)"}};
  if (entry.reproducible_checks)
    info.counters.push_back({"collision_checks",
                             "points (state validity) and segments (motion validity) tested by "
                             "the shared line-of-sight test"});
  info.stochastic = true;
  info.proves_no_path = false;  // gives up with limit after its budget
  info.params = entry.decls.specs();
  info.make = make;
  return info;
}

std::unique_ptr<Planner> make_ompl_planner(const OmplEntry& entry, const Params& params) {
  return std::make_unique<OmplPlanner>(entry, entry.decls.read(params));
}

}  // namespace agv
