#include "algos/swarm/aco.h"

// Choices the papers leave open, fixed here:
// - Pheromone lives on cells (one value per cell of the padded grid), and a move is scored by
//   the cell it enters: weight = tau(n)^alpha * eta(n)^beta, eta(n) = 1 / Euclidean distance
//   (cells) from n's centre to the goal's centre. The goal itself (eta infinite) is entered as
//   soon as it is an allowed move.
// - Moves: 8-connected under corner_rule (default allow: the "traditional" grid of paper 002's
//   comparison). Each ant keeps a tabu list (no cell visited twice); an ant with no allowed,
//   unvisited neighbour is in a dead end and dies (no backtracking, no deposit).
// - Update per iteration (ant-cycle): tau <- (1 - evaporation) * tau, then every ant that reached
//   the goal adds Q / L to each cell of its path (L: its length in cells). All ants of an
//   iteration walk on the pheromone of the previous one.
// - The result is the shortest path any ant found over all iterations (first found on ties).
//
// Evaporation scales every cell alike, so tau = scale * stored with one shared `scale`: an
// iteration multiplies scale only, a deposit adds Q / L / scale to `stored`, and each cell caches
// stored^alpha * eta^beta (a uniform factor cancels in the roulette); only deposits recompute a
// cell's weight. Cells are initialised lazily, by a per-plan stamp, on first sight.
//
// What an ant's step reads of each neighbour (its weight and both stamps) is one 16-byte entry,
// four to a cache line; what only first sight and deposits touch lives apart: a walk's loads
// stay in the cache on maps whose whole state would not.

#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "algos/search/grid_search_params.h"
#include "algos/search/heuristics.h"
#include "core/cell_blocks.h"
#include "core/corner_rule.h"
#include "core/line_of_sight.h"

namespace agv {

namespace {

// Below this the shared scale is folded into every seen cell, long before any value can
// under- or overflow.
constexpr double kRenormaliseBelow = 1e-30;
// Deadline poll period in ant steps; a power of two.
constexpr std::int64_t kStepDeadlineInterval = 1024;

// Per padded cell, what every ant step reads.
struct AcoHot {
  double weight = 0.0;      // stored^alpha * eta^beta
  std::uint32_t seen = 0;   // == plan stamp: this entry and the cell's AcoCold belong to this plan
  std::uint32_t visit = 0;  // == ant stamp: visited by the current ant
};

// Per padded cell, what first sight and deposits use.
struct AcoCold {
  double stored = 0.0;   // pheromone / scale
  double eta_pow = 0.0;  // eta^beta
};

struct AcoScratch {
  std::vector<AcoHot> hot;  // padded grid
  std::vector<AcoCold> cold;
  std::uint32_t plan_stamp = 0;
  std::uint32_t ant_stamp = 0;
  std::vector<int> walk;     // the current ant's cells
  std::vector<int> arrived;  // cells of this iteration's successful walks, concatenated
  std::vector<std::size_t> arrived_end;
  std::vector<double> arrived_length;
  std::vector<int> best;
};

struct AcoSettings {
  long long ants = 0;
  long long iterations = 0;
  double evaporation = 0.0;
  double alpha = 0.0;
  double beta = 0.0;
  double q = 0.0;
  double initial_pheromone = 0.0;
  CornerRule rule = CornerRule::allow;
};

class Colony {
 public:
  Colony(const PlanRequest& request, const AcoSettings& settings, AcoScratch& s)
      : grid_(request.grid),
        request_(request),
        settings_(settings),
        s_(s),
        goal_(request.grid.index(request.goal)),
        fresh_stored_(settings.initial_pheromone) {
    const auto size = static_cast<std::size_t>(grid_.padded_size());
    if (s_.hot.size() < size) {
      s_.hot.assign(size, AcoHot{});
      s_.cold.assign(size, AcoCold{});
      s_.plan_stamp = 0;
      s_.ant_stamp = 0;
    }
    if (++s_.plan_stamp == 0) {
      for (AcoHot& c : s_.hot) c.seen = 0;
      s_.plan_stamp = 1;
    }
    for (int d = 0; d < 8; ++d) offset_[d] = kDx[d] + kDy[d] * grid_.stride();
    // A cell's 3x3 block mask (core/cell_blocks.h: one load) to the moves the rule allows.
    constexpr std::uint32_t kBlockOf[8] = {kBlockRight,  kBlockDown,      kBlockLeft,
                                           kBlockUp,     kBlockDownRight, kBlockDownLeft,
                                           kBlockUpLeft, kBlockUpRight};
    const MoveTable& moves = move_table(settings.rule);
    for (unsigned m = 0; m < 256; ++m) {
      unsigned free_mask = 0;
      for (int d = 0; d < 8; ++d) free_mask |= static_cast<unsigned>((m & kBlockOf[d]) == 0) << d;
      allowed_[m] = moves[free_mask];
    }
  }

