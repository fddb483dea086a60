// GCC 12 flags the `_mm512_undefined_pd()` placeholders inside its own AVX-512 intrinsics once
// Eigen's packet min/max/sqrt are inlined here (GCC bug 105593, a false positive; as in
// algos/local/dwa.cpp). Before the includes: the warning is reported at the intrinsics header's
// lines.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "algos/swarm/hma_star.h"

// HMA* (paper 000 section 5, steps 8-13 and the pseudo-code; docs/PLANNERS.md "HMA*"):
// 1. MA* (the ma_star planner, run as configured here) gives the key nodes P0..Pm: its search
//    path after collinear (eq. 5.1a) and turning-point (eq. 5.1b) removal.
// 2. Sliding window n = 0 .. m-2: a swarm re-places P(n+1) between P(n) and P(n+2). A particle
//    is one point; its cost (eq. 5.1g resolved) is |P(n) - x| + |x - P(n+2)|, or +inf when
//    either segment is not free under SightRule::circles(r_obs, corner_rule) (the printed
//    f = k * c with c = 0 on collision would make colliding particles the best).
// 3. Initialisation eq. 5.1e over the window's bounding box widened by `window_margin` (clamped
//    to the map): pos = lo + (hi - lo) r, r per coordinate; velocity eq. 5.1f: vmax * r.
// 4. Each iteration (pseudo-code lines 21-29): costs; pbest / gbest (strictly smaller wins, so
//    the earlier particle keeps a tie); opposition-based learning (step 11): x_o = lo + hi - x,
//    the particle moves there when cost(x_o) <= cost(x), and pbest / gbest see its cost; the
//    inertia weight (`inertia`); the velocity / position update eq. 4.2a with r1, r2 per particle
//    and coordinate, velocities clamped to +-vmax, positions to the box.
// 5. After T_max iterations P(n+1) := gbest when gbest is feasible and shorter than the window's
//    current local path P(n) - P(n+1) - P(n+2); slide. Finally collinear and turning-point
//    removal again (step 13's "nodes of the final route").
// Every accepted change shortens the path and keeps its segments free under circles(r_obs), which
// includes the cells test under the corner rule; the removals never lengthen it. So the result
// is never longer than the MA* path and validates under MA*'s corner rule.
// Swarm positions and velocities are Eigen arrays updated as whole arrays; each iteration's
// (swarm x 2) segment checks go through the batched line of sight (core/line_of_sight_batch.h).
// Random draws, all from the run's Rng in a fixed order: per window 2 x swarm positions and
// 2 x swarm velocities, then per iteration rho (stochastic only) and 4 x swarm for r1, r2.
// Work counters: search_expansions are MA*'s; pso_evaluations the particle positions whose cost
// was computed; collision_checks MA*'s and every segment the swarm and the removals test.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "algos/postprocess/path_simplify.h"
#include "algos/search/ma_star.h"
#include "core/cell_geometry.h"
#include "core/line_of_sight.h"
#include "core/line_of_sight_batch.h"
#include "core/numbers.h"

namespace agv {

namespace {

// A window's gbest replaces P(n+1) only when it shortens the local path by more than rounding.
constexpr double kMinGain = 1e-9;

using Swarm = Eigen::Array<double, Eigen::Dynamic, 2>;
using Row2 = Eigen::Array<double, 1, 2>;

struct PsoSettings {
  int swarm = 30;
  int iterations = 50;
  double c1 = 1.5;
  double c2 = 1.5;
  double w_max = 0.9;
  double w_min = 0.4;
  Inertia inertia = Inertia::stochastic;
  double vmax_fraction = 0.2;
  double margin = 1.0;
  bool opposition = true;
};

// Per-thread buffers (request.scratch).
using Mask = Eigen::Array<bool, Eigen::Dynamic, 1>;

struct HmaScratch {
  Swarm x, v, pbest, xo, r1, r2;
  Eigen::ArrayXd length, length_o, cost, cost_o, pbest_cost;
  Mask need;
  std::vector<Point> points;
  std::vector<Eigen::Index> index;
  std::vector<std::uint8_t> free;
};

// One window's swarm.
class WindowSwarm {
 public:
  WindowSwarm(const Grid& grid, const SightRule& sight, const PsoSettings& pso, Rng& rng,
              HmaScratch& s)
      : grid_(grid), sight_(sight), pso_(pso), rng_(rng), s_(s) {}

