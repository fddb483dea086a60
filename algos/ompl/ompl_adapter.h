#pragma once
// One adapter from a grid map and the sweep's collision model to OMPL's geometric planners
// (docs/PLANNERS.md "OMPL planners"): the map is a 2D RealVectorStateSpace over [0, width] x
// [0, height] in continuous cell coordinates; a state is valid when the shared line-of-sight test
// (core/line_of_sight.h, the validator's own function) holds for the point, a motion when it holds
// for the segment, both under the planner's corner rule and clearance (which follow the collision
// model, algos/registry.h). Every OMPL planner is a thin entry (algos/ompl/ompl_planners.cpp):
// its name, its declared parameters and how to construct and set it up.
//
// Reproducibility. Each run terminates by a count (OMPL's IterationTerminationCondition idea:
// evaluations of the termination condition, one per iteration of a planner's main loop; roadmap
// milestones for PRM and PRM*), never by time: the run's deadline only ends it early, with
// `limit`. Every random draw of a run comes from generators seeded from the run's Rng: the
// planner's own generator (setLocalSeed) and every state sampler the run allocates (the state
// space's default sampler is ours, seeded at allocation), so a run does not depend on OMPL's
// process-wide seed sequence, hence not on the thread that runs it. Informed samplers are OMPL's
// RejectionInfSampler (on our seeded sampler) instead of the direct sampler, whose generator
// cannot be seeded from outside. PRM's own solve() grows the roadmap in a second thread and checks
// for a solution every millisecond; PRM and PRM* are driven here instead, single-threaded, one
// milestone at a time (growRoadmap only, no timed expansion phase).

#include <ompl/base/Planner.h>
#include <ompl/base/SpaceInformation.h>

#include <cstdint>
#include <memory>
#include <string>

#include "algos/planner_info.h"
#include "core/line_of_sight.h"
#include "core/params.h"

namespace agv {

// Every OMPL planner's options; each entry declares the ones it has.
struct OmplOptions {
  long long max_iterations = 0;  // termination-condition evaluations (solve-driven planners)
  long long samples = 0;         // roadmap milestones besides start and goal (PRM, PRM*)
  double range = 0.0;            // cells; 0 = OMPL's default (a fifth of the map's diagonal)
  double goal_bias = 0.0;
  double rewire_factor = 1.1;
  bool k_nearest = true;
  bool delay_cc = true;
  long long samples_per_batch = 100;
  bool pruning = true;
  long long max_nearest_neighbors = 10;
  SightRule sight = SightRule::cells();
};

// How a run is driven to its end.
enum class OmplDriver {
  solve,    // planner->solve(condition): stops at its own criterion or after max_iterations
  roadmap,  // PRM-family roadmap grown milestone by milestone (OmplEntry::make returns a PRM)
};

struct OmplEntry {
  std::string name;     // public name, "ompl_rrt"
  std::string summary;  // one line for `agvbench list`
  std::string source;   // the OMPL class and its paper
  ParamDecls<OmplOptions> decls;
  OmplDriver driver = OmplDriver::solve;
  // true: the first path found ends the run (the objective's threshold is infinite); false: an
  // optimizing planner runs its whole budget and returns the best path (threshold 0).
  bool first_solution = true;
  // solve: constructs the planner on `si`, its own generator (if it has one) seeded with `seed`
  // (the roadmap driver constructs its PRM itself: PRM* when !first_solution).
  ompl::base::PlannerPtr (*make)(const ompl::base::SpaceInformationPtr& si,
                                 std::uint32_t seed) = nullptr;
  // Sets the planner's parameters, after the adapter gave it the problem, before setup().
  void (*configure)(ompl::base::Planner& planner, const OmplOptions& options) = nullptr;
  // false: the planner's collision-check count is not reproducible and is not reported (BIT*:
  // docs/PLANNERS.md "OMPL planners"); its paths and samples are.
  bool reproducible_checks = true;
};

// The registry entry of an OMPL planner: kind sampling, stochastic, gives up with limit; `make`
// builds an adapter around `entry` (which must outlive it: the registration's static table).
PlannerInfo ompl_planner_info(const OmplEntry& entry,
                              std::unique_ptr<Planner> (*make)(const Params& params));
std::unique_ptr<Planner> make_ompl_planner(const OmplEntry& entry, const Params& params);

// The iteration budget, the corner rule and the clearance every OMPL planner declares.
ParamDecls<OmplOptions> ompl_iteration_decls(long long default_iterations);
ParamDecls<OmplOptions> ompl_sight_decls();

// A planner of class Base whose own generator is seeded from the run (rng_ is protected in
// every OMPL planner that has one).
template <class Base>
class SeededPlanner final : public Base {
 public:
  SeededPlanner(const ompl::base::SpaceInformationPtr& si, std::uint32_t seed) : Base(si) {
    this->rng_.setLocalSeed(seed);
  }
};

}  // namespace agv