  // Returns false when the deadline passed.
  bool run() {
    const int start = grid_.index(request_.start);
    for (long long it = 0; it < settings_.iterations; ++it) {
      s_.arrived.clear();
      s_.arrived_end.clear();
      s_.arrived_length.clear();
      for (long long ant = 0; ant < settings_.ants; ++ant) {
        double length = 0.0;
        const WalkEnd end = walk(start, length);
        if (end == WalkEnd::deadline) return false;
        if (end == WalkEnd::dead_end) continue;
        ++successful_;
        s_.arrived.insert(s_.arrived.end(), s_.walk.begin(), s_.walk.end());
        s_.arrived_end.push_back(s_.arrived.size());
        s_.arrived_length.push_back(length);
        if (length < best_length_) {
          best_length_ = length;
          s_.best = s_.walk;
        }
      }
      update_pheromone();
      ++iterations_done_;
    }
    return true;
  }

  bool found() const { return best_length_ < kInfinity; }
  std::int64_t steps() const { return steps_; }
  // Neighbour-cell occupancy tests: 8 at every position an ant chooses its next move from.
  std::int64_t cell_tests() const { return cell_tests_; }
  long long successful() const { return successful_; }
  long long iterations_done() const { return iterations_done_; }

 private:
  enum class WalkEnd { goal, dead_end, deadline };
  static constexpr double kInfinity = 1e300;

  // The cell's weight, its entries set up on first sight this plan.
  double weight(int index) {
    AcoHot& h = s_.hot[static_cast<std::size_t>(index)];
    if (h.seen != s_.plan_stamp) [[unlikely]]
      first_sight(index);
    return h.weight;
  }

  [[gnu::noinline]] void first_sight(int index) {
    AcoHot& h = s_.hot[static_cast<std::size_t>(index)];
    AcoCold& c = s_.cold[static_cast<std::size_t>(index)];
    const Cell at = grid_.cell_of(index);
    const double d = std::hypot(at.x - request_.goal.x, at.y - request_.goal.y);
    h.seen = s_.plan_stamp;
    c.stored = fresh_stored_;
    c.eta_pow = d > 0.0 ? std::pow(1.0 / d, settings_.beta) : 0.0;  // the goal: never scored
    h.weight = std::pow(c.stored, settings_.alpha) * c.eta_pow;
  }

  void next_ant() {
    if (++s_.ant_stamp == 0) {
      for (AcoHot& c : s_.hot) c.visit = 0;
      s_.ant_stamp = 1;
    }
  }