  // The best point found for the middle of a - ? - b and its cost (+inf when none is feasible).
  // `poll` is polled once per iteration; when it expires the swarm stops where it is (the
  // caller, seeing poll.has_expired(), gives up the plan).
  Point run(Point a, Point b, double& best_cost, DeadlinePoller& poll) {
    a_ = a;
    b_ = b;
    const double w = grid_.width();
    const double h = grid_.height();
    lo_ << std::clamp(std::min(a.x, b.x) - pso_.margin, 0.0, w),
        std::clamp(std::min(a.y, b.y) - pso_.margin, 0.0, h);
    hi_ << std::clamp(std::max(a.x, b.x) + pso_.margin, 0.0, w),
        std::clamp(std::max(a.y, b.y) + pso_.margin, 0.0, h);
    const Row2 extent = hi_ - lo_;
    const double vmax = pso_.vmax_fraction * std::hypot(extent(0), extent(1));
    const Eigen::Index n = pso_.swarm;

    // Eq. 5.1e over the widened box, eq. 5.1f.
    fill_uniform(s_.x, n);
    s_.x = (s_.x.rowwise() * extent).rowwise() + lo_;
    fill_uniform(s_.v, n);
    s_.v *= vmax;
    s_.pbest = s_.x;
    s_.pbest_cost.setConstant(n, kInf);
    gbest_ = s_.x.row(0);
    gbest_cost_ = kInf;

    for (int j = 1; j <= pso_.iterations; ++j) {
      if (poll.expired()) break;
      const double previous = gbest_cost_;
      // Line 23. Without opposition only a particle shorter than its pbest can change anything.
      lengths(s_.x, s_.length);
      if (pso_.opposition)
        s_.need.setConstant(n, true);
      else
        s_.need = s_.length < s_.pbest_cost;
      evaluate(s_.x, s_.length, s_.need, s_.cost);
      remember_best();  // line 24
      if (pso_.opposition) {
        // Lines 25-28: the opposite point in the box; move when it is no worse. Its cost is
        // needed where it decides the move (x feasible and x_o no longer) or may become a pbest
        // (x infeasible: the particle moves anyway); elsewhere it changes nothing.
        s_.xo = (-s_.x).rowwise() + (lo_ + hi_);
        lengths(s_.xo, s_.length_o);
        s_.need = (s_.cost < kInf && s_.length_o <= s_.cost) ||
                  (s_.cost == kInf && s_.length_o < s_.pbest_cost);
        evaluate(s_.xo, s_.length_o, s_.need, s_.cost_o);
        for (Eigen::Index i = 0; i < n; ++i) {
          if (s_.cost(i) < kInf && !s_.need(i)) continue;  // x_o is longer: no move
          if (s_.cost_o(i) <= s_.cost(i)) {
            s_.x.row(i) = s_.xo.row(i);
            s_.cost(i) = s_.cost_o(i);
          }
        }
        remember_best();
      }
      InertiaInputs in;
      in.j = j;
      in.t_max = pso_.iterations;
      in.w_max = pso_.w_max;
      in.w_min = pso_.w_min;
      if (pso_.inertia == Inertia::stochastic) in.rho = rng_.uniform(-0.1, 0.1);
      in.gbest = gbest_cost_;
      in.gbest_previous = previous;
      const double weight = inertia_weight(pso_.inertia, in);
      // Eq. 4.2a, r1 and r2 per particle and coordinate; clamping to +-vmax and to the box.
      fill_uniform(s_.r1, n);
      fill_uniform(s_.r2, n);
      s_.v = weight * s_.v + pso_.c1 * s_.r1 * (s_.pbest - s_.x) +
             pso_.c2 * s_.r2 * ((-s_.x).rowwise() + gbest_);
      s_.v = s_.v.max(-vmax).min(vmax);
      s_.x += s_.v;
      s_.x.col(0) = s_.x.col(0).max(lo_(0)).min(hi_(0));
      s_.x.col(1) = s_.x.col(1).max(lo_(1)).min(hi_(1));
    }
    best_cost = gbest_cost_;
    return {gbest_(0), gbest_(1)};
  }

  // Fitness evaluations so far: particle positions whose cost was computed (eq. 5.1g).
  std::int64_t evaluations() const { return evaluations_; }

 private:
  void fill_uniform(Swarm& m, Eigen::Index n) {
    m.resize(n, 2);
    for (Eigen::Index i = 0; i < n; ++i) {
      m(i, 0) = rng_.uniform01();
      m(i, 1) = rng_.uniform01();
    }
  }

  // |a - x| + |x - b| for each row of pos. A plain loop with std::sqrt, which GCC vectorises:
  // with EIGEN_FAST_MATH=0 (CMakeLists.txt) Eigen takes AVX-512's square roots one at a time.
  void lengths(const Swarm& pos, Eigen::ArrayXd& length) const {
    const Eigen::Index n = pos.rows();
    length.resize(n);
    const double* x = pos.col(0).data();
    const double* y = pos.col(1).data();
    double* out = length.data();
    for (Eigen::Index i = 0; i < n; ++i) {
      const double ax = x[i] - a_.x, ay = y[i] - a_.y, bx = x[i] - b_.x, by = y[i] - b_.y;
      out[i] = std::sqrt(ax * ax + ay * ay) + std::sqrt(bx * bx + by * by);
    }
  }

