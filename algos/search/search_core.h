#pragma once
// The one best-first grid search of the A* family (docs/ARCHITECTURE.md "Style" item 2, after
// warthog's unidirectional_search): Dijkstra, A* and the A* variants of docs/PLANNERS.md are small
// Policy types plugged into grid_search(), never copies of its loop.
//
// The loop: poll the deadline every kDeadlineInterval expansions; pop the best open cell and
// close it; stop at the goal; otherwise build the cell's free-neighbour byte from the padded
// occupancy, look the allowed moves up in the corner rule's table (core/corner_rule.h: one
// lookup per expansion), AND the policy's direction mask, and relax each allowed child that is
// not closed: a new child is pushed, an open one whose g improves gets its key updated. Closed
// cells are never reopened (closed set), also under inconsistent (weighted) heuristics.
//
// A Policy is a plain type with these members, called inline (no virtual call per node).
// Derive from PolicyDefaults and redeclare only what differs:
//
//   double heuristic(int x, int y, int index) const;
//       (a) the h term of cell (x, y) (padded index `index`), already weighted as the variant
//       wants: A* h(node); alternative A* H / Q(node) (paper 003 eq. 5); kinematic A*
//       (1.5 + r / R) * h (paper 004). Called once per relaxation (new or improved g).
//   double key(double g, double h, int dir_in, int dir_out) const;
//       (b) the open-list priority of a child with cost-so-far g and h from heuristic().
//       dir_in is the move parent -> node (kNoDirection at the start), dir_out the move
//       node -> child (directions of corner_rule.h). Default g + h; improved A* (paper 002
//       eq. 8-10): g + C * h with C = 1.2 when dir_in != dir_out.
//   double child_g(double parent_g, double step_cost, int x, int y) const;
//       (c) g of the child (x, y) reached from a node with g = parent_g by a move of cost
//       step_cost. Default parent_g + step_cost. MA* euclid_from_start (paper 000 eq. 4.1b as
//       printed): the straight-line distance from the start to (x, y), the same value on every
//       relaxation, so the strict `<` test below fixes g and the parent at discovery.
//   std::uint8_t direction_mask(int x, int y, int index, std::uint8_t free_mask) const;
//       (d) the directions (bit d = direction d) the node may expand, ANDed with the corner
//       rule's allowed moves. free_mask has bit d set when neighbour d is free (0xFF: the 3x3
//       neighbourhood is obstacle-free, kinematic A*'s five-direction case). Default 0xFF.
//
// (e) the corner rule and (f) diagonal_cost come in GridSearchSetup. (g) A Listener (default
// NullListener, whose empty inline hooks compile away, docs/ARCHITECTURE.md "Style" item 3) sees
// every cell put on the open list for the first time (generated, the source included), every
// expansion and every relaxation, for counting or for recording a search picture.
//
// The expansion itself (free-neighbour byte, move table, policy hooks, relaxation) is
// GridExpander::expand() on a SearchFrontier, so a search with more than one frontier
// (bidirectional A*) runs the same code per direction with its own loop and stopping rule.
//
// Open list (algos/search/open_list.h): a binary heap with decrease-key and a held slot, keys
// packed as (priority, g, cell index). Ties: equal priority -> larger g first -> lower padded
// index; deterministic. A re-relaxed cell's key may go up as well as down (turn-dependent keys).
//
// Memory, all in GridSearchBuffers (from Scratch: one per worker thread, shared by every grid
// planner): one byte of search stamp per padded cell (stamp == open: seen this search,
// open + 1: closed; anything else: unseen, so a search clears nothing; every 126 searches the
// stamps are zeroed once), one 16-byte SearchNode per padded cell (g, heap slot, parent
// direction), and the heap. They grow only when a grid is larger than any before (the heap when
// it outgrows its storage); nothing is allocated per expansion.
//
// perf/README.md "Grid search" records the designs measured before choosing this one.

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "algos/planner.h"
#include "algos/search/open_list.h"
#include "core/corner_rule.h"
#include "core/grid.h"
#include "core/line_of_sight.h"