  // Every ant step scans all 8 directions without a data-dependent branch but the rare first
  // sight of a cell and the goal: the moves the corner rule allows and the ant has not made are
  // packed in direction order with the running sum of their weights, as the original scan added
  // them (so `total` and each prefix are the same doubles), and the roulette counts the prefixes
  // at or below its draw instead of stopping at the first above it.
  WalkEnd walk(int start, double& length) {
    next_ant();
    s_.walk.clear();
    s_.walk.push_back(start);
    AcoHot* hot = s_.hot.data();
    const std::uint32_t ant = s_.ant_stamp;
    const std::uint32_t plan = s_.plan_stamp;
    hot[start].visit = ant;
    const std::uint32_t* blocks = grid_.cell_blocks().masks();
    int at = start;
    for (;;) {
      if (steps_ % kStepDeadlineInterval == 0 && request_.deadline.expired())
        return WalkEnd::deadline;
      const unsigned allowed_moves = allowed_[blocks[at] & 0xFFU];
      cell_tests_ += 8;
      int candidate_dir[8];
      double prefix[8];
      double total = 0.0;
      int count = 0;
      int goal_dir = -1;
      // In direction order, as the roulette reads them; the goal ends the scan.
      for (unsigned allowed = allowed_moves; allowed != 0; allowed &= allowed - 1) {
        const int d = std::countr_zero(allowed);
        const int n = at + offset_[d];
        if (n == goal_) {
          goal_dir = d;
          break;
        }
        if (hot[n].visit == ant) continue;
        total += weight(n);
        candidate_dir[count] = d;
        prefix[count] = total;
        ++count;
      }
      int next_dir = goal_dir;
      if (goal_dir < 0) {
        if (count == 0) return WalkEnd::dead_end;
        next_dir = candidate_dir[count > 1 ? roulette(prefix, count, total) : 0];
      }
      const int next = at + offset_[next_dir];
      ++steps_;
      length += is_diagonal(next_dir) ? kSqrt2 : 1.0;
      s_.walk.push_back(next);
      if (next == goal_) return WalkEnd::goal;
      hot[next].visit = ant;
      at = next;
    }
  }

  // Roulette wheel over count > 1 candidates with running sums `prefix` (the last is `total`):
  // P(k) = weight[k] / total, the first k whose running sum exceeds the draw; uniform when the
  // weights cannot be used (all zero, or their sum overflowed).
  int roulette(const double* prefix, int count, double total) {
    if (!(total > 0.0 && std::isfinite(total)))
      return static_cast<int>(request_.rng.below(static_cast<std::uint32_t>(count)));
    const double r = request_.rng.uniform01() * total;
    for (int k = 0; k < count; ++k)
      if (r < prefix[k]) return k;
    return count - 1;
  }

  void update_pheromone() {
    scale_ *= 1.0 - settings_.evaporation;
    std::size_t begin = 0;
    for (std::size_t w = 0; w < s_.arrived_end.size(); ++w) {
      const double deposit = settings_.q / s_.arrived_length[w] / scale_;
      for (std::size_t i = begin; i < s_.arrived_end[w]; ++i) {
        const auto index = static_cast<std::size_t>(s_.arrived[i]);
        weight(s_.arrived[i]);  // sets a cell first seen now up
        AcoCold& c = s_.cold[index];
        c.stored += deposit;
        s_.hot[index].weight = std::pow(c.stored, settings_.alpha) * c.eta_pow;
      }
      begin = s_.arrived_end[w];
    }
    if (scale_ < kRenormaliseBelow) {
      const double factor = std::pow(scale_, settings_.alpha);
      for (std::size_t i = 0; i < s_.hot.size(); ++i) {
        if (s_.hot[i].seen != s_.plan_stamp) continue;
        s_.cold[i].stored *= scale_;
        s_.hot[i].weight *= factor;
      }
      fresh_stored_ *= scale_;
      scale_ = 1.0;
    }
  }