  // Eq. 5.1g resolved, for the rows in `need` (the others get +inf, which no comparison that
  // reads them can tell from their true cost): the local path length, +inf when a segment is not
  // free. The segments to a go first, as one batch; those to b only for the points a sees.
  void evaluate(const Swarm& pos, const Eigen::ArrayXd& length, const Mask& need,
                Eigen::ArrayXd& cost) {
    cost.setConstant(pos.rows(), kInf);
    s_.points.clear();
    s_.index.clear();
    for (Eigen::Index i = 0; i < pos.rows(); ++i)
      if (need(i)) {
        s_.points.push_back({pos(i, 0), pos(i, 1)});
        s_.index.push_back(i);
      }
    evaluations_ += static_cast<std::int64_t>(s_.points.size());
    s_.free.resize(s_.points.size());
    segments_free_from(grid_, a_, s_.points, sight_, s_.free);
    std::size_t kept = 0;
    for (std::size_t k = 0; k < s_.points.size(); ++k)
      if (s_.free[k] != 0) {
        s_.points[kept] = s_.points[k];
        s_.index[kept] = s_.index[k];
        ++kept;
      }
    s_.points.resize(kept);
    s_.free.resize(kept);
    segments_free_from(grid_, b_, s_.points, sight_, s_.free);
    for (std::size_t k = 0; k < kept; ++k)
      if (s_.free[k] != 0) cost(s_.index[k]) = length(s_.index[k]);
  }

  void remember_best() {
    for (Eigen::Index i = 0; i < s_.cost.size(); ++i) {
      if (s_.cost(i) < s_.pbest_cost(i)) {
        s_.pbest_cost(i) = s_.cost(i);
        s_.pbest.row(i) = s_.x.row(i);
      }
      if (s_.cost(i) < gbest_cost_) {
        gbest_cost_ = s_.cost(i);
        gbest_ = s_.x.row(i);
      }
    }
  }

  const Grid& grid_;
  const SightRule& sight_;
  const PsoSettings& pso_;
  Rng& rng_;
  HmaScratch& s_;
  Point a_, b_;
  Row2 lo_, hi_, gbest_;
  double gbest_cost_ = kInf;
  std::int64_t evaluations_ = 0;
};

const ChoiceTable<Inertia>& inertia_names() {
  static const ChoiceTable<Inertia> table = {{"stochastic", Inertia::stochastic},
                                             {"adaptive", Inertia::adaptive},
                                             {"linear", Inertia::linear}};
  return table;
}

struct HmaStarOptions {
  MaStarOptions ma;  // stage 1; its smoothing stays `none`
  PsoSettings pso;
};

ParamDecls<HmaStarOptions> hma_star_decls() {
  using O = HmaStarOptions;
  auto pso = [](auto field) {
    return [field](O & o) -> auto& { return o.pso.*field; };
  };
  ParamDecls<O> d;
  d.include(&O::ma, ma_star_search_decls())
      .integer("swarm", pso(&PsoSettings::swarm), 30, 1, 10000, "particles per window")
      .integer("iterations", pso(&PsoSettings::iterations), 50, 1, 100000,
               "T_max: PSO iterations per window")
      .number("c1", pso(&PsoSettings::c1), 1.5, 0.0, 10.0, "self-learning factor c1 (eq. 4.2a)")
      .number("c2", pso(&PsoSettings::c2), 1.5, 0.0, 10.0, "social-learning factor c2 (eq. 4.2a)")
      .number("w_max", pso(&PsoSettings::w_max), 0.9, 0.0, 2.0, "maximum inertia weight")
      .number("w_min", pso(&PsoSettings::w_min), 0.4, 0.0, 2.0, "minimum inertia weight")
      .choice("inertia", pso(&PsoSettings::inertia), Inertia::stochastic, inertia_names(),
              "inertia weight: stochastic = eq. 5.1d, w_max - (w_max - w_min)(j/T_max)e^rho with "
              "rho uniform in [-0.1, 0.1] per iteration (default); adaptive = eq. 5.1c as "
              "printed, (w_max + w_min)(gbest_j / gbest_j-1) - w_max j / T_max; linear = eq. "
              "5.1d with rho = 0")
      .number("vmax_fraction", pso(&PsoSettings::vmax_fraction), 0.2, 0.0, 10.0,
              "maximum particle speed per coordinate, as a fraction of the (widened) window "
              "diagonal")
      .number("window_margin", pso(&PsoSettings::margin), 1.0, 0.0, 1000.0,
              "cells added on every side of the bounding box of P(n), P(n+2) where the swarm "
              "lives (eq. 5.1e's box, widened so that a detour is reachable)")
      .boolean("opposition", pso(&PsoSettings::opposition), true,
               "opposition-based learning each iteration (step 11): move a particle to lo + hi - "
               "x when that is no worse");
  return d;
}

class HmaStarPlanner final : public Planner {
 public:
  explicit HmaStarPlanner(const HmaStarOptions& options)
      : ma_star_(make_ma_star(options.ma)),
        sight_(SightRule::circles(options.ma.r_obs, options.ma.search.setup.rule)),
        pso_(options.pso) {}