namespace agv {

inline constexpr int kNoDirection = 8;
// Deadline poll period in expansions (docs/ARCHITECTURE.md "Style" item 7); a power of two.
inline constexpr std::int64_t kDeadlineInterval = 1024;

// collision_checks of a grid search (docs/METRICS.md "Work counters"): an expansion reads the
// occupancy of all 8 neighbours (the free-neighbour byte), whatever moves it then relaxes.
inline constexpr std::int64_t kCellTestsPerExpansion = 8;

// PlannerInfo::counters of the planners that are a grid search (plus post-processing).
inline std::vector<std::pair<std::string, std::string>> grid_search_counters() {
  return {
      {"search_expansions", "cells taken off the open list and closed, each once (goal included)"},
      {"collision_checks",
       "8 neighbour-cell tests per expanded cell (the goal is not expanded), plus the "
       "segments and points its post-processing tests"}};
}

struct GridSearchSetup {
  CornerRule rule = CornerRule::allow;
  double diagonal_cost = 1.41421356237309504880;
};

struct GridSearchOutcome {
  // none: the goal was reached; no_path: the open list ran empty; limit: the deadline passed.
  Failure failure = Failure::none;
  // Cells taken off the open list and closed (each at most once per search, the goal included).
  std::int64_t expanded = 0;
  double goal_g = 0.0;  // g of the goal when reached
};

struct NullListener {
  void generated(int /*index*/) {}
  void expanded(int /*index*/, double /*g*/) {}
  void relaxed(int /*index*/, double /*g*/, double /*key*/) {}
};

struct PolicyDefaults {
  double key(double g, double h, int /*dir_in*/, int /*dir_out*/) const { return g + h; }
  double child_g(double parent_g, double step_cost, int /*x*/, int /*y*/) const {
    return parent_g + step_cost;
  }
  std::uint8_t direction_mask(int /*x*/, int /*y*/, int /*index*/, std::uint8_t /*free*/) const {
    return 0xFF;
  }
};

// A*: f = g + h(node, goal) with a heuristic functor of algos/search/heuristics.h (Dijkstra: zero).
template <class H>
struct AStarPolicy : PolicyDefaults {
  AStarPolicy(H heuristic_fn, Cell goal) : h_fn(heuristic_fn), goal_cell(goal) {}
  double heuristic(int x, int y, int /*index*/) const {
    return h_fn(std::abs(goal_cell.x - x), std::abs(goal_cell.y - y));
  }
  H h_fn;
  Cell goal_cell;
};

// Per-thread buffers of every grid search (Scratch::get<GridSearchBuffers>()).
class GridSearchBuffers {
 public:
  // Makes room for a grid of `padded_size` cells and starts a new search number.
  void begin(int padded_size);
  std::uint8_t* stamps() { return stamps_.data(); }
  SearchNode* nodes() { return nodes_.data(); }
  const SearchNode* nodes() const { return nodes_.data(); }
  std::uint8_t open_stamp() const { return open_stamp_; }
  std::uint8_t closed_stamp() const { return static_cast<std::uint8_t>(open_stamp_ + 1); }
  OpenList& open() { return open_; }

