#include "algos/search/bidir_astar.h"

// Bidirectional A*: a forward search from the start (h = distance to the goal) and a backward
// search from the goal (h = distance to the start) alternate one expansion each.
//
// Why it is not a plain Policy of grid_search() (algos/search/search_core.h): that loop owns ONE
// open list and stops when it pops the goal; a policy can change the key, the cost, the
// heuristic and the move set, not the number of frontiers or the stopping rule. Here two
// frontiers interleave, every relaxation may update the best meeting cost mu across them, and
// the search stops on a test over both list tops. So this file has its own small loop over two
// SearchFrontiers (one GridSearchBuffers per direction), and each expansion is the core's own
// GridExpander::expand() with an AStarPolicy towards the other side's source; a listener on the
// relaxations updates mu.
//
// Termination (front-to-end bidirectional A* with a consistent heuristic): mu = min over cells
// labelled by both searches of g_forward + g_backward, updated whenever either search sets a g.
// Each list's minimum f is a lower bound on every start-goal path not yet found, so the search
// stops as soon as min f of EITHER open list is >= mu; mu is then optimal. With an inconsistent
// heuristic (e.g. euclidean under diagonal_cost < sqrt 2, or octile_as_printed) the closed set
// loses that guarantee; the default octile is consistent for every diagonal_cost in [1, 2].
// `meet: first` (paper 002's variant, docs/PLANNERS.md) drops that test and stops at the first
// cell closed by both searches: not optimal in general.
// Moves are symmetric under every corner rule (a diagonal's two side cells are the same both
// ways), so the backward search expands with the same move table.
//
// search_expansions: cells taken off either open list and closed (each at most once per
// direction); collision_checks: 8 neighbour-cell tests per expansion (docs/METRICS.md).

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "algos/postprocess/postprocess_params.h"
#include "algos/search/grid_search_params.h"
#include "algos/search/search_core.h"

namespace agv {

namespace {

struct BidirBuffers {
  GridSearchBuffers side[2];  // 0 forward, 1 backward
  std::vector<Cell> cells;
};

struct BidirOutcome {
  Failure failure = Failure::none;
  std::int64_t expanded = 0;
  int meet = -1;  // padded index of the meeting cell
};

// Sees one direction's relaxations: a child also labelled by the other direction is a meeting
// cell; mu keeps the cheapest.
struct MeetingListener {
  void generated(int /*index*/) {}
  void expanded(int /*index*/, double /*g*/) {}
  void relaxed(int index, double g, double /*key*/) {
    if (!other->labelled(index)) return;
    const double through = g + other->nodes[index].g;
    if (through < *mu) {
      *mu = through;
      *meet = index;
    }
  }
  const SearchFrontier* other;
  double* mu;
  int* meet;
};

enum class Meet { optimal, first };

template <class H>
BidirOutcome bidir_search(const Grid& grid, Cell start, Cell goal, const GridSearchSetup& setup,
                          Meet meet, const Deadline& deadline, H h_fn, BidirBuffers& buffers) {
  using open_key::index_of;
  const GridExpander expander(grid, setup);
  for (GridSearchBuffers& b : buffers.side) b.begin(grid.padded_size());
  SearchFrontier sides[2] = {SearchFrontier(buffers.side[0]), SearchFrontier(buffers.side[1])};
  // Forward towards the goal, backward towards the start.
  const AStarPolicy<H> policies[2] = {AStarPolicy<H>(h_fn, goal), AStarPolicy<H>(h_fn, start)};
  auto f_of = [&](int s, int index) {
    const Cell c = grid.cell_of(index);
    return sides[s].nodes[index].g + policies[s].heuristic(c.x, c.y, index);
  };

  BidirOutcome out;
  double mu = std::numeric_limits<double>::infinity();
  MeetingListener listeners[2] = {{&sides[1], &mu, &out.meet}, {&sides[0], &mu, &out.meet}};
  const Cell sources[2] = {start, goal};
  for (int s = 0; s < 2; ++s) {
    const int source = grid.index(sources[s]);
    sides[s].push_source(source, policies[s].heuristic(sources[s].x, sources[s].y, source),
                         listeners[s]);
  }
  if (start == goal) {
    out.meet = grid.index(start);
    return out;
  }

  int s = 0;
  for (;;) {
    SearchFrontier& side = sides[s];
    SearchFrontier& other = sides[1 - s];
    // A list that ran empty has labelled everything reachable from its source: mu is final.
    if (side.open.empty() || other.open.empty()) break;
    // Stopping test: either list's min f bounds every path not yet found from below.
    if (meet == Meet::optimal &&
        (f_of(s, index_of(side.open.top())) >= mu || f_of(1 - s, index_of(other.open.top())) >= mu))
      break;
    if ((out.expanded & (kDeadlineInterval - 1)) == 0 && deadline.expired()) {
      out.failure = Failure::limit;
      return out;
    }
    const int i = side.pop_and_close();
    ++out.expanded;
    // Meet-first: the path through the first cell both searches have closed.
    if (meet == Meet::first && other.stamp[i] == other.closed_stamp) {
      out.meet = i;
      break;
    }
    expander.expand(i, side.nodes[i].g, policies[s], side, listeners[s]);
    s = 1 - s;  // strict alternation
  }
  if (out.meet < 0) out.failure = Failure::no_path;
  return out;
}

// Start ... meet from the forward parents, then meet ... goal from the backward ones.
void trace_meeting(const Grid& grid, const BidirBuffers& buffers, int meet,
                   std::vector<Cell>& cells) {
  cells.clear();
  const int stride = grid.stride();
  const SearchNode* forward = buffers.side[0].nodes();
  for (int i = meet;;) {
    cells.push_back(grid.cell_of(i));
    const int d = forward[i].parent_dir;
    if (d == kNoDirection) break;
    i -= kDy[d] * stride + kDx[d];
  }
  std::reverse(cells.begin(), cells.end());
  const SearchNode* backward = buffers.side[1].nodes();
  for (int i = meet;;) {
    const int d = backward[i].parent_dir;
    if (d == kNoDirection) break;
    i -= kDy[d] * stride + kDx[d];
    cells.push_back(grid.cell_of(i));
  }
}

struct BidirOptions {
  GridSearchOptions search;
  Meet meet = Meet::optimal;
  PostprocessOptions post;  // smoothing only
};

ParamDecls<BidirOptions> bidir_decls() {
  ParamDecls<BidirOptions> d;
  d.include(&BidirOptions::search, grid_search_decls(CornerRule::allow, Heuristic::octile))
      .choice("meet", &BidirOptions::meet, Meet::optimal,
              ChoiceTable<Meet>{{"optimal", Meet::optimal}, {"first", Meet::first}},
              "stopping rule: optimal = when either list's min f reaches the best meeting cost "
              "(an optimal path); first = at the first cell both searches have closed, the path "
              "through it (paper 002's bidirectional A*, longer than its A*)")
      .include(&BidirOptions::post, smoothing_decls(SmoothingMode::none));
  return d;
}

class BidirAStarPlanner final : public Planner {
 public:
  explicit BidirAStarPlanner(const BidirOptions& options) : o_(options) {}

