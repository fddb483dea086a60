#include "algos/search/bidir_astar.h"

// Bidirectional A*: a forward search from the start (h = distance to the goal) and a backward
// search from the goal (h = distance to the start) alternate one expansion each.
//
// Why it is not a Policy of the one search core (algos/search/search_core.h): the core owns ONE open
// list and stops when it pops the goal; a policy can change the key, the cost, the heuristic and
// the move set, not the number of frontiers or the stopping rule. Here two frontiers interleave,
// every relaxation may update the best meeting cost mu across them, and the search stops on a
// test over both list tops. So this file has its own small loop, built from the same parts: the
// open list (algos/search/open_list.h, same key packing and tie rule), GridSearchBuffers (one per
// direction), and the corner rule's move table (core/corner_rule.h).
//
// Termination (front-to-end bidirectional A* with a consistent heuristic): mu = min over cells
// labelled by both searches of g_forward + g_backward, updated whenever either search sets a g.
// Each list's minimum f is a lower bound on every start-goal path not yet found, so the search
// stops as soon as min f of EITHER open list is >= mu; mu is then optimal. With an inconsistent
// heuristic (e.g. euclidean under diagonal_cost < sqrt 2, or octile_as_printed) the closed set
// loses that guarantee; the default octile is consistent for every diagonal_cost in [1, 2].
// Moves are symmetric under every corner rule (a diagonal's two side cells are the same both
// ways), so the backward search expands with the same move table.
//
// expanded_nodes: cells taken off either open list and closed (each at most once per direction).

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "algos/search/grid_search_params.h"
#include "algos/postprocess/postprocess_params.h"
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

template <class H>
BidirOutcome bidir_search(const Grid& grid, Cell start, Cell goal, const GridSearchSetup& setup,
                          const Deadline& deadline, H h_fn, BidirBuffers& buffers) {
  using open_key::index_of;
  using open_key::pack;
  const int stride = grid.stride();
  const std::uint8_t* occ = grid.occupancy();
  const MoveTable& moves = move_table(setup.rule);
  int offset[8];
  double step[8];
  for (int d = 0; d < 8; ++d) {
    offset[d] = kDy[d] * stride + kDx[d];
    step[d] = is_diagonal(d) ? setup.diagonal_cost : 1.0;
  }
  struct Side {
    std::uint8_t* stamp;
    SearchNode* nodes;
    OpenList* open;
    std::uint8_t open_stamp;
    std::uint8_t closed_stamp;
    Cell target;
  };
  Side sides[2];
  const Cell sources[2] = {start, goal};
  for (int s = 0; s < 2; ++s) {
    GridSearchBuffers& b = buffers.side[s];
    b.begin(grid.padded_size());
    sides[s] = {b.stamps(), b.nodes(), &b.open(), b.open_stamp(), b.closed_stamp(),
                sources[1 - s]};
    sides[s].open->reset(sides[s].nodes);
  }
  auto h_of = [&](const Side& side, int x, int y) {
    return h_fn(std::abs(side.target.x - x), std::abs(side.target.y - y));
  };
  auto f_of = [&](const Side& side, int index) {
    const Cell c = grid.cell_of(index);
    return side.nodes[index].g + h_of(side, c.x, c.y);
  };

  BidirOutcome out;
  double mu = std::numeric_limits<double>::infinity();
  for (int s = 0; s < 2; ++s) {
    Side& side = sides[s];
    const int source = grid.index(sources[s]);
    side.stamp[source] = side.open_stamp;
    side.nodes[source].g = 0.0;
    side.nodes[source].parent_dir = static_cast<std::uint8_t>(kNoDirection);
    side.open->push(pack(h_of(side, sources[s].x, sources[s].y), 0.0, source));
  }
  if (start == goal) {
    out.meet = grid.index(start);
    return out;
  }

  int s = 0;
  for (;;) {
    Side& side = sides[s];
    Side& other = sides[1 - s];
    // A list that ran empty has labelled everything reachable from its source: mu is final.
    if (side.open->empty() || other.open->empty()) break;
    // Stopping test: either list's min f bounds every path not yet found from below.
    if (f_of(side, index_of(side.open->top())) >= mu || f_of(other, index_of(other.open->top())) >= mu)
      break;
    if ((out.expanded & (kDeadlineInterval - 1)) == 0 && deadline.expired()) {
      out.failure = Failure::limit;
      return out;
    }
    const int i = index_of(side.open->pop());
    side.stamp[i] = side.closed_stamp;
    ++out.expanded;
    const double g = side.nodes[i].g;
    unsigned free_mask = 0;
    for (int d = 0; d < 8; ++d) free_mask |= static_cast<unsigned>(occ[i + offset[d]] == 0) << d;
    unsigned allowed = moves[free_mask];
    const Cell here = grid.cell_of(i);
    while (allowed != 0) {
      const int d = std::countr_zero(allowed);
      allowed &= allowed - 1;
      const int c = i + offset[d];
      const std::uint8_t seen = side.stamp[c];
      if (seen == side.closed_stamp) continue;
      const double child_g = g + step[d];
      SearchNode& child = side.nodes[c];
      if (seen == side.open_stamp && !(child_g < child.g)) continue;
      child.g = child_g;
      child.parent_dir = static_cast<std::uint8_t>(d);
      const double key = child_g + h_of(side, here.x + kDx[d], here.y + kDy[d]);
      if (seen == side.open_stamp) {
        side.open->update(pack(key, child_g, c));
      } else {
        side.stamp[c] = side.open_stamp;
        side.open->push(pack(key, child_g, c));
      }
      const std::uint8_t other_seen = other.stamp[c];
      if (other_seen == other.open_stamp || other_seen == other.closed_stamp) {
        const double through = child_g + other.nodes[c].g;
        if (through < mu) {
          mu = through;
          out.meet = c;
        }
      }
    }
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

class BidirAStarPlanner final : public Planner {
 public:
  explicit BidirAStarPlanner(const Params& params)
      : setup_(grid_search_setup_of(params)), heuristic_(heuristic_of(params)) {
    read_smoothing_params(params, post_);
  }

  PlanResult plan(const PlanRequest& request) const override {
    if (auto bad = check_grid_query(request, setup_.rule)) return std::move(*bad);
    PlanResult result;
    result.rule = setup_.rule;
    auto& buffers = request.scratch.get<BidirBuffers>();
    {
      PhaseTimer timer(result, "search");
      const BidirOutcome out = with_heuristic(heuristic_, setup_.diagonal_cost, [&](auto h) {
        return bidir_search(request.grid, request.start, request.goal, setup_, request.deadline,
                            h, buffers);
      });
      result.expanded_nodes = out.expanded;
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
    apply_postprocessing(request.grid, post_, result);
    return result;
  }

 private:
  GridSearchSetup setup_;
  Heuristic heuristic_;
  PostprocessOptions post_;
};

}  // namespace

PlannerInfo bidir_astar_planner() {
  PlannerInfo info;
  info.name = "bidir_astar";
  info.summary = "bidirectional A*: forward and backward searches alternate, stop when either "
                 "list's min f reaches the best meeting cost; optimal";
  info.source = "paper 002 baseline; PLANNERS.md Dijkstra, bidirectional A*";
  info.expanded_nodes_meaning =
      "cells taken off either open list and closed (forward and backward counted separately)";
  info.params = {corner_rule_param(CornerRule::allow), heuristic_param(Heuristic::octile),
                 diagonal_cost_param()};
  for (auto& spec : smoothing_params(SmoothingMode::none)) info.params.push_back(std::move(spec));
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<BidirAStarPlanner>(params);
  };
  return info;
}

}  // namespace agv