 private:
  std::vector<std::uint8_t> stamps_;
  std::vector<SearchNode> nodes_;
  std::uint8_t open_stamp_ = 0;
  OpenList open_;
};

namespace search_detail {

// n / d for 32-bit n by one multiplication (Lemire, Kaser, Kurz 2019, "fastdiv").
struct FastDivider {
  explicit FastDivider(std::uint32_t d) : m(~0ULL / d + 1) {}
  std::uint32_t operator()(std::uint32_t n) const {
    return static_cast<std::uint32_t>((static_cast<OpenKey>(m) * n) >> 64);
  }
  std::uint64_t m;
};

}  // namespace search_detail

// One search direction's state in its GridSearchBuffers (after begin()): the stamps with this
// search's open and closed values, the nodes and the open list.
struct SearchFrontier {
  explicit SearchFrontier(GridSearchBuffers& buffers)
      : stamp(buffers.stamps()),
        nodes(buffers.nodes()),
        open(buffers.open()),
        open_stamp(buffers.open_stamp()),
        closed_stamp(buffers.closed_stamp()) {
    open.reset(nodes);
  }
  // Labels `index` with g = 0 and no parent and pushes it with priority `key`.
  template <class Listener>
  void push_source(int index, double key, Listener& listener) {
    stamp[index] = open_stamp;
    nodes[index].g = 0.0;
    nodes[index].parent_dir = static_cast<std::uint8_t>(kNoDirection);
    listener.generated(index);
    open.push(open_key::pack(key, 0.0, index));
  }
  // Takes the best open cell off the list and closes it.
  int pop_and_close() {
    const int i = open_key::index_of(open.pop());
    stamp[i] = closed_stamp;
    return i;
  }
  bool labelled(int index) const {
    return stamp[index] == open_stamp || stamp[index] == closed_stamp;
  }

  std::uint8_t* stamp;
  SearchNode* nodes;
  OpenList& open;
  std::uint8_t open_stamp;
  std::uint8_t closed_stamp;
};

// What every expansion on one grid under one setup shares: move offsets and costs, the corner
// rule's move table, the padded index -> (x, y) division.
class GridExpander {
 public:
  GridExpander(const Grid& grid, const GridSearchSetup& setup)
      : stride_(grid.stride()),
        occ_(grid.occupancy()),
        moves_(move_table(setup.rule)),
        row_of_(static_cast<std::uint32_t>(grid.stride())) {
    for (int d = 0; d < 8; ++d) {
      offset_[d] = kDy[d] * stride_ + kDx[d];
      step_[d] = is_diagonal(d) ? setup.diagonal_cost : 1.0;
    }
  }

  int stride() const { return stride_; }

  // Relaxes the children of the just-closed cell i (cost so far g) that the corner rule and the
  // policy's direction mask allow and that are not closed: a new child is pushed, an open one
  // whose g improves gets its key updated.
  template <class Policy, class Listener>
  [[gnu::always_inline]] inline void expand(int i, double g, const Policy& policy,
                                            SearchFrontier& frontier, Listener& listener) const {
    using open_key::pack;
    unsigned free_mask = 0;
    for (int d = 0; d < 8; ++d) free_mask |= static_cast<unsigned>(occ_[i + offset_[d]] == 0) << d;
    // Padded index i = (y + 1) * stride + (x + 1).
    const auto padded_row = static_cast<int>(row_of_(static_cast<std::uint32_t>(i)));
    const int x = i - padded_row * stride_ - 1;
    const int y = padded_row - 1;
    const auto free_byte = static_cast<std::uint8_t>(free_mask);
    unsigned allowed = moves_[free_byte] & policy.direction_mask(x, y, i, free_byte);
    std::uint8_t* stamp = frontier.stamp;
    SearchNode* nodes = frontier.nodes;
    const std::uint8_t open = frontier.open_stamp;
    const std::uint8_t closed = frontier.closed_stamp;
    const int dir_in = nodes[i].parent_dir;

    while (allowed != 0) {
      const int d = std::countr_zero(allowed);
      allowed &= allowed - 1;
      const int c = i + offset_[d];
      const std::uint8_t seen = stamp[c];
      if (seen == closed) continue;
      const int cx = x + kDx[d];
      const int cy = y + kDy[d];
      const double child_g = policy.child_g(g, step_[d], cx, cy);
      SearchNode& child = nodes[c];
      if (seen == open && !(child_g < child.g)) continue;
      child.g = child_g;
      child.parent_dir = static_cast<std::uint8_t>(d);
      const double key = policy.key(child_g, policy.heuristic(cx, cy, c), dir_in, d);
      listener.relaxed(c, child_g, key);
      if (seen == open) {
        frontier.open.update(pack(key, child_g, c));
      } else {
        stamp[c] = open;
        listener.generated(c);
        frontier.open.push(pack(key, child_g, c));
      }
    }
  }

