#include "algos/ompl/ompl_planners.h"

#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/LazyPRMstar.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>

#include <array>
#include <memory>
#include <stdexcept>
#include <utility>

#include "algos/ompl/ompl_adapter.h"

namespace agv {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

// The parameter groups, each declared once with OMPL's defaults.
ParamDecls<OmplOptions>& range_decls(ParamDecls<OmplOptions>& d) {
  return d.number("range", &OmplOptions::range, 0.0, 0.0, 1e6,
                  "maximum length of a motion added to the tree, in cells (OMPL's setRange); 0 = "
                  "OMPL's default, a fifth of the map's diagonal");
}
ParamDecls<OmplOptions>& goal_bias_decls(ParamDecls<OmplOptions>& d) {
  return d.number("goal_bias", &OmplOptions::goal_bias, 0.05, 0.0, 1.0,
                  "probability that a sample is the goal state (OMPL's setGoalBias)");
}
ParamDecls<OmplOptions>& rrtstar_decls(ParamDecls<OmplOptions>& d) {
  range_decls(d);
  goal_bias_decls(d);
  return d
      .number("rewire_factor", &OmplOptions::rewire_factor, 1.1, 1.0, 100.0,
              "multiple of the asymptotically optimal rewiring radius (or number of neighbours) "
              "(OMPL's setRewireFactor)")
      .boolean("k_nearest", &OmplOptions::k_nearest, true,
               "rewire among the k nearest nodes instead of those within a radius (OMPL's "
               "setKNearest)")
      .boolean("delay_cc", &OmplOptions::delay_cc, true,
               "check a candidate parent's edge only when it would lower the cost (OMPL's "
               "setDelayCC)");
}
ParamDecls<OmplOptions>& samples_decls(ParamDecls<OmplOptions>& d) {
  return d.integer("samples", &OmplOptions::samples, 500, 0, 10000000,
                   "roadmap milestones grown besides start and goal (each a valid sample; OMPL's "
                   "valid-state sampler tries up to 100 draws per milestone)");
}
template <class P>
ob::PlannerPtr seeded(const ob::SpaceInformationPtr& si, std::uint32_t seed) {
  return std::make_shared<SeededPlanner<P>>(si, seed);
}
// Planners without a generator of their own (their randomness is the seeded samplers').
template <class P>
ob::PlannerPtr unseeded(const ob::SpaceInformationPtr& si, std::uint32_t) {
  return std::make_shared<P>(si);
}

void configure_rrt(ob::Planner& p, const OmplOptions& o) {
  auto& rrt = static_cast<og::RRT&>(p);
  if (o.range > 0.0) rrt.setRange(o.range);
  rrt.setGoalBias(o.goal_bias);
}
void configure_rrtconnect(ob::Planner& p, const OmplOptions& o) {
  if (o.range > 0.0) static_cast<og::RRTConnect&>(p).setRange(o.range);
}
void configure_rrtstar(ob::Planner& p, const OmplOptions& o) {
  auto& rrt = static_cast<og::RRTstar&>(p);
  if (o.range > 0.0) rrt.setRange(o.range);
  rrt.setGoalBias(o.goal_bias);
  rrt.setRewireFactor(o.rewire_factor);
  rrt.setKNearest(o.k_nearest);
  rrt.setDelayCC(o.delay_cc);
}
void configure_bitstar(ob::Planner& p, const OmplOptions& o) {
  auto& bit = static_cast<og::BITstar&>(p);
  bit.setSamplesPerBatch(static_cast<unsigned int>(o.samples_per_batch));
  bit.setRewireFactor(o.rewire_factor);
  bit.setUseKNearest(o.k_nearest);
  bit.setPruning(o.pruning);
}
void configure_prm(ob::Planner& p, const OmplOptions& o) {
  static_cast<og::PRM&>(p).setMaxNearestNeighbors(
      static_cast<unsigned int>(o.max_nearest_neighbors));
}

const char* const kOmplSource =
    "docs/PLANNERS.md OMPL planners; OMPL 1.5 (Sucan, Moll, Kavraki 2012) ";

// The table: one entry per OMPL planner.
std::vector<OmplEntry> make_entries() {
  std::vector<OmplEntry> entries;
  const auto add = [&](std::string name, std::string summary, std::string source,
                       ParamDecls<OmplOptions> decls, OmplDriver driver, bool first_solution,
                       auto make, auto configure) {
    OmplEntry e;
    e.name = std::move(name);
    e.summary = std::move(summary);
    e.source = kOmplSource + std::move(source);
    decls.include([](OmplOptions& o) -> OmplOptions& { return o; }, ompl_sight_decls());
    e.decls = std::move(decls);
    e.driver = driver;
    e.first_solution = first_solution;
    e.make = make;
    e.configure = configure;
    entries.push_back(std::move(e));
  };
  {
    ParamDecls<OmplOptions> d = ompl_iteration_decls(50000);
    range_decls(d);
    goal_bias_decls(d);
    add("ompl_rrt", "OMPL's RRT: one tree, goal bias, first path", "og::RRT; LaValle 1998",
        std::move(d), OmplDriver::solve, true, &seeded<og::RRT>, &configure_rrt);
  }
  {
    ParamDecls<OmplOptions> d = ompl_iteration_decls(50000);
    range_decls(d);
    add("ompl_rrtconnect", "OMPL's RRT-Connect: two trees grown towards each other, first path",
        "og::RRTConnect; Kuffner and LaValle 2000", std::move(d), OmplDriver::solve, true,
        &seeded<og::RRTConnect>, &configure_rrtconnect);
  }
  {
    ParamDecls<OmplOptions> d = ompl_iteration_decls(5000);
    rrtstar_decls(d);
    add("ompl_rrtstar", "OMPL's RRT*: asymptotically optimal RRT, the best path after the budget",
        "og::RRTstar; Karaman and Frazzoli 2011", std::move(d), OmplDriver::solve, false,
        &seeded<og::RRTstar>, &configure_rrtstar);
  }
  {
    ParamDecls<OmplOptions> d = ompl_iteration_decls(5000);
    rrtstar_decls(d);
    add("ompl_informed_rrtstar",
        "OMPL's Informed RRT*: RRT* sampling the ellipse that can still improve the path",
        "og::InformedRRTstar; Gammell, Srinivasa, Barfoot 2014", std::move(d), OmplDriver::solve,
        false, &seeded<og::InformedRRTstar>, &configure_rrtstar);
  }
  {
    ParamDecls<OmplOptions> d = ompl_iteration_decls(5000);
    d.integer("samples_per_batch", &OmplOptions::samples_per_batch, 100, 1, 1000000,
              "states sampled per batch (OMPL's setSamplesPerBatch)")
        .number("rewire_factor", &OmplOptions::rewire_factor, 1.1, 1.0, 100.0,
                "multiple of the asymptotically optimal connection radius or number of "
                "neighbours (OMPL's setRewireFactor)")
        .boolean("k_nearest", &OmplOptions::k_nearest, true,
                 "connect to the k nearest samples instead of those within a radius (OMPL's "
                 "setUseKNearest)")
        .boolean("pruning", &OmplOptions::pruning, true,
                 "drop samples and vertices that cannot improve the path (OMPL's setPruning)");
    add("ompl_bitstar", "OMPL's BIT*: batches of samples searched as an implicit graph, best path",
        "og::BITstar; Gammell, Srinivasa, Barfoot 2015", std::move(d), OmplDriver::solve, false,
        &unseeded<og::BITstar>, &configure_bitstar);
    entries.back().reproducible_checks = false;
  }
  {
    ParamDecls<OmplOptions> d;
    samples_decls(d);
    d.integer("max_nearest_neighbors", &OmplOptions::max_nearest_neighbors, 10, 1, 10000,
              "nearest milestones each new milestone tries to connect to (OMPL's "
              "setMaxNearestNeighbors)");
    add("ompl_prm", "OMPL's PRM: roadmap of k-nearest connections, first path",
        "og::PRM; Kavraki et al. 1996", std::move(d), OmplDriver::roadmap, true, nullptr,
        &configure_prm);
  }
  {
    ParamDecls<OmplOptions> d;
    samples_decls(d);
    add("ompl_prmstar", "OMPL's PRM*: roadmap with the asymptotically optimal k, best path",
        "og::PRMstar; Karaman and Frazzoli 2011", std::move(d), OmplDriver::roadmap, false, nullptr,
        nullptr);
  }
  {
    ParamDecls<OmplOptions> d;
    d.integer("max_iterations", &OmplOptions::max_iterations, 500, 1, 5000,
              "samples added to the lazy roadmap (one per iteration); it runs them all and "
              "returns its best path. At most 5000: every few edges added to the path's "
              "component it searches the whole roadmap again, so its cost grows faster than "
              "quadratically (5000 on a 160x160 maze: about 1.6 s)");
    add("ompl_lazyprmstar",
        "OMPL's LazyPRM*: PRM* whose edges are checked only on the candidate path, best path",
        "og::LazyPRMstar; Bohlin and Kavraki 2000, Karaman and Frazzoli 2011", std::move(d),
        OmplDriver::solve, false, &unseeded<og::LazyPRMstar>, nullptr);
  }
  return entries;
}

const std::vector<OmplEntry>& entries() {
  static const std::vector<OmplEntry> table = [] {
    std::vector<OmplEntry> t = make_entries();
    if (t.size() != kOmplPlanners) throw std::logic_error("kOmplPlanners is not the table's size");
    return t;
  }();
  return table;
}

template <std::size_t I>
std::unique_ptr<Planner> make_entry(const Params& params) {
  return make_ompl_planner(entries()[I], params);
}

template <std::size_t... I>
std::vector<PlannerInfo> infos(std::index_sequence<I...>) {
  return {ompl_planner_info(entries()[I], &make_entry<I>)...};
}

}  // namespace

std::vector<PlannerInfo> ompl_planners() {
  return infos(std::make_index_sequence<kOmplPlanners>());
}

}  // namespace agv