  const Grid& grid_;
  const PlanRequest& request_;
  const AcoSettings& settings_;
  AcoScratch& s_;
  const int goal_;
  int offset_[8] = {};
  std::uint8_t allowed_[256] = {};  // block mask (low 8 bits) -> allowed moves
  double scale_ = 1.0;
  double fresh_stored_;  // `stored` of a cell first seen now (initial pheromone / scale history)
  double best_length_ = kInfinity;
  std::int64_t steps_ = 0;
  std::int64_t cell_tests_ = 0;
  long long successful_ = 0;
  long long iterations_done_ = 0;
};

const ParamDecls<AcoSettings>& aco_decls() {
  static const ParamDecls<AcoSettings> decls = [] {
    ParamDecls<AcoSettings> d;
    d.integer("ants", &AcoSettings::ants, 20, 1, 1000000,
              "ants per iteration (paper 002 Table 2: 20)")
        .integer("iterations", &AcoSettings::iterations, 150, 1, 10000000,
                 "iterations; the best path over all of them is returned (paper 002 Table 2: "
                 "150)")
        .number("evaporation", &AcoSettings::evaporation, 0.5, 0.0, 0.999,
                "pheromone evaporation rate rho per iteration (paper 002 Table 2: 0.5)")
        .number("alpha", &AcoSettings::alpha, 1.1, 0.0, 10.0,
                "pheromone factor: exponent of tau (paper 002 Table 2: 1.1)")
        .number("beta", &AcoSettings::beta, 4.0, 0.0, 20.0,
                "heuristic factor: exponent of eta = 1 / distance to the goal (paper 002 Table "
                "2: 4)")
        .number("q", &AcoSettings::q, 1.0, 1e-9, 1e9,
                "deposit constant Q: an ant that reached the goal adds Q / L (L: its path length "
                "in cells) to each cell of its path (paper 002 gives no value)")
        .number("initial_pheromone", &AcoSettings::initial_pheromone, 1.0, 1e-9, 1e9,
                "pheromone tau0 of every cell at the start (paper 002 gives no value)")
        // The grid planners' corner_rule (algos/search/grid_search_params.h).
        .include(&AcoSettings::rule, corner_rule_decls(CornerRule::allow));
    return d;
  }();
  return decls;
}

class AcoPlanner final : public Planner {
 public:
  explicit AcoPlanner(const AcoSettings& settings) : settings_(settings) {}

  PlanResult plan(const PlanRequest& request) const override {
    PlanResult result;
    result.rule = settings_.rule;
    if (request.start == request.goal) {
      result.failure = Failure::none;
      result.path = {centre(request.start)};
      result.work.ant_steps = 0;
      return result;
    }
    AcoScratch& s = request.scratch.get<AcoScratch>();
    Colony colony(request, settings_, s);
    bool completed = false;
    {
      PhaseTimer timer(result, "search");
      completed = colony.run();
    }
    result.work.ant_steps = colony.steps();
    count_collision_checks(colony.cell_tests());
    result.extra.emplace_back("successful_ants", static_cast<double>(colony.successful()));
    result.extra.emplace_back("iterations", static_cast<double>(colony.iterations_done()));
    // A deadline that stops the colony is a limit even with a path in hand: the path of an
    // unfinished run depends on when the clock ran out (the planner contract).
    if (!colony.found() || !completed) {
      result.failure = Failure::limit;
      result.message = completed        ? "no ant reached the goal in any iteration"
                       : colony.found() ? "deadline passed before the last iteration"
                                        : "deadline passed before any ant reached the goal";
      return result;
    }
    result.failure = Failure::none;
    result.path.reserve(s.best.size());
    for (const int index : s.best) result.path.push_back(centre(request.grid.cell_of(index)));
    return result;
  }

 private:
  AcoSettings settings_;
};

}  // namespace

PlannerInfo aco_planner() {
  PlannerInfo info;
  info.kind = PlannerKind::swarm;
  info.name = "aco";
  info.summary = "ant colony (Ant System) on the 8-connected grid, paper 002 Table 2 defaults";
  info.source = "docs/PLANNERS.md Baselines; paper 002 section 5, Table 2; Dorigo et al. 1996";
  info.counters = {
      {"ant_steps", "moves made by all ants of all iterations"},
      {"collision_checks", "8 neighbour-cell tests at every position an ant moves on from"}};
  info.stochastic = true;
  info.proves_no_path = false;  // gives up with limit after its budget
  info.params = aco_decls().specs();
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<AcoPlanner>(aco_decls().read(params));
  };
  return info;
}

}  // namespace agv