 private:
  int stride_;
  const std::uint8_t* occ_;
  const MoveTable& moves_;
  int offset_[8];
  double step_[8];
  search_detail::FastDivider row_of_;
};

// Runs one search from start to goal (both in bounds and free). The parent chain of the goal is
// left in `buffers` for trace_cells().
template <class Policy, class Listener = NullListener>
GridSearchOutcome grid_search(const Grid& grid, Cell start, Cell goal, const GridSearchSetup& setup,
                              const Deadline& deadline, const Policy& policy,
                              GridSearchBuffers& buffers, Listener&& listener = Listener{}) {
  using open_key::index_of;
  const GridExpander expander(grid, setup);
  const int stride = expander.stride();
  buffers.begin(grid.padded_size());
  SearchFrontier frontier(buffers);
  const std::uint8_t* stamp = frontier.stamp;
  const OpenList& queue = frontier.open;

  GridSearchOutcome out;
  const int source = grid.index(start);
  const int target = grid.index(goal);
  const double start_h = policy.heuristic(start.x, start.y, source);
  frontier.push_source(source, policy.key(0.0, start_h, kNoDirection, kNoDirection), listener);

  while (!queue.empty()) {
    if ((out.expanded & (kDeadlineInterval - 1)) == 0 && deadline.expired()) {
      out.failure = Failure::limit;
      return out;
    }
    const int i = frontier.pop_and_close();
    if (!queue.empty()) {
      // The next cell to expand is usually the current top: fetch its three stamp rows while
      // this one is expanded (the stamp loads are the search's main cache misses).
      const int next = index_of(queue.top());
      __builtin_prefetch(stamp + next - stride - 1);
      __builtin_prefetch(stamp + next - 1);
      __builtin_prefetch(stamp + next + stride - 1);
    }
    ++out.expanded;
    const double g = frontier.nodes[i].g;
    listener.expanded(i, g);
    if (i == target) {
      out.goal_g = g;
      return out;
    }
    expander.expand(i, g, policy, frontier, listener);
  }
  out.failure = Failure::no_path;
  return out;
}

// The cells of the goal's parent chain after a successful grid_search(), start first.
void trace_cells(const GridSearchBuffers& buffers, const Grid& grid, Cell goal,
                 std::vector<Cell>& cells);
// Cell centres (x + 0.5, y + 0.5), in order.
std::vector<Point> cell_centres(const std::vector<Cell>& cells);

// Failure::invalid_input with a message when start or goal is outside the grid or blocked;
// nullopt when the query is searchable.
std::optional<PlanResult> check_grid_query(const PlanRequest& request, CornerRule rule);

// The whole plan call of a planner that is just a search: checks the query, runs grid_search()
// under a PhaseTimer "search", returns the cell-centre path and the search_expansions counter.
// `listener` sees the search (grid_search()); it is not called when the query is invalid.
template <class Policy, class Listener = NullListener>
PlanResult plan_grid_search(const PlanRequest& request, const GridSearchSetup& setup,
                            const Policy& policy, Listener&& listener = Listener{}) {
  if (auto bad = check_grid_query(request, setup.rule)) return std::move(*bad);
  PlanResult result;
  result.rule = setup.rule;
  {
    PhaseTimer timer(result, "search");
    auto& buffers = request.scratch.get<GridSearchBuffers>();
    const GridSearchOutcome out = grid_search(request.grid, request.start, request.goal, setup,
                                              request.deadline, policy, buffers, listener);
    result.work.search_expansions = out.expanded;
    // The goal is taken off the list but not expanded: its neighbours are never read.
    count_collision_checks(kCellTestsPerExpansion *
                           (out.expanded - (out.failure == Failure::none ? 1 : 0)));
    if (out.failure == Failure::none) {
      std::vector<Cell> cells;
      trace_cells(buffers, request.grid, request.goal, cells);
      result.path = cell_centres(cells);
      result.failure = Failure::none;
    } else {
      result.failure = out.failure;
      result.message = out.failure == Failure::limit ? "deadline passed during the search"
                                                     : "the goal is unreachable from the start";
    }
  }
  return result;
}

}  // namespace agv