  PlanResult plan(const PlanRequest& request) const override {
    PlanResult result = ma_star_->plan(request);  // phases "search" and "postprocess"
    result.work.pso_evaluations = 0;
    if (!result.ok()) return result;
    int windows = 0;
    int improvements = 0;
    std::int64_t evaluations = 0;
    bool cut = false;
    {
      PhaseTimer timer(result, "pso");
      HmaScratch& scratch = request.scratch.get<HmaScratch>();
      std::vector<Point>& path = result.path;
      WindowSwarm swarm(request.grid, sight_, pso_, request.rng, scratch);
      // Polled per window, per swarm iteration and by the final removal's sight tests.
      DeadlinePoller poll(request.deadline, 1);
      for (std::size_t n = 0; n + 2 < path.size() && !poll.expired(); ++n) {
        const double current =
            point_distance(path[n], path[n + 1]) + point_distance(path[n + 1], path[n + 2]);
        double best = kInf;
        const Point candidate = swarm.run(path[n], path[n + 2], best, poll);
        if (poll.has_expired()) break;
        ++windows;
        if (best < current - kMinGain) {
          path[n + 1] = candidate;
          ++improvements;
        }
      }
      if (!poll.has_expired()) {
        remove_collinear(path);
        remove_turning_points(request.grid, path, sight_, &poll);
      }
      cut = poll.has_expired();
      evaluations = swarm.evaluations();
    }
    if (cut) {
      PlanResult f = PlanResult::failed(Failure::limit, "time limit");
      f.work = result.work;
      f.work.pso_evaluations = evaluations;
      f.phases = std::move(result.phases);
      return f;
    }
    // MA*'s counts describe its own path; the swarm step re-placed and dropped waypoints, so
    // the counts are those of the path returned (docs/METRICS.md waypoints).
    result.waypoints_before_sampling = static_cast<std::int64_t>(result.path.size());
    for (auto& [name, value] : result.extra)
      if (name == "key_points") value = static_cast<double>(result.path.size());
    result.work.pso_evaluations = evaluations;
    result.extra.emplace_back("pso_windows", windows);
    result.extra.emplace_back("pso_improvements", improvements);
    return result;
  }

 private:
  std::unique_ptr<Planner> ma_star_;
  SightRule sight_;
  PsoSettings pso_;
};

}  // namespace

std::optional<Inertia> inertia_from_string(std::string_view name) {
  for (const auto& [n, mode] : inertia_names())
    if (n == name) return mode;
  return std::nullopt;
}

double inertia_weight(Inertia mode, const InertiaInputs& in) {
  const double progress = static_cast<double>(in.j) / in.t_max;
  switch (mode) {
    case Inertia::stochastic:  // paper 000 eq. 5.1d
      return in.w_max - (in.w_max - in.w_min) * progress * std::exp(in.rho);
    case Inertia::linear:  // eq. 5.1d with rho = 0
      return in.w_max - (in.w_max - in.w_min) * progress;
    case Inertia::adaptive: {  // eq. 5.1c as printed
      const bool known = in.j > 1 && std::isfinite(in.gbest) && std::isfinite(in.gbest_previous) &&
                         in.gbest_previous > 0.0;
      const double ratio = known ? in.gbest / in.gbest_previous : 1.0;
      return (in.w_max + in.w_min) * ratio - in.w_max * progress;
    }
  }
  return in.w_max;
}

PlannerInfo hma_star_planner() {
  PlannerInfo info;
  info.kind = PlannerKind::swarm;
  info.name = "hma_star";
  info.summary =
      "HMA*: MA* key nodes, then a sliding-window PSO with stochastic inertia weight "
      "and opposition-based learning re-placing each middle node";
  info.source = "paper 000 section 5 (eq. 4.2a, 5.1c-5.1g, pseudo-code); docs/PLANNERS.md HMA*";
  info.counters = {
      {"search_expansions", "MA*'s search expansions (cells closed, goal included)"},
      {"pso_evaluations", "particle positions whose cost (eq. 5.1g) was computed, all windows"},
      {"collision_checks",
       "MA*'s (8 neighbour-cell tests per expansion, its turning-point removal's segments) and "
       "every segment the swarm and the final removals test"}};
  info.stochastic = true;
  info.params = hma_star_decls().specs();
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<HmaStarPlanner>(hma_star_decls().read(params));
  };
  return info;
}

}  // namespace agv