  PlanResult plan(const PlanRequest& request) const override {
    if (auto bad = check_grid_query(request, o_.search.setup.rule)) return std::move(*bad);
    PlanResult result;
    result.rule = o_.search.setup.rule;
    auto& buffers = request.scratch.get<BidirBuffers>();
    {
      PhaseTimer timer(result, "search");
      const BidirOutcome out =
          with_heuristic(o_.search.heuristic, o_.search.setup.diagonal_cost, [&](auto h) {
            return bidir_search(request.grid, request.start, request.goal, o_.search.setup, o_.meet,
                                request.deadline, h, buffers);
          });
      result.work.search_expansions = out.expanded;
      // Every cell taken off a list is expanded (the meeting test is on relaxations).
      count_collision_checks(kCellTestsPerExpansion * out.expanded);
      if (out.failure == Failure::none) {
        trace_meeting(request.grid, buffers, out.meet, buffers.cells);
        result.path = cell_centres(buffers.cells);
        result.failure = Failure::none;
      } else {
        result.failure = out.failure;
        result.message = out.failure == Failure::limit ? "deadline passed during the search"
                                                       : "the goal is unreachable from the start";
      }
    }
    apply_postprocessing(request.grid, o_.post, result, request.deadline);
    return result;
  }

 private:
  BidirOptions o_;
};

}  // namespace

PlannerInfo bidir_astar_planner() {
  PlannerInfo info;
  info.name = "bidir_astar";
  info.summary =
      "bidirectional A*: forward and backward searches alternate, stop when either "
      "list's min f reaches the best meeting cost; optimal";
  info.source = "paper 002 baseline; docs/PLANNERS.md Dijkstra, bidirectional A*";
  info.counters = {
      {"search_expansions",
       "cells taken off either open list and closed (forward and backward counted separately)"},
      {"collision_checks", "8 neighbour-cell tests per expanded cell"}};
  info.params = bidir_decls().specs();
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<BidirAStarPlanner>(bidir_decls().read(params));
  };
  return info;
}

}  // namespace agv
